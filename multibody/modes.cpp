#include "multibody/modes.hpp"

#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "ring/errors.hpp"
#include "ring/sampling.hpp"

namespace multibody {

namespace {

using Dependent = ring::MultibodyOptions::Dependent;

/// The paper's dependent angles: the last two, plus (with a roller at hinge r) segment
/// r-1, or n-3 when r-1 is already among the last two.
std::vector<int> paper_dependents(const Chain& c) {
  const int n = c.n();
  std::vector<int> p{n - 2, n - 1};
  if (c.roller_hinge()) {
    const int r = *c.roller_hinge();
    p.insert(p.begin(), r - 1 <= n - 3 ? r - 1 : n - 3);
  }
  return p;
}

/// 2-norm condition number of the paper's block J_2 (last two angle columns of the closure).
double j2_condition(const Matrix& J, int n) {
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(J.block(0, n - 2, 2, 2).eval());
  const auto sv = svd.singularValues();
  return sv[0] / sv[1];
}

/// D^T A D for D = rows I: identity, rows P: X (c x r), without forming A D. O(N^2 c).
Matrix condense(const Matrix& A, const std::vector<int>& I, const std::vector<int>& P,
                const Matrix& X) {
  const int r = static_cast<int>(I.size()), c = static_cast<int>(P.size());
  Matrix AII(r, r), AIP(r, c), APP(c, c);
  for (int j = 0; j < r; ++j)
    for (int i = 0; i < r; ++i) AII(i, j) = A(I[i], I[j]);
  for (int j = 0; j < c; ++j) {
    for (int i = 0; i < r; ++i) AIP(i, j) = A(I[i], P[j]);
    for (int i = 0; i < c; ++i) APP(i, j) = A(P[i], P[j]);
  }
  const Matrix t = AIP * X;  // r x r
  Matrix R = AII + t + t.transpose() + X.transpose() * (APP * X);
  return 0.5 * (R + R.transpose());
}

/// y = G^{-1} M0 G^{-T} x with S = G G^T: the operator whose largest eigenvalues are
/// 1 / (omega^2 + s). O(r^2) per product.
class InverseOp {
 public:
  using Scalar = double;
  InverseOp(const Eigen::LLT<Matrix>& llt, const Matrix& M0) : llt_(llt), M0_(M0) {}
  Eigen::Index rows() const { return M0_.rows(); }
  Eigen::Index cols() const { return M0_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Vector> x(x_in, rows());
    Eigen::Map<Vector> y(y_out, rows());
    Vector t = llt_.matrixU().solve(x);
    y = M0_ * t;
    llt_.matrixL().solveInPlace(y);
  }

