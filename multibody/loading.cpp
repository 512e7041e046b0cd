#include "multibody/loading.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace multibody::detail {
namespace {

Eigen::Vector2d e(double a) { return {std::cos(a), std::sin(a)}; }
Eigen::Vector2d eprime(double a) { return {-std::sin(a), std::cos(a)}; }
/// a x b = a^T J b (the z-component of the cross product).
const Eigen::Matrix2d kCross = (Eigen::Matrix2d() << 0.0, 1.0, -1.0, 0.0).finished();
/// 4-point Gauss-Legendre on [0, 1]: nodes and weights.
constexpr std::array<double, 4> kXi{0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
constexpr std::array<double, 4> kW{0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};

}  // namespace

Loading::Loading(const Chain& chain, const ring::RingSpec& spec, const ring::Loads& loads, const std::string& section)
    : chain_(chain), f_(Eigen::Matrix2Xd::Zero(2, chain.n() + 1)), rest_(2, chain.n() + 1) {
  const int n = chain.n();
  const double l = chain.l();
  for (int k = 0; k <= n; ++k) rest_.col(k) = chain.hinge_rest(chain.arch() ? k : k % n);
  auto hinge = [&](double deg, const std::string& key) {
    const int k = chain.hinge_index(deg);
    if (k < 0)
      throw std::invalid_argument("multibody: " + key + " (=" + std::to_string(deg) + " deg) is not a hinge of the " +
                                  std::to_string(n) + "-segment chain anchored at " +
                                  std::to_string(chain.anchor_deg()) + " deg");
    return k;
  };
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const auto& p = loads.points[i];
    const std::string key =
        loads.points.size() == 1 ? section + ".at" : section + ".loads[" + std::to_string(i + 1) + "].at";
    f_.col(hinge(p.angle, key)) += Eigen::Vector2d(p.force[0], p.force[1]);
  }
  const Eigen::Vector2d g(loads.gravity[0], loads.gravity[1]);
  if (loads.has_gravity()) {
    const Eigen::Vector2d half = 0.5 * spec.rhoA() * l * g;
    for (int j = 0; j < n; ++j) {
      f_.col(j) += half;
      f_.col(j + 1) += half;
    }
    for (std::size_t i = 0; i < spec.masses.size(); ++i)
      f_.col(hinge(spec.masses[i].angle, "masses[" + std::to_string(i + 1) + "].at")) += spec.masses[i].mass * g;
  }
  const double p = loads.pressure.value;
  switch (loads.pressure.kind) {
    case ring::Pressure::Kind::dead:
      for (int j = 0; j < n; ++j) {
        const Eigen::Vector2d inward = eprime(chain.phi0()[j]);  // e(phi0) turned by +90 deg
        f_.col(j) += 0.5 * p * l * inward;
        f_.col(j + 1) += 0.5 * p * l * inward;
      }
      break;
    case ring::Pressure::Kind::follower:
      // Its potential p A: on an arch the polygon closes through its ends (the pair (n, 0)),
      // whose side is then constant only with both ends held (the checks ask for pins there).
      if (chain.arch() && p != 0.0 && !(chain.holds(0) && chain.holds(n)))
        throw std::invalid_argument("multibody: " + section + ".pressure of kind \"follower\" on an arch (ring.arc) "
                                    "needs both ends pinned");
      follower_ = p;
      break;
    case ring::Pressure::Kind::central: central_ = p; break;
  }
  if (spec.rotation.spinning()) {
    spin2_ = spec.rotation.speed * spec.rotation.speed;
    segment_mass_ = spec.rhoA() * l;
    for (std::size_t i = 0; i < spec.masses.size(); ++i)
      point_masses_.emplace_back(hinge(spec.masses[i].angle, "masses[" + std::to_string(i + 1) + "].at"),
                                 spec.masses[i].mass);
  }
  rest_shape_ = shape_potential(rest_);
}

