// The shifted solve of the sparse large-n path: (K + s M(q0))^{-1} on the null space of
// the constraint Jacobian J, in O(n), in chain coordinates (chain.hpp), never forming
// anything of size n^2.
//
// ## Method
// K and M(q0) are O(n) operators (M through the midpoint kinematics). S = K + s M is
// split as S = A + (rank-one cyclic spring at hinge 0) + (translation coupling, free
// ring), with the constraints J dq = 0 and those two couplings as a border of k <= 6
// extra unknowns (Schur complement of k prefactored solves).
//
// A is the "open chain": hinge 0 held, springs at hinges 1..n-1 only, full mass
// (m |midpoint displacement|^2 + Jr x^2). Its solve A x = f is the minimization of
// 1/2 x^T A x - f^T x, a chain of scalar decisions with the state z_i = (h_i, x_{i-1})
// (hinge i's displacement, previous angle), h_{i+1} = h_i + l e'(phi_i) x_i: a discrete
// Riccati sweep (backward: quadratic cost-to-go P_i, 3x3; forward: x_i). Every pivot is
// a scalar >= s Jr + s m l^2 / 4 + K > 0 and every P_i a Schur complement of a positive
// semidefinite matrix, so the sweep is Cholesky-stable; ~60 flops per segment per solve,
// 10 doubles per segment stored. One step of iterative refinement against S (applied in
// O(n)) takes the solve to its rounding level.
//
// ## As an operator of the eigen layer (modal/lanczos.hpp)
// ShiftedSolve is the shift-invert operator y = (K - sigma M)^{-1} x of the pencil
// (K, M) restricted to J dq = 0 (sigma = -s; set_shift factors), and MassProduct the B
// product y = M x. The range of the solve is the admissible subspace, so the Lanczos
// iteration stays there.
//
// Cost: set_shift O(n) (one backward sweep, k border solves); perform_op / solve_full
// O(n) (two sweeps per solve, two solves with the refinement, one S product); m_times,
// k_times, S_full O(n). Memory O(n k).
#pragma once

#include <Eigen/Dense>

#include "multibody/chain.hpp"

namespace multibody {

class ShiftedSolve {
 public:
  using Scalar = double;  ///< Spectra's operator interface
  /// Steps of iterative refinement with the residual of the bordered system: one takes
  /// the solve to its rounding level (docs/measured.md, "Accuracy, sparse path").
  static constexpr int kRefinementSteps = 1;

  /// Scratch of the products and solves below, owned by the caller (one per thread): a
  /// loop that reuses one Workspace and its output vectors allocates nothing per product
  /// or solve (fresh n-sized temporaries cost page faults at large n). Outputs must not
  /// alias inputs.
  struct Workspace {
    Vector r, t, v;
  };

  /// Trigonometry, the Householder QR of J^T; no factorization until set_shift.
  explicit ShiftedSolve(const Chain& chain);
  /// Factors S = K - sigma M for sigma < 0 (s = -sigma > 0 keeps S positive definite);
  /// std::invalid_argument for sigma >= 0. O(n).
  void set_shift(double sigma);

  Eigen::Index rows() const { return N_; }
  Eigen::Index cols() const { return N_; }
  /// y = the constrained solve of x (solve_full), for the eigen layer.
  void perform_op(const double* x_in, double* y_out) const;

  int dofs() const { return N_; }
  int r() const { return N_ - nc_; }  ///< dimension of the null space of J
  double shift() const { return s_; }  ///< s = -sigma
  const Eigen::HouseholderQR<Matrix>& qr() const { return qr_; }  ///< of J^T
  /// Euclidean projection onto the null space of J: v -= J^T (J J^T)^{-1} J v. O(n c).
  void project(Vector& v) const;
  /// y = S dq = (K + s M(q0)) dq in chain coordinates. O(n).
  void S_full(const Eigen::Ref<const Vector>& dq, Eigen::Ref<Vector> y, Workspace& ws) const;
  /// dq = the constrained solve [S J^T; J 0] [dq; lambda] = [f; 0] in chain coordinates
  /// (dq in the null space of J), refined `refinements` times against S_full: the
  /// multiplier part of the residual is absorbed by the next solve's lambda. O(n) each.
  void solve_full(const Eigen::Ref<const Vector>& f, Eigen::Ref<Vector> dq, Workspace& ws,
                  int refinements = kRefinementSteps) const;
  /// y = M(q0) v: Chain::mass_times at q0 with the trigonometry cached. O(n).
  void m_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y, Workspace& ws) const;
  /// y = K x: springs at every hinge (cyclic). O(n).
  void k_times(const Eigen::Ref<const Vector>& x, Eigen::Ref<Vector> y) const;

 private:
  void factor_open();
  void open_solve(double* fx) const;
  void border(const Matrix& J);
  void full_solve(const Eigen::Ref<const Vector>& f, Eigen::Ref<Vector> dq, Vector& lambda) const;

  const Chain& c_;
  double s_ = 0.0;
  const Vector& cos_;  ///< of phi0: the chain's own (Chain::cos0, sin0), not a copy
  const Vector& sin_;
  int N_ = 0, nc_ = 0, na_ = 0;
  Eigen::HouseholderQR<Matrix> qr_;
  Eigen::Matrix<double, 3, Eigen::Dynamic> hzx_;  ///< Riccati cross terms per segment
  Vector inv_hxx_;                                ///< 1 / Riccati pivots
  Matrix B_, C_, Z_;                              ///< border (n x k, k x n), Z = A^{-1} B
  Eigen::FullPivLU<Matrix> schur_;                ///< D - C Z, k x k
  Matrix Jt_;                                     ///< J^T, N x c
  Eigen::LLT<Matrix> jjt_;                        ///< J J^T, c x c
};

/// y = M(q0) x through ShiftedSolve::m_times: the B operator of the eigen layer.
class MassProduct {
 public:
  using Scalar = double;
  explicit MassProduct(const ShiftedSolve& solve) : solve_(solve) {}
  Eigen::Index rows() const { return solve_.rows(); }
  Eigen::Index cols() const { return solve_.cols(); }
  void perform_op(const double* x_in, double* y_out) const;

 private:
  const ShiftedSolve& solve_;
};

}  // namespace multibody