 private:
  const Eigen::LLT<Matrix>& llt_;
  const Matrix& M0_;
};

}  // namespace

LinearModel linearize(const Chain& chain, Dependent dependent) {
  const Vector q0 = chain.q0();
  const Matrix M = chain.mass_matrix(q0);
  const Matrix K = chain.stiffness_matrix();
  const Matrix J = chain.constraint_jacobian(q0);
  const int N = chain.dofs(), c = static_cast<int>(J.rows()), r = N - c;
  LinearModel lm;
  lm.j2_condition = j2_condition(J, chain.n());
  if (dependent == Dependent::paper) {
    const std::vector<int> P = paper_dependents(chain);
    std::vector<int> I;
    for (int i = 0; i < N; ++i)
      if (std::find(P.begin(), P.end(), i) == P.end()) I.push_back(i);
    Matrix JP(c, c), JI(c, r);
    for (int k = 0; k < c; ++k) JP.col(k) = J.col(P[k]);
    for (int k = 0; k < r; ++k) JI.col(k) = J.col(I[k]);
    Eigen::FullPivLU<Matrix> lu(JP);
    if (lu.rank() < c)
      throw ring::NumericalError("multibody: the paper's dependent block J_2 is singular (n = " +
                                 std::to_string(chain.n()) + ")");
    const Matrix X = -lu.solve(JI);  // c x r: the paper's -J_2^{-1} J_1
    lm.K0 = condense(K, I, P, X);
    lm.M0 = condense(M, I, P, X);
    lm.kind = Dependent::paper;
    lm.independent = I;
    lm.dependent = P;
    lm.X = X;
  } else {
    // Orthonormal null-space basis: the last r columns of Q in J^T = Q R. Q^T A Q is
    // applied as c Householder reflections from each side: O(N^2 c).
    lm.kind = Dependent::robust;
    lm.qr.compute(J.transpose());
    const auto Q = lm.qr.householderQ();
    auto reduce = [&](const Matrix& A) {
      const Matrix B = Q.transpose() * A;               // Q^T A
      const Matrix C = Q.transpose() * B.transpose();   // Q^T (A Q), A symmetric
      Matrix R = C.bottomRightCorner(r, r);
      return Matrix(0.5 * (R + R.transpose()));
    };
    lm.K0 = reduce(K);
    lm.M0 = reduce(M);
  }
  return lm;
}

Matrix LinearModel::expand(const Matrix& x) const {
  if (kind == Dependent::paper) {
    const int N = static_cast<int>(independent.size() + dependent.size());
    Matrix dq(N, x.cols());
    for (std::size_t k = 0; k < independent.size(); ++k) dq.row(independent[k]) = x.row(k);
    const Matrix xd = X * x;
    for (std::size_t k = 0; k < dependent.size(); ++k) dq.row(dependent[k]) = xd.row(k);
    return dq;
  }
  const int N = static_cast<int>(qr.rows()), r = static_cast<int>(x.rows());
  Matrix dq = Matrix::Zero(N, x.cols());
  dq.bottomRows(r) = x;
  return qr.householderQ() * dq;
}

Matrix LinearModel::basis() const {
  return expand(Matrix::Identity(K0.rows(), K0.rows()));
}

ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          int count) {
  const auto start = std::chrono::steady_clock::now();
  if (options.method == ring::MultibodyOptions::Method::sparse)
    throw std::invalid_argument(
        "multibody: method = sparse is not implemented; use automatic or dense (dense serves "
        "n up to a few thousand)");
  const Chain chain(spec, options);
  const int N = chain.dofs(), r = N - chain.constraint_count();
  const int expected_rigid = spec.supports.rigid_modes();
  if (count < 1 || count > r - expected_rigid)
    throw std::invalid_argument("multibody: count = " + std::to_string(count) +
                                " must satisfy 1 <= count <= " + std::to_string(r - expected_rigid) +
                                " (elastic modes of the n = " + std::to_string(chain.n()) + " chain)");

  ModalSolution sol;
  sol.model = linearize(chain, options.dependent);
  const Matrix& K0 = sol.model.K0;
  const Matrix& M0 = sol.model.M0;

  // M0 is positive definite in exact arithmetic (M = Jr I + m l^2 G^T G with G of full
  // column rank, D of full column rank); this guards against rounding at extreme n.
  if (Eigen::LLT<Matrix>(M0).info() != Eigen::Success)
    throw ring::NumericalError("multibody: reduced mass matrix M0 is not positive definite (n = " +
                               std::to_string(chain.n()) + ")");
  const double R = spec.radius;
  const double s = spec.EI() / (spec.rhoA() * R * R * R * R);
  const Eigen::LLT<Matrix> llt(K0 + s * M0);
  if (llt.info() != Eigen::Success)
    throw ring::NumericalError("multibody: K0 + s M0 is not positive definite (n = " +
                               std::to_string(chain.n()) + ")");

  // Largest eigenvalues mu of G^{-1} M0 G^{-T}, descending, with their vectors y.
  const int nev = std::min(r, count + expected_rigid + 2);
  Vector mu;
  Matrix y;
  if (r <= 300 || 3 * nev > r) {
    Matrix T = llt.matrixL().solve(M0);                  // G^{-1} M0
    Matrix C = llt.matrixL().solve(T.transpose());       // G^{-1} M0 G^{-T}
    C = 0.5 * (C + C.transpose());
    Eigen::SelfAdjointEigenSolver<Matrix> es(C);
    if (es.info() != Eigen::Success)
      throw ring::NumericalError("multibody: dense eigensolver did not converge");
    mu = es.eigenvalues().reverse();
    y = es.eigenvectors().rowwise().reverse();
  } else {
    InverseOp op(llt, M0);
    const int ncv = std::min(r, std::max(2 * nev + 1, nev + 20));
    Spectra::SymEigsSolver<InverseOp> eigs(op, nev, ncv);
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestAlge, 1000, 1e-13);
    if (eigs.info() != Spectra::CompInfo::Successful)
      throw ring::NumericalError("multibody: Lanczos (Spectra) did not converge for " +
                                 std::to_string(nev) + " modes of " + std::to_string(r));
    mu = eigs.eigenvalues();
    y = eigs.eigenvectors();
  }

  // Classify: rigid when omega^2 < kRigidThreshold * s; keep the `count` lowest elastic.
  std::vector<double> rigid;
  std::vector<int> keep;
  for (int i = 0; i < mu.size(); ++i) {
    if (!(mu[i] > 0.0)) break;  // M0 positive definite: the remaining spectrum is unusable
    const double w2 = 1.0 / mu[i] - s;
    if (w2 < kRigidThreshold * s)
      rigid.push_back(w2);
    else if (static_cast<int>(keep.size()) < count)
      keep.push_back(i);
  }
  if (static_cast<int>(keep.size()) < count)
    throw ring::NumericalError("multibody: found only " + std::to_string(keep.size()) + " of " +
                               std::to_string(count) + " elastic modes");
  sol.rigid_omega2 = Eigen::Map<Vector>(rigid.data(), static_cast<Eigen::Index>(rigid.size()));

  ring::ModalResult& res = sol.result;
  res.solver = "multibody";
  res.model["n"] = static_cast<long long>(chain.n());
  res.model["rotary_inertia"] = options.rotary_inertia;
  res.model["dependent"] = ring::to_string(options.dependent);
  res.model["method"] = std::string("dense");
  res.rigid_modes = static_cast<int>(rigid.size());
  res.unknowns = r;
  sol.x.resize(r, count);
  for (int k = 0; k < count; ++k) {
    Vector x = llt.matrixU().solve(y.col(keep[k]));  // G^{-T} y
    x /= std::sqrt(x.dot(M0 * x));
    const double w2 = 1.0 / mu[keep[k]] - s;
    const Vector Kx = K0 * x, Mx = M0 * x;
    res.max_residual = std::max(res.max_residual, (Kx - w2 * Mx).norm() / (Kx.norm() + w2 * Mx.norm()));
    res.omega.push_back(std::sqrt(w2));
    sol.x.col(k) = x;
  }
  sol.dq = sol.model.expand(sol.x);
  // Solver time: everything up to the chain-coordinate shapes; the sampling at the
  // common stations below is output formatting (ring::sample_polygon, ~10 us per mode).
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Hinge displacements delta p_k = delta p_0 + l sum_{j<k} e'(phi0_j) delta phi_j.
  const int n = chain.n();
  const Vector& phi0 = chain.phi0();
  for (int k = 0; k < count; ++k) {
    std::vector<double> ux(n), uy(n);
    double x = chain.free() ? sol.dq(n, k) : 0.0, yv = chain.free() ? sol.dq(n + 1, k) : 0.0;
    for (int j = 0; j < n; ++j) {
      ux[j] = x;
      uy[j] = yv;
      x -= chain.l() * std::sin(phi0[j]) * sol.dq(j, k);
      yv += chain.l() * std::cos(phi0[j]) * sol.dq(j, k);
    }
    res.shapes.push_back(ring::sample_polygon(chain.anchor_deg(), ux, uy));
  }
  return sol;
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                int count) {
  return solve_modes(spec, options, count).result;
}

}  // namespace multibody
