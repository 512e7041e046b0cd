#include "lumped_mass/terms.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

namespace lumped {

Eigen::Vector2d angle_gradient(const Eigen::Vector2d& v) { return Eigen::Vector2d(-v.y(), v.x()) / v.squaredNorm(); }

Eigen::Matrix2d angle_hessian(const Eigen::Vector2d& v) {
  const double r2 = v.squaredNorm();
  Eigen::Matrix2d J;
  J << 0.0, -1.0, 1.0, 0.0;
  const Eigen::Matrix2d h = (J * r2 - 2.0 * (J * v) * v.transpose()) / (r2 * r2);
  return 0.5 * (h + h.transpose());
}

int node_of(double deg, double anchor, int n, const std::string& key) {
  if (!std::isfinite(deg) || !ring::on_node(deg, anchor, n))
    throw std::invalid_argument("lumped: " + key + " (= " + std::to_string(deg) + " deg) is not a node of the n = " +
                                std::to_string(n) + " model (valid: anchor " + std::to_string(anchor) +
                                " deg + 360 k / n)");
  return static_cast<int>(std::lround(ring::wrap_degrees(deg - anchor) * n / 360.0)) % n;
}

int node_at(const ring::RingSpec& spec, double deg, int pieces, const std::string& key) {
  if (!spec.is_arch()) return node_of(deg, spec.anchor(), pieces, key);
  const int k = std::isfinite(deg) ? ring::node_index(spec, deg, pieces) : -1;
  if (k < 0)
    throw std::invalid_argument("lumped: " + key + " (= " + std::to_string(deg) + " deg) is not a node of the n = " +
                                std::to_string(pieces) + " model of the arch (ring.arc = [" +
                                std::to_string(spec.arc->from) + ", " + std::to_string(spec.arc->to) +
                                "]; valid: from + span k / n, k = 0..n)");
  return k;
}

Section section_at(const ring::RingSpec& spec, double deg) {
  if (!spec.varies()) return {spec.EA(), spec.EI(), spec.rhoA(), spec.rhoI(), spec.kGA()};
  return {spec.EA_at(deg), spec.EI_at(deg), spec.rhoA_at(deg), spec.rhoI_at(deg), spec.kGA_at(deg)};
}

double piece_mass(const ring::RingSpec& spec, double from_deg, double to_deg, double length) {
  if (!spec.varies()) return spec.rhoA() * length;
  const double mid = 0.5 * (from_deg + to_deg), half = 0.5 * (to_deg - from_deg), x = std::sqrt(0.6);
  const double mean = (5.0 * spec.rhoA_at(mid - x * half) + 8.0 * spec.rhoA_at(mid) + 5.0 * spec.rhoA_at(mid + x * half)) / 18.0;
  return mean * length;
}

double hinge_spring(const ring::RingSpec& spec, double deg, double side) {
  return (spec.varies() ? spec.EI_at(deg) : spec.EI()) / side;
}

void check_nonnegative(double v, const std::string& key) {
  if (!(v >= 0.0) || !std::isfinite(v))
    throw std::invalid_argument("lumped: " + key + " (= " + std::to_string(v) + ") must be finite and >= 0");
}

Terms::Terms(const ring::RingSpec& spec, int dofs_per_node, double anchor_deg, double side, const Eigen::VectorXd& rest)
    : n_(static_cast<int>(rest.size() / 2)), dpn_(dofs_per_node), open_(spec.is_arch()), rest_(rest) {
  const int n = n_, dpn = dpn_;
  k4_.resize(n);
  for (int h = 0; h < n; ++h)  // the node's polar angle from its rest position
    k4_[h] = 4.0 * hinge_spring(spec, std::atan2(rest[2 * h + 1], rest[2 * h]) * 180.0 / M_PI, side);
  const int pieces = open_ ? n - 1 : n;  // an arch's n + 1 nodes bound n pieces
  auto node = [&](double deg, const std::string& key) {
    return open_ ? node_at(spec, deg, pieces, key) : node_of(deg, anchor_deg, n, key);
  };
  auto stiffness = [&](std::vector<std::pair<int, double>> row, double k) {
    if (k > 0.0) springs_.push_back({-1, std::move(row), k});
  };
  const ring::Foundation& f = spec.foundation;
  check_nonnegative(f.radial, "foundation.radial");
  check_nonnegative(f.tangential, "foundation.tangential");
  if (f.any())
    for (int k = 0; k < n; ++k) {
      const double rr = std::hypot(rest[2 * k], rest[2 * k + 1]), rx = rest[2 * k] / rr, ry = rest[2 * k + 1] / rr;
      const double w = open_ && (k == 0 || k == n - 1) ? 0.5 * side : side;  // an arch's end: half a piece
      stiffness({{dpn * k, rx}, {dpn * k + 1, ry}}, f.radial * w);
      stiffness({{dpn * k, -ry}, {dpn * k + 1, rx}}, f.tangential * w);
    }
  std::vector<double> kr(n, 0.0);  // rotational springs to the ground by node (a clamp: infinite)
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i) {
    const ring::Spring& s = spec.supports.springs[i];
    const std::string key = "supports.springs[" + std::to_string(i + 1) + "]";
    const int h = node(s.angle, key);
    check_nonnegative(s.kx, key + ".kx");
    check_nonnegative(s.ky, key + ".ky");
    check_nonnegative(s.kr, key + ".kr");
    stiffness({{dpn * h, 1.0}}, s.kx);
    stiffness({{dpn * h + 1, 1.0}}, s.ky);
    kr[h] += s.kr;
  }
  const bool chain = dpn == 2;
  if (chain && spec.supports.clamp) kr[node(*spec.supports.clamp, "supports.clamp")] = HUGE_VAL;
  for (int h = 0; h < n; ++h)
    if (kr[h] > 0.0) {
      const double k4 = hinge_stiffness(h);
      springs_.push_back({h, {}, !chain ? kr[h] : std::isinf(kr[h]) ? k4 : k4 * kr[h] / (k4 + kr[h])});
    }
  std::map<int, Inertia> by_node;
  for (std::size_t i = 0; i < spec.masses.size(); ++i) {
    const ring::PointMass& pm = spec.masses[i];
    const std::string key = "masses[" + std::to_string(i + 1) + "]";
    const int h = node(pm.angle, key);
    check_nonnegative(pm.mass, key + ".mass");
    check_nonnegative(pm.inertia, key + ".inertia");
    Inertia& in = by_node[h];
    in.node = h;
    in.mass += pm.mass;
    if (!chain) in.rotary += pm.inertia;  // the chain's J rides on chi (hinge_rotations_)
  }
  for (const auto& [h, in] : by_node) {
    inertia_.push_back(in);
    double J = 0.0;
    for (const ring::PointMass& pm : spec.masses)
      if (node(pm.angle, "masses") == h) J += pm.inertia;
    if (chain && J > 0.0 && !std::isinf(kr[h])) hinge_rotations_.push_back({h, kr[h], J});
  }
}

