#include "multibody/modes.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <Spectra/SymEigsSolver.h>
#include <Spectra/SymGEigsSolver.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>
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

namespace {

/// The sparse large-n path: the same reduced problem (orthonormal null-space basis
/// Q = Householder factor of J^T, applied implicitly in O(n c)), but K0, M0 and
/// S0 = K0 + s M0 only as operators. M(q0) is applied in O(n) through the midpoint
/// kinematics, and S0^{-1} by one sparse LU of a banded saddle-point system in
/// (angles x, midpoint velocities V = v_t + l L E' x, back-sums W = L^T m V,
/// multipliers lambda), where L's cumulative sums become bidiagonal relations:
///   V_i - V_{i-1} = l (E'x_{i-1} + E'x_i) / 2,   W_j - W_{j+1} = m (V_j + V_{j+1}) / 2,
///   (K + s Jr) x + s l (-sin phi_j W_x + cos phi_j W_y) + J^T lambda = f,   J x = 0.
/// Rows are scaled by 1/K (angles), 1/(s m) (translations), 1/l, 1/m. The constraints J x = 0 border this banded system
/// (unknowns 5n (+2)), eliminated with c extra solves. O(n) factorization and solves.
class SparseReduced {
 public:
  static constexpr int kRefinementSteps = 2;
  SparseReduced(const Chain& c, double shift) : c_(c), q0_(c.q0()), s_(shift) {
    cos_ = c.phi0().array().cos();
    sin_ = c.phi0().array().sin();
    const Matrix J = c.constraint_jacobian(q0_);
    qr_.compute(J.transpose());
    N_ = c.dofs();
    nc_ = static_cast<int>(J.rows());
    assemble(J);
  }
  int r() const { return N_ - nc_; }
  Vector expand(const Vector& xr) const {
    Vector v = Vector::Zero(N_);
    v.tail(r()) = xr;
    return qr_.householderQ() * v;
  }
  Vector reduce(const Vector& v) const { return (qr_.householderQ().transpose() * v).tail(r()); }
  Vector K0(const Vector& xr) const { return reduce(k_times(expand(xr))); }
  Vector M0(const Vector& xr) const { return reduce(m_times(expand(xr))); }
  Vector S0(const Vector& xr) const {
    const Vector x = expand(xr);
    return reduce(k_times(x) + s_ * m_times(x));
  }
  /// S0^{-1} yr: the constrained solve by bordering, x = z - Z lambda with
  /// lambda = (J Z)^{-1} J z, where A0 z = f and A0 Z = J^T (prefactored). O(n).
  Vector S0_solve(const Vector& yr) const {
    // One step of iterative refinement with the residual taken in angle coordinates
    // (S0 applied in O(n) without the mixed variables) removes the error that the mixed
    // banded system's conditioning adds at large n.
    Vector x = border_solve(yr);
    for (int step = 0; step < kRefinementSteps; ++step) x += border_solve(yr - S0(x));
    return x;
  }
  const Eigen::HouseholderQR<Matrix>& qr() const { return qr_; }

