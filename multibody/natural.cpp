// The chain in natural coordinates (natural.hpp).
#include "multibody/natural.hpp"

#include <algorithm>
#include <cmath>

#include "multibody/attachments.hpp"

namespace multibody::natural {

constexpr double kPi = 3.14159265358979323846;

double Natural::radius() const { return n * l / (2.0 * kPi); }

Natural make_natural(const Chain& chain, const std::vector<int>& pins) {
  Natural c;
  c.n = chain.n();
  c.l = chain.l();
  c.m = chain.m();
  c.Jr = chain.Jr();
  c.K = chain.K();
  c.theta0 = 2.0 * kPi / c.n;
  c.pin = chain.hinge_rest(0);
  c.pinned = !chain.free();
  if (const auto r = chain.roller_hinge()) {
    c.roller = *r;
    const Eigen::Vector2d d = (chain.hinge_rest(*r) - c.pin).normalized();
    c.nu = Eigen::Vector2d(-d.y(), d.x());
  }
  c.pins = pins;
  for (int h : pins) c.pinned_at.push_back(chain.hinge_rest(h));
  return c;
}

Eigen::Vector2d rest_link(const Chain& chain, int k) {
  const int n = chain.n();
  k = (k + n) % n;
  return (chain.hinge_rest((k + 1) % n) - chain.hinge_rest(k)).normalized();
}

Vec rest(const Chain& chain) {
  Vec x(2 * chain.n());
  for (int k = 0; k < chain.n(); ++k) x.segment<2>(2 * k) = chain.hinge_rest(k);
  return x;
}

double turn_angle(const Vec6& y) {
  const Eigen::Vector2d a = y.segment<2>(2) - y.segment<2>(0), b = y.segment<2>(4) - y.segment<2>(2);
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // angle(b) - angle(a)
}

namespace {

/// The gradient and Hessian of a vector's polar angle.
Eigen::Vector2d grad_angle(const Eigen::Vector2d& v) { return Eigen::Vector2d(-v.y(), v.x()) / v.squaredNorm(); }
Eigen::Matrix2d hess_angle(const Eigen::Vector2d& v) {
  const double s2 = v.squaredNorm() * v.squaredNorm();
  Eigen::Matrix2d h;
  h << 2 * v.x() * v.y(), v.y() * v.y() - v.x() * v.x(), v.y() * v.y() - v.x() * v.x(), -2 * v.x() * v.y();
  return h / s2;
}

/// The gradient and, if `hessian`, the Hessian in y of wa angle(a) + wb angle(b), a = y_1 - y_0,
/// b = y_2 - y_1 (theta left at 0).
Turn link_angles(const Vec6& y, double wa, double wb, bool hessian) {
  const Eigen::Vector2d a = y.segment<2>(2) - y.segment<2>(0), b = y.segment<2>(4) - y.segment<2>(2);
  Turn t;
  t.theta = 0.0;
  const Eigen::Vector2d ga = wa * grad_angle(a), gb = wb * grad_angle(b);
  t.d << -ga, ga - gb, gb;
  if (!hessian) {
    t.dd.setZero();
    return t;
  }
  const Eigen::Vector3d pa(-1, 1, 0), pb(0, -1, 1);
  const Eigen::Matrix2d ha = wa * hess_angle(a), hb = wb * hess_angle(b);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.dd.block<2, 2>(2 * i, 2 * j) = pa(i) * pa(j) * ha + pb(i) * pb(j) * hb;
  return t;
}

/// The angle from the unit vector e to v, in (-pi, pi].
double angle_from(const Eigen::Vector2d& e, const Eigen::Vector2d& v) {
  return std::atan2(e.x() * v.y() - e.y() * v.x(), e.dot(v));
}

}  // namespace

Turn turn(const Vec6& y, bool hessian) {
  Turn t = link_angles(y, -1.0, 1.0, hessian);  // angle(b) - angle(a)
  t.theta = turn_angle(y);
  return t;
}

Turn mean_rotation(const Vec6& y, const Eigen::Vector2d& ea, const Eigen::Vector2d& eb, bool hessian) {
  Turn t = link_angles(y, 0.5, 0.5, hessian);
  t.theta = 0.5 * (angle_from(ea, y.segment<2>(2) - y.segment<2>(0)) + angle_from(eb, y.segment<2>(4) - y.segment<2>(2)));
  return t;
}

Vec6 local(const Natural& c, const Vec& x, int k) {
  Vec6 y;
  y << hinge(x, (k + c.n - 1) % c.n), hinge(x, k), hinge(x, (k + 1) % c.n);
  return y;
}

Vec turning_changes(const Natural& c, const Vec& x) {
  Vec e(c.n);
  for (int k = 0; k < c.n; ++k) e[k] = turn_angle(local(c, x, k)) - c.theta0;
  return e;
}

double spring_energy(const Natural& c, const Vec& x) {
  double V = 0.0;
  for (int k = 0; k < c.n; ++k) {
    const double d = turn_angle(local(c, x, k)) - c.theta0;
    V += 0.5 * c.K * d * d;
  }
  return V;
}

/// M x for the constant bar mass matrix: per bar (m/4) [1 1; 1 1] + (Jr/l^2) [1 -1; -1 1].
Vec mass_times(const Natural& c, const Vec& v) {
  Vec out;
  mass_times(c, v, out);
  return out;
}

void mass_times(const Natural& c, const Vec& v, Vec& out) {
  out.setZero(2 * c.n);
  const double s = 0.25 * c.m, r = c.Jr / (c.l * c.l);
  for (int i = 0; i < c.n; ++i) {
    const int j = (i + 1) % c.n;
    const Eigen::Vector2d a = hinge(v, i), b = hinge(v, j);
    out.segment<2>(2 * i) += s * (a + b) + r * (a - b);
    out.segment<2>(2 * j) += s * (a + b) + r * (b - a);
  }
}

/// Constraint values at x (rows: links, pin x, pin y, roller, further pins).
Vec constraints(const Natural& c, const Vec& x) {
  Vec g;
  constraints(c, x, g);
  return g;
}

void constraints(const Natural& c, const Vec& x, Vec& g) {
  g.resize(c.rows());
  for (int i = 0; i < c.n; ++i) {
    const Eigen::Vector2d e = hinge(x, (i + 1) % c.n) - hinge(x, i);
    g(i) = (e.squaredNorm() - c.l * c.l) / (2.0 * c.l);
  }
  if (c.pinned) g.segment<2>(c.n) = hinge(x, 0) - c.pin;
  if (c.roller >= 0) g(c.roller_row()) = c.nu.dot(hinge(x, c.roller) - c.pin);
  for (std::size_t i = 0; i < c.pins.size(); ++i)
    g.segment<2>(c.pins_row() + 2 * i) = hinge(x, c.pins[i]) - c.pinned_at[i];
  for (std::size_t i = 0; i < c.slides.size(); ++i)
    g(c.slides_row() + static_cast<int>(i)) = c.slide_dir[i].dot(hinge(x, c.slides[i]) - c.slide_at[i]);
  for (std::size_t i = 0; i < c.centres.size(); ++i)
    g(c.centres_row() + static_cast<int>(i)) =
        c.centre_dir[i].dot(hinge(x, c.centres[i][0]) + hinge(x, c.centres[i][1]) - c.centre_at[i]);
}

/// Adds the constraint gradients G(x) to the KKT matrix whose multipliers start at
/// `offset`: as columns (G^T, `transpose`) or as rows, and G(x)^T lambda to `force`
/// when not null.
void add_constraint_jacobian(const Natural& c, const Vec& x, int offset, bool transpose, double scale,
                             BandedKkt& kkt, const Vec* lambda, Vec* force) {
  auto put = [&](int row, int dof, double v) {
    if (transpose) kkt.add(dof, offset + row, scale * v);
    else kkt.add(offset + row, dof, scale * v);
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
  if (c.pinned) {
    put(c.n, 0, 1.0);
    put(c.n + 1, 1, 1.0);
  }
  if (c.roller >= 0)
    for (int a = 0; a < 2; ++a) put(c.roller_row(), 2 * c.roller + a, c.nu(a));
  for (std::size_t i = 0; i < c.pins.size(); ++i)
    for (int a = 0; a < 2; ++a) put(c.pins_row() + 2 * static_cast<int>(i) + a, 2 * c.pins[i] + a, 1.0);
  for (std::size_t i = 0; i < c.slides.size(); ++i)
    for (int a = 0; a < 2; ++a) put(c.slides_row() + static_cast<int>(i), 2 * c.slides[i] + a, c.slide_dir[i](a));
  for (std::size_t i = 0; i < c.centres.size(); ++i)
    for (int h : c.centres[i])
      for (int a = 0; a < 2; ++a) put(c.centres_row() + static_cast<int>(i), 2 * h + a, c.centre_dir[i](a));
}

void add_spring(const Natural& c, int k, const Vec6& g, const Mat6& J, Vec& r, BandedKkt& kkt) {
  const int hk[3] = {(k + c.n - 1) % c.n, k, (k + 1) % c.n};
  int dofs[6];
  for (int a = 0; a < 3; ++a) {
    r.segment<2>(2 * hk[a]) += g.segment<2>(2 * a);
    dofs[2 * a] = 2 * hk[a];
    dofs[2 * a + 1] = 2 * hk[a] + 1;
  }
  kkt.add(dofs, J);
}

void add_constraint_curvature(const Natural& c, const Vec& lambda, double weight, BandedKkt& kkt) {
  for (int i = 0; i < c.n; ++i) {
    const int j = (i + 1) % c.n;
    const double w = weight * lambda(i) / c.l;
    for (int a = 0; a < 2; ++a) {
      kkt.add(2 * i + a, 2 * i + a, w);
      kkt.add(2 * j + a, 2 * j + a, w);
      kkt.add(2 * i + a, 2 * j + a, -w);
      kkt.add(2 * j + a, 2 * i + a, -w);
    }
  }
}

void add_mass(const Natural& c, double scale, BandedKkt& kkt) {
  const double s = 0.25 * c.m, r = c.Jr / (c.l * c.l);
  for (int i = 0; i < c.n; ++i) {
    const int j = (i + 1) % c.n;
    for (int a = 0; a < 2; ++a) {
      kkt.add(2 * i + a, 2 * i + a, scale * (s + r));
      kkt.add(2 * j + a, 2 * j + a, scale * (s + r));
      kkt.add(2 * i + a, 2 * j + a, scale * (s - r));
      kkt.add(2 * j + a, 2 * i + a, scale * (s - r));
    }
  }
}

namespace {

/// Adds a moment M(theta) with tangent dM/dtheta on an angle t at hinge `at`: its force
/// M grad theta and Jacobian (dM/dtheta) grad theta grad theta^T + M Hess theta.
void add_angle_moment(const Natural& c, int at, double moment, double tangent, const Turn& t, Vec& force,
                      BandedKkt& kkt) {
  add_spring(c, at, moment * t.d, tangent * t.d * t.d.transpose() + moment * t.dd, force, kkt);
}

/// Adds the energy k (t.theta - t0)^2 / 2 of an angle t at hinge `at` (its force and
/// Jacobian) to `force` and the KKT matrix.
void add_angle_spring(const Natural& c, int at, double k, const Turn& t, double t0, Vec& force, BandedKkt& kkt) {
  const double d = t.theta - t0;
  add_spring(c, at, k * d * t.d, k * (t.d * t.d.transpose() + d * t.dd), force, kkt);
}

}  // namespace

void add_stiffness(const Chain& chain, const Natural& c, const detail::Attachments& terms, const Vec& x, Vec& force,
                   BandedKkt& kkt, const HingeBending* bending) {
  for (int k = 0; k < c.n; ++k) {
    const Vec6 y = local(c, x, k);
    const Turn t = turn(y);
    if (bending) {
      const HingeBending::Point b = bending->at(k, t.theta - c.theta0);
      add_angle_moment(c, k, b.force, b.tangent, t, force, kkt);
    } else {
      add_angle_spring(c, k, c.K, t, c.theta0, force, kkt);
    }
    // kr and the clamp on the mean rotation of the hinge's links (attachments.hpp).
    if (const double kr = terms.rotation_stiffness(k); kr > 0.0)
      add_angle_spring(c, k, kr, mean_rotation(y, rest_link(chain, k - 1), rest_link(chain, k)), 0.0, force, kkt);
    add_hinge_spring(terms, k, x, 1.0, force, kkt);
  }
}

void add_hinge_spring(const detail::Attachments& terms, int k, const Vec& x, double weight, Vec& force,
                      BandedKkt& kkt) {
  const Eigen::Matrix2d& B = terms.hinge_stiffness(k);
  if (B.isZero()) return;
  force.segment<2>(2 * k) += terms.hinge_force(k, hinge(x, k));
  const int dofs[2] = {2 * k, 2 * k + 1};
  kkt.add(dofs, Eigen::Matrix2d(weight * B));
}

void add_point_masses(const Natural& c, const detail::Attachments& terms, double scale, const Eigen::Ref<const Vec>& x, Vec* mx,
                      BandedKkt* kkt) {
  for (int k = 0; k < c.n; ++k) {
    const double m = scale * terms.hinge_mass(k);
    if (m == 0.0) continue;
    if (mx) mx->segment<2>(2 * k) += m * x.segment<2>(2 * k);
    if (kkt)
      for (int a = 0; a < 2; ++a) kkt->add(2 * k + a, 2 * k + a, m);
  }
}

double turns_a_link_by(const Natural& c, const Vec& dx) {
  double worst = 0.0;
  for (int k = 0; k < c.n; ++k)
    worst = std::max(worst, (hinge(dx, (k + 1) % c.n) - hinge(dx, k)).norm() / c.l);
  return worst;
}

bool NewtonStop::converged(double step, double constraint) {
  constexpr double kTolerance = 1e-12, kFloor = 1e-9;
  const bool at_floor = step <= kFloor * R_ && step > 0.25 * previous_;
  previous_ = step;
  return (step <= kTolerance * R_ || at_floor) && constraint <= kTolerance * R_;
}

namespace {

/// Calls visit(i, j) for every (i, j) that the KKT matrix of the chain may hold (natural
/// order, repeats allowed): the springs' blocks (hinges k-1, k, k+1, which cover the mass
/// matrix's and the links' curvature blocks), the links' gradients as rows and columns,
/// the pin's, the roller's and the further pins'.
template <class Visit>
void kkt_pattern(const Natural& c, Visit visit) {
  const int N = 2 * c.n;
  auto hinges = [&](int a, int b) {
    for (int p = 0; p < 2; ++p)
      for (int q = 0; q < 2; ++q) visit(2 * a + p, 2 * b + q);
  };
  auto row = [&](int r, int k) {  // constraint row r on hinge k, and its column
    for (int p = 0; p < 2; ++p) {
      visit(N + r, 2 * k + p);
      visit(2 * k + p, N + r);
    }
  };
  for (int k = 0; k < c.n; ++k) {
    const int hk[3] = {(k + c.n - 1) % c.n, k, (k + 1) % c.n};
    for (int a : hk)
      for (int b : hk) hinges(a, b);
    row(k, k);
    row(k, hk[2]);
  }
  if (c.pinned) {
    row(c.n, 0);
    row(c.n + 1, 0);
  }
  if (c.roller >= 0) row(c.roller_row(), c.roller);
  for (std::size_t i = 0; i < c.pins.size(); ++i)
    for (int a = 0; a < 2; ++a) row(c.pins_row() + 2 * static_cast<int>(i) + a, c.pins[i]);
  for (std::size_t i = 0; i < c.slides.size(); ++i) row(c.slides_row() + static_cast<int>(i), c.slides[i]);
  for (std::size_t i = 0; i < c.centres.size(); ++i)
    for (int h : c.centres[i]) row(c.centres_row() + static_cast<int>(i), h);
}

}  // namespace

BandedKkt::BandedKkt(const Natural& c) : perm_(Eigen::VectorXi::Constant(c.size(), -1)) {
  const int N = 2 * c.n;  // the order of natural.hpp: the band in chain order, the border
  int next = 0;
  auto put_hinge = [&](int k) {
    perm_(2 * k) = next++;
    perm_(2 * k + 1) = next++;
  };
  for (int k = 1; k <= c.n - 2; ++k) {
    perm_(N + k - 1) = next++;  // link k-1, between hinges k-1 and k
    put_hinge(k);
  }
  perm_(N + c.n - 2) = next++;  // link n-2
  const int band = next;
  for (int k : {c.n - 1, 0}) put_hinge(k);
  perm_(N + c.n - 1) = next++;
  for (int row = c.n; row < c.rows(); ++row) perm_(N + row) = next++;  // pin, roller, further pins, slides, centres
  band_ = detail::BorderedBand(band, c.size() - band, [&](auto mark) {
    kkt_pattern(c, [&](int i, int j) { mark(perm_[i], perm_[j]); });
  });
}

Vec BandedKkt::solve(const Vec& rhs) const {
  Vec z = rhs, scratch;
  solve(z, scratch);
  return z;
}

void BandedKkt::solve(Vec& z, Vec& scratch) const {
  scratch.resize(z.size());
  for (Eigen::Index i = 0; i < z.size(); ++i) scratch[perm_[i]] = z[i];
  band_.solve(scratch.data());
  for (Eigen::Index i = 0; i < z.size(); ++i) z[i] = scratch[perm_[i]];
}

}  // namespace multibody::natural
