// Internal to multibody/: the ring's terms beyond the paper's chain (ring/spec.hpp: further
// pins, a clamp, elastic supports, point masses, the Winkler foundation), each written once
// as a term on hinge displacements, with its energy, gradient and Hessian in the chain's
// coordinates at any configuration q; the linear modes evaluate them at rest (linear_terms),
// the dense statics along the path. The O(n) statics (statics_natural.cpp) takes the same
// terms by hinge (hinge_stiffness, hinge_force, rotation_stiffness, pinned_hinges) on hinge
// positions.
//
// ## Terms (hinge k at rest P_k, displacement u_k = p_k(q) - P_k)
// - foundation: a spring l (k_r r_k r_k^T + k_t t_k t_k^T) at every hinge (r_k, t_k the
//   radial and tangential unit vectors of the rest hinge, l the length of ring a hinge
//   stands for): the Winkler foundation lumped at the hinges, its energy exactly quadratic
//   in u_k since its directions are those of the undeformed point;
// - an elastic support at hinge h: diag(kx, ky) on u_h, and kr on the hinge's rotation psi;
// - a point mass at hinge h: m on u_h, its inertia J on psi;
// - a further pin at hinge h: u_h = 0 (2 constraint rows);
// - a clamp at hinge h: psi = 0.
// On an arch (chain.hpp) an end hinge has one segment: its half spring 2EI/l joins that
// segment to psi, so a clamped end is 2EI/l on the end segment's rotation (the segment against
// the wall over half its length) and kr is in series with 2EI/l (mean_rotation,
// condensed_rotation_stiffness).
// The hinge's rotation psi: the spring EI/l at a hinge stands for the bending from one
// segment's midpoint to the next; split in two halves of 2EI/l, each from a segment to the
// hinge's own (massless) rotation psi, it is the same spring with psi = the mean m of the two
// segments' rotations. A rotational spring kr from psi to the ground, psi condensed, is a
// spring 4EI/l and kr in series on m (4K kr / (4K + kr) with K = EI/l), and
// psi = 4K m / (4K + kr). A clamp is kr -> infinity: 4K on m. (A constraint m = 0 instead
// converges at order 1 only, 1.04 measured over n = 80 .. 320: the curvature jumps at a
// clamp, so m = O(l) there.) m is linear in the angles, so these terms are quadratic in q.
// A point inertia cannot be condensed so (psi then moves with its own inertia): in the linear
// modes psi becomes an unknown of its own, on the two half springs (linear_model.hpp). The
// inertia put on m instead converges at order 1 only, for the same reason as the clamp's
// constraint (measured: 2.60, 1.43, 0.75 % at n = 80, 160, 320 on scenes/thick-ring.toml
// with a 1e-4 kg m^2 inertia, against the FE reference; order 2 with psi an unknown: 0.31,
// 0.08, 0.02 %). The lumped chain, this chain's second implementation, makes the same psi an
// unknown (lumped_mass/model.cpp; tests/lumped_mass/vs_multibody_test.cpp holds them together).
//
// ## Pull-back
// u_k depends on the angles through p_k = p_0 + l sum_{j<k} e(phi_j): d u_k / d phi_j =
// c_j = l e'(phi_j) for j < k (and the identity in the free ring's (x_0, y_0)), and
// d^2 u_k / d phi_j^2 = -l e(phi_j). So E = sum_k u_k^T B_k u_k / 2 has
//   grad_j = c_j . F_{j+1},   Hess_ij = c_i^T S_{max(i,j)+1} c_j - delta_ij l e(phi_j) . F_{j+1},
// with the suffix sums F_m = sum_{k >= m} B_k u_k and S_m = sum_{k >= m} B_k: O(n) for the
// gradient, O(n^2) for the dense Hessian, as the dense path.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

#include "multibody/chain.hpp"
#include "ring/spec.hpp"

