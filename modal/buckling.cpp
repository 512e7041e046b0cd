#include "modal/buckling.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <stdexcept>

#include "modal/modes.hpp"
#include "ring/errors.hpp"

namespace modal {

CriticalFactors critical_factors(const Eigen::MatrixXd& K0, const Eigen::MatrixXd& K1, int count,
                                 const std::string& who) {
  const Eigen::LLT<Eigen::MatrixXd> llt(K0);
  if (llt.info() != Eigen::Success)
    throw std::invalid_argument(who + ": the stiffness at rest is not positive definite: the ring has a rigid "
                                "mode that the supports leave free; add a support");
  Eigen::MatrixXd C = llt.matrixL().solve(K1.selfadjointView<Eigen::Lower>().toDenseMatrix());
  C = llt.matrixL().solve(C.transpose()).eval();  // L^-1 K_1 L^-T (K_1 symmetric)
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (C + C.transpose()));
  if (eig.info() != Eigen::Success) throw std::runtime_error(who + ": the buckling eigenproblem did not converge");
  const Eigen::VectorXd& mu = eig.eigenvalues();  // ascending: the most negative first
  const double floor = 1e-12 * mu.cwiseAbs().maxCoeff();
  int positive = 0;
  while (positive < mu.size() && mu[positive] < -floor) ++positive;
  if (positive < count)
    throw std::invalid_argument(who + ": buckling.count = " + std::to_string(count) + ", but the loads have only " +
                                std::to_string(positive) + " positive critical load factor" +
                                (positive == 1 ? "" : "s") + " in this model (the others buckle under the loads "
                                "reversed, or never); ask for fewer");
  CriticalFactors out;
  out.factors.resize(count);
  for (int i = 0; i < count; ++i) out.factors[i] = -1.0 / mu[i];
  out.vectors = llt.matrixU().solve(eig.eigenvectors().leftCols(count));  // L^-T y
  return out;
}

Eigen::MatrixXd kernel_basis(const Eigen::MatrixXd& G, Eigen::Index N) {
  if (G.rows() == 0) return Eigen::MatrixXd::Identity(N, N);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(G.transpose());
  return Eigen::MatrixXd(qr.householderQ()).rightCols(N - qr.rank());
}

int unstable_directions(const Eigen::MatrixXd& T, const Eigen::MatrixXd& G) {
  const Eigen::MatrixXd Z = kernel_basis(G, T.rows());
  const Eigen::MatrixXd reduced = Z.transpose() * T * Z;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (reduced + reduced.transpose()),
                                                           Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& v = eig.eigenvalues();
  const double floor = 1e-12 * v.cwiseAbs().maxCoeff();
  int negative = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) negative += v[i] < -floor ? 1 : 0;
  return negative;
}

LeastStable least_stable(const Eigen::MatrixXd& T, const Eigen::MatrixXd& G) {
  const Eigen::MatrixXd Z = kernel_basis(G, T.rows());
  const Eigen::MatrixXd reduced = Z.transpose() * T * Z;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (reduced + reduced.transpose()));
  return {Z * eig.eigenvectors().col(0), eig.eigenvalues()[0]};
}

LoadedModes loaded_modes(const Eigen::MatrixXd& T, const Eigen::MatrixXd& M, double shift, int count,
                         const std::string& who) {
  const Eigen::Index r = T.rows();
  if (count < 1 || count > r)
    throw std::invalid_argument(who + ": modes.count (=" + std::to_string(count) + ") must be between 1 and the " +
                                std::to_string(r) + " modes of the loaded model");
  const Eigen::MatrixXd Ts = 0.5 * (T + T.transpose());
  const Eigen::LLT<Eigen::MatrixXd> llt(Ts + shift * M);
  if (llt.info() != Eigen::Success)
    throw ring::NumericalError(who + ": the loaded ring is at or past a critical load (T + s M is not positive "
                               "definite on the constraints' tangent space)");
  Eigen::MatrixXd C = llt.matrixL().solve(M);
  C = llt.matrixL().solve(C.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (C + C.transpose()));
  LoadedModes out;
  out.omega2.resize(count);
  out.vectors.resize(r, count);
  for (int k = 0; k < count; ++k) {
    const double w2 = 1.0 / eig.eigenvalues()[r - 1 - k] - shift;
    if (!(w2 > 0.0))
      throw ring::NumericalError(who + ": omega^2 = " + std::to_string(w2) +
                                 " <= 0 at the equilibrium: the loaded ring is at or past a critical load");
    const Eigen::VectorXd y = llt.matrixU().solve(eig.eigenvectors().col(r - 1 - k));
    out.max_residual = worst(out.max_residual, (Ts * y - w2 * M * y).norm() / ((Ts * y).norm() + w2 * (M * y).norm()));
    out.omega2(k) = w2;
    out.vectors.col(k) = y;
  }
  return out;
}

}  // namespace modal
