// Internal to multibody/: the Timoshenko chain's sections (ring.theory = "timoshenko") for
// the nonlinear statics and response, the nonlinear form of linear_model.hpp's model.
//
// ## Model
// The segments stay the centroid line (chords of fixed length l: the closure, the supports,
// the hinge positions and the loads depend on the segment angles phi only). Segment j also
// carries a shear angle gamma_j; its section turns by psi_j - psi0_j = theta_j + gamma_j
// (theta = phi - phi0). Every term acting on a rotation acts on the sections':
//   V_s = 1/2 (theta + gamma)^T A (theta + gamma) + 1/2 kGA l |gamma|^2,
//   A   = the hinge springs EI/l between neighbouring sections (cyclic 2, -1, -1) + the
//         terms on a hinge's rotation (kr, a clamp: attachments.hpp, condensed on the mean
//         rotation of the hinge's two sections),
//   T_s = 1/2 rho I l |phi' + gamma'|^2 (the section's rotary inertia; the segment's own
//         m l^2 / 12 stays on phi, MultibodyOptions::rotary_inertia, as in the linear model).
// A relative rotation theta_k - theta_{k-1} rather than phi_k - phi_{k-1} keeps the 2 pi of
// the closed ring out of the springs. V_s and T_s are quadratic in (theta, gamma) and their
// rates with constant coefficients: in the unknowns (phi, gamma) the Hessian is
//   [A, A; A, A + S],  S = kGA l I,  and the mass  [M(phi) + J, J; J, J],  J = rho I l I,
// so the response's residual and tangent are the Euler-Bernoulli chain's bordered by
// constant blocks (newton_backend.hpp), and at rest they are linear_model.hpp's K and M.
//
// ## Statics: gamma condensed exactly
// Nothing but V_s involves gamma (constraints and loads act on the centroid line), so
// dV/dgamma = 0 gives gamma = -(A + S)^{-1} A theta, and V_s at that gamma is
//   1/2 theta^T K_c theta,  K_c = A - A (A + S)^{-1} A  (= S (A + S)^{-1} A),
// a dense constant matrix: the statics runs on phi alone with K_c in place of the hinge
// springs and the rotation terms (statics.hpp, DenseTangent). Exact, not an approximation:
// the condensed energy has the same stationary points and, since A + S is positive
// definite, the same stability on the constraints' tangent space. The statics report hinge
// positions only, so gamma is not recovered.
//
// Cost: O(n^2) memory (A); the condensation is one Cholesky of A + S, O(n^3), once.
#pragma once

#include <Eigen/Dense>

#include "multibody/attachments.hpp"
#include "multibody/chain.hpp"
#include "multibody/linear_model.hpp"

namespace multibody::detail {

class Sections {
 public:
  /// The sections of `chain` with its rotation terms (`terms`, may be null) and `shear`
  /// (kGA l > 0; rho I l >= 0). O(n^2).
  Sections(const Chain& chain, const Attachments* terms, const Shear& shear);

  int n() const { return n_; }
  const Shear& shear() const { return shear_; }
  /// A: the stiffness on the sections' rotations (file comment), n x n.
  const Matrix& rotation_stiffness() const { return A_; }

  // x = (phi, gamma, ...): the first 2n entries (the point inertias' hinge rotations may
  // follow, attachments.hpp: HingeInertias); v, a its rates; matrices likewise (their
  // leading 2n x 2n block).
  /// V_s, J. O(n^2).
  double energy(const Vector& x) const;
  /// Adds dV_s/dx to r (2n). O(n^2).
  void add_forces(const Vector& x, Eigen::Ref<Vector> r) const;
  /// Adds the Hessian [A, A; A, A + S] to T (2n x 2n). O(n^2).
  void add_stiffness(Eigen::Ref<Matrix> T) const;
  /// T_s, J. O(n).
  double kinetic_energy(const Vector& v) const;
  /// Adds the section inertia's force J (a_phi + a_gamma) to both halves of r. O(n).
  void add_inertia_forces(const Vector& a, Eigen::Ref<Vector> r) const;
  /// Adds c times its mass [J, J; J, J] to M (2n x 2n). O(n).
  void add_mass(double c, Eigen::Ref<Matrix> M) const;
  /// Adds [J, J; J, J] E to out for the columns of E (2n x k). O(n k).
  void add_mass_times(const Matrix& E, Eigen::Ref<Matrix> out) const;

  /// K_c = A - A (A + S)^{-1} A: the energy of phi with gamma condensed (file comment), n x n.
  /// O(n^3), 3 n^2 doubles at its peak besides A.
  Matrix condensed() const;

 private:
  /// The Cholesky factor of A + S (positive definite: S > 0, A >= 0); throws
  /// ring::NumericalError if it is not. O(n^3).
  Eigen::LLT<Matrix> shear_block() const;

  const Chain& chain_;
  const int n_;
  const Shear shear_;
  Matrix A_;
};

}  // namespace multibody::detail
