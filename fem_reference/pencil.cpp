// The dense eigen step of the beam's pencils and its extended-precision refinement
// (pencil.hpp), shared by linear buckling and the frequencies under load.
#include "fem_reference/pencil.hpp"

#include <limits>
#include <sstream>

#include "fem_reference/buckling.hpp"
#include "modal/buckling.hpp"
#include "modal/modes.hpp"

namespace fem::detail {

Eigen::MatrixXd dense(const SparseMatrix<double>& A) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(A.m(), A.n());
  for (auto it = A.begin(); it != A.end(); ++it) D(it->row(), it->column()) = it->value();
  return D;
}

void check_dense_size(const Setup& setup, unsigned int N, bool refining, const std::string& analysis) {
  if (N <= kDenseBucklingLimit) return;
  const std::string m = std::to_string(setup.cells()) + " cells of degree " + std::to_string(setup.degree) + " give " +
                        std::to_string(N) + " unknowns, more than the dense " + analysis + " eigen step takes (" +
                        std::to_string(kDenseBucklingLimit) + ")";
  if (refining) throw ring::NumericalError("fem: the " + analysis + " reference refinement reached " + m);
  throw std::invalid_argument("fem: fem.elements (=" + std::to_string(setup.elements) + ") with fem.degree (=" +
                              std::to_string(setup.degree) + "): " + m + "; use fewer elements or a lower degree");
}

Pairs raw_pairs(const Eigen::MatrixXd& P, const Eigen::MatrixXd& Q, int count, unsigned int N) {
  const int guarded = static_cast<int>(std::min<unsigned int>(N, count + kGuardModes));
  modal::CriticalFactors cf;
  try {
    cf = modal::critical_factors(P, Q, guarded, "fem");
  } catch (const std::invalid_argument&) {
    if (guarded == count) throw;
    cf = modal::critical_factors(P, Q, count, "fem");
  }
  Pairs p;
  p.factors.assign(cf.factors.data(), cf.factors.data() + cf.factors.size());
  p.vectors = cf.vectors;
  return p;
}

Pairs refine(const LinearModel& model, const SparseDirectUMFPACK& P_inverse, const Eigen::MatrixXd& E,
             const Eigen::MatrixXd& Q, Pairs p, int count, const std::string& who) {
  const unsigned int N = model.n_free();
  const int m = static_cast<int>(p.vectors.cols());
  const bool corrected = E.size() > 0;
  Eigen::MatrixXd& X = p.vectors;
  Eigen::MatrixXd PX(N, m);
  Vector<double> x(N), z(N), r(N);
  auto stiffness = [&](int j) {  // column j of PX, and the Gram column X^T P x_j in extended precision
    for (unsigned int i = 0; i < N; ++i) x[i] = X(i, j);
    std::vector<Real> px = model.stiffness_product(x);
    if (corrected) {
      const Eigen::VectorXd ex = E * X.col(j);
      for (unsigned int i = 0; i < N; ++i) px[i] += ex(i);
    }
    for (unsigned int i = 0; i < N; ++i) PX(i, j) = static_cast<double>(px[i]);
    return px;
  };
  auto ritz = [&]() {
    Eigen::MatrixXd A0(m, m);
    for (int j = 0; j < m; ++j) {
      const std::vector<Real> px = stiffness(j);
      for (int k = 0; k < m; ++k) {
        Real a = 0;
        for (unsigned int i = 0; i < N; ++i) a += X(i, k) * px[i];
        A0(k, j) = static_cast<double>(a);
      }
    }
    A0 = 0.5 * (A0 + A0.transpose()).eval();
    Eigen::MatrixXd A1 = X.transpose() * Q * X;
    A1 = 0.5 * (A1 + A1.transpose()).eval();
    // The small pencil: A0 = L L^T, mu of L^-1 A1 L^-T ascending (lambda = -1/mu).
    const Eigen::LLT<Eigen::MatrixXd> llt(A0);
    if (llt.info() != Eigen::Success) throw ring::NumericalError(who + ": the refinement's Gram matrix lost its rank");
    Eigen::MatrixXd C = llt.matrixL().solve(A1);
    C = llt.matrixL().solve(C.transpose()).eval();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (C + C.transpose()));
    for (int k = 0; k < count; ++k)
      if (!(eig.eigenvalues()[k] < 0))
        throw ring::NumericalError(who + ": the refinement lost eigenvalue " + std::to_string(k + 1));
    for (int k = 0; k < m; ++k) p.factors[k] = -1.0 / eig.eigenvalues()[k];
    X = (X * llt.matrixU().solve(eig.eigenvectors())).eval();
    for (int j = 0; j < m; ++j) stiffness(j);
  };
  p.residuals.assign(count, 0.0);
  double previous = std::numeric_limits<double>::infinity();
  for (unsigned int round = 0;; ++round) {
    ritz();
    const Eigen::MatrixXd QX = Q * X;
    double worst = 0.0;
    Eigen::MatrixXd next = X;
    for (int k = 0; k < m; ++k) {
      if (k < count) {
        for (unsigned int i = 0; i < N; ++i) r[i] = PX(i, k) + p.factors[k] * QX(i, k);
        P_inverse.vmult(z, r);
        double xpx = 0.0;
        for (unsigned int i = 0; i < N; ++i) xpx += X(i, k) * PX(i, k);
        const double rz = r * z;
        p.residuals[k] = rz >= 0 && xpx > 0 ? std::sqrt(rz / xpx) : std::numeric_limits<double>::infinity();
        worst = modal::worst(worst, p.residuals[k]);
        for (unsigned int i = 0; i < N; ++i) next(i, k) -= z[i];
      } else {
        for (unsigned int i = 0; i < N; ++i) r[i] = QX(i, k);
        P_inverse.vmult(z, r);
        for (unsigned int i = 0; i < N; ++i) next(i, k) = z[i];
      }
    }
    p.residual = worst;
    if (worst <= kRefinedResidual || worst > 0.5 * previous || round + 1 >= kMaxRefinementRounds) break;
    previous = worst;
    X = std::move(next);
  }
  if (!(p.residual <= kAcceptedResidual)) {
    std::ostringstream msg;
    msg.precision(3);
    msg << who << ": the eigen step lost its accuracy: a wanted pair keeps a relative residual of " << p.residual
        << " after refinement (accepted: " << kAcceptedResidual << "; " << N
        << " unknowns): use fewer elements or a lower degree";
    throw ring::NumericalError(msg.str());
  }
  return p;
}

}  // namespace fem::detail
