// Frequencies under load of the geometrically exact FE beam (modes.preload = "static"):
// the lowest modes of small oscillations about the static equilibrium q* of [static] at
// its full load,
//
//   T(q*, 1) x = omega^2 M x,
//
// T(q, s) = hess V(q) - s hess Phi(q) the beam's Newton tangent (nonlinear.hpp,
// BeamPotential: the beam, springs, foundation, and the load stiffness of follower and
// central pressure), M the beam's mass. NO deal.II includes here (see modes.hpp).
//
// Method (preload.cpp), one discretization (fem.elements cells of fem.degree):
//  - q*: the FE statics' own equilibrium path from rest to the full load (static_path.hpp,
//    trace_path: load stepping, arc length through limit points), as fem::solve_static
//    follows it; statics.path is ignored (the modes need the full load's equilibrium). A
//    path that does not reach the full load (past a bifurcation or a limit point, contact)
//    is a ring::NumericalError;
//  - T(q*, 1) on the reduced unknowns of the beam (make_beam: RingModel, or the Reissner
//    TimoshenkoModel for ring.theory = "timoshenko"): the supports are linear constraints,
//    exact at any displacement and eliminated, so the reduced space is the constraints'
//    tangent space at q* and they carry no multiplier (prestress) term: the prestress is
//    in the beam's own Hessian (EA eps and EI kappa at q*);
//  - M: the model's mass(), the linear model's consistent mass, which is the geometrically
//    exact beam's: the fields are polar components in the basis of the undeformed point
//    (x = X + u t0 + w n0 with t0, n0 fixed in time), so the kinetic energy
//    rho A/2 int |x_t|^2 ds0 is quadratic in the field rates with constant coefficients
//    (the Reissner beam adds rho I/2 int psi_t^2 ds0, exact: psi_t is the section's
//    angular velocity).
//    Point masses: m on the vertex's Cartesian velocity (exact); J on the rate of the
//    linearized vertex rotation (u - w')/R, the response's constant mass (nonlinear.hpp):
//    exact for small rotations of the vertex. These are exactly the frequencies of
//    fem::respond's small oscillations about q*;
//  - the pencil by the chains' loaded-modes step (modal::loaded_modes: with
//    s = modal::bending_scale(spec), P = T + s M = L L^T and the largest eigenvalues
//    1 / (omega^2 + s) of L^-1 M L^-T; count + 8 pairs), then refined as the buckling
//    factors are (pencil.hpp: Ritz with K_0 = T(0, 0) applied in extended precision and
//    E = T(q*, 1) - K_0 + s M in double; inverse-iteration corrections with the sparse LU
//    of P). P not positive definite, or an omega^2 <= 0, is a ring::NumericalError: the
//    loaded ring is at or past a critical load;
//  - shapes: the displacement field x about the deformed state, sampled at the
//    ring::kStations common stations by RingModel::sample (radial and tangential in the
//    undeformed point's directions), as the modes' and buckling's.
// Inextensible (fem.extensible = false): the modes' rule, omega^2 at EA = beta EI / R^2 for
// beta = 1e6 and 2e6 (each with its own equilibrium), extrapolated to 2 omega^2(2 beta) -
// omega^2(beta); shapes of 2 beta.
// Reference (fem.reference = true): refused (check_preloaded_modes), see "Accuracy".
//
// Under a uniform follower pressure on the inextensible ring the equilibrium is the
// circle and T(q*, 1) = K_0 + p K_1 (buckling.hpp): each omega^2 falls to zero, linearly,
// at its critical pressure. The extensible beam shrinks by the hoop strain p R / EA first.
//
// max_residual: the modes' ratio ||r||_* / (||T x||_* + omega^2 ||M x||_*) in the dual
// norm of P = T - sigma M, sigma = -s (residual_norm = kDualResidualNorm, modes.hpp): it
// says that the eigen step solved the assembled pencil (~1e-11), not how well the
// assembled T(q*, 1) represents the model (below).
//
// Accuracy. The linear modes and buckling apply their stiffness K_0 in extended precision
// from the strain fields; the loaded tangent exists only as an assembled double matrix, and
// its rounding (~eps of the membrane entries EA) reaches a bending mode amplified by the
// membrane-to-bending spread of the stiffness, as the dense step's does: the refinement
// takes K_0 exactly but E = T(q*, 1) - K_0 + s M carries that rounding. Measured on the
// paper's ring (pin 270 deg, roller 90 deg; docs/measured.md), as the worst change of four
// omega when the same ring is meshed from the opposite pin (pin 90, roller 270: the same
// model, other rounding), at half the critical pressure: extensible, 16 elements,
// 2.6e-10 (p = 3) to 3.6e-9 (p = 8), 2.7e-8 (p = 12), 2.8e-7 (p = 16), 3.2e-9 at 64 cubic
// elements; inextensible (beta = 2e6: 18 times the paper's membrane stiffness, then
// extrapolated) 3e-8 (p = 3, 8), and a spread of 1.5e-7 between degrees 6 to 12. At a
// vanishing load, where E holds little, the unloaded modes (compute_modes) to 1.5e-9
// (p = 6, 8; the load's own change is 1e-9). The refinement does not remove that rounding
// (the dense step alone is at the same level at half the critical load, and 3 to 60 times
// farther from the unloaded modes at a vanishing load): it makes the pairs those of the
// assembled pencil, with a residual that says so. A reference refinement that stops when
// successive discretizations agree to fem.tolerance (default 1e-9) would stall on that
// rounding, so fem.reference is refused; the convergence is measured instead: order 3.98
// to 4.00 in the elements at p = 3, and 53 to 190 times per degree at 16 elements
// (p = 2..5), 16 elements of degree 6 within 2e-8 of 32 of degree 8 (extensible: follower
// pressure at half its critical value, and a squeeze of 3 EI/R^2 that shortens a diameter
// by 0.62 R). Against the multibody chain (inextensible): its error falls at order 2.00
// (fitted over n = 40, 80, 160: 1.993 to 2.005 for four modes and both loads), 3.6e-5 to
// 1.2e-3 at n = 160 (tests/fem_reference/fem_preload_test.cpp).
//
// Cost per discretization of N reduced unknowns: the statics (per Newton iteration an
// assembly and a sparse LU, O(N p)), two assemblies, one sparse LU, the dense step O(N^3)
// time and O(N^2) memory (about eight dense N x N matrices), the refinement
// O(rounds (m N p + N^2 m)) for m = count + 8 pairs; twice that when inextensible. The
// dense step stops at fem::kDenseBucklingLimit unknowns. Measured (release build, four
// modes): 16 cubic elements (N = 109) 0.04 s (pressure) to 0.09 s (squeeze); 16 of degree 8
// (N = 269) 0.25 to 0.33 s, inextensible 0.4 to 1.0 s; 32 of degree 8 (N = 541) 0.6 to 0.9 s.
#pragma once

