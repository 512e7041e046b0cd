// Internal to multibody/: the chain in natural coordinates (hinge positions), shared by
// the energy-momentum integrator (energy_momentum.hpp) and the O(n) statics
// (statics.hpp): constant bar mass matrix, quadratic link constraints, springs on the
// turning angle. The model is documented in energy_momentum.hpp.
#pragma once

#include <Eigen/Dense>

#include <array>
#include <cassert>
#include <memory>
#include <optional>
#include <vector>

#include "multibody/bending.hpp"
#include "multibody/bordered_band.hpp"
#include "multibody/chain.hpp"
#include "multibody/statics.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"

namespace multibody::detail {
class Attachments;
}

namespace multibody::natural {

using Vec = Eigen::VectorXd;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// The chain in hinge positions.
struct Natural {
  int n = 0;
  double l = 0, m = 0, Jr = 0, K = 0, theta0 = 0;
  Eigen::Vector2d pin, nu;  ///< pin position; unit normal of the roller's line
  bool pinned = true;       ///< hinge 0 pinned (2 rows after the links'); false: a free ring
  int roller = -1;
  /// Further pinned hinges and their rest positions (attachments.hpp): 2 rows each, after
  /// the roller's, from pins_row().
  std::vector<int> pins;
  std::vector<Eigen::Vector2d> pinned_at;
  /// Hinges held on a line through their rest position (one row each, after the further pins'):
  /// dir . (x_h - at) = 0. [plates]' no-slide rows (plates.hpp).
  std::vector<int> slides;
  std::vector<Eigen::Vector2d> slide_dir, slide_at;
  /// Pairs of hinges whose midpoint is held on a line (one row each, after the slides'):
  /// dir . (x_a + x_b - at) = 0, `at` the sum of their rest positions. [plates]' centre row
  /// (plates.hpp).
  std::vector<std::array<int, 2>> centres;
  std::vector<Eigen::Vector2d> centre_dir, centre_at;
  int roller_row() const { return n + (pinned ? 2 : 0); }
  int pins_row() const { return roller_row() + (roller >= 0 ? 1 : 0); }
  int slides_row() const { return pins_row() + 2 * static_cast<int>(pins.size()); }
  int centres_row() const { return slides_row() + static_cast<int>(slides.size()); }
  int rows() const { return centres_row() + static_cast<int>(centres.size()); }
  int size() const { return 2 * n + rows(); }
  /// Radius of the hinges' circle, m (the scale of positions and their round-off).
  double radius() const;
};

/// The natural model of `chain` with further pins at hinges `pins` (attachments.hpp,
/// pinned_hinges; the loads are detail::Loading's). O(n).
Natural make_natural(const Chain& chain, const std::vector<int>& pins = {});
/// The rest positions (x_0, y_0, ..., x_{n-1}, y_{n-1}).
Vec rest(const Chain& chain);

inline Eigen::Vector2d hinge(const Vec& x, int k) { return x.segment<2>(2 * k); }

/// Turning angle at a hinge and its gradient and Hessian in y = (x_{k-1}, x_k, x_{k+1}).
struct Turn {
  double theta;
  Vec6 d;
  Mat6 dd;
};
/// The turning angle, its gradient and, if `hessian` (else zero), its Hessian.
Turn turn(const Vec6& y, bool hessian = true);
/// The mean rotation from rest of the two links at a hinge, (alpha_a + alpha_b) / 2, alpha
/// the angle from the link's rest direction (ea, eb: unit vectors) to the link (a = y_1 - y_0,
/// b = y_2 - y_1), in (-pi, pi]; its gradient and, if `hessian`, its Hessian in y. The
/// hinge's rotation that kr and a clamp act on (attachments.hpp).
Turn mean_rotation(const Vec6& y, const Eigen::Vector2d& ea, const Eigen::Vector2d& eb, bool hessian = true);
/// The rest direction of link k (cyclic: k = -1 is link n - 1), from hinge k to k + 1: the
/// directions mean_rotation measures from. O(1).
Eigen::Vector2d rest_link(const Chain& chain, int k);
/// The turning angle alone (the same value as turn(y).theta).
double turn_angle(const Vec6& y);
/// The six coordinates of hinge k and its neighbours.
Vec6 local(const Natural& c, const Vec& x, int k);
/// The change of every hinge's turning angle from rest, theta_k - 2 pi / n (rad): the
/// hinges' strains (bending.hpp). O(n).
Vec turning_changes(const Natural& c, const Vec& x);
double spring_energy(const Natural& c, const Vec& x);
/// M v for the constant bar mass matrix. O(n).
Vec mass_times(const Natural& c, const Vec& v);
/// The same into `out` (resized; no allocation when it has the size).
void mass_times(const Natural& c, const Vec& v, Vec& out);
/// Constraint values (rows: links, pin x, pin y (if pinned), roller, further pins, slides, centres). O(n).
Vec constraints(const Natural& c, const Vec& x);
/// The same into `g` (resized; no allocation when it has the size).
void constraints(const Natural& c, const Vec& x, Vec& g);
/// The chain's KKT matrix, assembled straight into its factorization's storage: a
/// detail::BorderedBand in a symmetric order of the unknowns (natural order: hinge
/// coordinates 2k, 2k + 1, then the multipliers from 2n: links, pin, roller, further pins). The band:
/// link 0, hinge 1, link 1, ..., hinge n-2, link n-2 (chain order; widths 7, from the
/// springs, which couple hinge k with k +- 2). The border: hinges n-1 and 0 (every spring
/// and link that wraps around touches one of them), link n-1, the pin's two rows, the
/// roller's row, two rows per further pin; only its four hinge coordinates, the roller's
/// and the further pins' rows have entries in the band (each such row one more solved
/// border column: O(n) more per factorization). The LU (pivoting inside the band) fills only the band and the border: O(n) time
/// and memory per assembly, factorization and solve, whatever the pivots (a general
/// sparse LU with COLAMD ignores the pivoting that the statics' weak diagonal forces, and
/// fills far beyond O(n)). The pattern (kkt_pattern in natural.cpp) is fixed at
/// construction; n >= 4. Usage, per Newton iteration:
///   kkt.clear(); kkt.add(i, j, v) ...; if (kkt.factor()) dz = kkt.solve(rhs);
class BandedKkt {
 public:
  explicit BandedKkt(const Natural& c);
  /// Zero matrix (before assembly). O(n).
  void clear() { band_.clear(); }
  /// A(i, j) += v, i and j in the natural order (hinge coordinates, then multipliers);
  /// (i, j) must be in the structural pattern. O(1).
  void add(int i, int j, double v) { band_.add(perm_[i], perm_[j], v); }
  /// A(dofs[a], dofs[b]) += block(a, b) for all a, b: add() with each unknown mapped
  /// once.
  template <int K>
  void add(const int (&dofs)[K], const Eigen::Matrix<double, K, K>& block) {
    int p[K];
    for (int a = 0; a < K; ++a) p[a] = perm_[dofs[a]];
    for (int b = 0; b < K; ++b)
      for (int a = 0; a < K; ++a) band_.add(p[a], p[b], block(a, b));
  }
  /// Factors the assembled matrix (which it overwrites); false when it is singular
  /// (BorderedBand's test).
  bool factor() { return band_.factor(); }
  /// A^-1 rhs with the last factorization.
  Vec solve(const Vec& rhs) const;
  /// z = A^-1 z in place, with `scratch` for the permuted copy (resized; no allocation
  /// of n-sized vectors when both have the size).
  void solve(Vec& z, Vec& scratch) const;

