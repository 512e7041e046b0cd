// modal/ against pencils whose spectra are known in closed form, not computed by the
// code under test:
// - linear finite elements of -u'' = lambda u on (0, 1), u(0) = u(1) = 0, n interior
//   nodes, h = 1/(n+1): A = tridiag(-1, 2, -1) / h, B = h tridiag(1, 4, 1) / 6, with
//   lambda_k = (6 / h^2) (1 - cos t_k) / (2 + cos t_k), t_k = k pi / (n+1) (the discrete
//   sine transform diagonalizes both matrices; e.g. Strang & Fix, An Analysis of the
//   Finite Element Method, sec. 6.1);
// - the periodic second difference, A = circulant(-1, 2, -1) / h, B = h I, h = 1/n:
//   lambda_k = (2 - 2 cos(2 pi k / n)) / h^2, k = 0 (a rigid mode, the constant) and
//   double eigenvalues for 0 < k < n/2; with the constraint sum(u) = 0 as a bordered
//   (constrained) solve, the constant is excluded and the rest remains.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <cmath>
#include <stdexcept>

#include "modal/lanczos.hpp"
#include "modal/modes.hpp"
#include "ring/errors.hpp"
#include "support/close.hpp"

namespace {

using SpMat = Eigen::SparseMatrix<double>;
using Eigen::VectorXd;

SpMat tridiag(int n, double diag, double off, bool periodic) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, diag);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, off);
      t.emplace_back(i + 1, i, off);
    }
  }
  if (periodic) {
    t.emplace_back(0, n - 1, off);
    t.emplace_back(n - 1, 0, off);
  }
  SpMat m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

/// y = (A - sigma B)^{-1} x, or with constraints C (rows) the bordered solve
/// [A - sigma B, C^T; C, 0] [y; mu] = [x; 0], whose range is C y = 0.
class ShiftSolve {
 public:
  using Scalar = double;
  ShiftSolve(const SpMat& A, const SpMat& B, const SpMat& C) : A_(A), B_(B), C_(C) {}
  Eigen::Index rows() const { return A_.rows(); }
  Eigen::Index cols() const { return A_.cols(); }
  void set_shift(double sigma) {
    const Eigen::Index n = A_.rows(), c = C_.rows();
    std::vector<Eigen::Triplet<double>> t;
    const SpMat S = A_ - sigma * B_;
    for (int j = 0; j < S.outerSize(); ++j)
      for (SpMat::InnerIterator it(S, j); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
    for (int j = 0; j < C_.outerSize(); ++j)
      for (SpMat::InnerIterator it(C_, j); it; ++it) {
        t.emplace_back(n + it.row(), it.col(), it.value());
        t.emplace_back(it.col(), n + it.row(), it.value());
      }
    K_.resize(n + c, n + c);
    K_.setFromTriplets(t.begin(), t.end());
    lu_.compute(K_);
    if (lu_.info() != Eigen::Success) throw std::runtime_error("test: LU failed");
  }
  void perform_op(const double* x, double* y) const {
    VectorXd b = VectorXd::Zero(K_.rows());
    b.head(rows()) = Eigen::Map<const VectorXd>(x, rows());
    Eigen::Map<VectorXd>(y, rows()) = lu_.solve(b).head(rows());
  }

 private:
  const SpMat &A_, &B_, &C_;
  SpMat K_;
  Eigen::SparseLU<SpMat> lu_;
};

class Product {
 public:
  using Scalar = double;
  explicit Product(const SpMat& B) : B_(B) {}
  Eigen::Index rows() const { return B_.rows(); }
  Eigen::Index cols() const { return B_.cols(); }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<VectorXd>(y, rows()) = B_ * Eigen::Map<const VectorXd>(x, rows());
  }

 private:
  const SpMat& B_;
};

// Tolerance of the eigenvalues: the shift-invert pencil's rounding, ~eps ||A|| / lambda_1
// relative = eps (n / pi)^2 ~ 1e-12 for n = 400 (the closed forms are exact); 1e-10
// leaves a factor 100.
constexpr double kEigTol = 1e-10;

