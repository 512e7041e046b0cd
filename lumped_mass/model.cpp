#include "lumped_mass/model.hpp"

#include "lumped_mass/terms.hpp"
#include "lumped_mass/checks.hpp"
#include "ring/errors.hpp"

#include <array>
#include <functional>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace lumped {
namespace {

struct Vec2 {
  double x, y;
};

/// Node positions on the regular n-gon, node k at anchor + 360 k / n degrees (an arch: its
/// n + 1 nodes at from + span k / n, ring::node_angles). O(n).
std::vector<Vec2> polygon(const ring::RingSpec& spec, int pieces, double circumradius) {
  const std::vector<double> angles = ring::node_angles(spec, pieces);
  std::vector<Vec2> p(angles.size());
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double a = angles[k] * M_PI / 180.0;
    p[k] = {circumradius * std::cos(a), circumradius * std::sin(a)};
  }
  return p;
}

void check_spec(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  check_theory(spec, options);
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
SpMat support_rows(const ring::RingSpec& spec, const std::vector<Vec2>& p, int dpn, double anchor, int cols) {
  const int n = static_cast<int>(p.size());
  const int pieces = spec.is_arch() ? n - 1 : n;
  auto node = [&](double deg, const std::string& key) { return node_at(spec, deg, pieces, key); };
  Triplets t;
  int rows = 0;
  if (spec.supports.roller && !spec.supports.pin)
    throw std::invalid_argument("supports.roller needs supports.pin");
  if (!spec.is_arch() && !spec.supports.pin && (!spec.supports.pins.empty() || spec.supports.clamp))
    throw std::invalid_argument("lumped: supports.pins and supports.clamp need supports.pin (the first pinned point)");
  for (std::size_t i = 0; i < spec.supports.pinned().size(); ++i) {
    const double a = spec.supports.pinned()[i];
    const int k = node(a, i == 0 ? "supports.pin" : "supports.pins");
    t.emplace_back(rows++, dpn * k, 1.0);
    t.emplace_back(rows++, dpn * k + 1, 1.0);
  }
  if (spec.supports.clamp) {
    const double a = *spec.supports.clamp;
    const int k = node(a, "supports.clamp");
    bool pinned = false;
    for (double q : spec.supports.pinned()) pinned = pinned || node(q, "supports.pins") == k;
    if (!pinned)
      throw std::invalid_argument("lumped: supports.clamp (= " + std::to_string(a) +
                                  " deg) must be a pinned point (supports.pin or one of supports.pins)");
    if (dpn == 3) t.emplace_back(rows++, 3 * k + 2, 1.0);
  }
  if (spec.supports.roller && spec.is_arch())
    throw std::invalid_argument("lumped: supports.roller on an arch (ring.arc) is not offered: its ends take pins, "
                                "clamps and springs");
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
  SpMat S(rows, cols);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

/// Chain: hinges at the nodes, side j is a rigid link of length l from node j to j+1.
/// An arch (m.open): the n + 1 nodes' n links, the n - 1 interior hinges (model.hpp).
void assemble_chain(const ring::RingSpec& spec, const std::vector<Vec2>& p, double l, Model& m) {
  const int n = m.n, N = 2 * n, links = m.links;
  // ring.variations (terms.hpp, written once): link j's mass from rho A over its arc, hinge j's
  // spring from the local EI at the hinge; a uniform ring: rho A l and EI / l.
  const std::vector<double> angle = ring::node_angles(spec, links);  // node k's polar angle, deg
  const double piece = (m.open ? spec.arc->to - spec.arc->from : 360.0) / links;
  std::vector<double> mass(links), k(n);
  for (int j = 0; j < links; ++j) mass[j] = piece_mass(spec, angle[j], angle[j] + piece, l);
  for (int j = 0; j < n; ++j) k[j] = hinge_spring(spec, angle[j], l);
  // Unit side vectors t_j and their left normals nu_j (t rotated by +90 deg).
  std::vector<Vec2> t(links), nu(links);
  for (int j = 0; j < links; ++j) {
    const Vec2& a = p[j];
    const Vec2& b = p[(j + 1) % n];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    t[j] = {(b.x - a.x) / len, (b.y - a.y) / len};
    nu[j] = {-t[j].y, t[j].x};
  }
  // Link lengths |P_{j+1} - P_j| = l, linearised: t_j . (u_{j+1} - u_j) = 0.
  Triplets c;
  for (int j = 0; j < links; ++j) {
    const int a = 2 * j, b = 2 * ((j + 1) % n);
    c.emplace_back(j, a, -t[j].x);
    c.emplace_back(j, a + 1, -t[j].y);
    c.emplace_back(j, b, t[j].x);
    c.emplace_back(j, b + 1, t[j].y);
  }
  m.C.resize(links, N);
  m.C.setFromTriplets(c.begin(), c.end());

  // Spring at hinge j: theta_j = atan2(a x b, a . b), a = P_j - P_{j-1} (side j-1),
  // b = P_{j+1} - P_j (side j). d theta_j = d phi(b) - d phi(a), and the direction
  // angle phi of a side vector v changes by d phi = (v x dv) / |v|^2 = nu . dv / l.
  Triplets kt, bt;
  const int first = m.open ? 1 : 0, hinges = m.open ? n - 2 : n;  // an arch's ends have no hinge spring
  for (int j = first; j < first + hinges; ++j) {
    const int jm = (j + n - 1) % n, jp = (j + 1) % n, row = j - first;
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
      bt.emplace_back(row, 2 * node[r], g[r].x);
      bt.emplace_back(row, 2 * node[r] + 1, g[r].y);
    }
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) {
        const double gr[2] = {g[r].x, g[r].y}, gs[2] = {g[s].x, g[s].y};
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) kt.emplace_back(2 * node[r] + a, 2 * node[s] + b, k[j] * gr[a] * gs[b]);
      }
  }
  m.K.resize(N, N);
  m.K.setFromTriplets(kt.begin(), kt.end());
  m.B.resize(hinges, N);
  m.B.setFromTriplets(bt.begin(), bt.end());
  m.D.resize(hinges);
  for (int j = first; j < first + hinges; ++j) m.D[j - first] = k[j];

  // Point mass at the midpoint (P_j + P_{j+1}) / 2 of side j: T = m/2 |(u_j + u_{j+1})/2|'^2.
  Triplets mt;
  for (int j = 0; j < links; ++j) {
    const int a = j, b = (j + 1) % n;
    for (int d = 0; d < 2; ++d) {
      mt.emplace_back(2 * a + d, 2 * a + d, mass[j] / 4.0);
      mt.emplace_back(2 * b + d, 2 * b + d, mass[j] / 4.0);
      mt.emplace_back(2 * a + d, 2 * b + d, mass[j] / 4.0);
      mt.emplace_back(2 * b + d, 2 * a + d, mass[j] / 4.0);
    }
  }
  m.M.resize(N, N);
  m.M.setFromTriplets(mt.begin(), mt.end());
  m.massless.assign(N, 0);
}

