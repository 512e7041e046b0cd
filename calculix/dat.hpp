// Reading ccx's .dat file of a *FREQUENCY step with *NODE PRINT U.
//
// The file holds the table "E I G E N V A L U E   O U T P U T" (mode number, eigenvalue,
// frequency in rad/time and cycles/time, imaginary part: 7 significant digits), then for
// each mode a block "E I G E N V A L U E    N U M B E R   k" with the lines
// "node ux uy uz" of the printed node set (the beam nodes: ccx prints the mean of the
// expanded section's nodes). The eigenvectors are normalized to U^T M U = 1.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

namespace calculix {

struct DatMode {
  double omega = 0.0;  ///< rad/s, from the frequency column
  std::vector<double> ux, uy, uz;  ///< [node - 1], m per unit modal mass
};

/// Parses the modes of a .dat text whose nodes are 1 .. nodes. Throws
/// ring::NumericalError naming `name` and the line for a file that is not what ccx writes
/// (a missing table, a mode without displacements, a node out of range).
std::vector<DatMode> read_frequency_dat(const std::string& text, int nodes, const std::string& name = "ring.dat");

/// A mode of a *COMPLEX FREQUENCY, CORIOLIS step: x(t) = Re(x e^{i omega t}) (checked: so read,
/// the lower mode of each of a spinning ring's pairs travels with the spin, as in the closed
/// form, tests/calculix/calculix_spin_test.cpp).
struct DatComplexMode {
  double omega = 0.0;  ///< rad/s, the real part from the rad/time column (the frame that turns)
  double imag = 0.0;   ///< rad/s, ccx's imaginary part (round-off of an undamped model)
  std::vector<std::complex<double>> ux, uy;  ///< [node - 1], real + i imaginary part
};

/// Parses the complex modes of a .dat text whose nodes are 1 .. nodes: the last eigenvalue
/// table (mode, rad/time, cycles/time, imaginary part), then per mode the blocks "R E A L
/// P A R T" and "I M A G I N A R Y   P A R T" of *NODE PRINT U. Throws ring::NumericalError
/// naming `name` and the line for a file that is not what ccx writes.
std::vector<DatComplexMode> read_complex_dat(const std::string& text, int nodes, const std::string& name = "ring.dat");

/// The eigenvalues (rad^2/s^2, signed: a negative one is a mode without stiffness) of the
/// first eigenvalue table of a .dat text: a *FREQUENCY step's (mode, eigenvalue, rad/time,
/// cycles/time, imaginary part). Throws ring::NumericalError naming `name` when there is none.
std::vector<double> read_real_eigenvalues(const std::string& text, const std::string& name = "ring.dat");

/// A static step's .dat (*NODE PRINT U of every node after every increment: "displacements
/// (vx,vy,vz) for set NALL and time t"; with displacement control also *NODE PRINT RF of the
/// driven node: "forces (fx,fy,fz) for set NDRIVE and time t", after the displacements; with
/// [plates] the totals of the plate node sets after them).
struct DatStatic {
  /// One converged increment. `time` is ccx's total time: with steps of period 1, the
  /// step's number minus 1 plus its fraction done.
  struct Increment {
    double time = 0.0;
    std::vector<double> ux, uy;  ///< [node - 1], m
    /// The one node's reaction force of the forces block (N; NaN without one).
    std::array<double, 2> force{NAN, NAN};
    /// [plates]: the total RF of the plate nodes of NPLATE0 and NPLATE1 ("total force
    /// (fx,fy,fz) for set NPLATEp and time t", *NODE PRINT, TOTALS=ONLY), N; NaN without.
    std::array<std::array<double, 2>, 2> plates{{{NAN, NAN}, {NAN, NAN}}};
  };
  double time = 0.0;           ///< the total time of the last block
  int increments = 0;          ///< blocks printed: the converged increments
  std::vector<double> ux, uy;  ///< [node - 1], m, of the last block
  std::array<double, 2> force{NAN, NAN};  ///< of the last block
  std::vector<Increment> all;  ///< every block, in order
};

/// Parses a static step's .dat of nodes 1 .. nodes. Throws ring::NumericalError naming the
/// line for a file that is not what ccx writes, or that has no displacements; a forces block
/// must hold one node's row and follow its increment's displacements.
DatStatic read_static_dat(const std::string& text, int nodes, const std::string& name = "ring.dat");

/// The displacement history of a dynamic step's .dat (*NODE PRINT of a node set after
/// every increment).
struct DatHistory {
  std::vector<double> t;                    ///< [increment], s
  std::vector<std::vector<double>> ux, uy;  ///< [node of `nodes`][increment], m
};

/// Parses the blocks of the nodes `nodes` (1-based numbers, in the order wanted; each must
/// be printed once per block). Throws ring::NumericalError naming the line.
DatHistory read_history_dat(const std::string& text, const std::vector<int>& nodes, const std::string& name = "ring.dat");

/// ccx's "number of equations" in its log (the size of its system), or 0 if absent.
long long equation_count(const std::string& log);

}  // namespace calculix
