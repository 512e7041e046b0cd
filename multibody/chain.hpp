// The paper's rigid-segment chain (Yin & Wang 1989/90, sections 2-3 and 5): kinematics,
// mass matrix (12), quadratic-velocity terms, springs, generalized forces of point loads,
// closure constraints (13) and the roller constraint (27-28), all with their full
// nonlinear dependence on the coordinates, so that linear modes (modes.hpp) and the
// nonlinear statics/dynamics reuse one description.
//
// ## Model
// n equal straight rigid segments of length l = 2 pi R / n (perimeter = circumference)
// form, undeformed, a regular n-gon. Hinges sit at its vertices, at the polar angles
// ring::node_angles(spec, n): hinge k at a_k = anchor + 360 k / n degrees, where the
// anchor is spec.anchor() (the pin, or the free ring's free_anchor). The polygon's
// centre is the origin of the ring-centred reporting frame, so hinge k rests at
// Rp (cos a_k, sin a_k) with circumradius Rp = l / (2 sin(pi/n)) (slightly above R).
// Segment i (i = 0..n-1) runs from hinge i to hinge i+1 (hinge n = hinge 0), so the
// chain is traversed counter-clockwise. Segment mass m = rho A l at its midpoint,
// rotary inertia Jr = m l^2 / 12 about it (0 when MultibodyOptions::rotary_inertia is
// false). A rotational spring K = EI / l sits at every hinge (n springs; its law, elastic
// or ring.plastic's, is bending.hpp's, and K its rest stiffness): the spring at
// hinge k joins segments k-1 and k (hinge 0 joins segments n-1 and 0).
//
// ## Coordinates q (ordering)
//   q = (phi_0, ..., phi_{n-1})                 pinned ring: dofs() = n
//   q = (phi_0, ..., phi_{n-1}, x_0, y_0)       free ring:   dofs() = n + 2
// phi_i: angle (rad) of segment i with +x, counter-clockwise (the paper's phi, 0-based:
// the paper's phi_1 is our phi_0). Undeformed: phi0_i = a_i + pi/2 + pi/n (rad).
// theta = phi - phi0 is the paper's theta. (x_0, y_0): displacement (m) of hinge 0 from
// its rest position, present only for a free ring; for a pinned ring hinge 0 never
// moves (the paper: "hinge 1 sits at the origin for all time").
// Positions:  p_k = P_0 + (x_0, y_0) + l sum_{j<k} e(phi_j),  e(a) = (cos a, sin a),
//             midpoint_i = p_i + (l/2) e(phi_i).
//
// ## Equations of motion (Lagrange, with multipliers for the constraints)
//   mass_matrix(q) qdd + quadratic_velocity(q, qd) + spring_forces(q)
//       = generalized forces - constraint_jacobian(q)^T lambda,
//   constraints(q) = 0,  constraint_jacobian(q) qdd + constraint_jdot_qdot(q, qd) = 0.
// The paper's mu(phi) is mass_matrix restricted to the angles:
//   mu_jk = m l^2 (L^T L)_jk cos(phi_j - phi_k) + Jr delta_jk,
//   (L^T L)_jj = n - 1 - j + 1/4,  (L^T L)_jk = n - 1 - max(j,k) + 1/2  (0-based).
//
// ## Constraints (all in metres)
// closure (2 rows): g(q) = l sum_j e(phi_j) = p_n - p_0 (the chain closes on hinge 0).
// roller (1 row, only with a roller support, which needs a pin): hinge r stays on the
// line through the pin and its own rest position: h(q) = nu . (p_r(q) - P_0) where
// nu is the unit normal of that line, nu = (-d_y, d_x), d = (P_r - P_0)/|P_r - P_0|.
// constraints() stacks them: rows (closure x, closure y[, roller]).
//
// ## The arch (ring.arc = [from, to], spec.is_arch())
// An OPEN chain of n segments from `from` to `to`: hinge k at a_k = from + span k / n, k = 0..n
// (n + 1 hinges, ring::node_angles). The rule for l is the ring's: the chain's length is the
// arch's, l = R span / n (span in rad), so the hinges sit on the circle of circumradius
// Rp = l / (2 sin(span / 2n)) (slightly above R) and the chain converges to the inextensible
// arch of radius R at order 2 in 1/n. phi0_i = a_i + pi/2 + span / 2n. Hinge 0 is held when
// the `from` end is pinned (supports.pin or .pins there); otherwise the chain is free()
// and carries (x_0, y_0). The closure rows become the far end's pin rows: with the `to`
// end pinned, g(q) = p_n(q) - P_n = base + l sum_j e(phi_j) - P_n (2 rows, with the identity
// in (x_0, y_0) when free); without, no rows. The hinge springs EI/l sit at the interior
// hinges 1 .. n-1 only (spring k joins segments k-1 and k); a clamped end's half-hinge 2EI/l
// to the wall is a term on its segment's rotation (attachments.hpp). No roller.
//
// Every member is const and thread-safe; a Chain is an immutable description (O(n) memory).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace multibody {

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

