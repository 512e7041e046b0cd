#include "multibody/shifted_solve.hpp"

#include <stdexcept>
#include <string>

namespace multibody {

ShiftedSolve::ShiftedSolve(const Chain& c) : c_(c), cos_(c.cos0()), sin_(c.sin0()) {
  Jt_ = c.constraint_jacobian(c.q0()).transpose();
  qr_.compute(Jt_);
  N_ = c.dofs();
  nc_ = static_cast<int>(Jt_.cols());
  jjt_.compute(Jt_.transpose() * Jt_);
}

void ShiftedSolve::set_shift(double sigma) {
  if (!(sigma < 0.0))
    throw std::invalid_argument("multibody: the shifted solve needs sigma < 0 (sigma = " + std::to_string(sigma) +
                                "): S = K - sigma M must be positive definite");
  s_ = -sigma;
  factor_open();
  border(Jt_.transpose());
}

void ShiftedSolve::perform_op(const double* x_in, double* y_out) const {
  Workspace ws;
  Eigen::Map<Vector> y(y_out, N_);
  solve_full(Eigen::Map<const Vector>(x_in, N_), y, ws);
}

void ShiftedSolve::project(Vector& v) const { v.noalias() -= Jt_ * jjt_.solve(Jt_.transpose() * v); }

void ShiftedSolve::S_full(const Eigen::Ref<const Vector>& dq, Eigen::Ref<Vector> y, Workspace& ws) const {
  k_times(dq, y);
  ws.t.resize(N_);
  m_times(dq, ws.t, ws);
  y += s_ * ws.t;
}

void ShiftedSolve::solve_full(const Eigen::Ref<const Vector>& f, Eigen::Ref<Vector> dq, Workspace& ws,
                              int refinements) const {
  Vector lambda(nc_), dl(nc_);
  full_solve(f, dq, lambda);
  ws.r.resize(N_);
  for (int step = 0; step < refinements; ++step) {
    // The residual of the bordered system, J^T lambda included: without it the
    // residual is dominated by the multiplier part and the refinement gains nothing.
    S_full(dq, ws.r, ws);
    ws.r = f - ws.r;
    ws.r.noalias() -= Jt_ * lambda;
    full_solve(ws.r, ws.r, dl);  // the correction, in place
    dq += ws.r;
    lambda += dl;
  }
}

void ShiftedSolve::m_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y, Workspace& ws) const {
  const int n = c_.n();
  const double l = c_.l(), m = c_.m(), Jr = c_.Jr();
  // Forward: midpoint displacements V_i; backward: W_j = sum_{i >= j} m V_i - m V_j / 2.
  double ax = c_.free() ? v[n] : 0.0, ay = c_.free() ? v[n + 1] : 0.0;
  ws.v.resize(2 * n);
  double* V = ws.v.data();
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
}

void ShiftedSolve::k_times(const Eigen::Ref<const Vector>& x, Eigen::Ref<Vector> y) const {
  const int n = c_.n();
  const double K = c_.K();
  y.setZero();
  y[0] = K * (2 * x[0] - x[n - 1] - x[1 % n]);
  for (int k = 1; k + 1 < n; ++k) y[k] = K * (2 * x[k] - x[k - 1] - x[k + 1]);
  if (n > 1) y[n - 1] = K * (2 * x[n - 1] - x[n - 2] - x[0]);
}

/// Backward Riccati sweep of the open chain (matrix part, once). For segment i the
/// stage cost in (z_i, x_i) plus the cost-to-go 1/2 z_{i+1}^T P_{i+1} z_{i+1},
/// z_{i+1} = F z_i + g_i x_i (F keeps h, drops x_{i-1}; g_i = (l e'_i, 1)), is a
/// quadratic with Hessian [[Hzz, hzx], [hzx^T, hxx]]; eliminating x_i gives
/// P_i = Hzz - hzx hzx^T / hxx.
void ShiftedSolve::factor_open() {
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

/// x = A^{-1} f for the open chain, in place (fx holds f on entry, x on return; both
/// sweeps read entry i before they write it). Two sweeps, O(n).
void ShiftedSolve::open_solve(double* fx) const {
  const int n = c_.n();
  const double l = c_.l();
  // Backward: linear cost-to-go term q_i (cost -q^T z); hx_i = f_i + g_i^T q_{i+1}.
  const double* f = fx;
  double* hx = fx;
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
  double* x = fx;
  double zx = 0.0, zy = 0.0, zp = 0.0;
  for (int i = 0; i < n; ++i) {
    const double xi = (hx[i] - hzx_(0, i) * zx - hzx_(1, i) * zy - hzx_(2, i) * zp) * inv_hxx_[i];
    x[i] = xi;
    zx += -l * sin_[i] * xi;
    zy += l * cos_[i] * xi;
    zp = xi;
  }
}

/// Border of the open chain: extra unknowns e = (alpha = x_0 - x_{n-1} for the cyclic
/// spring at hinge 0; translation a (free ring); multipliers lambda):
///   A x + B e = f_x,   C x + D e = (f_a, 0...)  with
///   B = [K u, s A_xa, J_x^T],  C = [u^T; s A_xa^T; J_x],  D = diag(-1, [s m n I, J_a^T], [J_a, 0]).
void ShiftedSolve::border(const Matrix& J) {
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
  Z_ = B_;
  for (int j = 0; j < k; ++j) open_solve(Z_.col(j).data());
  schur_.compute(D - C_ * Z_);
  na_ = na;
}

/// The constrained solve in chain coordinates: [S J^T; J 0] [dq; lambda] = [f; 0]. O(n k).
/// dq may be f itself (f's translation entries are read before dq's are written).
void ShiftedSolve::full_solve(const Eigen::Ref<const Vector>& f, Eigen::Ref<Vector> dq, Vector& lambda) const {
  const int n = c_.n(), k = static_cast<int>(Z_.cols());
  Vector g = Vector::Zero(k);
  for (int a = 0; a < na_; ++a) g[1 + a] = f[n + a];
  if (dq.data() != f.data()) dq.head(n) = f.head(n);
  open_solve(dq.data());  // x0 = A^{-1} f_x in dq's first n entries
  const Vector e = schur_.solve(g - C_ * dq.head(n));
  dq.head(n).noalias() -= Z_ * e;
  for (int a = 0; a < na_; ++a) dq[n + a] = e[1 + a];
  lambda = e.tail(nc_);
}

void MassProduct::perform_op(const double* x_in, double* y_out) const {
  ShiftedSolve::Workspace ws;
  Eigen::Map<Vector> y(y_out, solve_.rows());
  solve_.m_times(Eigen::Map<const Vector>(x_in, solve_.rows()), y, ws);
}

}  // namespace multibody