TEST(ModalLanczos, DirichletLaplacianFEMatchesClosedForm) {
  const int n = 400, nev = 12;
  const double h = 1.0 / (n + 1);
  const SpMat A = tridiag(n, 2.0 / h, -1.0 / h, false);
  const SpMat B = tridiag(n, 4.0 * h / 6.0, h / 6.0, false);
  const SpMat C(0, n);
  ShiftSolve op(A, B, C);
  Product bop(B);
  modal::ShiftInvertLanczos<ShiftSolve, Product> eigs(op, bop, nev, -1.0);
  ASSERT_EQ(eigs.compute(), modal::Status::Successful);
  EXPECT_EQ(eigs.ncv(), modal::subspace_size(nev, n));
  const VectorXd& lam = eigs.eigenvalues();
  const Eigen::MatrixXd& X = eigs.eigenvectors();
  ASSERT_EQ(lam.size(), nev);
  for (int k = 1; k <= nev; ++k) {
    const double t = k * M_PI / (n + 1);
    const double exact = 6.0 / (h * h) * (1.0 - std::cos(t)) / (2.0 + std::cos(t));
    EXPECT_TRUE(ringtest::IsClose(lam[k - 1], exact, kEigTol)) << "k = " << k;
  }
  // B-orthonormal vectors (Lanczos with full reorthogonalization: ~eps sqrt(n) ncv).
  // Backward error: the stopping rule ||T x - nu x||_B < tol nu (T the shift-invert
  // operator) bounds it by ~tol = LanczosOptions::tol = 1e-10 (measured 1.5e-13).
  const Eigen::MatrixXd G = X.transpose() * B * X;
  EXPECT_LT((G - Eigen::MatrixXd::Identity(nev, nev)).cwiseAbs().maxCoeff(), 1e-12);
  const double na = modal::norm_estimate([&](const VectorXd& v) { return VectorXd(A * v); }, n, 50);
  const double nb = modal::norm_estimate([&](const VectorXd& v) { return VectorXd(B * v); }, n, 50);
  for (int k = 0; k < nev; ++k) {
    const VectorXd x = X.col(k);
    const modal::PairResidual r = modal::pair_residual(A * x, B * x, lam[k], x.norm(), na, nb);
    EXPECT_LT(r.backward, modal::LanczosOptions{}.tol) << "k = " << k + 1;
  }
  // The norm estimate is a lower bound within a few % of ||A|| = 4 / h cos^2(pi/(2(n+1))).
  EXPECT_LE(na, 4.0 / h);
  EXPECT_GT(na, 0.9 * 4.0 / h);
}

TEST(ModalLanczos, PeriodicLaplacianRigidModeAndDoubleEigenvalues) {
  const int n = 300, nev = 9;  // k = 0, 1, 1, 2, 2, 3, 3, 4, 4
  const double h = 1.0 / n;
  const SpMat A = tridiag(n, 2.0 / h, -1.0 / h, true);
  SpMat B(n, n);
  B.setIdentity();
  B *= h;
  const SpMat C(0, n);
  ShiftSolve op(A, B, C);
  Product bop(B);
  const double scale = 1.0;  // lambda_1 = 4 pi^2 ~ 39.5: elastic; the constant is rigid
  modal::ShiftInvertLanczos<ShiftSolve, Product> eigs(op, bop, nev, -scale);
  ASSERT_EQ(eigs.compute(), modal::Status::Successful);
  const VectorXd& lam = eigs.eigenvalues();
  const modal::Selection sel = modal::select_modes("test", lam, scale, nev - 1);
  ASSERT_EQ(sel.rigid.size(), 1u);
  // The rigid mode's lambda is round-off: |lambda_0| <= eps ||A|| / ... (absolute,
  // ~1e-16 * 4 n^2 ~ 4e-11; bound 1e-8 = the threshold's 1e-6 scale with margin).
  EXPECT_LT(std::abs(sel.rigid_omega2[0]), 1e-8);
  ring::ModalResult res;
  modal::assemble(res, "test", lam, sel);
  EXPECT_EQ(res.rigid_modes, 1);
  ASSERT_EQ(res.omega.size(), static_cast<std::size_t>(nev - 1));
  for (int i = 0; i < nev - 1; ++i) {
    const int k = i / 2 + 1;
    const double exact = (2.0 - 2.0 * std::cos(2.0 * M_PI * k / n)) / (h * h);
    EXPECT_TRUE(ringtest::IsClose(res.omega[i] * res.omega[i], exact, kEigTol)) << "i = " << i;
  }
}