Eigen::Matrix2Xd Loading::positions(const Vector& q) const {
  const int n = chain_.n();
  Eigen::Matrix2Xd p(2, n + 1);
  p.col(0) = chain_.hinge_position(q, 0);
  for (int j = 0; j < n; ++j) p.col(j + 1) = p.col(j) + chain_.l() * e(q[j]);
  return p;
}

Eigen::Matrix2Xd Loading::hinge_gradient(const Eigen::Matrix2Xd& p, std::vector<Block>* H) const {
  const int n = chain_.n();
  Eigen::Matrix2Xd g = -f_;
  if (follower_ != 0.0) {
    // p A with A = 1/2 sum over the closed polygon's edges (k, k+1), the last edge (n, 0).
    for (int k = 0; k <= n; ++k) {
      const int m = k < n ? k + 1 : 0;
      g.col(k) += 0.5 * follower_ * kCross * p.col(m);
      g.col(m) += 0.5 * follower_ * kCross.transpose() * p.col(k);
      if (H) {
        H->push_back({k, m, 0.5 * follower_ * kCross});
        H->push_back({m, k, 0.5 * follower_ * kCross.transpose()});
      }
    }
  }
  if (central_ != 0.0) {
    const double l = chain_.l();
    for (int j = 0; j < n; ++j) {
      Eigen::Matrix2d haa = Eigen::Matrix2d::Zero(), hab = haa, hbb = haa;  // the segment's blocks
      for (std::size_t q = 0; q < kXi.size(); ++q) {
        const double a = 1.0 - kXi[q], b = kXi[q], w = central_ * l * kW[q];
        const Eigen::Vector2d x = a * p.col(j) + b * p.col(j + 1);
        const double r = x.norm();
        const Eigen::Vector2d u = x / r;
        g.col(j) += w * a * u;
        g.col(j + 1) += w * b * u;
        if (!H) continue;
        const Eigen::Matrix2d h = w * (Eigen::Matrix2d::Identity() - u * u.transpose()) / r;
        haa += a * a * h;
        hab += a * b * h;
        hbb += b * b * h;
      }
      if (H) {
        H->push_back({j, j, haa});
        H->push_back({j, j + 1, hab});
        H->push_back({j + 1, j, hab});
        H->push_back({j + 1, j + 1, hbb});
      }
    }
  }
  if (spin2_ != 0.0) {
    // -speed^2 / 2 m |c_j|^2, c_j = (p_j + p_{j+1}) / 2: gradient -speed^2 m c_j / 2 at each end.
    const double w = spin2_ * segment_mass_;
    const Eigen::Matrix2d h = -0.25 * w * Eigen::Matrix2d::Identity();
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d c = 0.5 * (p.col(j) + p.col(j + 1));
      g.col(j) -= 0.5 * w * c;
      g.col(j + 1) -= 0.5 * w * c;
      if (H) {
        H->push_back({j, j, h});
        H->push_back({j, j + 1, h});
        H->push_back({j + 1, j, h});
        H->push_back({j + 1, j + 1, h});
      }
    }
    for (const auto& [k, m] : point_masses_) {
      g.col(k) -= spin2_ * m * p.col(k);
      if (H) H->push_back({k, k, -spin2_ * m * Eigen::Matrix2d::Identity()});
    }
  }
  return g;
}

double Loading::shape_potential(const Eigen::Matrix2Xd& p) const {
  double area = 0.0, radius = 0.0;
  if (follower_ != 0.0)
    for (Eigen::Index k = 0; k < p.cols(); ++k) {
      const Eigen::Index m = (k + 1) % p.cols();
      area += 0.5 * (p(0, k) * p(1, m) - p(1, k) * p(0, m));
    }
  if (central_ != 0.0)
    for (Eigen::Index j = 0; j + 1 < p.cols(); ++j)
      for (std::size_t i = 0; i < kXi.size(); ++i)
        radius += chain_.l() * kW[i] * ((1.0 - kXi[i]) * p.col(j) + kXi[i] * p.col(j + 1)).norm();
  double spin = 0.0;  // sum_j m |c_j|^2 + sum_k m_k |p_k|^2
  if (spin2_ != 0.0) {
    for (Eigen::Index j = 0; j + 1 < p.cols(); ++j) spin += segment_mass_ * (0.5 * (p.col(j) + p.col(j + 1))).squaredNorm();
    for (const auto& [k, m] : point_masses_) spin += m * p.col(k).squaredNorm();
  }
  return follower_ * area + central_ * radius - 0.5 * spin2_ * spin;
}