 private:
  Eigen::VectorXi perm_;  ///< perm_[old] = new
  detail::BorderedBand band_;
};

/// Adds the constraint gradients G(x), times `scale`, to a KKT matrix whose multipliers
/// start at `offset`: as columns (G^T, `transpose`) or as rows; adds G(x)^T lambda to
/// `force` when not null.
void add_constraint_jacobian(const Natural& c, const Vec& x, int offset, bool transpose, double scale,
                             BandedKkt& kkt, const Vec* lambda, Vec* force);
/// Adds a spring's force g and Jacobian J, in the coordinates of hinge k and its
/// neighbours (local()), to the residual r and the KKT matrix.
void add_spring(const Natural& c, int k, const Vec6& g, const Mat6& J, Vec& r, BandedKkt& kkt);
/// Adds sum_i lambda_i Hess c_i (the links' constant Hessians), times `weight`.
void add_constraint_curvature(const Natural& c, const Vec& lambda, double weight, BandedKkt& kkt);
/// Adds `scale` times the constant bar mass matrix (mass_times's) to the KKT matrix. O(n).
void add_mass(const Natural& c, double scale, BandedKkt& kkt);
/// Adds `scale` times the point masses (attachments.hpp) to M x (`mx`, when not null; `x`
/// is read only then) and to the KKT matrix's diagonal (when not null): the one place the
/// energy-momentum scheme's constant mass and the modes' pencil take them. O(n).
void add_point_masses(const Natural& c, const detail::Attachments& terms, double scale, const Eigen::Ref<const Vec>& x, Vec* mx,
                      BandedKkt* kkt);
/// Adds hinge k's quadratic terms (the foundation and the translational springs,
/// attachments.hpp: u_k^T B_k u_k / 2) at hinge positions x: their force B_k u_k to `force`
/// and `weight` B_k to the KKT matrix (the energy-momentum scheme's Jacobian at the
/// midpoint takes 1/2). Nothing where B_k = 0. O(1).
void add_hinge_spring(const detail::Attachments& terms, int k, const Vec& x, double weight, Vec& force,
                      BandedKkt& kkt);
/// The ring's stiffness on hinge positions, written once for the O(n) statics and the O(n)
/// linear modes (whose K is its tangent at rest): the hinge springs on the turning angle, kr
/// and the clamp on the mean rotation of a hinge's links, the foundation and the
/// translational springs on the hinges' displacements (attachments.hpp, by hinge). Adds its
/// gradient at x to `force` (2n) and its Hessian to `kkt`. O(n).
/// The hinge springs follow `bending` (bending.hpp: its trial law from the committed states)
/// when given, else the rest stiffness c.K (the linear modes' tangent at rest).
void add_stiffness(const Chain& chain, const Natural& c, const detail::Attachments& terms, const Vec& x, Vec& force,
                   BandedKkt& kkt, const HingeBending* bending = nullptr);

/// The largest change of a link's direction that the position correction dx makes,
/// |dx_{k+1} - dx_k| / l (rad, to first order): compared with detail::kBasin, as the
/// angle paths compare their corrections (a bound on |dx| itself would shrink with
/// l = 2 pi R / n). O(n).
double turns_a_link_by(const Natural& c, const Vec& dx);

/// Newton's stopping rule on hinge positions: converged when the correction and the
/// constraints are below 1e-12 R, or when the correction has reached the solve's
/// round-off floor (it grows with n: ~1e-11 R at n = 10^4): below 1e-9 R and no longer
/// contracting (full Newton contracts quadratically above the floor).
class NewtonStop {
 public:
  explicit NewtonStop(double radius) : R_(radius) {}
  /// After a correction of size `step` (max norm), with constraints `constraint` (max |c|).
  bool converged(double step, double constraint);

 private:
  double R_, previous_ = 0.0;
};

/// The chain's static equilibrium in hinge positions for the continuation driver
/// (statics_natural.cpp), with the terms of `spec` (attachments.hpp) and every load of
/// `loads` (loading.hpp): one BandedKkt factorization per Newton iteration, O(n).
/// `drive`: static.displacement on the last further pin, as detail::angle_equilibrium's.
/// `plates`: [plates] (plates.hpp), the penalty by hinge and the no-slide rows after the pins'.
std::unique_ptr<detail::StaticEquilibrium> static_equilibrium(const Chain& chain, const ring::RingSpec& spec,
                                                              const ring::Loads& loads, double depth,
                                                              std::optional<Eigen::Vector2d> drive = std::nullopt,
                                                              const ring::StaticOptions::Plates* plates = nullptr);

}  // namespace multibody::natural