TEST(ModalLanczos, ConstrainedSolveExcludesTheConstrainedMode) {
  const int n = 300, nev = 8;
  const double h = 1.0 / n;
  const SpMat A = tridiag(n, 2.0 / h, -1.0 / h, true);
  SpMat B(n, n);
  B.setIdentity();
  B *= h;
  SpMat C(1, n);  // sum(u) = 0: orthogonal to the constant
  for (int i = 0; i < n; ++i) C.insert(0, i) = 1.0;
  ShiftSolve op(A, B, C);
  Product bop(B);
  modal::ShiftInvertLanczos<ShiftSolve, Product> eigs(op, bop, nev, -1.0);
  ASSERT_EQ(eigs.compute(), modal::Status::Successful);
  const VectorXd& lam = eigs.eigenvalues();
  const Eigen::MatrixXd& X = eigs.eigenvectors();
  for (int i = 0; i < nev; ++i) {
    const int k = i / 2 + 1;
    const double exact = (2.0 - 2.0 * std::cos(2.0 * M_PI * k / n)) / (h * h);
    EXPECT_TRUE(ringtest::IsClose(lam[i], exact, kEigTol)) << "i = " << i;
    // Admissible: |sum u| / (sqrt(n) ||u||) at round-off (a few eps; 1e-12 with margin).
    EXPECT_LT(std::abs(X.col(i).sum()) / (std::sqrt(n) * X.col(i).norm()), 1e-12);
  }
}

TEST(ModalLanczos, ArgumentsThatCannotWorkThrow) {
  const int n = 30;
  const SpMat A = tridiag(n, 2.0, -1.0, false);
  const SpMat B = tridiag(n, 1.0, 0.0, false);
  const SpMat C(0, n);
  ShiftSolve op(A, B, C);
  Product bop(B);
  using Eigs = modal::ShiftInvertLanczos<ShiftSolve, Product>;
  EXPECT_THROW(Eigs(op, bop, 0, -1.0), std::invalid_argument);
  EXPECT_THROW(Eigs(op, bop, n, -1.0), std::invalid_argument);
  modal::LanczosOptions o;
  o.ncv = 5;
  EXPECT_THROW(Eigs(op, bop, 5, -1.0, o), std::invalid_argument);
  const SpMat B2 = tridiag(n + 1, 1.0, 0.0, false);
  Product bop2(B2);
  EXPECT_THROW(Eigs(op, bop2, 3, -1.0), std::invalid_argument);
  Eigs e(op, bop, 3, -1.0);
  EXPECT_EQ(e.info(), modal::Status::NotComputed);
  EXPECT_THROW(e.eigenvalues(), ring::NumericalError);
  EXPECT_THROW(modal::subspace_size(0, 10), std::invalid_argument);
  EXPECT_EQ(modal::subspace_size(3, 10), 10);
  EXPECT_EQ(modal::subspace_size(26, 1000), 53);
}

TEST(ModalModes, SelectionCountsRigidAndFailsWhenShort) {
  const VectorXd w2 = (VectorXd(5) << 9.0, 1e-12, 4.0, -1e-13, 1.0).finished();
  const modal::Selection s = modal::select_modes("test", w2, 1.0, 3);
  EXPECT_EQ(s.rigid.size(), 2u);
  EXPECT_EQ(s.elastic, (std::vector<int>{4, 2, 0}));
  EXPECT_THROW(modal::select_modes("test", w2, 1.0, 4), ring::NumericalError);
  const VectorXd bad = (VectorXd(2) << 1.0, std::nan("")).finished();
  EXPECT_THROW(modal::select_modes("test", bad, 1.0, 1), ring::NumericalError);
  EXPECT_THROW(modal::select_modes("test", w2, 0.0, 1), std::invalid_argument);
}

}  // namespace