/// One straight two-node element in local DOFs (u1, v1, th1, u2, v2, th2), u along the side
/// from node 1 to node 2, v normal to it (left), th the rotation (ccw): its stiffness k, mass
/// m, strain rows b (energy 1/2 sum_i d_i (b x)_i^2 = 1/2 x^T k x) and the DOFs it leaves
/// without mass.
struct Element {
  Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, Eigen::Dynamic, 6> b;
  Eigen::VectorXd d;
  bool massless_rotations = false;
};

/// Local indices of the bending DOFs (v1, th1, v2, th2).
constexpr std::array<int, 4> kBend{1, 2, 4, 5};

/// Euler-Bernoulli: linear axial bar (EA), cubic Hermite bending (EI). Rows of b: axial strain
/// (u2 - u1)/l, d = EA l; curvature v'' of the Hermite cubic at the Gauss points, with
/// N1'' = -6/l^2 + 12x/l^3, N2'' = -4/l + 6x/l^2, N3'' = 6/l^2 - 12x/l^3, N4'' = -2/l + 6x/l^2
/// on (v1, th1, v2, th2), d = EI l/2 (two-point Gauss integrates the linear curvature's
/// energy exactly). Mass rho A l/2 per end on the translations (lumped, rotations massless)
/// or the consistent matrix.
Element euler_element(const Section& sec, double l, bool consistent) {
  const double EA = sec.EA, EI = sec.EI, rA = sec.rhoA;
  Element e;
  e.k(0, 0) = e.k(3, 3) = EA / l;
  e.k(0, 3) = e.k(3, 0) = -EA / l;
  const double kb[4][4] = {{12, 6 * l, -12, 6 * l},
                           {6 * l, 4 * l * l, -6 * l, 2 * l * l},
                           {-12, -6 * l, 12, -6 * l},
                           {6 * l, 2 * l * l, -6 * l, 4 * l * l}};
  for (int r = 0; r < 4; ++r)
    for (int s = 0; s < 4; ++s) e.k(kBend[r], kBend[s]) = EI / (l * l * l) * kb[r][s];
  if (consistent) {
    e.m(0, 0) = e.m(3, 3) = rA * l / 3.0;
    e.m(0, 3) = e.m(3, 0) = rA * l / 6.0;
    const double mb[4][4] = {{156, 22 * l, 54, -13 * l},
                             {22 * l, 4 * l * l, 13 * l, -3 * l * l},
                             {54, 13 * l, 156, -22 * l},
                             {-13 * l, -3 * l * l, -22 * l, 4 * l * l}};
    for (int r = 0; r < 4; ++r)
      for (int s = 0; s < 4; ++s) e.m(kBend[r], kBend[s]) = rA * l / 420.0 * mb[r][s];
  } else {
    for (int i : {0, 1, 3, 4}) e.m(i, i) = rA * l / 2.0;  // isotropic, so rotation-invariant
    e.massless_rotations = true;
  }
  e.b = Eigen::Matrix<double, 3, 6>::Zero();
  e.b(0, 0) = -1.0 / l;
  e.b(0, 3) = 1.0 / l;
  for (int g = 0; g < 2; ++g) {
    const double x = 0.5 * l * (1.0 + (g == 0 ? -1.0 : 1.0) / std::sqrt(3.0));
    e.b(1 + g, 1) = -6.0 / (l * l) + 12.0 * x / (l * l * l);
    e.b(1 + g, 2) = -4.0 / l + 6.0 * x / (l * l);
    e.b(1 + g, 4) = 6.0 / (l * l) - 12.0 * x / (l * l * l);
    e.b(1 + g, 5) = -2.0 / l + 6.0 * x / (l * l);
  }
  e.d.resize(3);
  e.d << EA * l, EI * l / 2.0, EI * l / 2.0;
  return e;
}