 private:
  Vector border_solve(const Vector& yr) const {
    const Vector f = expand(yr);
    Vector rhs = Vector::Zero(lu_.rows());
    for (int i = 0; i < N_; ++i) rhs[xi_[i]] = f[i] * row_scale_[i];
    const Vector z = lu_.solve(rhs);
    Vector x(N_);
    for (int i = 0; i < N_; ++i) x[i] = z[xi_[i]];
    x -= Zx_ * jz_lu_.solve(J_ * x);
    return reduce(x);
  }
  /// Chain::mass_times at q0 with the trigonometry cached (same recurrences). O(n).
  Vector m_times(const Vector& v) const {
    const int n = c_.n();
    const double l = c_.l(), m = c_.m(), Jr = c_.Jr();
    std::vector<double> Vx(n), Vy(n);
    double ax = c_.free() ? v[n] : 0.0, ay = c_.free() ? v[n + 1] : 0.0;
    for (int i = 0; i < n; ++i) {
      const double tx = -l * v[i] * sin_[i], ty = l * v[i] * cos_[i];
      Vx[i] = ax + 0.5 * tx;
      Vy[i] = ay + 0.5 * ty;
      ax += tx;
      ay += ty;
    }
    Vector y(N_);
    double bx = 0.0, by = 0.0;
    for (int j = n - 1; j >= 0; --j) {
      const double wx = bx + 0.5 * m * Vx[j], wy = by + 0.5 * m * Vy[j];
      y[j] = l * (-sin_[j] * wx + cos_[j] * wy) + Jr * v[j];
      bx += m * Vx[j];
      by += m * Vy[j];
    }
    if (c_.free()) {
      y[n] = bx;
      y[n + 1] = by;
    }
    return y;
  }
  Vector k_times(const Vector& x) const {
    const int n = c_.n();
    Vector y = Vector::Zero(N_);
    for (int k = 0; k < n; ++k) y[k] = c_.K() * (2 * x[k] - x[(k + n - 1) % n] - x[(k + 1) % n]);
    return y;
  }
  // Unknowns and equations interleaved per segment i, block [x_i, Vx_i, Vy_i, Wx_i, Wy_i]
  // at 5i (+2 after the translations of a free ring, which come first): a band of width
  // ~10 plus the cyclic spring between segments n-1 and 0.
  void assemble(const Matrix& J) {
    const int n = c_.n();
    const double l = c_.l(), m = c_.m(), K = c_.K(), Jr = c_.Jr();
    const int o = c_.free() ? 2 : 0;
    auto X = [&](int i) { return o + 5 * i; };
    auto VX = [&](int i) { return o + 5 * i + 1; };
    auto VY = [&](int i) { return o + 5 * i + 2; };
    auto WX = [&](int i) { return o + 5 * i + 3; };
    auto WY = [&](int i) { return o + 5 * i + 4; };
    const int T = o + 5 * n;
    xi_.resize(N_);
    row_scale_.assign(N_, 1.0 / K);
    for (int i = 0; i < n; ++i) xi_[i] = X(i);
    if (c_.free()) {
      xi_[n] = 0;
      xi_[n + 1] = 1;
      row_scale_[n] = row_scale_[n + 1] = 1.0 / (s_ * m);
    }
    const Vector& phi = c_.phi0();
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(25 * n + 8));
    for (int j = 0; j < n; ++j) {  // angle rows / K: (K + s Jr) x + s l (-sin W_x + cos W_y)
      const double sj = std::sin(phi[j]), cj = std::cos(phi[j]);
      t.emplace_back(X(j), X(j), 2.0 + s_ * Jr / K);
      t.emplace_back(X(j), X((j + n - 1) % n), -1.0);
      t.emplace_back(X(j), X((j + 1) % n), -1.0);
      t.emplace_back(X(j), WX(j), -s_ * l * sj / K);
      t.emplace_back(X(j), WY(j), s_ * l * cj / K);
    }
    if (c_.free()) {  // translation rows / (s m): s (W_0 + m V_0 / 2) = f_t
      t.emplace_back(0, WX(0), 1.0 / m);
      t.emplace_back(0, VX(0), 0.5);
      t.emplace_back(1, WY(0), 1.0 / m);
      t.emplace_back(1, VY(0), 0.5);
    }
    for (int i = 0; i < n; ++i) {  // V rows / l: V_i - V_{i-1} = l (E'x_{i-1} + E'x_i) / 2
      t.emplace_back(VX(i), VX(i), 1.0 / l);
      t.emplace_back(VY(i), VY(i), 1.0 / l);
      t.emplace_back(VX(i), X(i), 0.5 * std::sin(phi[i]));
      t.emplace_back(VY(i), X(i), -0.5 * std::cos(phi[i]));
      if (i == 0) {
        if (c_.free()) {  // V_0 = v_t + l E'x_0 / 2
          t.emplace_back(VX(0), 0, -1.0 / l);
          t.emplace_back(VY(0), 1, -1.0 / l);
        }
      } else {
        t.emplace_back(VX(i), VX(i - 1), -1.0 / l);
        t.emplace_back(VY(i), VY(i - 1), -1.0 / l);
        t.emplace_back(VX(i), X(i - 1), 0.5 * std::sin(phi[i - 1]));
        t.emplace_back(VY(i), X(i - 1), -0.5 * std::cos(phi[i - 1]));
      }
    }
    for (int j = 0; j < n; ++j) {  // W rows / m: W_j - W_{j+1} = m (V_j + V_{j+1}) / 2
      t.emplace_back(WX(j), WX(j), 1.0 / m);
      t.emplace_back(WY(j), WY(j), 1.0 / m);
      t.emplace_back(WX(j), VX(j), -0.5);
      t.emplace_back(WY(j), VY(j), -0.5);
      if (j + 1 < n) {
        t.emplace_back(WX(j), WX(j + 1), -1.0 / m);
        t.emplace_back(WY(j), WY(j + 1), -1.0 / m);
        t.emplace_back(WX(j), VX(j + 1), -0.5);
        t.emplace_back(WY(j), VY(j + 1), -0.5);
      }
    }
    Eigen::SparseMatrix<double> A(T, T);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    lu_.analyzePattern(A);
    lu_.factorize(A);
    if (lu_.info() != Eigen::Success)
      throw ring::NumericalError("multibody: sparse LU of the chain's banded system failed (n = " +
                                 std::to_string(n) + "): " + lu_.lastErrorMessage());
    // Border: Z = A0^{-1} [J^T / K; 0], then the small c x c system J Z.
    J_ = J;
    Zx_.resize(N_, nc_);
    for (int a = 0; a < nc_; ++a) {
      Vector rhs = Vector::Zero(T);
      for (int i = 0; i < N_; ++i) rhs[xi_[i]] = J(a, i) * row_scale_[i];
      const Vector z = lu_.solve(rhs);
      for (int i = 0; i < N_; ++i) Zx_(i, a) = z[xi_[i]];
    }
    jz_lu_.compute(J_ * Zx_);
  }

