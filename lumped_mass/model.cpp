#include "lumped_mass/model.hpp"

#include "lumped_mass/terms.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace lumped {
namespace {

struct Vec2 {
  double x, y;
};

/// Node positions on the regular n-gon, node k at anchor + 360 k / n degrees. O(n).
std::vector<Vec2> polygon(int n, double anchor_deg, double circumradius) {
  std::vector<Vec2> p(n);
  for (int k = 0; k < n; ++k) {
    const double a = (anchor_deg + 360.0 * k / n) * M_PI / 180.0;
    p[k] = {circumradius * std::cos(a), circumradius * std::sin(a)};
  }
  return p;
}

void check_spec(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  if (options.n < 4)
    throw std::invalid_argument("lumped.n (=" + std::to_string(options.n) + ") must be >= 4");
  const std::array<std::pair<const char*, double>, 5> positive{{{"ring.radius", spec.radius},
                                                                {"ring.E", spec.E},
                                                                {"ring.rho", spec.rho},
                                                                {"section area", spec.A()},
                                                                {"section inertia", spec.I()}}};
  for (const auto& [name, v] : positive)
    if (!(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string(name) + " (=" + std::to_string(v) + ") must be > 0");
}

/// Support rows: every pinned point (supports.pinned(): the pin at node 0, then `pins`)
/// blocks both translations of its node; a roller blocks the roller node's displacement
/// normal to the line through the pin and itself; a clamp on a frame blocks its node's
/// rotation (the chain's clamp is a spring on its chord rotation, add_terms()).
SpMat support_rows(const ring::RingSpec& spec, const std::vector<Vec2>& p, int dpn, double anchor) {
  const int n = static_cast<int>(p.size());
  Triplets t;
  int rows = 0;
  if (spec.supports.roller && !spec.supports.pin)
    throw std::invalid_argument("supports.roller needs supports.pin");
  if (!spec.supports.pin && (!spec.supports.pins.empty() || spec.supports.clamp))
    throw std::invalid_argument("lumped: supports.pins and supports.clamp need supports.pin (the first pinned point)");
  for (std::size_t i = 0; i < spec.supports.pinned().size(); ++i) {
    const double a = spec.supports.pinned()[i];
    const int k = node_of(a, anchor, n, i == 0 ? "supports.pin" : "supports.pins");
    t.emplace_back(rows++, dpn * k, 1.0);
    t.emplace_back(rows++, dpn * k + 1, 1.0);
  }
  if (spec.supports.clamp) {
    const double a = *spec.supports.clamp;
    const int k = node_of(a, anchor, n, "supports.clamp");
    bool pinned = false;
    for (double q : spec.supports.pinned()) pinned = pinned || node_of(q, anchor, n, "supports.pins") == k;
    if (!pinned)
      throw std::invalid_argument("lumped: supports.clamp (= " + std::to_string(a) +
                                  " deg) must be a pinned point (supports.pin or one of supports.pins)");
    if (dpn == 3) t.emplace_back(rows++, 3 * k + 2, 1.0);
  }
  if (spec.supports.roller) {
    const double r = *spec.supports.roller;
    if (!ring::on_node(r, anchor, n))
      throw std::invalid_argument("supports.roller (=" + std::to_string(r) +
                                  " deg) must be a node: pin + 360 k / " + std::to_string(n));
    const int k = static_cast<int>(std::lround(ring::wrap_degrees(r - anchor) * n / 360.0)) % n;
    if (k == 0) throw std::invalid_argument("supports.roller must differ from supports.pin");
    const double dx = p[k].x - p[0].x, dy = p[k].y - p[0].y, d = std::hypot(dx, dy);
    // Normal to the pin-roller line: the blocked direction.
    t.emplace_back(rows, dpn * k, -dy / d);
    t.emplace_back(rows, dpn * k + 1, dx / d);
    ++rows;
  }
  SpMat S(rows, dpn * n);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

/// Chain: hinges at the nodes, side j is a rigid link of length l from node j to j+1.
void assemble_chain(const ring::RingSpec& spec, const std::vector<Vec2>& p, double l, Model& m) {
  const int n = m.n, N = 2 * n;
  const double mass = spec.rhoA() * l, k = spec.EI() / l;
  // Unit side vectors t_j and their left normals nu_j (t rotated by +90 deg).
  std::vector<Vec2> t(n), nu(n);
  for (int j = 0; j < n; ++j) {
    const Vec2& a = p[j];
    const Vec2& b = p[(j + 1) % n];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    t[j] = {(b.x - a.x) / len, (b.y - a.y) / len};
    nu[j] = {-t[j].y, t[j].x};
  }
  // Link lengths |P_{j+1} - P_j| = l, linearised: t_j . (u_{j+1} - u_j) = 0.
  Triplets c;
  for (int j = 0; j < n; ++j) {
    const int a = 2 * j, b = 2 * ((j + 1) % n);
    c.emplace_back(j, a, -t[j].x);
    c.emplace_back(j, a + 1, -t[j].y);
    c.emplace_back(j, b, t[j].x);
    c.emplace_back(j, b + 1, t[j].y);
  }
  m.C.resize(n, N);
  m.C.setFromTriplets(c.begin(), c.end());

  // Spring at hinge j: theta_j = atan2(a x b, a . b), a = P_j - P_{j-1} (side j-1),
  // b = P_{j+1} - P_j (side j). d theta_j = d phi(b) - d phi(a), and the direction
  // angle phi of a side vector v changes by d phi = (v x dv) / |v|^2 = nu . dv / l.
  Triplets kt, bt;
  for (int j = 0; j < n; ++j) {
    const int jm = (j + n - 1) % n, jp = (j + 1) % n;
    // grad theta_j as (node, coefficient vector) pairs; nodes jm, j, jp.
    const std::array<int, 3> node{jm, j, jp};
    std::array<Vec2, 3> g{};
    // + nu_j . (u_{j+1} - u_j) / l
    g[2].x += nu[j].x / l;  g[2].y += nu[j].y / l;
    g[1].x -= nu[j].x / l;  g[1].y -= nu[j].y / l;
    // - nu_{j-1} . (u_j - u_{j-1}) / l
    g[1].x -= nu[jm].x / l; g[1].y -= nu[jm].y / l;
    g[0].x += nu[jm].x / l; g[0].y += nu[jm].y / l;
    for (int r = 0; r < 3; ++r) {
      bt.emplace_back(j, 2 * node[r], g[r].x);
      bt.emplace_back(j, 2 * node[r] + 1, g[r].y);
    }
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) {
        const double gr[2] = {g[r].x, g[r].y}, gs[2] = {g[s].x, g[s].y};
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) kt.emplace_back(2 * node[r] + a, 2 * node[s] + b, k * gr[a] * gs[b]);
      }
  }
  m.K.resize(N, N);
  m.K.setFromTriplets(kt.begin(), kt.end());
  m.B.resize(n, N);
  m.B.setFromTriplets(bt.begin(), bt.end());
  m.D = Eigen::VectorXd::Constant(n, k);

  // Point mass at the midpoint (P_j + P_{j+1}) / 2 of side j: T = m/2 |(u_j + u_{j+1})/2|'^2.
  Triplets mt;
  for (int j = 0; j < n; ++j) {
    const int a = j, b = (j + 1) % n;
    for (int d = 0; d < 2; ++d) {
      mt.emplace_back(2 * a + d, 2 * a + d, mass / 4.0);
      mt.emplace_back(2 * b + d, 2 * b + d, mass / 4.0);
      mt.emplace_back(2 * a + d, 2 * b + d, mass / 4.0);
      mt.emplace_back(2 * b + d, 2 * a + d, mass / 4.0);
    }
  }
  m.M.resize(N, N);
  m.M.setFromTriplets(mt.begin(), mt.end());
  m.massless.assign(N, 0);
}

/// Frame: element j on side j from node j to j+1. Local DOFs (u1, v1, th1, u2, v2, th2)
/// along / normal to the side; global = R^T local R with R = blockdiag(r, r),
/// r = [[c, s, 0], [-s, c, 0], [0, 0, 1]].
void assemble_frame(const ring::RingSpec& spec, const std::vector<Vec2>& p, double l, bool consistent,
                    Model& m) {
  const int n = m.n, N = 3 * n;
  const double EA = spec.EA(), EI = spec.EI(), rA = spec.rhoA();
  Eigen::Matrix<double, 6, 6> kl = Eigen::Matrix<double, 6, 6>::Zero(), ml = kl;
  // Linear axial bar.
  kl(0, 0) = kl(3, 3) = EA / l;
  kl(0, 3) = kl(3, 0) = -EA / l;
  // Cubic Hermite bending on (v1, th1, v2, th2) = local 1, 2, 4, 5.
  const std::array<int, 4> bi{1, 2, 4, 5};
  const double kb[4][4] = {{12, 6 * l, -12, 6 * l},
                           {6 * l, 4 * l * l, -6 * l, 2 * l * l},
                           {-12, -6 * l, 12, -6 * l},
                           {6 * l, 2 * l * l, -6 * l, 4 * l * l}};
  for (int r = 0; r < 4; ++r)
    for (int s = 0; s < 4; ++s) kl(bi[r], bi[s]) = EI / (l * l * l) * kb[r][s];
  if (consistent) {
    ml(0, 0) = ml(3, 3) = rA * l / 3.0;
    ml(0, 3) = ml(3, 0) = rA * l / 6.0;
    const double mb[4][4] = {{156, 22 * l, 54, -13 * l},
                             {22 * l, 4 * l * l, 13 * l, -3 * l * l},
                             {54, 13 * l, 156, -22 * l},
                             {-13 * l, -3 * l * l, -22 * l, 4 * l * l}};
    for (int r = 0; r < 4; ++r)
      for (int s = 0; s < 4; ++s) ml(bi[r], bi[s]) = rA * l / 420.0 * mb[r][s];
  } else {
    for (int i : {0, 1, 3, 4}) ml(i, i) = rA * l / 2.0;  // isotropic, so rotation-invariant
  }
  // Strain rows in local DOFs: axial (u2 - u1)/l; curvature v'' of the Hermite cubic at
  // the Gauss points, with N1'' = -6/l^2 + 12x/l^3, N2'' = -4/l + 6x/l^2,
  // N3'' = 6/l^2 - 12x/l^3, N4'' = -2/l + 6x/l^2 on (v1, th1, v2, th2).
  Eigen::Matrix<double, 3, 6> bl = Eigen::Matrix<double, 3, 6>::Zero();
  bl(0, 0) = -1.0 / l;
  bl(0, 3) = 1.0 / l;
  for (int g = 0; g < 2; ++g) {
    const double x = 0.5 * l * (1.0 + (g == 0 ? -1.0 : 1.0) / std::sqrt(3.0));
    bl(1 + g, 1) = -6.0 / (l * l) + 12.0 * x / (l * l * l);
    bl(1 + g, 2) = -4.0 / l + 6.0 * x / (l * l);
    bl(1 + g, 4) = 6.0 / (l * l) - 12.0 * x / (l * l * l);
    bl(1 + g, 5) = -2.0 / l + 6.0 * x / (l * l);
  }
  m.D.resize(3 * n);
  Triplets kt, mt, bt;
  for (int j = 0; j < n; ++j) {
    m.D.segment(3 * j, 3) << EA * l, EI * l / 2.0, EI * l / 2.0;
    const int a = j, b = (j + 1) % n;
    const double dx = p[b].x - p[a].x, dy = p[b].y - p[a].y, len = std::hypot(dx, dy);
    const double c = dx / len, s = dy / len;
    Eigen::Matrix<double, 6, 6> R = Eigen::Matrix<double, 6, 6>::Zero();
    for (int o : {0, 3}) {
      R(o, o) = c; R(o, o + 1) = s;
      R(o + 1, o) = -s; R(o + 1, o + 1) = c;
      R(o + 2, o + 2) = 1.0;
    }
    const Eigen::Matrix<double, 6, 6> kg = R.transpose() * kl * R, mg = R.transpose() * ml * R;
    const Eigen::Matrix<double, 3, 6> bg = bl * R;
    const std::array<int, 6> dof{3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2};
    for (int r = 0; r < 3; ++r)
      for (int s2 = 0; s2 < 6; ++s2)
        if (bg(r, s2) != 0.0) bt.emplace_back(3 * j + r, dof[s2], bg(r, s2));
    for (int r = 0; r < 6; ++r)
      for (int s2 = 0; s2 < 6; ++s2) {
        if (kg(r, s2) != 0.0) kt.emplace_back(dof[r], dof[s2], kg(r, s2));
        if (mg(r, s2) != 0.0) mt.emplace_back(dof[r], dof[s2], mg(r, s2));
      }
  }
  m.K.resize(N, N);
  m.K.setFromTriplets(kt.begin(), kt.end());
  m.M.resize(N, N);
  m.M.setFromTriplets(mt.begin(), mt.end());
  m.B.resize(3 * n, N);
  m.B.setFromTriplets(bt.begin(), bt.end());
  m.C.resize(0, N);
  m.massless.assign(N, 0);
  if (!consistent)
    for (int k = 0; k < n; ++k) m.massless[3 * k + 2] = 1;
}

/// Rows [A; extra] (extra's row indices count from 0). O(nonzeros).
SpMat stacked(const SpMat& A, const Triplets& extra, int extra_rows) {
  Triplets t;
  t.reserve(A.nonZeros() + extra.size());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SpMat::InnerIterator it(A, j); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  for (const auto& e : extra) t.emplace_back(static_cast<int>(A.rows()) + e.row(), e.col(), e.value());
  SpMat S(A.rows() + extra_rows, A.cols());
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

/// The spec's terms beyond the bare ring (terms.hpp, written once for the linear and the
/// nonlinear analyses), linearised at rest:
/// - every stiffness term (foundation, springs kx, ky, kr, the chain's clamp) is one row of B,
///   its measure's gradient at rest, with D = its stiffness (the mixed system needs D > 0: zero
///   stiffnesses add no row);
/// - point mass at node h: m on (ux_h, uy_h); J on the rotation g = grad rotation(h) at rest,
///   J g g^T (a frame's rotation with J > 0 becomes inertial: the lumped frame keeps it, not
///   condensed). The chain's rotational terms follow multibody/attachments.hpp (terms.hpp,
///   model.hpp). O(n).
void add_terms(const ring::RingSpec& spec, const std::vector<Vec2>& p, Model& m) {
  Eigen::VectorXd rest(2 * m.n);
  for (int k = 0; k < m.n; ++k) rest.segment<2>(2 * k) << p[k].x, p[k].y;
  const Terms terms(spec, m.dofs_per_node, m.anchor_deg, m.side, rest);
  const int dpn = m.dofs_per_node;
  Triplets bt, mt;
  std::vector<double> d;
  const int rows = terms.rest_rows(0, bt, d);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dpn * m.n);
  for (const Terms::Inertia& in : terms.inertia()) {
    const int h = in.node;
    mt.emplace_back(dpn * h, dpn * h, in.mass);
    mt.emplace_back(dpn * h + 1, dpn * h + 1, in.mass);
    if (in.rotary > 0.0) {
      const Measure g = terms.rotation(zero, h, false);
      for (std::size_t a = 0; a < g.dofs.size(); ++a)
        for (std::size_t b = 0; b < g.dofs.size(); ++b)
          mt.emplace_back(g.dofs[a], g.dofs[b], in.rotary * g.grad[static_cast<Eigen::Index>(a)] * g.grad[static_cast<Eigen::Index>(b)]);
      if (dpn == 3) m.massless[3 * h + 2] = 0;
    }
  }
  if (rows > 0) {
    SpMat Bx(rows, m.B.cols());
    Bx.setFromTriplets(bt.begin(), bt.end());
    const SpMat DBx = Eigen::Map<const Eigen::VectorXd>(d.data(), rows).asDiagonal() * Bx;
    m.K += SpMat(Bx.transpose() * DBx);
    m.B = stacked(m.B, bt, rows);
    m.D.conservativeResize(m.D.size() + rows);
    m.D.tail(rows) = Eigen::Map<const Eigen::VectorXd>(d.data(), rows);
  }
  if (!mt.empty()) {
    SpMat Mx(m.M.rows(), m.M.cols());
    Mx.setFromTriplets(mt.begin(), mt.end());
    m.M += Mx;
  }
}

}  // namespace

Model assemble(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  check_spec(spec, options);
  Model m;
  m.variant = options.variant;
  m.n = options.n;
  m.dofs_per_node = options.variant == ring::LumpedOptions::Variant::chain ? 2 : 3;
  m.anchor_deg = spec.supports.pin.value_or(0.0);
  m.side = 2.0 * M_PI * spec.radius / m.n;
  m.circumradius = m.side / (2.0 * std::sin(M_PI / m.n));
  m.expected_rigid = spec.rigid_modes();
  m.lambda_scale = spec.EI() / (spec.rhoA() * std::pow(spec.radius, 4));
  const std::vector<Vec2> p = polygon(m.n, m.anchor_deg, m.circumradius);
  if (options.variant == ring::LumpedOptions::Variant::chain)
    assemble_chain(spec, p, m.side, m);
  else
    assemble_frame(spec, p, m.side, options.variant == ring::LumpedOptions::Variant::frame_consistent, m);
  add_terms(spec, p, m);
  m.S = support_rows(spec, p, m.dofs_per_node, m.anchor_deg);
  return m;
}

}  // namespace lumped