class Chain {
 public:
  /// Builds the chain of `spec` with `options.n` segments, hinge 0 at spec.anchor().
  /// `loaded_angle` (degrees), if given, must be a hinge. Throws std::invalid_argument when
  /// n < 4, when the roller or the loaded point is not on a hinge, or when the roller
  /// coincides with the pin. O(n).
  Chain(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
        std::optional<double> loaded_angle = std::nullopt);

  // ---- parameters ----
  int n() const { return n_; }
  double l() const { return l_; }                ///< segment length, m
  double m() const { return m_; }                ///< segment mass rho A l, kg
  double Jr() const { return jr_; }              ///< segment rotary inertia, kg m^2 (0 if off)
  double K() const { return k_; }                ///< hinge spring at rest, EI / l, N m / rad (bending.hpp)
  double circumradius() const { return rp_; }    ///< Rp = l / (2 sin(pi/n)), m
  bool free() const { return free_; }            ///< no pin: two translation coordinates
  int dofs() const { return free_ ? n_ + 2 : n_; }
  int constraint_count() const { return arch_ ? (end_pinned_ ? 2 : 0) : (roller_ ? 3 : 2); }
  /// An open arch (file comment) rather than the closed ring.
  bool arch() const { return arch_; }
  /// The number of hinges: n (ring), n + 1 (arch: hinge n is the `to` end).
  int hinges() const { return arch_ ? n_ + 1 : n_; }
  /// The first hinge with a spring EI/l: 0 (ring), 1 (arch: the ends have none). Spring k
  /// joins segments k - 1 (cyclic) and k.
  int first_spring() const { return arch_ ? 1 : 0; }
  /// True when the chain's own coordinates or rows hold hinge k still: hinge 0 when not
  /// free(), an arch's hinge n when its `to` end is pinned (the closure rows).
  bool holds(int k) const { return (k == 0 && !free_) || (arch_ && k == n_ && end_pinned_); }
  /// The hinge index at polar angle `deg`, or -1 when no hinge is there. O(1).
  int hinge_index(double deg) const;
  double anchor_deg() const { return anchor_deg_; }       ///< polar angle of hinge 0
  const std::vector<double>& hinge_angles_deg() const { return angles_; }  ///< rest angles
  /// Hinge index at polar angle `deg` (rest configuration); throws std::invalid_argument
  /// if no hinge is there. O(1).
  int hinge_at(double deg) const;
  /// Index of the roller hinge, if the spec has a roller.
  std::optional<int> roller_hinge() const { return roller_; }
  /// Undeformed segment angles phi0 (n-vector, rad), their cosines and sines (computed
  /// once: at n = 10^6 the trigonometry of every O(n) rest product was 8 % of the modes).
  const Vector& phi0() const { return phi0_; }
  const Vector& cos0() const { return cos0_; }
  const Vector& sin0() const { return sin0_; }
  /// Rest coordinates: (phi0[, 0, 0]).
  Vector q0() const;
  /// Rest position of hinge k (ring-centred frame, m).
  Eigen::Vector2d hinge_rest(int k) const;

  // ---- kinematics (q has dofs() entries) ----
  /// Position of hinge k, 0 <= k <= n (k = n is the chain's far end, equal to hinge 0
  /// when closed). O(k).
  Eigen::Vector2d hinge_position(const Vector& q, int k) const;
  /// All hinge positions, column k = hinge k, k = 0..hinges()-1. O(n).
  Eigen::Matrix2Xd hinge_positions(const Vector& q) const;
  /// All segment midpoints, column i = segment i. O(n).
  Eigen::Matrix2Xd midpoints(const Vector& q) const;
  /// Hinge displacements of a small change dq about rest, to first order (column k =
  /// hinge k): dp_k = dp_0 + l sum_{j<k} e'(phi0_j) dq_j. O(n).
  Eigen::Matrix2Xd rest_displacements(const Vector& dq) const;
  /// The same, sampled at the common stations (a mode shape, ring/results.hpp). O(n).
  ring::ModeShape rest_shape(const Vector& dq) const;
  /// rest_shape of every column of dq, with one pair of n-sized buffers for all of them
  /// (fresh ones per mode were half the page faults of 23 modes at n = 10^6). O(n) each.
  std::vector<ring::ModeShape> rest_shapes(const Matrix& dq) const;
  /// Hinge displacements of a small change dq about the state q, to first order, and
  /// their sampling at the common stations (mode shapes about a deformed state). O(n).
  Eigen::Matrix2Xd displacements_at(const Vector& q, const Vector& dq) const;
  ring::ModeShape shape_at(const Vector& q, const Vector& dq) const;
  /// d p_k / d q (2 x dofs()). O(n).
  Matrix hinge_jacobian(const Vector& q, int k) const;

