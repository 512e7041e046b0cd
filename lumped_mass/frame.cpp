#include "lumped_mass/frame.hpp"

#include <cmath>

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Vec2 = Eigen::Vector2d;
using Sparse = Eigen::SparseMatrix<double>;
constexpr double kPi = 3.14159265358979323846;

}  // namespace

Vec Frame::positions(const Vec& q) const {
  Vec x(2 * n);
  for (int j = 0; j < n; ++j) x.segment<2>(2 * j) = q.segment<2>(3 * j);
  return x;
}

Frame make_frame(const ring::RingSpec& spec, const ring::LumpedOptions& o) {
  Frame f;
  f.n = o.n;
  f.l = 2.0 * kPi * spec.radius / f.n;
  f.k = natural_stiffness(spec, f.l, o.variant);
  const Eigen::Matrix2d& Kb = f.k.bending;
  f.bending = Bending(spec, f.n, f.l, 0.5 * (Kb(0, 0) - Kb(0, 1)));
  f.linear_mode = 0.5 * (Kb(0, 0) + Kb(0, 1));
  // The linear model checks every point of the spec and gives the support rows and the mass
  // (translations, section rotations, point masses): one code for the linear and the
  // nonlinear frame.
  const Model m = assemble(spec, o);
  f.S = m.S;
  f.M = m.M;
  f.geometry.n = f.n;
  f.geometry.l = f.l;
  f.geometry.rho = m.circumradius;
  f.geometry.depth = spec.section.depth();
  f.geometry.anchor_deg = m.anchor_deg;
  f.rest = Vec::Zero(3 * f.n);
  f.rest_xy.resize(2 * f.n);
  const auto angles = ring::node_angles(spec, f.n);
  for (int j = 0; j < f.n; ++j) {
    f.rest_xy[2 * j] = f.rest[3 * j] = m.circumradius * std::cos(angles[j] * kPi / 180.0);
    f.rest_xy[2 * j + 1] = f.rest[3 * j + 1] = m.circumradius * std::sin(angles[j] * kPi / 180.0);
  }
  f.geometry.rest = f.rest_xy;
  f.terms.emplace(spec, 3, m.anchor_deg, f.l, f.rest_xy);
  f.scale = spec.EI() / (f.l * f.l * f.l);
  return f;
}

FrameElement frame_element(const Frame& f, const Vec& q, int j, bool with_hessian) {
  const int a = j, b = (j + 1) % f.n;
  const Vec2 d = q.segment<2>(3 * b) - q.segment<2>(3 * a);
  const Vec2 d0 = f.rest.segment<2>(3 * b) - f.rest.segment<2>(3 * a);
  const double L = d.norm(), L0 = d0.norm();
  const Vec2 e = d / L, e0 = d0 / L0;
  const double alpha = std::atan2(e0.x() * d.y() - e0.y() * d.x(), e0.dot(d));
  const double u = L - L0;
  const Eigen::Vector2d t(q[3 * a + 2] - alpha, q[3 * b + 2] - alpha);
  // Gradients on (x_a, y_a, th_a, x_b, y_b, th_b): u, alpha, and t_i = th_i - alpha.
  using V6 = Eigen::Matrix<double, 6, 1>;
  const Vec2 g = angle_gradient(d);
  V6 gu, ga, gt1, gt2;
  gu << -e, 0.0, e, 0.0;
  ga << -g, 0.0, g, 0.0;
  gt1 = -ga;
  gt1[2] += 1.0;
  gt2 = -ga;
  gt2[5] += 1.0;
  const double EA = f.k.axial;
  // The bending block in its two modes (bending.hpp): the constant curvature
  // b = t2 - t1 = th_b - th_a (linear in q) under the bending law, the linear mode
  // v = t1 + t2 elastic; the end moments are d/dt of their energies. Inside the law's band
  // that is the element's own 1/2 te^T Kb te with te = t less the plastic rotation split
  // between the ends (te = t with none), written as the elastic element always was, so that
  // an elastic frame is bit for bit the same; past the band, the two modes apart.
  const ring::BilinearLaw::Point bend = f.bending.at(j, q[3 * b + 2] - q[3 * a + 2]);
  const Eigen::Matrix2d& Kb = f.k.bending;
  const double half_plastic = 0.5 * f.bending.plastic(j);
  const Eigen::Vector2d te(t[0] + half_plastic, t[1] - half_plastic);
  const double v = t[0] + t[1], kv = f.linear_mode;
  const Eigen::Vector2d mom = bend.yielding ? Eigen::Vector2d(kv * v - bend.force, kv * v + bend.force)
                                            : Eigen::Vector2d(Kb * te);
  FrameElement out;
  out.energy = 0.5 * EA * u * u + (bend.yielding ? bend.potential + 0.5 * kv * v * v : 0.5 * te.dot(mom));
  out.grad = EA * u * gu + mom[0] * gt1 + mom[1] * gt2;
  if (with_hessian) {
    if (bend.yielding) {
      V6 gb = V6::Zero();
      gb[2] = -1.0;
      gb[5] = 1.0;
      const V6 gv = gt1 + gt2;
      out.hess = EA * gu * gu.transpose() + bend.tangent * gb * gb.transpose() + kv * gv * gv.transpose();
    } else {
      out.hess = EA * gu * gu.transpose() + Kb(0, 0) * gt1 * gt1.transpose() +
                 Kb(0, 1) * (gt1 * gt2.transpose() + gt2 * gt1.transpose()) + Kb(1, 1) * gt2 * gt2.transpose();
    }
    // The curvature terms: EA u Hess L - (m1 + m2) Hess alpha, both on d = x_b - x_a.
    const Eigen::Matrix2d H = EA * u * (Eigen::Matrix2d::Identity() - e * e.transpose()) / L -
                              (mom[0] + mom[1]) * angle_hessian(d);
    out.hess.block<2, 2>(0, 0) += H;
    out.hess.block<2, 2>(3, 3) += H;
    out.hess.block<2, 2>(0, 3) -= H;
    out.hess.block<2, 2>(3, 0) -= H;
  }
  return out;
}