double Loading::potential(const Vector& q) const {
  const Eigen::Matrix2Xd p = positions(q);
  return -(f_.cwiseProduct(p - rest_)).sum() + shape_potential(p) - rest_shape_;
}

Vector Loading::forces(const Vector& q) const {
  const int n = chain_.n();
  const Eigen::Matrix2Xd g = hinge_gradient(positions(q), nullptr);
  Vector out = Vector::Zero(chain_.dofs());
  Eigen::Vector2d G = g.col(n);  // sum_{k > j} g_k
  for (int j = n - 1; j >= 0; --j) {
    out[j] = -chain_.l() * eprime(q[j]).dot(G);
    G += g.col(j);
  }
  if (chain_.free()) out.tail<2>() = -G;
  return out;
}

Vector Loading::angle_curvature(const Vector& q, const Eigen::Matrix2Xd& g) const {
  const int n = chain_.n();
  Vector d(n);
  Eigen::Vector2d G = g.col(n);  // sum_{k > j} g_k
  for (int j = n - 1; j >= 0; --j) {
    d[j] = -chain_.l() * e(q[j]).dot(G);
    G += g.col(j);
  }
  return d;
}

Vector Loading::constant_stiffness_diagonal(const Vector& q) const {
  if (shape_dependent()) throw std::logic_error("Loading::constant_stiffness_diagonal: a shape-dependent load");
  Vector d = Vector::Zero(chain_.dofs());
  d.head(chain_.n()) = angle_curvature(q, -f_);
  return d;
}

void Loading::add_stiffness(const Vector& q, double s, Eigen::Ref<Matrix> hess) const {
  const int n = chain_.n(), dofs = chain_.dofs();
  const double l = chain_.l();
  const Eigen::Matrix2Xd p = positions(q);
  std::vector<Block> blocks;
  const Eigen::Matrix2Xd g = hinge_gradient(p, shape_dependent() ? &blocks : nullptr);
  hess.diagonal().head(n) += s * angle_curvature(q, g);
  if (!shape_dependent()) return;
  // S(a, b) = sum_{k >= a, m >= b} H_km by two-dimensional suffix sums, one array per entry
  // of the 2 x 2 blocks; row/column n + 1 is zero.
  std::array<Matrix, 4> S;
  for (auto& x : S) x = Matrix::Zero(n + 2, n + 2);
  for (const Block& b : blocks)
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) S[2 * r + c](b.k, b.m) += b.h(r, c);
  for (auto& x : S)
    for (int a = n; a >= 0; --a)
      for (int b = n; b >= 0; --b) x(a, b) += x(a + 1, b) + x(a, b + 1) - x(a + 1, b + 1);
  auto block = [&](int a, int b) {
    Eigen::Matrix2d m;
    m << S[0](a, b), S[1](a, b), S[2](a, b), S[3](a, b);
    return m;
  };
  Eigen::Matrix2Xd c(2, n);
  for (int j = 0; j < n; ++j) c.col(j) = l * eprime(q[j]);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) hess(i, j) += s * c.col(i).dot(block(i + 1, j + 1) * c.col(j));
  if (!chain_.free()) return;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d row = block(i + 1, 0).transpose() * c.col(i);
    const Eigen::Vector2d col = block(0, i + 1) * c.col(i);
    hess(i, dofs - 2) += s * row[0];
    hess(i, dofs - 1) += s * row[1];
    hess(dofs - 2, i) += s * col[0];
    hess(dofs - 1, i) += s * col[1];
  }
  hess.bottomRightCorner(2, 2) += s * block(0, 0);
}

}  // namespace multibody::detail