namespace multibody::detail {

/// The terms on hinge h's rotation: a rotational spring to the ground kr (N m/rad; infinity:
/// a clamp) and a point inertia (kg m^2).
struct HingeRotation {
  int hinge = 0;
  double kr = 0.0;
  double inertia = 0.0;
  /// The inertia turns the hinge's rotation into an unknown of its own (linear_model.hpp);
  /// a clamp holds it still.
  bool moves() const { return inertia > 0.0 && !std::isinf(kr); }
};

/// kr and the two half springs 2 EI/l of a hinge (file comment) condensed onto the mean
/// rotation of its segments: 4K kr / (4K + kr), 4K for a clamp. K = EI/l. At an arch's end
/// (`end`) the hinge has one segment and one half spring: 2K kr / (2K + kr), 2K for a clamp
/// (the end segment against the wall over half its length).
inline double condensed_rotation_stiffness(double kr, double K, bool end = false) {
  const double half = end ? 2.0 * K : 4.0 * K;
  return std::isinf(kr) ? half : half * kr / (half + kr);
}

/// True for an arch's end hinge (0 or n). O(1).
inline bool is_end(const Chain& chain, int h) { return chain.arch() && (h == 0 || h == chain.n()); }

/// The "mean rotation" of hinge h as weights on the segments' rotations: (h - 1 cyclic, 1/2)
/// and (h, 1/2); at an arch's end hinge its one segment's, (0, 1) or (n - 1, 1). O(1).
inline std::vector<std::pair<int, double>> mean_rotation(const Chain& chain, int h) {
  const int n = chain.n();
  if (is_end(chain, h)) return {{h == 0 ? 0 : n - 1, 1.0}};
  return {{(h + n - 1) % n, 0.5}, {h, 0.5}};
}

/// The spec's terms on a chain (whose anchor is spec.anchor()). Immutable; every member O(n) memory.
class Attachments {
 public:
  /// Throws std::invalid_argument naming the key when a point is not a hinge. O(n).
  Attachments(const Chain& chain, const ring::RingSpec& spec);

  /// Energy of the foundation and the springs (translational and rotational, the clamp's
  /// included) at q, J; `rotations` = false leaves out the terms on the hinges' rotation
  /// (as add_stiffness). O(n).
  double energy(const Vector& q, bool rotations = true) const;
  /// Adds its gradient to `grad` (dofs) and, if not null, its Hessian to `hess` (dofs x
  /// dofs, dense, e.g. a block of a bigger matrix). O(n) and O(n^2); nothing without such
  /// terms. `rotations` = false leaves out the terms on the hinges' rotation (rotational
  /// springs, the clamp), which hinge_rotations() gives apart.
  void add_stiffness(const Vector& q, Vector& grad, Eigen::Ref<Matrix>* hess, bool rotations = true) const;
  /// Adds the constant Hessian of the terms on the hinges' rotation (rotational springs, the
  /// clamp: condensed on the mean rotation of the hinge's two segments) to `A`, n x n on the
  /// segments' rotations: the Timoshenko chain puts it on its sections' (sections.hpp). O(n^2).
  void add_rotation_stiffness(Eigen::Ref<Matrix> A) const;
  /// The point masses' mass matrix at rest, their translations only (dofs x dofs, dense;
  /// their inertias are hinge_rotations()'). O(n^2).
  Matrix rest_mass() const;
  /// Adds their mass matrix at q to M (dofs x dofs): sum_k m_k (d u_k/dq)^T (d u_k/dq),
  /// whose angle block is l^2 sum_{k > max(i,j)} m_k cos(phi_i - phi_j), the structure of the
  /// chain's own (dynamics_model.hpp: the quadratic-velocity terms follow from its constants).
  /// O(n^2); nothing without point masses.
  void add_mass(const Vector& q, Eigen::Ref<Matrix> M) const;
  bool has_mass() const { return has_mass_; }
  /// Their kinetic energy sum_k m_k |d u_k/dt|^2 / 2 at (q, v), J. O(n).
  double kinetic_energy(const Vector& q, const Vector& v) const;
  /// The terms on the hinges' rotations as they are, for the linear modes: kr (infinity at a
  /// clamp) and the point inertias, by hinge. O(n).
  std::vector<HingeRotation> hinge_rotations() const;
  /// The rest Hessian of the terms (as add_stiffness at rest, the rotations' included) times
  /// v, added to *kv, and the point masses' rest mass matrix times v, added to *mv (dofs each;
  /// either may be null): the dense path's K and M of the terms as O(n) products, through the
  /// suffix sums of the file comment. O(n).
  void add_rest_products(const Vector& v, Vector* kv, Vector* mv) const;

  /// The further pins' rows (2 per pin): g = u_h, G = d u_h / d q (2p x dofs), and the
  /// rows' Hessians, diagonal in the angles (hess(i, j) = d^2 g_i / d phi_j^2), as
  /// Chain::ConstraintKinematics. O(n p).
  Chain::ConstraintKinematics pins(const Vector& q) const;
  int pin_rows() const { return 2 * static_cast<int>(pins_.size()); }
  /// The chain's constraint rows (closure, roller) with the further pins' after them, as
  /// Chain::constraint_kinematics: what the dense statics and response hold. O(n p).
  Chain::ConstraintKinematics constraints(const Vector& q) const;

