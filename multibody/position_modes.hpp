// Internal to multibody/: the linear modes' pencil in hinge positions (natural.hpp), the O(n)
// path of the modes for the terms beyond the paper's ring (modes.hpp; the paper's ring keeps
// the angle path of shifted_solve.hpp).
//
// ## Pencil
// About rest without load the multipliers are zero, so K is the tangent at rest of the O(n)
// statics' energy (natural::add_stiffness, the one assembly: hinge springs on the turning
// angle, kr and the clamp on the mean rotation of a hinge's links, the foundation and the
// translational springs), M the constant bar mass matrix of the energy-momentum model (per
// bar (m/4) [1 1; 1 1] + (Jr/l^2) [1 -1; -1 1]) plus the point masses m I2 at their hinges, and
// the constraints G u = 0 are natural.hpp's rows linearized at rest (links, hinge 0's pin,
// the roller, the further pins). On G u = 0 this is the chain's pencil (modes.hpp) in other
// coordinates: the links hold, so u_{k+1} - u_k = l e'_k dphi_k (e_k the rest direction of
// link k, e'_k = (-e_y, e_x)), a bijection with the chain coordinates (chain_coordinates
// below); the bar's rotary term (Jr/l^2) |u_{k+1} - u_k|^2 / 2 is Jr dphi_k^2 / 2 there, the
// midpoints and hinges move as the chain's, the turning angle's tangent is
// dphi_k - dphi_{k-1} and the mean rotation's (dphi_{k-1} + dphi_k) / 2. So the eigenvalues
// are the dense path's, in exact arithmetic.
//
// ## Shift-invert operator (modal/lanczos.hpp)
// y = (K - sigma M)^{-1} x on G y = 0 is one solve of the bordered band
//   [K - sigma M, kappa G^T; kappa G, 0] [y; mu / kappa] = [x; 0]
// (natural::BandedKkt, factored once by set_shift), the rows scaled by kappa = K / l^2 as in
// the statics. M is positive semidefinite everywhere and definite on G u = 0 (where it is
// the chain's M(q0) plus the point masses), which is all the B product of the eigen layer needs.
//
// ## Refinement
// The assembled K - sigma M cannot hold the low modes to working precision: its entries are
// ~K/l^2 while the low modes' stiffness and mass are ~s m = (l/R)^4 smaller (s the bending
// scale), so the rounding of the entries alone (and the LU's backward error) moves the lowest
// eigenvalues by ~eps (R/l)^4 = eps (n / 2 pi)^4 relative (measured: 3e-10 at n = 300, 1e-3 at
// n = 16000). Each solve is therefore refined against the pencil's product evaluated in link
// rotations: dphi_k = e'_k . (y_{k+1} - y_k) / l from differences, the hinge moments
// K (dphi_k - dphi_{k-1}) and the mean rotations' kr (dphi_{k-1} + dphi_k) / 2 gathered into
// link torques tau_k, the hinge forces tau_{k-1} e'_{k-1} / l - tau_k e'_k / l (the same
// energy's gradient without adding K/l^2-sized entries): its rounding is a relative eps n in
// the low modes' energies. Each refinement step divides the error by ~eps (n / 2 pi)^4
// (at most kMaxRefinementSteps; it stops at the rounding floor), so the path converges to the
// closed form at order 2 up to n = 16000 (tests/multibody/test_modes_terms.cpp: without
// refinement mode 1's error was 1e-3 there; scenes/tyre-ring.toml: still order 2 at n = 80000)
// and fails near n = 10^5, where one band solve no longer contracts (its pairs miss modes.cpp's
// residual gate, exit 3): check_modes refuses n > kPositionModesMaxN (backend.hpp).
//
// Cost: set_shift O(n) (assembly and the band LU), perform_op and PositionMass O(n);
// memory: the band's factors, O(n).
#pragma once

#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "multibody/attachments.hpp"
#include "multibody/chain.hpp"
#include "multibody/natural.hpp"

namespace multibody::natural {

/// The shift-invert operator of the pencil in hinge positions (file comment), for
/// modal::ShiftInvertLanczos. Unknowns: (x_0, y_0, ..., x_{n-1}, y_{n-1}), hinge displacements.
class ShiftedKkt {
 public:
  using Scalar = double;  ///< Spectra's operator interface
  /// The model of `chain` with `terms` (both must outlive this); no factorization until set_shift.
  ShiftedKkt(const Chain& chain, const detail::Attachments& terms);
  /// Assembles and factors K - sigma M with the constraint rows. Throws ring::NumericalError
  /// when the band LU finds it singular (sigma an eigenvalue). O(n).
  void set_shift(double sigma);
  Eigen::Index rows() const { return N_; }
  Eigen::Index cols() const { return N_; }
  /// y = the constrained solve of x, refined (file comment). O(n) per refinement step.
  void perform_op(const double* x_in, double* y_out) const;
  /// Steps of iterative refinement against the pencil's product in link rotations, at most
  /// (file comment): until a correction is below 1e-14 of the solution or no longer halves.
  static constexpr int kMaxRefinementSteps = 6;
  /// r_x -= (K - sigma M) y + G^T mu and r_c -= G y, the bordered system's product at rest
  /// in link rotations (file comment). O(n).
  void subtract_product(const Vec& y, const Vec& mu, Vec& r_x, Vec& r_c) const;
  /// The dimension of G u = 0: 2n less the constraint rows.
  int unknowns() const { return N_ - c_.rows(); }
  const Natural& model() const { return c_; }

 private:
  const Chain& chain_;
  const detail::Attachments& terms_;
  const Natural c_;
  const int N_;
  const double kappa_;
  BandedKkt kkt_;
  double sigma_ = 0.0;
  Eigen::Matrix2Xd normal_;           ///< e'_k = (-e_y, e_x) of link k at rest
  std::vector<double> kr_;            ///< rotation_stiffness by hinge
  std::vector<Eigen::Matrix2d> B_;    ///< hinge_stiffness + (-sigma) hinge_mass by hinge, set by set_shift
};

/// y = M x, M the bar masses and the point masses (file comment): the B operator. O(n).
class PositionMass {
 public:
  using Scalar = double;
  PositionMass(const Natural& c, const detail::Attachments& terms);
  Eigen::Index rows() const { return 2 * c_.n; }
  Eigen::Index cols() const { return 2 * c_.n; }
  void perform_op(const double* x_in, double* y_out) const;

 private:
  const Natural& c_;
  const detail::Attachments& terms_;
};

/// The chain coordinates (chain.hpp) of hinge displacements u (2n x k, columns as
/// ShiftedKkt's unknowns) that keep the links: dphi_k = e_k x (u_{k+1} - u_k) / l (cyclic),
/// and (x_0, y_0) = u_0 on a free ring. dofs x k. O(n k).
Matrix chain_coordinates(const Chain& chain, const Matrix& u);

}  // namespace multibody::natural
