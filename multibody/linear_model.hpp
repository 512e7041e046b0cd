// The linear model of the chain about the undeformed n-gon (the paper's section 4):
// the constraint null-space basis D and the reduced matrices K0, M0.
//
// ## Problem
// Linearized about the undeformed n-gon q0 (no preload, so neither the constraint
// forces nor the quadratic-velocity terms contribute), with a basis D of the null space
// of the constraint Jacobian J = Chain::constraint_jacobian(q0) (delta q = D x):
//   \f$ K_0 x = \omega^2 M_0 x,\quad K_0 = D^T K D,\quad M_0 = D^T M(q_0) D \f$
// (the paper's equations 24-26). Unknowns r = dofs - constraints: n - 2 (pin),
// n - 3 (pin + roller), n (free ring).
//
// ## Dependent coordinates (MultibodyOptions::dependent)
// - `paper`: the last two angles are dependent, D = [I; -J_2^{-1} J_1] (equation 17),
//   J_2 = the 2x2 block of the last two columns, det J_2 = l^2 sin(2 pi / n): its
//   condition number grows like n. With a roller the third dependent angle is that of
//   segment r-1 (r = roller hinge; segment n-3 if r-1 >= n-2), whose roller-row entry is
//   the only one among the three dependent columns.
// - `robust` (default): D = the last r columns of the orthogonal factor Q of a
//   Householder QR of J^T (an orthonormal null-space basis, condition number 1 for any
//   n and any configuration), applied implicitly (O(n^2) for Q^T A Q).
//
// ## The Timoshenko chain (shear given)
// Each segment also carries a shear angle gamma_i (section rotation psi_i = theta_i +
// gamma_i), a shear spring kGA l and the section's rotary inertia rho I l; the hinge springs,
// kr, the clamp and point inertias act on the sections' rotations. gamma, not psi, is the
// unknown, so the stiff shear block of a thin ring stays apart from the bending: no rounding
// loss at kGA l = 1e8 EI/l (tests/multibody/test_timoshenko.cpp). The modes converge at
// order 2 to the inextensible Timoshenko ring in closed form.
//
// ## ring.variations (LocalChain)
// A ring whose depth and density vary around the circumference (RingSpec::variations) keeps
// the rest n-gon (the centroid line is the uniform ring's) and makes two things local, here
// and nowhere else: segment i's mass m_i = rho A(mid_i) l at the polar angle mid_i of its
// midpoint (midpoint rule: the centroid stays at the midpoint; the neglected first moment
// rho A' l^3 / 12 and the second moment's correction are O(l^2) relative, so the order 2 in
// 1/n holds), its rotary inertia m_i l^2 / 12 (when MultibodyOptions::rotary_inertia), and
// hinge k's spring K_k = EI(a_k) / l at the hinge's own angle a_k (the midpoint rule of the
// flexibility integral of 1/EI from midpoint to midpoint: also O(l^2)). The mass matrix at
// rest is then sum_i m_i A_i^T A_i + diag(J_i) with A_i the midpoint's velocity map:
//   M_jk = l^2 cos(phi_j - phi_k) (S_max(j,k) + m_max(j,k) / 2)  (j != k),
//   M_jj = l^2 (S_j + m_j / 4) + J_j,   S_j = sum_{i > j} m_i,
// and for a free ring M_(j, x0) = l e'(phi_j) (S_j + m_j / 2), M_(x0, x0) = sum m_i. Only the
// dense linear modes at rest take it (checks.cpp refuses the rest by the key ring.variations).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "multibody/attachments.hpp"
#include "multibody/chain.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// The linearized, constraint-reduced problem about the n-gon (for tests and studies).
struct LinearModel {
  Matrix K0;           ///< r x r, D^T K D
  Matrix M0;           ///< r x r, D^T M(q0) D
  double j2_condition = 0.0;  ///< 2-norm condition of the paper's block J_2 (the last two
                              ///< angle columns of the closure Jacobian), for reporting
  /// delta q = D x for the columns of x (r x k): O(n k). Chain coordinates of reduced vectors.
  Matrix expand(const Matrix& x) const;
  /// D itself, dofs x r (dense, O(n^2)).
  Matrix basis() const;

  // D is kept implicit: paper: rows `independent` = identity, rows `dependent` = X;
  // robust: the last r columns of the Householder factor Q of J^T.
  ring::MultibodyOptions::Dependent kind = ring::MultibodyOptions::Dependent::robust;
  std::vector<int> independent, dependent;
  Matrix X;                           ///< paper: -J_P^{-1} J_I, c x r
  Eigen::HouseholderQR<Matrix> qr;    ///< robust: QR of J^T
};

/// The Timoshenko chain's per-segment shear spring and section inertia (file comment).
struct Shear {
  double stiffness = 0.0;  ///< kGA l, N m (per rad^2 of shear angle)
  double inertia = 0.0;    ///< rho I l, kg m^2
  /// Of `spec`'s Timoshenko ring on segments of length l.
  static Shear of(const ring::RingSpec& spec, double l) { return {spec.kGA() * l, spec.rhoI() * l}; }
};

/// The local segment masses and hinge springs of a varying ring (file comment), n each.
struct LocalChain {
  Vector mass;    ///< m_i = rho A(midpoint of segment i) l, kg
  Vector rotary;  ///< J_i = m_i l^2 / 12, or 0 when the chain has no rotary inertia, kg m^2
  Vector spring;  ///< K_k = EI(hinge k) / l, N m / rad
  /// Of `spec` on `chain` (the chain built from spec). O(n).
  static LocalChain of(const Chain& chain, const ring::RingSpec& spec);
  /// The chain's mass matrix at rest q0 with these masses (file comment), dofs x dofs. O(n^2).
  Matrix rest_mass_matrix(const Chain& chain) const;
};

/// The unknowns of the linear model, in this order: the chain's coordinates q, the shear
/// angles gamma (one per segment, when `shear` is given), the hinge rotations that carry a
/// point inertia (`terms`). O(1).
int linear_unknowns(const Chain& chain, const detail::LinearTerms* terms, const Shear* shear);

/// Assembles K0 and M0 (and the implicit D) for `chain` with the given dependent-coordinate
/// choice, with `terms` (attachments.hpp: foundation, springs, masses, further pins, a
/// clamp) added to K, M(q0) and the constraint rows when given (robust only), and with the
/// shear angles of the Timoshenko chain when `shear` is given (file comment: the unknowns
/// become (q, gamma), dofs + n). Cost O(N^2 c) time, O(N^2) memory (c = constraints, N the
/// unknowns). `local`, when given, replaces the chain's uniform segment masses and hinge
/// springs (a varying ring, file comment; not with `shear`). Throws ring::NumericalError if
/// the paper's block J_2 is singular.
LinearModel linearize(const Chain& chain, ring::MultibodyOptions::Dependent dependent,
                      const detail::LinearTerms* terms = nullptr, const Shear* shear = nullptr,
                      const LocalChain* local = nullptr);

/// 2-norm condition number of the paper's block J_2 (the last two angle columns of the
/// closure rows of J, c x dofs). O(1).
double j2_condition(const Matrix& J, int n);

}  // namespace multibody
