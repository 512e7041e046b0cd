#include "multibody/modes.hpp"

#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <chrono>
#include <functional>
#include <optional>
#include <cmath>
#include <numeric>
#include <random>
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
/// kinematics. S0^{-1} is a constrained solve of S = K + s M in chain coordinates,
/// split as S = A + (rank-one cyclic spring at hinge 0) + (translation coupling, free
/// ring), with the constraints J dq = 0 and those two couplings as a border of k <= 6
/// extra unknowns (Schur complement of k prefactored solves).
///
/// A is the "open chain": hinge 0 held, springs at hinges 1..n-1 only, full mass
/// (m |midpoint displacement|^2 + Jr x^2). Its solve A x = f is the minimization of
/// 1/2 x^T A x - f^T x, a chain of scalar decisions with the state z_i = (h_i, x_{i-1})
/// (hinge i's displacement, previous angle), h_{i+1} = h_i + l e'(phi_i) x_i: a discrete
/// Riccati sweep (backward: quadratic cost-to-go P_i, 3x3; forward: x_i). Every pivot is
/// a scalar >= s Jr + s m l^2 / 4 + K > 0 and every P_i a Schur complement of a positive
/// semidefinite matrix, so the sweep is Cholesky-stable; ~60 flops per segment per solve,
/// 10 doubles per segment stored. The previous banded mixed (angle, midpoint velocity,
/// back-sum) system with a general sparse LU cost ~20x more per solve and grew
/// superlinearly (3.2 s for n = 40000).
class SparseReduced {
 public:
  /// Steps of iterative refinement with the residual in reduced coordinates. One step
  /// takes the solve to its rounding level (measured: a second step changes the 23
  /// frequencies by < 1e-14 relative at n = 1e5).
  static constexpr int kRefinementSteps = 1;
  SparseReduced(const Chain& c, double shift) : c_(c), s_(shift) {
    cos_ = c.phi0().array().cos();
    sin_ = c.phi0().array().sin();
    const Matrix J = c.constraint_jacobian(c.q0());
    qr_.compute(J.transpose());
    N_ = c.dofs();
    nc_ = static_cast<int>(J.rows());
    factor_open();
    border(J);
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
  /// S0^{-1} yr, refined against S0 applied in O(n) (kRefinementSteps). O(n).
  Vector S0_solve(const Vector& yr) const {
    return reduce(solve_full(expand(yr)));
  }
  const Eigen::HouseholderQR<Matrix>& qr() const { return qr_; }
  int dofs() const { return N_; }
  const Matrix& Jt() const { return Jt_; }
  /// Euclidean projection onto the null space of J: v -= J^T (J J^T)^{-1} J v. O(n c).
  void project(Vector& v) const { v.noalias() -= Jt_ * jjt_.solve(Jt_.transpose() * v); }
  /// S dq = (K + s M(q0)) dq in chain coordinates. O(n).
  Vector S_full(const Vector& dq) const { return k_times(dq) + s_ * m_times(dq); }
  /// The constrained solve [S J^T; J 0] [dq; lambda] = [f; 0] in chain coordinates
  /// (dq in the null space of J), refined kRefinementSteps times against S_full: the
  /// multiplier part of the residual is absorbed by the next solve's lambda. O(n).
  Vector solve_full(const Vector& f) const {
    Vector lambda(nc_), dl(nc_);
    Vector dq = full_solve(f, lambda);
    for (int step = 0; step < kRefinementSteps; ++step) {
      // The residual of the bordered system, J^T lambda included: without it the
      // residual is dominated by the multiplier part and the refinement gains nothing.
      dq += full_solve(f - S_full(dq) - Jt_ * lambda, dl);
      lambda += dl;
    }
    return dq;
  }
  /// D^T Y for the columns of Y (N x k): Householder reflections blocked over the columns.
  Matrix reduce_cols(const Matrix& Y) const {
    return (qr_.householderQ().transpose() * Y).bottomRows(r());
  }
  /// Chain::mass_times at q0 with the trigonometry cached (same recurrences). O(n).
  Vector m_times(const Vector& v) const {
    const int n = c_.n();
    const double l = c_.l(), m = c_.m(), Jr = c_.Jr();
    // Forward: midpoint displacements V_i; backward: W_j = sum_{i >= j} m V_i - m V_j / 2.
    Vector y(N_);
    double ax = c_.free() ? v[n] : 0.0, ay = c_.free() ? v[n + 1] : 0.0;
    std::vector<double> V(2 * static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double tx = -l * v[i] * sin_[i], ty = l * v[i] * cos_[i];
      V[2 * i] = ax + 0.5 * tx;
      V[2 * i + 1] = ay + 0.5 * ty;
      ax += tx;
      ay += ty;
    }
    double bx = 0.0, by = 0.0;
    for (int j = n - 1; j >= 0; --j) {
      const double wx = bx + 0.5 * m * V[2 * j], wy = by + 0.5 * m * V[2 * j + 1];
      y[j] = l * (-sin_[j] * wx + cos_[j] * wy) + Jr * v[j];
      bx += m * V[2 * j];
      by += m * V[2 * j + 1];
    }
    if (c_.free()) {
      y[n] = bx;
      y[n + 1] = by;
    }
    return y;
  }
  /// K dq: springs at every hinge (cyclic). O(n).
  Vector k_times(const Vector& x) const {
    const int n = c_.n();
    const double K = c_.K();
    Vector y = Vector::Zero(N_);
    y[0] = K * (2 * x[0] - x[n - 1] - x[1 % n]);
    for (int k = 1; k + 1 < n; ++k) y[k] = K * (2 * x[k] - x[k - 1] - x[k + 1]);
    if (n > 1) y[n - 1] = K * (2 * x[n - 1] - x[n - 2] - x[0]);
    return y;
  }

 private:
  /// Backward Riccati sweep of the open chain (matrix part, once). For segment i the
  /// stage cost in (z_i, x_i) plus the cost-to-go 1/2 z_{i+1}^T P_{i+1} z_{i+1},
  /// z_{i+1} = F z_i + g_i x_i (F keeps h, drops x_{i-1}; g_i = (l e'_i, 1)), is a
  /// quadratic with Hessian [[Hzz, hzx], [hzx^T, hxx]]; eliminating x_i gives
  /// P_i = Hzz - hzx hzx^T / hxx.
  void factor_open() {
    const int n = c_.n();
    const double l = c_.l(), m = c_.m(), K = c_.K(), Jr = c_.Jr(), s = s_;
    hzx_.resize(3, n);
    inv_hxx_.resize(n);
    Eigen::Matrix3d P = Eigen::Matrix3d::Zero();  // P_n: open end, no cost
    for (int i = n - 1; i >= 0; --i) {
      const double gx = -l * sin_[i], gy = l * cos_[i];
      const Eigen::Vector3d g(gx, gy, 1.0);
      const Eigen::Vector3d Pg = P * g;
      const double spring = i >= 1 ? K : 0.0;
      const double hxx = spring + s * (m * l * l / 4.0 + Jr) + g.dot(Pg);
      // hzx = stage cross terms + F^T P g (F^T picks the h rows).
      Eigen::Vector3d hzx(s * m * 0.5 * gx + Pg[0], s * m * 0.5 * gy + Pg[1], -spring);
      Eigen::Matrix3d Hzz = Eigen::Matrix3d::Zero();
      Hzz.topLeftCorner<2, 2>() = P.topLeftCorner<2, 2>();
      Hzz(0, 0) += s * m;
      Hzz(1, 1) += s * m;
      Hzz(2, 2) = spring;
      P = Hzz - hzx * hzx.transpose() / hxx;
      hzx_.col(i) = hzx;
      inv_hxx_[i] = 1.0 / hxx;
    }
  }
  /// x = A^{-1} f for the open chain (first n entries of f). Two sweeps, O(n).
  Vector open_solve(const Vector& f) const {
    const int n = c_.n();
    const double l = c_.l();
    // Backward: linear cost-to-go term q_i (cost -q^T z); hx_i = f_i + g_i^T q_{i+1}.
    Vector hx(n);
    double q0 = 0.0, q1 = 0.0, q2 = 0.0;
    for (int i = n - 1; i >= 0; --i) {
      const double gx = -l * sin_[i], gy = l * cos_[i];
      const double h = f[i] + gx * q0 + gy * q1 + q2;
      hx[i] = h;
      const double t = h * inv_hxx_[i];
      // q_i = F^T q_{i+1} - hzx hx / hxx
      q0 = q0 - hzx_(0, i) * t;
      q1 = q1 - hzx_(1, i) * t;
      q2 = -hzx_(2, i) * t;
    }
    // Forward: x_i = (hx_i - hzx_i^T z_i) / hxx_i, z_0 = 0.
    Vector x(n);
    double zx = 0.0, zy = 0.0, zp = 0.0;
    for (int i = 0; i < n; ++i) {
      const double xi = (hx[i] - hzx_(0, i) * zx - hzx_(1, i) * zy - hzx_(2, i) * zp) * inv_hxx_[i];
      x[i] = xi;
      zx += -l * sin_[i] * xi;
      zy += l * cos_[i] * xi;
      zp = xi;
    }
    return x;
  }
  /// Border of the open chain: extra unknowns e = (alpha = x_0 - x_{n-1} for the cyclic
  /// spring at hinge 0; translation a (free ring); multipliers lambda):
  ///   A x + B e = f_x,   C x + D e = (f_a, 0...)  with
  ///   B = [K u, s A_xa, J_x^T],  C = [u^T; s A_xa^T; J_x],  D = diag(-1, [s m n I, J_a^T], [J_a, 0]).
  void border(const Matrix& J) {
    const int n = c_.n();
    const double l = c_.l(), m = c_.m(), K = c_.K();
    const int na = c_.free() ? 2 : 0;
    const int k = 1 + na + nc_;
    B_ = Matrix::Zero(n, k);
    C_ = Matrix::Zero(k, n);
    Matrix D = Matrix::Zero(k, k);
    B_(0, 0) = K;
    B_(n - 1, 0) = -K;
    C_(0, 0) = 1.0;
    C_(0, n - 1) = -1.0;
    D(0, 0) = -1.0;
    for (int a = 0; a < na; ++a) {
      // d^2 (s m/2 sum |y_j|^2) / dx_i da = s m l e'_i (n - i - 1/2).
      for (int i = 0; i < n; ++i) {
        const double e = a == 0 ? -sin_[i] : cos_[i];
        B_(i, 1 + a) = s_ * m * l * e * (n - i - 0.5);
      }
      C_.row(1 + a) = B_.col(1 + a).transpose();
      D(1 + a, 1 + a) = s_ * m * n;
    }
    for (int b = 0; b < nc_; ++b) {
      B_.col(1 + na + b) = J.row(b).head(n).transpose();
      C_.row(1 + na + b) = J.row(b).head(n);
      for (int a = 0; a < na; ++a) {
        D(1 + a, 1 + na + b) = J(b, n + a);
        D(1 + na + b, 1 + a) = J(b, n + a);
      }
    }
    Z_.resize(n, k);
    for (int j = 0; j < k; ++j) Z_.col(j) = open_solve(B_.col(j));
    schur_.compute(D - C_ * Z_);
    na_ = na;
    Jt_ = J.transpose();
    jjt_.compute(J * Jt_);
  }
  /// The constrained solve in chain coordinates: [S J^T; J 0] [dq; lambda] = [f; 0]. O(n k).
  Vector full_solve(const Vector& f, Vector& lambda) const {
    const int n = c_.n(), k = static_cast<int>(Z_.cols());
    const Vector x0 = open_solve(f.head(n));
    Vector g = Vector::Zero(k);
    for (int a = 0; a < na_; ++a) g[1 + a] = f[n + a];
    const Vector e = schur_.solve(g - C_ * x0);
    Vector dq(N_);
    dq.head(n) = x0 - Z_ * e;
    for (int a = 0; a < na_; ++a) dq[n + a] = e[1 + a];
    lambda = e.tail(nc_);
    return dq;
  }
  const Chain& c_;
  double s_;
  Vector cos_, sin_;  ///< of phi0
  int N_ = 0, nc_ = 0, na_ = 0;
  Eigen::HouseholderQR<Matrix> qr_;
  Eigen::Matrix<double, 3, Eigen::Dynamic> hzx_;  ///< Riccati cross terms per segment
  Vector inv_hxx_;                                ///< 1 / Riccati pivots
  Matrix B_, C_, Z_;                              ///< border (n x k, k x n), Z = A^{-1} B
  Eigen::FullPivLU<Matrix> schur_;                ///< D - C Z, k x k
  Matrix Jt_;                                     ///< J^T, N x c
  Eigen::LLT<Matrix> jjt_;                        ///< J J^T, c x c
};

/// Lanczos for the largest eigenvalues mu of T = S_c M (S_c: the constrained solve
/// SparseReduced::solve_full), run in chain coordinates on the null space of J: T is
/// self-adjoint there in the S inner product and equals S0^{-1} M0 in the reduced
/// coordinates x = D^T dq, so the Ritz values are those of the reduced pencil and the
/// Householder basis D is applied only to the final vectors. No restart: the wanted
/// mu = 1/(omega^2 + s) are the best separated end of the spectrum (omega^2 grows like
/// k^4), so ~2 nev steps converge them (measured: 45..50 steps for nev = 26, n = 2000 ..
/// 10^6).
/// Step k: p = M v_k, w = S_c p; since S w = p - J^T lambda and J v_j = 0, the local
/// coefficients <w, v_j>_S = v_j^T p (j = k-1, k) need no S product; then one full
/// classical Gram-Schmidt pass with the true S w (two reads of the basis per step
/// instead of Spectra's repeated S products and reallocations, ~10x faster here).
/// Stops when the nev largest Ritz values have residual |beta_k y_k| <= tol * theta
/// (Spectra's criterion, tol = 1e-13), or when the Krylov space is invariant.
/// Cost per step: two Riccati solves, one M and three S products (O(n)), 2 k N for the
/// reorthogonalization. Memory: N x (steps + 1). Returns chain-coordinate vectors.
void sparse_lanczos(const SparseReduced& sp, int nev, Vector& mu, Matrix& vecs) {
  const int N = sp.dofs(), r = sp.r();
  const int max_steps = std::min(r, 4 * nev + 60);
  // Residual estimate |beta y_last| <= 1e-8 theta: the Ritz values come from the exact
  // Rayleigh quotient V^T M V, so their error is quadratic in the residual (~1e-16 theta
  // for gaps ~theta). The estimate stagnates near 1e-9 (the solve's rounding in the S
  // norm; measured n = 2000 .. 2e5), so Spectra's 1e-13 would never be met here.
  constexpr double tol = 1e-8;
  Matrix V(N, max_steps + 1);
  std::mt19937_64 gen(20260421);  // fixed seed: reproducible runs
  std::uniform_real_distribution<double> uni(-0.5, 0.5);
  Vector w(N);
  for (int i = 0; i < N; ++i) w[i] = uni(gen);
  w = sp.solve_full(w);  // a start vector in the null space of J
  w /= std::sqrt(w.dot(sp.S_full(w)));
  V.col(0) = w;
  Eigen::SelfAdjointEigenSolver<Matrix> es;
  int m = 0;  // Krylov dimension reached
  bool done = false;
  Matrix H = Matrix::Zero(max_steps, max_steps);  // V^T M V = V^T S T V, by columns
  for (int k = 0; k < max_steps && !done; ++k) {
    const Vector p = sp.m_times(V.col(k));
    const auto Vk = V.leftCols(k + 1);
    // Column k of the Rayleigh quotient V^T M V: exact up to the dot products' rounding,
    // whatever the solve's error (which only slows convergence).
    const Vector h = Vk.transpose() * p;
    H.col(k).head(k + 1) = h;
    H.row(k).head(k + 1) = h.transpose();
    w = sp.solve_full(p);
    const double b0 = std::sqrt(std::max(0.0, w.dot(p)));  // ||w||_S before orthogonalization
    w.noalias() -= Vk * h;  // Gram-Schmidt with <w, v_j>_S = v_j^T (p - J^T lambda) = h_j
    Vector q = sp.S_full(w);
    double b = std::sqrt(std::max(0.0, w.dot(q)));
    if (!(b > 0.7 * b0)) {  // DGKS: cancellation, so a second pass with the true S w
      const Vector h2 = Vk.transpose() * q;
      w.noalias() -= Vk * h2;
      q = sp.S_full(w);
      b = std::sqrt(std::max(0.0, w.dot(q)));
    }
    m = k + 1;
    if (!(b > 1e-10 * b0) && m < r) {
      // The Krylov space closed (a single start vector spans one copy of each multiple
      // eigenvalue: the free ring's three rigid modes and its cos/sin pairs): continue
      // with a fresh random direction in the null space, S-orthogonal to V. H stays the
      // exact Rayleigh quotient (its new column comes from the next step's dots).
      for (int i = 0; i < N; ++i) w[i] = uni(gen);
      w = sp.solve_full(w);
      for (int pass = 0; pass < 2; ++pass) w.noalias() -= Vk * (Vk.transpose() * sp.S_full(w)).eval();
      sp.project(w);
      b = std::sqrt(std::max(0.0, w.dot(sp.S_full(w))));
      V.col(k + 1) = w / b;
      continue;
    }
    const bool invariant = m == r;
    if (m >= nev) {
      es.compute(H.topLeftCorner(m, m));
      if (es.info() != Eigen::Success) throw ring::NumericalError("multibody: Ritz eigensolver failed");
      done = invariant;
      if (!done) {
        done = true;
        for (int i = 0; i < nev; ++i) {
          const int j = m - 1 - i;  // ascending order: the largest last
          const double theta = es.eigenvalues()[j];
          if (std::abs(b * es.eigenvectors()(m - 1, j)) > tol * std::abs(theta)) done = false;
        }
      }
    }
    if (!done) {
      sp.project(w);  // rounding (and, at invariance, noise) off the null space of J
      V.col(k + 1) = w / b;  // the projection moves w by rounding only (not invariant here)
    }
  }
  if (!done)
    throw ring::NumericalError("multibody: sparse Lanczos did not converge for " + std::to_string(nev) +
                               " modes of " + std::to_string(r) + " in " + std::to_string(max_steps) + " steps");
  mu.resize(nev);
  Matrix Y(m, nev);
  for (int i = 0; i < nev; ++i) {
    mu[i] = es.eigenvalues()[m - 1 - i];
    Y.col(i) = es.eigenvectors().col(m - 1 - i);
  }
  vecs = V.leftCols(m) * Y;
}

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
  // Automatic choice: the sparse path also needs few modes relative to r (its Lanczos
  // basis grows with the count; asking for a third of the spectrum or more is the dense
  // path's job, as in the small-problem rule of the dense path itself). Set below.
  bool sparse = uses_sparse_path(options);
  if (sparse && options.dependent == Dependent::paper)
    throw std::invalid_argument(
        "multibody: method = sparse needs dependent = robust (the paper's dependent angles are "
        "offered on the dense path only)");
  const Chain chain(spec, options);
  // Forced sparse path: measured right from n = 10 (every support, with and without rotary
  // inertia, against the dense path: tests/multibody/test_modes_sparse.cpp), wrong at n = 8.
  if (sparse && options.method == ring::MultibodyOptions::Method::sparse && chain.n() < 10)
    throw std::invalid_argument("multibody: method = sparse needs n >= 10 (n = " + std::to_string(chain.n()) +
                                "); use method = \"dense\" or \"auto\"");
  const int N = chain.dofs(), r = N - chain.constraint_count();
  const int expected_rigid = spec.supports.rigid_modes();
  if (count < 1 || count > r - expected_rigid)
    throw std::invalid_argument("multibody: count = " + std::to_string(count) +
                                " must satisfy 1 <= count <= " + std::to_string(r - expected_rigid) +
                                " (elastic modes of the n = " + std::to_string(chain.n()) + " chain)");
  if (sparse && options.method == ring::MultibodyOptions::Method::automatic &&
      3 * std::min(r, count + expected_rigid + 2) > r)
    sparse = false;
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
    sparse_lanczos(*sp, nev, mu, vecs);
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
  // Norms for the backward error: ||K0||_2 and ||M0||_2 estimated by power iteration
  // (10 products from an alternating start; the Rayleigh quotient is a lower bound and
  // converges to ~1 % for these spectra, which is all a backward error's scale needs).
  auto norm_est = [](const std::function<Vector(const Vector&)>& op, int dim) {
    Vector v(dim);
    for (int i = 0; i < dim; ++i) v[i] = (i % 2 ? 1.0 : -1.0) * (1.0 + 0.25 * std::sin(1.0 + i));
    double lam = 0.0;
    for (int it = 0; it < 10; ++it) {
      v /= v.norm();
      const Vector y = op(v);
      lam = v.dot(y);
      v = y;
    }
    return lam;
  };
  sol.x.resize(r, count);
  if (!sparse) {
    for (int k = 0; k < count; ++k) {
      Vector x = vecs.col(keep[k]);
      Vector Mx = M0x(x);
      const double norm = std::sqrt(x.dot(Mx));
      x /= norm;
      Mx /= norm;
      sol.x.col(k) = x;
    }
  } else {
    // Chain-coordinate Ritz vectors (in the null space of J): M-normalize them, then
    // x = D^T dq in one blocked Householder application.
    sol.dq.resize(N, count);
    for (int k = 0; k < count; ++k) {
      Vector d = vecs.col(keep[k]);
      d /= std::sqrt(d.dot(sp->m_times(d)));
      sol.dq.col(k) = d;
    }
    vecs.resize(0, 0);
    sol.x = sp->reduce_cols(sol.dq);
  }
  // Scales: dense, ||K0|| and ||M0||; sparse, ||K|| and ||M|| of the chain (N = r + c:
  // the c constrained directions barely move the largest eigenvalue), O(n) per product.
  double normK, normM;
  if (!sparse) {
    normK = norm_est(K0x, r);
    normM = norm_est(M0x, r);
  } else {
    normK = norm_est([&sp](const Vector& v) { return sp->k_times(v); }, N);
    normM = norm_est([&sp](const Vector& v) { return sp->m_times(v); }, N);
  }
  // D^T K dq and D^T M dq on the sparse path in blocks of columns: one blocked Householder
  // application per block instead of one per vector (2.4 s -> ~0.5 s at n = 10^6), with
  // the extra memory bounded by 4 N kBlock doubles.
  constexpr int kBlock = 6;
  for (int k0 = 0; k0 < count; k0 += kBlock) {
    const int nb = std::min(kBlock, count - k0);
    Matrix KX(r, nb), MX(r, nb);
    if (!sparse) {
      for (int j = 0; j < nb; ++j) {
        KX.col(j) = K0x(sol.x.col(k0 + j));
        MX.col(j) = M0x(sol.x.col(k0 + j));
      }
    } else {  // D^T K dq, D^T M dq with dq = D x
      Matrix Kd(N, nb), Md(N, nb);
      for (int j = 0; j < nb; ++j) {
        Kd.col(j) = sp->k_times(sol.dq.col(k0 + j));
        Md.col(j) = sp->m_times(sol.dq.col(k0 + j));
      }
      KX = sp->reduce_cols(Kd);
      MX = sp->reduce_cols(Md);
    }
    for (int j = 0; j < nb; ++j) {
      const int k = k0 + j;
      const double w2 = 1.0 / mu[keep[k]] - s;
      const double rn = (KX.col(j) - w2 * MX.col(j)).norm();
      res.max_residual = std::max(res.max_residual, rn / (KX.col(j).norm() + w2 * MX.col(j).norm()));
      sol.backward_error = std::max(sol.backward_error, rn / ((normK + w2 * normM) * sol.x.col(k).norm()));
      res.omega.push_back(std::sqrt(w2));
    }
  }
  if (!sparse) sol.dq = sol.model.expand(sol.x);
  // Solver time: everything up to the chain-coordinate shapes; the sampling at the
  // common stations below is output formatting (ring::sample_polygon, ~10 us per mode).
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Hinge displacements delta p_k = delta p_0 + l sum_{j<k} e'(phi0_j) delta phi_j.
  const int n = chain.n();
  const Vector& phi0 = chain.phi0();
  const Vector ls = chain.l() * phi0.array().sin(), lc = chain.l() * phi0.array().cos();
  sol.hinge_ux.resize(n, count);
  sol.hinge_uy.resize(n, count);
  for (int k = 0; k < count; ++k) {
    double x = chain.free() ? sol.dq(n, k) : 0.0, yv = chain.free() ? sol.dq(n + 1, k) : 0.0;
    for (int j = 0; j < n; ++j) {
      sol.hinge_ux(j, k) = x;
      sol.hinge_uy(j, k) = yv;
      x -= ls[j] * sol.dq(j, k);
      yv += lc[j] * sol.dq(j, k);
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
