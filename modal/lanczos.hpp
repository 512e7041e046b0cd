// The lowest modes of a symmetric pencil given as operators: shift-invert Lanczos
// (Spectra::SymGEigsShiftSolver in GEigsMode::ShiftInvert) behind a small API.
//
// ## Problem
//   \f$ A x = \lambda B x \f$, A symmetric, B symmetric positive definite on the space
//   that matters, both never formed. The caller supplies two operators:
//   - OpType: y = (A - sigma B)^{-1} x (typically a factorization or an O(n) solve).
//     It may be a *constrained* solve, [A - sigma B, C^T; C, 0] [y; mu] = [x; 0], whose
//     range is the admissible subspace C y = 0: the iteration then stays in that subspace
//     (the start vector is op(B r)), and the M-orthogonal complement only contributes
//     eigenvalues nu = 0 of the transformed operator, the far end of the spectrum.
//     Interface (Spectra's SymShiftInvert): `using Scalar = double; rows(); cols();
//     set_shift(double sigma); perform_op(const double* x, double* y) const`.
//   - BOpType: y = B x. Interface (Spectra's DenseSymMatProd): `using Scalar = double;
//     rows(); cols(); perform_op(const double* x, double* y) const`.
//
// ## Method
// Lanczos on T = (A - sigma B)^{-1} B in the B inner product, implicitly restarted
// (Spectra, after ARPACK's dsaupd), full reorthogonalization; the nev eigenvalues
// nu = 1 / (lambda - sigma) of largest magnitude are the lambda closest to sigma. With
// sigma below the whole spectrum (the solvers here take sigma = -EI/(rho A R^4)) these
// are the nev lowest lambda, rigid modes (lambda ~ 0) included, and the transformed
// spectrum is well separated (lambda grows like k^4 for a ring), so one Lanczos pass of
// ncv steps (subspace_size) usually converges them. Convergence: Spectra's Ritz
// estimate |beta_m y_m| < tol * |nu| for all nev values.
//
// ## Cost
// Per Lanczos step: one operator application and one B product, then Spectra's
// reorthogonalization, repeated until max |V^T B f| <= eps ||f||_B, at most five times;
// each repetition is one B product and two passes over the basis (O(n k), k = step).
// For n >= ~10^4 rounding alone fails that test, so all five run: 14 B products and 11
// passes over the basis per step (modal/README.md). ncv steps per restart; memory
// n x ncv doubles for the basis.
//
// ## Errors
// Arguments that can never work (nev outside 1..n-1, ncv outside nev+1..n, operators of
// different sizes) throw std::invalid_argument at construction; a numerical outcome is a
// status (info()), and `eigenvalues()` / `eigenvectors()` of anything but Successful
// throw ring::NumericalError.
//
// Usage (a dense pencil; see tests/modal for the operators):
//   MyShiftSolve op(A, B);  MyBProduct bop(B);
//   modal::ShiftInvertLanczos<MyShiftSolve, MyBProduct> eigs(op, bop, 6, -1.0);
//   if (eigs.compute() != modal::Status::Successful) ...;
//   const Eigen::VectorXd& lambda = eigs.eigenvalues();   // ascending
#pragma once

#include <Spectra/SymGEigsShiftSolver.h>

#include <Eigen/Dense>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>

#include "modal/subspace.hpp"
#include "ring/errors.hpp"