  // ---- inertia ----
  /// Mass matrix M(q) (dofs x dofs, dense, symmetric positive definite). O(n^2).
  Matrix mass_matrix(const Vector& q) const;
  /// M(q) v without forming M. O(n).
  Vector mass_times(const Vector& q, const Vector& v) const;
  /// Quadratic-velocity (centripetal) vector c(q, qd) = Mdot qd - d/dq (qd^T M qd)/2:
  /// c_j = m l^2 sum_k (L^T L)_jk sin(phi_j - phi_k) qd_k^2 for the angles, and
  /// -m l sum_k c_k e(phi_k) qd_k^2 with c_k = n - k - 1/2 for (x_0, y_0). O(n).
  Vector quadratic_velocity(const Vector& q, const Vector& qd) const;
  /// M(q) V for the k columns of V (dofs x k), with one evaluation of the n sines and
  /// cosines. O(n k).
  Matrix mass_times_columns(const Vector& q, const Matrix& V) const;
  /// Kinetic energy qd^T M(q) qd / 2, J. O(n).
  double kinetic_energy(const Vector& q, const Vector& qd) const;

  // ---- springs ----
  /// Relative rotation of spring k (hinge k): theta_k - theta_{k-1}, cyclic (n entries; an
  /// arch's entry 0 is 0: its ends have no spring). O(n).
  Vector hinge_rotations(const Vector& q) const;
  /// Spring energy K/2 sum_k (theta_k - theta_{k-1})^2, J. O(n).
  double spring_energy(const Vector& q) const;
  /// Gradient of spring_energy (the paper's K theta, zero in x_0, y_0). O(n).
  Vector spring_forces(const Vector& q) const;
  /// Constant stiffness matrix: K times the cyclic (2, -1, -1) matrix on the angles,
  /// zero rows/columns for x_0, y_0 (dofs x dofs, dense). O(n^2) memory.
  Matrix stiffness_matrix() const;

  // ---- loads ----
  /// Generalized forces of a dead force F (N, ring-centred frame) at hinge k, by virtual
  /// work: hinge_jacobian(q, k)^T F. O(n).
  Vector point_load_forces(const Vector& q, int k, const Eigen::Vector2d& F) const;

  // ---- constraints ----
  /// Closure gap l sum_j e(phi_j), m (an arch: the far end's gap p_n - P_n). O(n).
  Eigen::Vector2d closure(const Vector& q) const;
  /// Its Jacobian (2 x dofs): column j = l (-sin phi_j, cos phi_j); zero for x_0, y_0. O(n).
  Matrix closure_jacobian(const Vector& q) const;
  /// Jdot qd for the closure: -l sum_j e(phi_j) qd_j^2. O(n).
  Eigen::Vector2d closure_jdot_qdot(const Vector& q, const Vector& qd) const;
  /// Roller residual nu . (p_r - P_0), m (requires a roller). O(n).
  double roller(const Vector& q) const;
  /// Its Jacobian (1 x dofs as a vector of dofs entries). O(n).
  Vector roller_jacobian(const Vector& q) const;
  /// Its Jdot qd: -l sum_{j<r} (nu . e(phi_j)) qd_j^2. O(n).
  double roller_jdot_qdot(const Vector& q, const Vector& qd) const;
  /// All constraints stacked (closure x, closure y[, roller]). O(n).
  Vector constraints(const Vector& q) const;
  Matrix constraint_jacobian(const Vector& q) const;  ///< constraint_count() x dofs. O(n).
  /// constraints(q), constraint_jacobian(q) and the constraints' Hessians, which are
  /// diagonal (hess(i, j) = d^2 g_i / d phi_j^2; zero in x_0, y_0), with one evaluation
  /// of the n sines and cosines. O(n).
  struct ConstraintKinematics {
    Vector g;
    Matrix G, hess;
  };
  ConstraintKinematics constraint_kinematics(const Vector& q) const;
  Vector constraint_jdot_qdot(const Vector& q, const Vector& qd) const;  ///< O(n).

 private:
  void check(const Vector& q) const;
  Eigen::Vector2d base(const Vector& q) const;  ///< position of hinge 0
  /// dp_k = dp_0 + l sum_{j<k} (-sin_j, cos_j) dq_j for the tangents of some state, into
  /// ux[k], uy[k] (hinges() entries each).
  void accumulate(const Vector& cos, const Vector& sin, const Eigen::Ref<const Vector>& dq, double* ux,
                  double* uy) const;
  /// The hinge displacements sampled at the common stations: sample_polygon, or sample_arc.
  ring::ModeShape sample(const std::vector<double>& ux, const std::vector<double>& uy) const;

  int n_;
  ring::RingSpec where_;  ///< the spec's geometry and supports, for ring::node_index
  bool arch_ = false, end_pinned_ = false;
  double span_ = 0.0;  ///< rad: 2 pi for the ring
  double l_, m_, jr_, k_, rp_;
  bool free_;
  double anchor_deg_;
  std::vector<double> angles_;
  Vector phi0_, cos0_, sin0_;
  std::optional<int> roller_;
  Eigen::Vector2d roller_normal_{0.0, 0.0};
};

}  // namespace multibody