bool Terms::own_rotation(int h) const {
  for (const HingeRotation& r : hinge_rotations_)
    if (r.node == h) return true;
  return false;
}

Measure Terms::rotation(const Eigen::VectorXd& u, int h, bool with_hessian) const {
  Measure m;
  if (dpn_ == 3) {
    m.value = u[3 * h + 2];
    m.dofs = {3 * h + 2};
    m.grad = Eigen::VectorXd::Ones(1);
    return m;
  }
  const int n = n_, hm = (h + n - 1) % n, hp = (h + 1) % n;
  if (open_ && (h == 0 || h == n - 1)) return end_rotation(u, h, with_hessian);
  auto pos = [&](int k) { return Eigen::Vector2d(rest_[2 * k] + u[2 * k], rest_[2 * k + 1] + u[2 * k + 1]); };
  auto rest = [&](int k) { return Eigen::Vector2d(rest_[2 * k], rest_[2 * k + 1]); };
  // Link rotation from its rest direction e: atan2(e x d, e . d).
  auto turn = [](const Eigen::Vector2d& e, const Eigen::Vector2d& d) {
    return std::atan2(e.x() * d.y() - e.y() * d.x(), e.dot(d));
  };
  const Eigen::Vector2d da = pos(h) - pos(hm), db = pos(hp) - pos(h);
  const Eigen::Vector2d ea = (rest(h) - rest(hm)).normalized(), eb = (rest(hp) - rest(h)).normalized();
  m.value = 0.5 * (turn(ea, da) + turn(eb, db));
  m.dofs = {2 * hm, 2 * hm + 1, 2 * h, 2 * h + 1, 2 * hp, 2 * hp + 1};
  const Eigen::Vector2d ga = angle_gradient(da), gb = angle_gradient(db);
  m.grad.resize(6);
  m.grad << -0.5 * ga, 0.5 * (ga - gb), 0.5 * gb;
  if (with_hessian) {
    const Eigen::Matrix2d Ha = 0.5 * angle_hessian(da), Hb = 0.5 * angle_hessian(db);
    m.hess = Eigen::MatrixXd::Zero(6, 6);
    // Link a joins blocks 0 and 1, link b blocks 1 and 2: d = x_second - x_first.
    m.hess.block<2, 2>(0, 0) += Ha;
    m.hess.block<2, 2>(0, 2) -= Ha;
    m.hess.block<2, 2>(2, 0) -= Ha;
    m.hess.block<2, 2>(2, 2) += Ha + Hb;
    m.hess.block<2, 2>(2, 4) -= Hb;
    m.hess.block<2, 2>(4, 2) -= Hb;
    m.hess.block<2, 2>(4, 4) += Hb;
  }
  return m;
}