#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem {

/// The `count` lowest modes about the equilibrium of `statics` at its full load (file
/// comment).
/// \param spec     as fem::solve_static takes it (supports that hold every rigid motion).
/// \param options  elements, degree (the reduced unknowns at most kDenseBucklingLimit),
///                 extensible; no reference, no rotary inertia (check_preloaded_modes).
/// \param statics  the loads (point loads, pressure, gravity) and the load steps of the
///                 path from rest; record and path are not used.
/// \param count    modes wanted, 1 <= count <= the reduced unknowns.
/// \return solver "fem"; model {elements, cells, degree, geometry, theory, extensible,
///         rotary_inertia (true for the Timoshenko theory, else false), preload = "static",
///         reference = false};
///         rigid_modes 0 (the supports, or the loads, hold every rigid motion); omega
///         ascending (rad/s); shapes at ring::kStations stations; unknowns (reduced);
///         max_residual (dual norm, residual_norm = kDualResidualNorm); seconds.
/// \throws std::invalid_argument for input that can never work (check_preloaded_modes;
///         count outside 1..unknowns; a discretization above kDenseBucklingLimit, naming
///         fem.elements), ring::NumericalError when the path does not reach the full load,
///         when the loaded ring is at or past a critical load (T + s M not positive
///         definite, or omega^2 <= 0), or when the refinement fails.
ring::ModalResult compute_modes_under_load(const ring::RingSpec& spec, const ring::FemOptions& options,
                                           const ring::StaticOptions& statics, int count);

}  // namespace fem