  const Chain& c_;
  Vector q0_;
  double s_;
  Vector cos_, sin_;  ///< of phi0
  int N_ = 0, nc_ = 0;
  Eigen::HouseholderQR<Matrix> qr_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  std::vector<int> xi_;     ///< position of chain coordinate i among the sparse unknowns
  std::vector<double> row_scale_;  ///< scaling of chain coordinate i's equation
  Matrix J_, Zx_;           ///< constraint Jacobian (c x N) and A0^{-1} J^T / K (N x c)
  Eigen::PartialPivLU<Matrix> jz_lu_;
};

/// Spectra operator objects over SparseReduced: A = M0 and B = S0 (with B^{-1}).
struct SparseAOp {
  using Scalar = double;
  const SparseReduced& p;
  Eigen::Index rows() const { return p.r(); }
  Eigen::Index cols() const { return p.r(); }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<Vector>(y, p.r()) = p.M0(Eigen::Map<const Vector>(x, p.r()));
  }
};
struct SparseBOp {
  using Scalar = double;
  const SparseReduced& p;
  Eigen::Index rows() const { return p.r(); }
  Eigen::Index cols() const { return p.r(); }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<Vector>(y, p.r()) = p.S0(Eigen::Map<const Vector>(x, p.r()));
  }
  void solve(const double* x, double* y) const {
    Eigen::Map<Vector>(y, p.r()) = p.S0_solve(Eigen::Map<const Vector>(x, p.r()));
  }
};

/// Lanczos parameters shared by both paths: ncv >= 2 nev + 1, tolerance 1e-13 relative
/// on the Ritz residuals (eigenvalue error ~ residual^2 / gap: far below 1e-8).
int ncv_for(int nev, int r) { return std::min(r, std::max(2 * nev + 1, nev + 20)); }

}  // namespace