  // The terms by hinge, the one place they are written: the members above pull them back
  // to the angles, the O(n) statics (statics_natural.cpp) takes them on hinge positions.

  /// B_k, the foundation's and the translational springs' stiffness at hinge k (2 x 2, N/m):
  /// the energy u_k^T B_k u_k / 2, u_k = p_k - P_k. O(1).
  const Eigen::Matrix2d& hinge_stiffness(int k) const { return stiff_[k]; }
  /// Its force B_k u_k (the energy's gradient in p_k) at hinge k's position p, N. O(1).
  Eigen::Vector2d hinge_force(int k, const Eigen::Vector2d& p) const {
    return stiff_[k] * (p - chain_.hinge_rest(k));
  }
  /// The point mass at hinge k, kg (its translation; 0 without one). O(1).
  double hinge_mass(int k) const { return mass_[k](0, 0); }
  /// The stiffness on the mean rotation of hinge k's two segments (kr and the clamp,
  /// condensed: condensed_rotation_stiffness), N m/rad; 0 without such a term. O(1).
  double rotation_stiffness(int k) const { return rot_k_[k]; }
  /// The further pins' hinges, in the order of their rows. O(1).
  const std::vector<int>& pinned_hinges() const { return pins_; }

 private:
  /// Adds the rotational springs' and the clamp's force at the rotations dq from rest
  /// (condensed on the mean rotations) to grad. O(n).
  void add_rotation_forces(const Vector& dq, Vector& grad) const;

  const Chain& chain_;
  std::vector<Eigen::Matrix2d> stiff_, mass_;  ///< B_k of the springs and of the masses, by hinge
  std::vector<double> rot_k_;                  ///< condensed on the mean rotation m_h, by hinge
  std::vector<HingeRotation> rotations_;       ///< kr and inertias as given
  std::vector<int> pins_;                      ///< hinges of the further pins
  Vector q0_;
  bool has_stiffness_ = false;                 ///< a foundation, a spring or a clamp
  bool has_mass_ = false;                      ///< a point mass
};

/// A term on the hinges given by hinge, pulled back to the angles of q (file comment, "Pull-back"):
/// adds sum_k (d u_k/dq)^T f[k] to `grad` (dofs) and, if `hess` is not null, the Hessian of a
/// term whose gradient in p_k is f[k] and whose Hessian in p_k is B[k] (2 x 2, none across
/// hinges) to `*hess` (dofs x dofs): sum_k (d u_k/dq)^T B_k (d u_k/dq) plus the curvature of the
/// positions, -delta_ij l e(phi_j) . F_{j+1}. `B` may be null when `hess` is. The plates'
/// contact (plates.hpp) is such a term whose B_k changes along the path. O(n), O(n^2) with hess.
void add_hinge_term(const Chain& chain, const Vector& q, const std::vector<Eigen::Vector2d>& f,
                    const std::vector<Eigen::Matrix2d>* B, Vector& grad, Eigen::Ref<Matrix>* hess);

/// The constraint rows held along a path: the chain's, and `terms`' further pins when given;
/// their rate Gdot v = hess v.^2 (every row is a sum of single-angle sinusoids). O(n p).
Chain::ConstraintKinematics constraint_kinematics(const Chain& chain, const Attachments* terms, const Vector& q);
/// The values of those rows alone (constraint_kinematics(...).g without the matrices). O(n p).
Vector constraint_values(const Chain& chain, const Attachments* terms, const Vector& q);
inline Vector constraint_jdot_qdot(const Chain::ConstraintKinematics& ck, const Vector& v) {
  return ck.hess * v.cwiseAbs2();
}

/// The hinges whose rotation chi is an unknown (HingeRotation::moves), written once for the
/// linear modes (linear_model.cpp) and the nonlinear analyses (HingeInertias): hinge h's
/// spring K between its segments a = h - 1 and b = h is split in two halves 2K, from a to
/// chi and from b to chi; kr joins chi to the ground and the inertia sits on chi. Calls
/// spring(i, j, c) for a spring c (r_i - r_j)^2 / 2 between rotations i and j (i, j < n: the
/// segments'; n + x: the x-th moving hinge's chi, in the order of `rotations`; a negative c
/// takes the hinge's own spring out), ground(i, c) for c r_i^2 / 2 and mass(i, J) for
/// J r_i'^2 / 2. O(moving hinges).
/// `Kat` is the hinge spring K, or a callable K(hinge) (a varying ring's local springs,
/// linear_model.hpp's LocalChain).
template <class Stiffness, class Spring, class Ground, class Mass>
void split_hinges(const std::vector<HingeRotation>& rotations, int n, Stiffness Kat, Spring spring, Ground ground,
                  Mass mass) {
  int x = n;
  for (const HingeRotation& t : rotations) {
    if (!t.moves()) continue;
    const int a = (t.hinge + n - 1) % n, b = t.hinge;
    double K;
    if constexpr (std::is_invocable_v<Stiffness, int>)
      K = Kat(t.hinge);
    else
      K = Kat;
    spring(a, b, -K);
    spring(a, x, 2.0 * K);
    spring(b, x, 2.0 * K);
    ground(x, t.kr);
    mass(x, t.inertia);
    ++x;
  }
}

/// True when a point mass of `spec` has a rotary inertia (HingeInertias below). O(masses).
inline bool has_point_inertia(const ring::RingSpec& spec) {
  for (const ring::PointMass& m : spec.masses)
    if (m.inertia > 0.0) return true;
  return false;
}

/// The point inertias' hinge rotations chi as unknowns of the nonlinear response and of the
/// modes under load (pinned): the state is x = (q, chi), chi the hinges' rotations from rest,
/// or on the Timoshenko chain x = (q, gamma, chi) with the split springs on the sections'
/// rotations theta + gamma (sections.hpp). split_hinges' springs are quadratic in (theta,
/// [gamma,] chi) with constant coefficients, so they are a constant border H of the chain's
/// tangent, and J a constant mass on chi, as the Timoshenko chain's sections. H holds the
/// split springs minus what Chain and Attachments (or the Sections' A) already put at those
/// hinges (the hinge spring K, kr condensed on the mean rotation): condensing chi out of H
/// gives zero, so the statics (no inertia) stay exact without chi, and the response and the
/// modes under load border the chain's matrices with H. Memory (n + p)^2 for H (the dense
/// path's size).
class HingeInertias {
 public:
  /// `shear`: on the Timoshenko chain's unknowns (q, gamma, chi) (class comment).
  HingeInertias(const Chain& chain, const Attachments& terms, bool shear = false);