std::vector<double> bending_strains(const Frame& f, const Vec& q) {
  std::vector<double> e(static_cast<std::size_t>(f.n));
  for (int j = 0; j < f.n; ++j) e[static_cast<std::size_t>(j)] = q[3 * ((j + 1) % f.n) + 2] - q[3 * j + 2];
  return e;
}

Springs frame_energy(const Frame& f, const Vec& q, double hess_scale) {
  Springs s;
  s.grad = Vec::Zero(3 * f.n);
  add_terms(*f.terms, q - f.rest, hess_scale, s);
  for (int j = 0; j < f.n; ++j) {
    const FrameElement el = frame_element(f, q, j, hess_scale != 0.0);
    const int a = 3 * j, b = 3 * ((j + 1) % f.n);
    const int dofs[6] = {a, a + 1, a + 2, b, b + 1, b + 2};
    s.energy += el.energy;
    for (int i = 0; i < 6; ++i) s.grad[dofs[i]] += el.grad[i];
    if (hess_scale != 0.0)
      for (int i = 0; i < 6; ++i)
        for (int k = 0; k < 6; ++k) s.hess.emplace_back(dofs[i], dofs[k], hess_scale * el.hess(i, k));
  }
  return s;
}

namespace {

/// The translational block of the frame's mass on the 2n node positions (for gravity).
Sparse translational_mass(const Frame& f) {
  Triplets t;
  for (int c = 0; c < f.M.outerSize(); ++c)
    for (Sparse::InnerIterator it(f.M, c); it; ++it)
      if (it.row() % 3 != 2 && it.col() % 3 != 2)
        t.emplace_back(2 * (it.row() / 3) + it.row() % 3, 2 * (it.col() / 3) + it.col() % 3, it.value());
  Sparse M(2 * f.n, 2 * f.n);
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

int q_index(int i) { return 3 * (i / 2) + i % 2; }

}  // namespace

FrameLoads::FrameLoads(const Frame& f, const ring::RingSpec& spec, const ring::Loads& loads, const std::string& section)
    : f_(f) {
  std::vector<int> nodes;
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const std::string key =
        loads.points.size() == 1 ? section + ".at" : section + ".loads[" + std::to_string(i + 1) + "].at";
    nodes.push_back(node_of(loads.points[i].angle, f.geometry.anchor_deg, f.n, key));
    if (spec.supports.pin && nodes.back() == 0) throw std::invalid_argument("lumped: " + key + " acts at the pin");
  }
  loads_.emplace(loads, f.rest_xy, f.l, translational_mass(f), nodes);
}

void FrameLoads::set_spin(double speed) { loads_->set_spin(speed, translational_mass(f_)); }

double FrameLoads::potential(const Vec& q) const { return loads_->potential(f_.positions(q)); }

Vec FrameLoads::gradient(const Vec& q) const {
  const Vec g2 = loads_->gradient(f_.positions(q));
  Vec g = Vec::Zero(3 * f_.n);
  for (int i = 0; i < 2 * f_.n; ++i) g[q_index(i)] = g2[i];
  return g;
}

void FrameLoads::add_hessian(const Vec& q, double scale, Triplets& out) const {
  if (!loads_->has_stiffness()) return;
  Triplets t2;
  loads_->add_hessian(f_.positions(q), scale, t2);
  for (const auto& e : t2) out.emplace_back(q_index(e.row()), q_index(e.col()), e.value());
}

}  // namespace lumped