namespace modal {

/// Outcome of a compute() (Spectra's CompInfo).
enum class Status { NotComputed, Successful, NotConverging, NumericalIssue };

struct LanczosOptions {
  int max_restarts = 1000;         ///< implicit restarts before NotConverging
  /// Relative Ritz-residual bound on nu = 1 / (lambda - sigma) (Spectra's tol): the
  /// eigenvalue error is ~ (tol nu)^2 / gap, far below tol for separated eigenvalues.
  double tol = 1e-10;
  std::uint64_t seed = 20261121;   ///< start vector op(B r), r uniform in [-1, 1]^n
  int ncv = 0;                     ///< 0: subspace_size(nev, n)
};

/// The nev eigenpairs of A x = lambda B x closest to sigma, by shift-invert Lanczos.
template <typename OpType, typename BOpType>
class ShiftInvertLanczos {
 public:
  /// \param op   y = (A - sigma B)^{-1} x, possibly constrained (see the file comment);
  ///             set_shift(sigma) is called once here.
  /// \param bop  y = B x.
  /// \param nev  1 <= nev <= n - 1 (n = op.rows()).
  /// \param sigma the shift, not an eigenvalue.
  ShiftInvertLanczos(OpType& op, BOpType& bop, int nev, double sigma, const LanczosOptions& options = {})
      : op_(op), bop_(bop), nev_(nev), sigma_(sigma), options_(options) {
    const auto n = op.rows();
    if (op.cols() != n || bop.rows() != n || bop.cols() != n)
      throw std::invalid_argument("modal: the shift-invert operator (" + std::to_string(n) + " x " +
                                  std::to_string(op.cols()) + ") and the B operator (" +
                                  std::to_string(bop.rows()) + " x " + std::to_string(bop.cols()) +
                                  ") must be square and of one size");
    ncv_ = subspace_size(nev, static_cast<int>(n));
    if (options.ncv != 0) {
      if (options.ncv <= nev || options.ncv > n)
        throw std::invalid_argument("modal: ncv = " + std::to_string(options.ncv) + " must satisfy " +
                                    std::to_string(nev + 1) + " <= ncv <= " + std::to_string(n) +
                                    " (nev < ncv <= n)");
      ncv_ = options.ncv;
    }
    if (!(options.tol > 0.0) || options.max_restarts < 1)
      throw std::invalid_argument("modal: tol (= " + std::to_string(options.tol) + ") must be > 0 and "
                                  "max_restarts (= " + std::to_string(options.max_restarts) + ") >= 1");
  }

  /// Runs the iteration. Cost: see the file comment.
  Status compute() {
    using Solver = Spectra::SymGEigsShiftSolver<OpType, BOpType, Spectra::GEigsMode::ShiftInvert>;
    const Eigen::Index n = op_.rows();
    Solver eigs(op_, bop_, nev_, ncv_, sigma_);  // calls op.set_shift(sigma)
    // Start in the range of the operator (the admissible subspace of a constrained solve).
    std::mt19937_64 gen(options_.seed);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    Eigen::VectorXd r(n), br(n), v0(n);
    for (Eigen::Index i = 0; i < n; ++i) r[i] = uni(gen);
    bop_.perform_op(r.data(), br.data());
    op_.perform_op(br.data(), v0.data());
    if (!v0.allFinite() || v0.squaredNorm() == 0.0) {
      status_ = Status::NumericalIssue;
      return status_;
    }
    eigs.init(v0.data());
    eigs.compute(Spectra::SortRule::LargestMagn, options_.max_restarts, options_.tol,
                 Spectra::SortRule::SmallestAlge);
    restarts_ = static_cast<int>(eigs.num_iterations());
    operations_ = static_cast<int>(eigs.num_operations());
    switch (eigs.info()) {
      case Spectra::CompInfo::Successful: status_ = Status::Successful; break;
      case Spectra::CompInfo::NotConverging: status_ = Status::NotConverging; break;
      default: status_ = Status::NumericalIssue; break;
    }
    if (status_ == Status::Successful) {
      lambda_ = eigs.eigenvalues();
      vectors_ = eigs.eigenvectors();
      if (!lambda_.allFinite()) status_ = Status::NumericalIssue;
    }
    return status_;
  }

  Status info() const { return status_; }
  /// The nev eigenvalues lambda, ascending.
  const Eigen::VectorXd& eigenvalues() const { return checked(lambda_); }
  /// n x nev, B-orthonormal columns in the order of eigenvalues().
  const Eigen::MatrixXd& eigenvectors() const { return checked(vectors_); }
  /// Lanczos passes (1 + implicit restarts) and operator applications of the last compute().
  int restarts() const { return restarts_; }
  int operations() const { return operations_; }
  int ncv() const { return ncv_; }

 private:
  template <typename T>
  const T& checked(const T& value) const {
    if (status_ != Status::Successful)
      throw ring::NumericalError("modal: shift-invert Lanczos " +
                                 std::string(status_ == Status::NotComputed     ? "was not run"
                                             : status_ == Status::NotConverging ? "did not converge"
                                                                                : "met a numerical issue") +
                                 " (" + std::to_string(nev_) + " eigenpairs, n = " +
                                 std::to_string(op_.rows()) + ", ncv = " + std::to_string(ncv_) +
                                 ", shift " + std::to_string(sigma_) + ")");
    return value;
  }

  OpType& op_;
  BOpType& bop_;
  int nev_ = 0, ncv_ = 0;
  double sigma_ = 0.0;
  LanczosOptions options_;
  Status status_ = Status::NotComputed;
  int restarts_ = 0, operations_ = 0;
  Eigen::VectorXd lambda_;
  Eigen::MatrixXd vectors_;
};

}  // namespace modal