  /// The unknowns chi (moving hinges), p.
  int n() const { return p_; }
  /// H's energy y^T H y / 2, y = (theta, [gamma,] chi) at x: the split springs less
  /// the terms they replace (class comment), J. O(n^2).
  double energy(const Vector& x) const;
  /// Adds H (theta, [gamma,] chi) to r (all unknowns). O(n^2).
  void add_forces(const Vector& x, Eigen::Ref<Vector> r) const;
  /// Adds c times H to T (the unknowns square); `springs_only`: the hinge springs' part, without
  /// kr (the hinge dampers follow it). O(n^2).
  void add_stiffness(double c, Eigen::Ref<Matrix> T, bool springs_only = false) const;
  /// J chi'^2 / 2, J. O(p).
  double kinetic_energy(const Vector& v) const;
  /// Adds J a_chi to r's tail. O(p).
  void add_inertia_forces(const Vector& a, Eigen::Ref<Vector> r) const;
  /// Adds c diag(0, J) to M. O(p).
  void add_mass(double c, Eigen::Ref<Matrix> M) const;
  /// Adds diag(0, J) E to out for the columns of E. O(p k).
  void add_mass_times(const Matrix& E, Eigen::Ref<Matrix> out) const;

 private:
  /// theta = q - q0, [gamma,] chi, as one vector on H's rows.
  Vector relative(const Vector& x) const;
  const Chain& chain_;
  int p_ = 0;
  Matrix H_, springs_;  ///< on (q, chi): all of H, and its hinge springs' part
  Vector J_;            ///< the inertias on chi
};

/// The terms linearized about the rest n-gon, for the linear modes. The terms on a hinge's
/// rotation are kept as they are: the Euler-Bernoulli chain puts them on its segment angles,
/// the Timoshenko chain on its sections' rotations, and a point inertia makes the hinge's
/// rotation an unknown of its own (linear_model.hpp).
struct LinearTerms {
  Matrix K;  ///< dofs x dofs stiffness of the translations (foundation, springs' kx, ky)
  Matrix M;  ///< dofs x dofs mass of the translations (point masses)
  Matrix J;  ///< the further pins' rows x dofs
  std::vector<HingeRotation> rotations;  ///< springs' kr, the clamp, point inertias
  /// The hinge rotations that are unknowns (HingeRotation::moves).
  int hinge_dofs() const {
    int d = 0;
    for (const HingeRotation& r : rotations) d += r.moves();
    return d;
  }
};
LinearTerms linear_terms(const Chain& chain, const ring::RingSpec& spec);

}  // namespace multibody::detail