/// Timoshenko: Przemieniecki's element (Theory of Matrix Structural Analysis, 1968, sec. 5.6),
/// the exact static solution of a straight shear-flexible beam without span load, with
/// phi = 12 EI / (kappa G A l^2): on (v1, th1, v2, th2)
///   k = EI / ((1 + phi) l^3) [12, 6l, -12, 6l; 6l, (4 + phi) l^2, -6l, (2 - phi) l^2; ...],
/// th the rotation of the cross-section. Its energy in the element's two deformations, with
/// beta = (v2 - v1)/l the chord rotation, s = (th1 + th2)/2 - beta and d = th2 - th1:
/// curvature th' = d/l - 6 s (1 - 2x/l) / (l (1 + phi)) (linear), shear strain
/// gamma = th - v' = phi s / (1 + phi) (constant). Rows of b: axial strain (d = EA l), the
/// curvature at the two Gauss points (d = EI l/2, exact for its square), the shear strain
/// (d = kappa G A l): 1/2 b^T d b equals k (tests/lumped_mass/timoshenko_test.cpp checks it).
/// phi -> 0 gives the Hermite element exactly and the shear row's energy 6 EI phi s^2 /
/// (l (1 + phi)^2) vanishes with phi: no shear locking, whatever the slenderness.
/// Mass lumped (row sum): rho A l/2 per end on the translations and rho I l/2 on the
/// rotations (the section's rotary inertia; every DOF inertial, none condensed).
Element timoshenko_element(const Section& sec, double l) {
  const double EA = sec.EA, EI = sec.EI, kGA = sec.kGA;
  const double phi = 12.0 * EI / (kGA * l * l);
  Element e;
  e.k(0, 0) = e.k(3, 3) = EA / l;
  e.k(0, 3) = e.k(3, 0) = -EA / l;
  const double kb[4][4] = {{12, 6 * l, -12, 6 * l},
                           {6 * l, (4 + phi) * l * l, -6 * l, (2 - phi) * l * l},
                           {-12, -6 * l, 12, -6 * l},
                           {6 * l, (2 - phi) * l * l, -6 * l, (4 + phi) * l * l}};
  for (int r = 0; r < 4; ++r)
    for (int s = 0; s < 4; ++s) e.k(kBend[r], kBend[s]) = EI / ((1.0 + phi) * l * l * l) * kb[r][s];
  for (int i : {0, 1, 3, 4}) e.m(i, i) = sec.rhoA * l / 2.0;
  for (int i : {2, 5}) e.m(i, i) = sec.rhoI * l / 2.0;
  // s and d on (v1, th1, v2, th2).
  const double s[4] = {1.0 / l, 0.5, -1.0 / l, 0.5}, d[4] = {0.0, -1.0, 0.0, 1.0};
  e.b = Eigen::Matrix<double, 4, 6>::Zero();
  e.b(0, 0) = -1.0 / l;
  e.b(0, 3) = 1.0 / l;
  for (int g = 0; g < 2; ++g) {
    const double slope = -6.0 * (g == 0 ? 1.0 : -1.0) / std::sqrt(3.0) / (l * (1.0 + phi));  // 1 - 2x/l = +-1/sqrt 3
    for (int r = 0; r < 4; ++r) e.b(1 + g, kBend[r]) = d[r] / l + slope * s[r];
  }
  for (int r = 0; r < 4; ++r) e.b(3, kBend[r]) = phi / (1.0 + phi) * s[r];
  e.d.resize(4);
  e.d << EA * l, EI * l / 2.0, EI * l / 2.0, kGA * l;
  return e;
}

