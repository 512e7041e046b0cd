// The chain in natural coordinates (natural.hpp).
#include "multibody/natural.hpp"

#include <algorithm>
#include <cmath>

namespace multibody::natural {

constexpr double kPi = 3.14159265358979323846;

double Natural::radius() const { return n * l / (2.0 * kPi); }

Natural make_natural(const Chain& chain, double load_deg, const Eigen::Vector2d& F) {
  Natural c;
  c.n = chain.n();
  c.l = chain.l();
  c.m = chain.m();
  c.Jr = chain.Jr();
  c.K = chain.K();
  c.theta0 = 2.0 * kPi / c.n;
  c.pin = chain.hinge_rest(0);
  if (const auto r = chain.roller_hinge()) {
    c.roller = *r;
    const Eigen::Vector2d d = (chain.hinge_rest(*r) - c.pin).normalized();
    c.nu = Eigen::Vector2d(-d.y(), d.x());
  }
  c.load = chain.hinge_at(load_deg);
  c.F = F;
  return c;
}

Vec rest(const Chain& chain) {
  Vec x(2 * chain.n());
  for (int k = 0; k < chain.n(); ++k) x.segment<2>(2 * k) = chain.hinge_rest(k);
  return x;
}

Turn turn(const Vec6& y) {
  const Eigen::Vector2d a = y.segment<2>(2) - y.segment<2>(0), b = y.segment<2>(4) - y.segment<2>(2);
  // Explicit return types: an `auto` lambda would return an expression that refers to a
  // destroyed temporary.
  auto grad_angle = [](const Eigen::Vector2d& v) -> Eigen::Vector2d {
    return Eigen::Vector2d(-v.y(), v.x()) / v.squaredNorm();
  };
  auto hess_angle = [](const Eigen::Vector2d& v) -> Eigen::Matrix2d {
    const double s2 = v.squaredNorm() * v.squaredNorm();
    Eigen::Matrix2d h;
    h << 2 * v.x() * v.y(), v.y() * v.y() - v.x() * v.x(), v.y() * v.y() - v.x() * v.x(), -2 * v.x() * v.y();
    return h / s2;
  };
  Turn t;
  t.theta = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // angle(b) - angle(a)
  const Eigen::Vector2d ga = grad_angle(a), gb = grad_angle(b);
  t.d << ga, -ga - gb, gb;
  const Eigen::Vector3d pa(-1, 1, 0), pb(0, -1, 1);
  const Eigen::Matrix2d ha = hess_angle(a), hb = hess_angle(b);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.dd.block<2, 2>(2 * i, 2 * j) = -pa(i) * pa(j) * ha + pb(i) * pb(j) * hb;
  return t;
}

Vec6 local(const Natural& c, const Vec& x, int k) {
  Vec6 y;
  y << hinge(x, (k + c.n - 1) % c.n), hinge(x, k), hinge(x, (k + 1) % c.n);
  return y;
}

double spring_energy(const Natural& c, const Vec& x) {
  double V = 0.0;
  for (int k = 0; k < c.n; ++k) {
    const double d = turn(local(c, x, k)).theta - c.theta0;
    V += 0.5 * c.K * d * d;
  }
  return V;
}

/// M x for the constant bar mass matrix: per bar (m/4) [1 1; 1 1] + (Jr/l^2) [1 -1; -1 1].
Vec mass_times(const Natural& c, const Vec& v) {
  Vec out = Vec::Zero(2 * c.n);
  const double s = 0.25 * c.m, r = c.Jr / (c.l * c.l);
  for (int i = 0; i < c.n; ++i) {
    const int j = (i + 1) % c.n;
    const Eigen::Vector2d a = hinge(v, i), b = hinge(v, j);
    out.segment<2>(2 * i) += s * (a + b) + r * (a - b);
    out.segment<2>(2 * j) += s * (a + b) + r * (b - a);
  }
  return out;
}

/// Constraint values at x (rows: links, pin x, pin y, roller).
Vec constraints(const Natural& c, const Vec& x) {
  Vec g(c.rows());
  for (int i = 0; i < c.n; ++i) {
    const Eigen::Vector2d e = hinge(x, (i + 1) % c.n) - hinge(x, i);
    g(i) = (e.squaredNorm() - c.l * c.l) / (2.0 * c.l);
  }
  g.segment<2>(c.n) = hinge(x, 0) - c.pin;
  if (c.roller >= 0) g(c.n + 2) = c.nu.dot(hinge(x, c.roller) - c.pin);
  return g;
}

/// Adds the constraint gradients G(x) to the KKT matrix whose multipliers start at
/// `offset`: as columns (G^T, `transpose`) or as rows, and G(x)^T lambda to `force`
/// when not null.
void add_constraint_jacobian(const Natural& c, const Vec& x, int offset, bool transpose, double scale,
                             Triplets& t, const Vec* lambda, Vec* force) {
  auto put = [&](int row, int dof, double v) {
    if (transpose) t.emplace_back(dof, offset + row, scale * v);
    else t.emplace_back(offset + row, dof, scale * v);
    if (force) (*force)(dof) += v * (*lambda)(row);
  };
  for (int i = 0; i < c.n; ++i) {
    const int j = (i + 1) % c.n;
    const Eigen::Vector2d e = (hinge(x, j) - hinge(x, i)) / c.l;
    for (int a = 0; a < 2; ++a) {
      put(i, 2 * i + a, -e(a));
      put(i, 2 * j + a, e(a));
    }
  }
  put(c.n, 0, 1.0);
  put(c.n + 1, 1, 1.0);
  if (c.roller >= 0)
    for (int a = 0; a < 2; ++a) put(c.n + 2, 2 * c.roller + a, c.nu(a));
}

void add_spring(const Natural& c, int k, const Vec6& g, const Mat6& J, Vec& r, Triplets& t) {
  const int hk[3] = {(k + c.n - 1) % c.n, k, (k + 1) % c.n};
  for (int a = 0; a < 3; ++a) {
    r.segment<2>(2 * hk[a]) += g.segment<2>(2 * a);
    for (int b = 0; b < 3; ++b)
      for (int p = 0; p < 2; ++p)
        for (int q = 0; q < 2; ++q) t.emplace_back(2 * hk[a] + p, 2 * hk[b] + q, J(2 * a + p, 2 * b + q));
  }
}

void add_constraint_curvature(const Natural& c, const Vec& lambda, double weight, Triplets& t) {
  for (int i = 0; i < c.n; ++i) {
    const int j = (i + 1) % c.n;
    const double w = weight * lambda(i) / c.l;
    for (int a = 0; a < 2; ++a) {
      t.emplace_back(2 * i + a, 2 * i + a, w);
      t.emplace_back(2 * j + a, 2 * j + a, w);
      t.emplace_back(2 * i + a, 2 * j + a, -w);
      t.emplace_back(2 * j + a, 2 * i + a, -w);
    }
  }
}

double turns_a_link_by(const Natural& c, const Vec& dx) {
  double worst = 0.0;
  for (int k = 0; k < c.n; ++k)
    worst = std::max(worst, (hinge(dx, (k + 1) % c.n) - hinge(dx, k)).norm() / c.l);
  return worst;
}

Eigen::VectorXi banded_order(const Natural& c) {
  const int N = 2 * c.n;
  Eigen::VectorXi perm = Eigen::VectorXi::Constant(c.size(), -1);
  int next = 0;
  auto put_hinge = [&](int k) {
    perm(2 * k) = next++;
    perm(2 * k + 1) = next++;
  };
  for (int k = 2; k <= c.n - 2; ++k) {
    perm(N + k - 1) = next++;  // link k-1, between hinges k-1 and k
    put_hinge(k);
  }
  perm(N + c.n - 2) = next++;  // link n-2
  for (int k : {c.n - 1, 0, 1}) put_hinge(k);
  perm(N + c.n - 1) = next++;
  perm(N) = next++;
  for (int row = c.n; row < c.rows(); ++row) perm(N + row) = next++;  // pin, roller
  return perm;
}

bool NewtonStop::converged(double step, double constraint) {
  constexpr double kTolerance = 1e-12, kFloor = 1e-9;
  const bool at_floor = step <= kFloor * R_ && step > 0.25 * previous_;
  previous_ = step;
  return (step <= kTolerance * R_ || at_floor) && constraint <= kTolerance * R_;
}

BandedKkt::BandedKkt(const Natural& c) : perm_(banded_order(c)) {
  // The border of banded_order: hinges n-1, 0, 1 (6), links n-1 and 0 (2), pin and roller.
  core_ = c.size() - (8 + c.rows() - c.n);
}

bool BandedKkt::factor(const Eigen::SparseMatrix<double>& A) {
  const int m = core_, b = static_cast<int>(A.rows()) - core_;
  int kl = 0, ku = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const int r = perm_[it.row()], col = perm_[j];
      if (r < m && col < m) {
        kl = std::max(kl, r - col);
        ku = std::max(ku, col - r);
      }
    }
  band_.resize(m, kl, ku);
  B_.setZero(m, b);
  C_.setZero(b, m);
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(b, b);
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const int r = perm_[it.row()], col = perm_[j];
      if (r < m && col < m)
        band_.at(r, col) += it.value();
      else if (r < m)
        B_(r, col - m) += it.value();
      else if (col < m)
        C_(r - m, col) += it.value();
      else
        D(r - m, col - m) += it.value();
    }
  if (!band_.factor()) return false;
  X_ = B_;
  band_.solve_many(X_.data(), m, b);
  schur_.compute(D - C_ * X_);
  const double pivot = schur_.matrixLU().diagonal().cwiseAbs().minCoeff();
  return std::isfinite(pivot) && pivot > 0.0;
}

Vec BandedKkt::solve(const Vec& rhs) const {
  const int m = core_;
  Vec f(m), g(rhs.size() - m);
  for (Eigen::Index i = 0; i < rhs.size(); ++i) {
    const int k = perm_[i];
    if (k < m) f[k] = rhs[i];
    else g[k - m] = rhs[i];
  }
  band_.solve(f.data());
  const Vec y = schur_.solve(g - C_ * f);
  f -= X_ * y;
  Vec out(rhs.size());
  for (Eigen::Index i = 0; i < rhs.size(); ++i) {
    const int k = perm_[i];
    out[i] = k < m ? f[k] : y[k - m];
  }
  return out;
}

}  // namespace multibody::natural
