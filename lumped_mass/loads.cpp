#include "lumped_mass/loads.hpp"

#include <cmath>

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Vec2 = Eigen::Vector2d;

Vec2 at(const Vec& x, int j, int n) {
  j = ((j % n) + n) % n;
  return {x[2 * j], x[2 * j + 1]};
}

/// Twice the enclosed area, sum_j x_j x x_{j+1} over the links.
double twice_area(const Vec& x, int n, int links) {
  double a = 0.0;
  for (int j = 0; j < links; ++j) {
    const Vec2 p = at(x, j, n), q = at(x, j + 1, n);
    a += p.x() * q.y() - p.y() * q.x();
  }
  return a;
}

double midpoint_radii(const Vec& x, int n, int links) {
  double s = 0.0;
  for (int j = 0; j < links; ++j) s += (0.5 * (at(x, j, n) + at(x, j + 1, n))).norm();
  return s;
}

}  // namespace

ChainLoads::ChainLoads(const ring::Loads& loads, const Vec& rest, double side,
                       const Eigen::SparseMatrix<double>& translational_mass, const std::vector<int>& hinges, bool open)
    : n_(static_cast<int>(rest.size() / 2)), links_(open ? n_ - 1 : n_), l_(side), pressure_(loads.pressure), rest_(rest) {
  const int n = n_;
  dead_ = Vec::Zero(2 * n);
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    dead_[2 * hinges[i]] += loads.points[i].force[0];
    dead_[2 * hinges[i] + 1] += loads.points[i].force[1];
  }
  if (loads.has_gravity()) {
    Vec G(2 * n);
    for (int k = 0; k < n; ++k) G.segment<2>(2 * k) << loads.gravity[0], loads.gravity[1];
    dead_ += translational_mass * G;
  }
  if (pressure_.any() && pressure_.kind == ring::Pressure::Kind::dead)
    for (int j = 0; j < links_; ++j) {
      const Vec2 d = at(rest, j + 1, n) - at(rest, j, n);
      const Vec2 nu = Vec2(-d.y(), d.x()).normalized();  // inward on the counter-clockwise chain
      const Vec2 f = 0.5 * pressure_.value * l_ * nu;
      dead_.segment<2>(2 * j) += f;
      dead_.segment<2>(2 * ((j + 1) % n)) += f;
    }
  // The follower pressure's area: the closed polygon's, the closing chord included (on an arch
  // whose ends are pinned the chord is fixed: the area between chain and chord; loads.hpp).
  area0_ = 0.5 * twice_area(rest, n, n);
  central0_ = midpoint_radii(rest, n, links_);
}

bool ChainLoads::has_stiffness() const {
  return (pressure_.any() && pressure_.kind != ring::Pressure::Kind::dead) || spin2_ != 0.0;
}

double ChainLoads::potential(const Vec& x) const {
  double P = -dead_.dot(x - rest_);
  if (spin2_ != 0.0) P -= 0.5 * spin2_ * (x.dot(mass_ * x) - rest_.dot(mass_ * rest_));
  if (!pressure_.any()) return P;
  const double p = pressure_.value;
  if (pressure_.kind == ring::Pressure::Kind::follower) P += p * (0.5 * twice_area(x, n_, n_) - area0_);
  if (pressure_.kind == ring::Pressure::Kind::central) P += p * l_ * (midpoint_radii(x, n_, links_) - central0_);
  return P;
}

Vec ChainLoads::gradient(const Vec& x) const {
  Vec g = -dead_;
  if (spin2_ != 0.0) g -= spin2_ * (mass_ * x);
  if (!pressure_.any()) return g;
  const double p = pressure_.value;
  const int n = n_;
  if (pressure_.kind == ring::Pressure::Kind::follower)
    // d A / d x_j = -1/2 J (x_{j+1} - x_{j-1}), J the rotation by +90 deg.
    for (int j = 0; j < n; ++j) {
      const Vec2 c = at(x, j + 1, n) - at(x, j - 1, n);
      g[2 * j] += 0.5 * p * c.y();
      g[2 * j + 1] -= 0.5 * p * c.x();
    }
  if (pressure_.kind == ring::Pressure::Kind::central)
    for (int j = 0; j < links_; ++j) {
      const Vec2 y = 0.5 * (at(x, j, n) + at(x, j + 1, n));
      const Vec2 f = 0.5 * p * l_ * y / y.norm();
      g.segment<2>(2 * j) += f;
      g.segment<2>(2 * ((j + 1) % n)) += f;
    }
  return g;
}

void ChainLoads::add_hessian(const Vec& x, double scale, Triplets& out) const {
  if (!has_stiffness() || scale == 0.0) return;
  if (spin2_ != 0.0)
    for (int k = 0; k < mass_.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(mass_, k); it; ++it)
        out.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), -scale * spin2_ * it.value());
  if (!pressure_.any()) return;
  const double p = pressure_.value;
  const int n = n_;
  if (pressure_.kind == ring::Pressure::Kind::follower)
    // d2 A / dx_j dx_{j+1} = -J / 2 = [[0, 1/2], [-1/2, 0]]; its transpose for (j+1, j).
    for (int j = 0; j < n; ++j) {
      const int a = 2 * j, b = 2 * ((j + 1) % n);
      const double h = 0.5 * p * scale;
      out.emplace_back(a, b + 1, h);
      out.emplace_back(a + 1, b, -h);
      out.emplace_back(b + 1, a, h);
      out.emplace_back(b, a + 1, -h);
    }
  if (pressure_.kind == ring::Pressure::Kind::central)
    for (int j = 0; j < links_; ++j) {
      const Vec2 y = 0.5 * (at(x, j, n) + at(x, j + 1, n));
      const double r = y.norm();
      const Vec2 e = y / r;
      const Eigen::Matrix2d H = scale * p * l_ / (4.0 * r) * (Eigen::Matrix2d::Identity() - e * e.transpose());
      const int idx[2] = {2 * j, 2 * ((j + 1) % n)};
      for (int a : idx)
        for (int b : idx)
          for (int r1 = 0; r1 < 2; ++r1)
            for (int c1 = 0; c1 < 2; ++c1) out.emplace_back(a + r1, b + c1, H(r1, c1));
    }
}

}  // namespace lumped