/// Frame: element j on side j from node j to j+1, the element `element(j)` rotated into the global
/// DOFs: global = R^T local R with R = blockdiag(r, r), r = [[c, s, 0], [-s, c, 0], [0, 0, 1]].
/// O(n).
void assemble_frame(const std::function<Element(int)>& element, const std::vector<Vec2>& p, Model& m) {
  const int n = m.n, N = 3 * n, rows = static_cast<int>(element(0).b.rows());
  m.D.resize(rows * n);
  Triplets kt, mt, bt;
  bool massless_rotations = false;
  for (int j = 0; j < n; ++j) {
    const Element e = element(j);
    massless_rotations = e.massless_rotations;
    m.D.segment(rows * j, rows) = e.d;
    const int a = j, b = (j + 1) % n;
    const double dx = p[b].x - p[a].x, dy = p[b].y - p[a].y, len = std::hypot(dx, dy);
    const double c = dx / len, s = dy / len;
    Eigen::Matrix<double, 6, 6> R = Eigen::Matrix<double, 6, 6>::Zero();
    for (int o : {0, 3}) {
      R(o, o) = c; R(o, o + 1) = s;
      R(o + 1, o) = -s; R(o + 1, o + 1) = c;
      R(o + 2, o + 2) = 1.0;
    }
    const Eigen::Matrix<double, 6, 6> kg = R.transpose() * e.k * R, mg = R.transpose() * e.m * R;
    const Eigen::Matrix<double, Eigen::Dynamic, 6> bg = e.b * R;
    const std::array<int, 6> dof{3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2};
    for (int r = 0; r < rows; ++r)
      for (int s2 = 0; s2 < 6; ++s2)
        if (bg(r, s2) != 0.0) bt.emplace_back(rows * j + r, dof[s2], bg(r, s2));
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
  m.B.resize(rows * n, N);
  m.B.setFromTriplets(bt.begin(), bt.end());
  m.C.resize(0, N);
  m.massless.assign(N, 0);
  if (massless_rotations)
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
///   model.hpp);
/// - the chain's hinge h with a point inertia (Terms::hinge_rotations) gets its rotation chi
///   as an unknown after the node DOFs (model.hpp). Its half springs 2K from each link's
///   chord rotation phi_a, phi_b to chi are, with theta_h = phi_b - phi_a and the chord
///   rotation m_h = (phi_a + phi_b) / 2,
///     K (phi_a - chi)^2 + K (phi_b - chi)^2 = K theta_h^2 / 2 + 4K (m_h - chi)^2 / 2,
///   so the hinge's row theta_h (D = K) stays and one row m_h - chi with D = 4K joins it
///   (the same energy as two rows phi - chi with D = 2K, and B keeps one row per hinge);
///   kr is a row on chi (D = kr): the gradients at rest of Terms::split's measures. J is
///   chi's mass. O(n).
void add_terms(const ring::RingSpec& spec, const std::vector<Vec2>& p, Model& m) {
  Eigen::VectorXd rest(2 * m.n);
  for (int k = 0; k < m.n; ++k) rest.segment<2>(2 * k) << p[k].x, p[k].y;
  const Terms terms(spec, m.dofs_per_node, m.anchor_deg, m.side, rest);
  const int dpn = m.dofs_per_node;
  Triplets bt, mt;
  std::vector<double> d;
  int rows = terms.rest_rows(0, bt, d);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dpn * m.n);
  const int N0 = dpn * m.n, N = N0 + static_cast<int>(terms.hinge_rotations().size());
  if (N > N0) {
    m.K.conservativeResize(N, N);
    m.M.conservativeResize(N, N);
    m.B.conservativeResize(m.B.rows(), N);
    m.C.conservativeResize(m.C.rows(), N);
    m.massless.resize(N, 0);  // chi carries J
  }
  for (std::size_t i = 0; i < terms.hinge_rotations().size(); ++i) {
    const int chi = N0 + static_cast<int>(i);
    for (const Terms::Split& sp : terms.split(zero, i, 0.0, chi, false)) {  // m_h - chi (4K), chi (kr)
      for (std::size_t a = 0; a < sp.r.dofs.size(); ++a)
        bt.emplace_back(rows, sp.r.dofs[a], sp.r.grad[static_cast<Eigen::Index>(a)]);
      d.push_back(sp.k);
      ++rows;
    }
    mt.emplace_back(chi, chi, terms.hinge_rotations()[i].inertia);
  }
  for (const Terms::Inertia& in : terms.inertia()) {
    const int h = in.node;
    mt.emplace_back(dpn * h, dpn * h, in.mass);
    mt.emplace_back(dpn * h + 1, dpn * h + 1, in.mass);
    if (in.rotary > 0.0) {  // the frames' (the chain's J is chi's mass, above)
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

NaturalStiffness natural_stiffness(const ring::RingSpec& spec, double l, ring::LumpedOptions::Variant variant) {
  using Variant = ring::LumpedOptions::Variant;
  if (variant == Variant::chain) throw std::invalid_argument("lumped: the chain has no frame element");
  const Section sec{spec.EA(), spec.EI(), spec.rhoA(), spec.rhoI(), spec.kGA()};  // uniform (the corotational frame)
  const Element e = variant == Variant::timoshenko_frame ? timoshenko_element(sec, l) : euler_element(sec, l, false);
  NaturalStiffness k;
  k.axial = e.k(0, 0);
  k.bending << e.k(2, 2), e.k(2, 5), e.k(5, 2), e.k(5, 5);
  return k;
}

Model assemble(const ring::RingSpec& spec, const ring::LumpedOptions& options) {
  check_spec(spec, options);
  Model m;
  m.variant = options.variant;
  m.open = spec.is_arch();
  if (m.open && options.variant != ring::LumpedOptions::Variant::chain)
    throw ring::InputError("", "ring.arc", "lumped: lumped.variant = \"" + ring::to_string(options.variant) +
                                               "\" does not take an arch (ring.arc) yet; use lumped.variant = \"chain\"");
  m.links = options.n;
  m.n = options.n + (m.open ? 1 : 0);
  m.dofs_per_node = options.variant == ring::LumpedOptions::Variant::chain ? 2 : 3;
  m.anchor_deg = spec.anchor();
  const double angle = spec.opening();  // the centroid line's, rad
  m.side = angle * spec.radius / m.links;
  m.circumradius = m.side / (2.0 * std::sin(0.5 * angle / m.links));
  m.expected_rigid = spec.rigid_modes();
  m.lambda_scale = spec.EI() / (spec.rhoA() * std::pow(spec.radius, 4));
  const std::vector<Vec2> p = polygon(spec, m.links, m.circumradius);
  using Variant = ring::LumpedOptions::Variant;
  // ring.variations in the frames: element j's section at its midpoint's polar angle (the
  // midpoint rule over the element, O(l^2) per element, the frames' order; terms.hpp).
  const double l = m.side, step = 360.0 / m.links, mid0 = m.anchor_deg + 0.5 * step;
  const auto section = [&](int j) { return section_at(spec, mid0 + step * j); };
  switch (options.variant) {
    case Variant::chain: assemble_chain(spec, p, m.side, m); break;
    case Variant::frame: assemble_frame([&](int j) { return euler_element(section(j), l, false); }, p, m); break;
    case Variant::frame_consistent:
      assemble_frame([&](int j) { return euler_element(section(j), l, true); }, p, m);
      break;
    case Variant::timoshenko_frame: assemble_frame([&](int j) { return timoshenko_element(section(j), l); }, p, m); break;
  }
  add_terms(spec, p, m);
  m.S = support_rows(spec, p, m.dofs_per_node, m.anchor_deg, static_cast<int>(m.K.cols()));
  return m;
}

}  // namespace lumped