bool uses_sparse_path(const ring::MultibodyOptions& options) {
  using Method = ring::MultibodyOptions::Method;
  if (options.method == Method::sparse) return true;
  if (options.method == Method::dense) return false;
  return options.dependent == Dependent::robust && options.n > kSparseThreshold;
}

ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          int count) {
  const auto start = std::chrono::steady_clock::now();
  const bool sparse = uses_sparse_path(options);
  if (sparse && options.dependent == Dependent::paper)
    throw std::invalid_argument(
        "multibody: method = sparse needs dependent = robust (the paper's dependent angles are "
        "offered on the dense path only)");
  const Chain chain(spec, options);
  const int N = chain.dofs(), r = N - chain.constraint_count();
  const int expected_rigid = spec.supports.rigid_modes();
  if (count < 1 || count > r - expected_rigid)
    throw std::invalid_argument("multibody: count = " + std::to_string(count) +
                                " must satisfy 1 <= count <= " + std::to_string(r - expected_rigid) +
                                " (elastic modes of the n = " + std::to_string(chain.n()) + " chain)");
  const double R = spec.radius;
  const double s = spec.EI() / (spec.rhoA() * R * R * R * R);
  const int nev = std::min(r, count + expected_rigid + 2);

  ModalSolution sol;
  // Largest eigenvalues mu of S0^{-1} M0 (descending) and their reduced vectors (any scale).
  Vector mu;
  Matrix vecs;
  std::function<Vector(const Vector&)> K0x, M0x;
  std::optional<SparseReduced> sp;
  if (!sparse) {
    sol.model = linearize(chain, options.dependent);
    const Matrix& K0 = sol.model.K0;
    const Matrix& M0 = sol.model.M0;
    // M0 is positive definite in exact arithmetic (M = Jr I + m l^2 G^T G with G of full
    // column rank, D of full column rank); this guards against rounding at extreme n.
    if (Eigen::LLT<Matrix>(M0).info() != Eigen::Success)
      throw ring::NumericalError("multibody: reduced mass matrix M0 is not positive definite (n = " +
                                 std::to_string(chain.n()) + ")");
    const Eigen::LLT<Matrix> llt(K0 + s * M0);
    if (llt.info() != Eigen::Success)
      throw ring::NumericalError("multibody: K0 + s M0 is not positive definite (n = " +
                                 std::to_string(chain.n()) + ")");
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
      Spectra::SymEigsSolver<InverseOp> eigs(op, nev, ncv_for(nev, r));
      eigs.init();
      eigs.compute(Spectra::SortRule::LargestAlge, 1000, 1e-13);
      if (eigs.info() != Spectra::CompInfo::Successful)
        throw ring::NumericalError("multibody: Lanczos (Spectra) did not converge for " +
                                   std::to_string(nev) + " modes of " + std::to_string(r));
      mu = eigs.eigenvalues();
      y = eigs.eigenvectors();
    }
    vecs = llt.matrixU().solve(y);  // x = G^{-T} y
    K0x = [&K0](const Vector& x) { return Vector(K0 * x); };
    M0x = [&M0](const Vector& x) { return Vector(M0 * x); };
  } else {
    // M0 is positive definite by construction (see above); on this path it is never formed,
    // so the check is that every Ritz value mu = x^T M0 x / x^T S0 x comes out > 0.
    sp.emplace(chain, s);
    SparseAOp aop{*sp};
    SparseBOp bop{*sp};
    Spectra::SymGEigsSolver<SparseAOp, SparseBOp, Spectra::GEigsMode::RegularInverse> eigs(
        aop, bop, nev, ncv_for(nev, r));
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestAlge, 1000, 1e-13);
    if (eigs.info() != Spectra::CompInfo::Successful)
      throw ring::NumericalError("multibody: sparse Lanczos (Spectra) did not converge for " +
                                 std::to_string(nev) + " modes of " + std::to_string(r));
    mu = eigs.eigenvalues();
    vecs = eigs.eigenvectors();
    if (!(mu.minCoeff() > 0.0))
      throw ring::NumericalError("multibody: non-positive Ritz value of S0^{-1} M0: M0 is not "
                                 "positive definite (n = " + std::to_string(chain.n()) + ")");
    K0x = [&sp](const Vector& x) { return sp->K0(x); };
    M0x = [&sp](const Vector& x) { return sp->M0(x); };
    sol.model.kind = Dependent::robust;
    sol.model.qr = sp->qr();
    sol.model.j2_condition = j2_condition(chain.constraint_jacobian(chain.q0()), chain.n());
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
  res.model["method"] = std::string(sparse ? "sparse" : "dense");
  res.rigid_modes = static_cast<int>(rigid.size());
  res.unknowns = r;
  sol.x.resize(r, count);
  for (int k = 0; k < count; ++k) {
    Vector x = vecs.col(keep[k]);
    Vector Mx = M0x(x);
    const double norm = std::sqrt(x.dot(Mx));
    x /= norm;
    Mx /= norm;
    const double w2 = 1.0 / mu[keep[k]] - s;
    const Vector Kx = K0x(x);
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
  sol.hinge_ux.resize(n, count);
  sol.hinge_uy.resize(n, count);
  for (int k = 0; k < count; ++k) {
    double x = chain.free() ? sol.dq(n, k) : 0.0, yv = chain.free() ? sol.dq(n + 1, k) : 0.0;
    for (int j = 0; j < n; ++j) {
      sol.hinge_ux(j, k) = x;
      sol.hinge_uy(j, k) = yv;
      x -= chain.l() * std::sin(phi0[j]) * sol.dq(j, k);
      yv += chain.l() * std::cos(phi0[j]) * sol.dq(j, k);
    }
    const Vector ux = sol.hinge_ux.col(k), uy = sol.hinge_uy.col(k);
    res.shapes.push_back(ring::sample_polygon(chain.anchor_deg(), std::vector<double>(ux.data(), ux.data() + n),
                                              std::vector<double>(uy.data(), uy.data() + n)));
  }
  return sol;
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                int count) {
  return solve_modes(spec, options, count).result;
}

}  // namespace multibody