Measure Terms::end_rotation(const Eigen::VectorXd& u, int h, bool with_hessian) const {
  // The one link of an arch's end: from node 0 to 1, or from n - 2 to n - 1; d = x_b - x_a.
  const int a = h == 0 ? 0 : h - 1, b = a + 1;
  auto pos = [&](int k) { return Eigen::Vector2d(rest_[2 * k] + u[2 * k], rest_[2 * k + 1] + u[2 * k + 1]); };
  const Eigen::Vector2d d = pos(b) - pos(a);
  const Eigen::Vector2d e = Eigen::Vector2d(rest_[2 * b] - rest_[2 * a], rest_[2 * b + 1] - rest_[2 * a + 1]).normalized();
  Measure m;
  m.value = std::atan2(e.x() * d.y() - e.y() * d.x(), e.dot(d));
  m.dofs = {2 * a, 2 * a + 1, 2 * b, 2 * b + 1};
  const Eigen::Vector2d g = angle_gradient(d);
  m.grad.resize(4);
  m.grad << -g, g;
  if (with_hessian) {
    const Eigen::Matrix2d H = angle_hessian(d);
    m.hess = Eigen::MatrixXd::Zero(4, 4);
    m.hess.block<2, 2>(0, 0) = H;
    m.hess.block<2, 2>(0, 2) = -H;
    m.hess.block<2, 2>(2, 0) = -H;
    m.hess.block<2, 2>(2, 2) = H;
  }
  return m;
}

Measure Terms::measure(const Spring& s, const Eigen::VectorXd& u, bool with_hessian) const {
  if (s.node >= 0) return rotation(u, s.node, with_hessian);
  Measure m;
  m.grad.resize(static_cast<Eigen::Index>(s.row.size()));
  for (std::size_t i = 0; i < s.row.size(); ++i) {
    m.dofs.push_back(s.row[i].first);
    m.grad[static_cast<Eigen::Index>(i)] = s.row[i].second;
    m.value += s.row[i].second * u[s.row[i].first];
  }
  return m;
}

void add_spring(const Measure& r, double k, double* energy, Eigen::VectorXd* grad, double hess_scale, Triplets* out) {
  if (energy) *energy += 0.5 * k * r.value * r.value;
  if (grad)
    for (std::size_t i = 0; i < r.dofs.size(); ++i) (*grad)[r.dofs[i]] += k * r.value * r.grad[static_cast<Eigen::Index>(i)];
  if (!out || hess_scale == 0.0) return;
  const Eigen::Index q = r.grad.size();
  for (Eigen::Index i = 0; i < q; ++i)
    for (Eigen::Index j = 0; j < q; ++j) {
      double h = r.grad[i] * r.grad[j];
      if (r.hess.size() > 0) h += r.value * r.hess(i, j);
      if (h != 0.0) out->emplace_back(r.dofs[i], r.dofs[j], hess_scale * k * h);
    }
}

bool Terms::left_out(const Spring& s, HingeRotations hinges) const {
  return hinges == HingeRotations::unknowns && s.node >= 0 && own_rotation(s.node);
}

double Terms::energy(const Eigen::VectorXd& u, HingeRotations hinges) const {
  double e = 0.0;
  for (const Spring& s : springs_)
    if (!left_out(s, hinges)) add_spring(measure(s, u, false), s.k, &e, nullptr, 0.0, nullptr);
  return e;
}

void Terms::add_gradient(const Eigen::VectorXd& u, Eigen::VectorXd& grad, HingeRotations hinges) const {
  for (const Spring& s : springs_)
    if (!left_out(s, hinges)) add_spring(measure(s, u, false), s.k, nullptr, &grad, 0.0, nullptr);
}

void Terms::add_hessian(const Eigen::VectorXd& u, double scale, Triplets& out, HingeRotations hinges) const {
  for (const Spring& s : springs_)
    if (!left_out(s, hinges)) add_spring(measure(s, u, true), s.k, nullptr, nullptr, scale, &out);
}

std::vector<Terms::Split> Terms::split(const Eigen::VectorXd& u, std::size_t i, double chi, int chi_dof,
                                       bool with_hessian) const {
  const HingeRotation& hr = hinge_rotations_.at(i);
  std::vector<Split> out(1);
  Measure& r = out[0].r;
  r = rotation(u, hr.node, with_hessian);  // m_h
  r.value -= chi;
  r.dofs.push_back(chi_dof);
  r.grad.conservativeResize(r.grad.size() + 1);
  r.grad[r.grad.size() - 1] = -1.0;
  if (with_hessian) r.hess.conservativeResizeLike(Eigen::MatrixXd::Zero(r.grad.size(), r.grad.size()));
  out[0].k = hinge_stiffness(hr.node);
  if (hr.kr > 0.0) {
    Measure g;
    g.value = chi;
    g.dofs = {chi_dof};
    g.grad = Eigen::VectorXd::Ones(1);
    out.push_back({std::move(g), hr.kr});
  }
  return out;
}

int Terms::rest_rows(int row0, Triplets& rows, std::vector<double>& d) const {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dpn_ * n_);
  int r = row0;
  for (const Spring& s : springs_) {
    if (left_out(s, HingeRotations::unknowns)) continue;  // kr on chi (split(), model.cpp)
    const Measure m = measure(s, zero, false);
    for (std::size_t i = 0; i < m.dofs.size(); ++i) rows.emplace_back(r, m.dofs[i], m.grad[static_cast<Eigen::Index>(i)]);
    d.push_back(s.k);
    ++r;
  }
  return r - row0;
}

}  // namespace lumped
