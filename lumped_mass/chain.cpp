#include "lumped_mass/chain.hpp"

#include <cmath>
#include <stdexcept>

#include "lumped_mass/model.hpp"

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Vec2 = Eigen::Vector2d;
using Sparse = Eigen::SparseMatrix<double>;
constexpr double kPi = 3.14159265358979323846;

}  // namespace

Chain make_chain(const ring::RingSpec& spec, const ring::LumpedOptions& o) {
  Chain c;
  c.open = spec.is_arch();
  c.n = o.n + (c.open ? 1 : 0);
  const double angle = spec.opening();  // the centroid line's, rad
  c.step_deg = angle / o.n * 180.0 / kPi;
  c.l = angle * spec.radius / o.n;
  c.k = spec.EI() / c.l;
  c.m = spec.rhoA() * c.l;
  c.rho = c.l / (2.0 * std::sin(0.5 * angle / o.n));
  c.theta0 = angle / o.n;
  c.depth = spec.section.depth();
  c.anchor_deg = spec.anchor();
  // The linear model checks every point of the spec (a node, the clamp at a pinned point,
  // the roller apart from the pin) and gives the support rows: one code for both analyses.
  c.S = assemble(spec, o).S;
  c.rest.resize(2 * c.n);
  const auto angles = ring::node_angles(spec, o.n);
  for (int j = 0; j < c.n; ++j) {
    c.rest[2 * j] = c.rho * std::cos(angles[j] * kPi / 180.0);
    c.rest[2 * j + 1] = c.rho * std::sin(angles[j] * kPi / 180.0);
  }
  c.terms.emplace(spec, 2, c.anchor_deg, c.l, c.rest);
  c.bending = Bending(spec, c.n, c.l, c.k);
  return c;
}

Sparse with_point_rows(const Sparse& S, int dof) {
  Triplets t;
  for (int col = 0; col < S.outerSize(); ++col)
    for (Sparse::InnerIterator it(S, col); it; ++it) t.emplace_back(static_cast<int>(it.row()), col, it.value());
  const int r = static_cast<int>(S.rows());
  t.emplace_back(r, dof, 1.0);
  t.emplace_back(r + 1, dof + 1, 1.0);
  Sparse out(r + 2, S.cols());
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

void drive(Chain& c, int hinge, const Vec2& value) {
  c.S = with_point_rows(c.S, 2 * hinge);
  c.driven = hinge;
  c.drive = value;
}

Vec constraint_rate(const Chain& c) {
  Vec r = Vec::Zero(c.rows());
  if (c.driven >= 0) r.tail(2) = -c.drive;
  return r;
}

void hold_plates(Chain& c, const ring::RingSpec& spec, const ring::StaticOptions::Plates& plates) {
  c.plates.emplace(spec, plates);
  c.plate_nodes = {c.hinge(plates.axis), c.hinge(plates.axis + 180.0)};
  // The no-slide rows, roller-like: e . (x_k - X_k) = 0, e = (-sin axis, cos axis).
  const Vec2 e(-c.plates->d[1], c.plates->d[0]);
  Triplets t;
  for (int col = 0; col < c.S.outerSize(); ++col)
    for (Sparse::InnerIterator it(c.S, col); it; ++it) t.emplace_back(static_cast<int>(it.row()), col, it.value());
  const int r = static_cast<int>(c.S.rows());
  for (int p = 0; p < 2; ++p) {
    t.emplace_back(r + p, 2 * c.plate_nodes[p], e.x());
    t.emplace_back(r + p, 2 * c.plate_nodes[p] + 1, e.y());
  }
  // The centre row d_0 . (u_a + u_b) = 0: the midpoint of the two points stays on the plates'
  // midline. While the ring touches both plates their penalty holds it there (the multiplier
  // ~0 by symmetry), but a ring that has sprung back clear of them on unloading is free
  // along d_0, and the tangent would be singular.
  for (int p = 0; p < 2; ++p) {
    t.emplace_back(r + 2, 2 * c.plate_nodes[p], c.plates->d[0]);
    t.emplace_back(r + 2, 2 * c.plate_nodes[p] + 1, c.plates->d[1]);
  }
  Sparse S(r + 3, 2 * c.n);
  S.setFromTriplets(t.begin(), t.end());
  c.S = S;
}

Vec2 plate_point(const Chain& c, const Vec& x, int j) {
  return c.at(x, j) - (1.0 - c.plates->R / c.rho) * c.at(c.rest, j);
}

void add_plates(const Chain& c, const Vec& x, double s, double hess_scale, Springs& out) {
  if (!c.plates) return;
  const ring::PlatePair& pp = *c.plates;
  for (int j = 0; j < c.n; ++j) {
    const Vec2 p = plate_point(c, x, j);
    for (int plate = 0; plate < 2; ++plate) {
      const double sign = plate == 0 ? 1.0 : -1.0;
      const Vec2 d(sign * pp.d[0], sign * pp.d[1]);
      const double g = pp.gap(plate, p.x(), p.y(), s);
      out.energy += c.l * pp.energy(g);
      out.grad.segment<2>(2 * j) += c.l * pp.pressure(g) * d;
      if (hess_scale != 0.0 && pp.in_contact(g))
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) out.hess.emplace_back(2 * j + a, 2 * j + b, hess_scale * c.l * pp.k * d[a] * d[b]);
    }
  }
}

Vec plate_rate(const Chain& c, const Vec& x, double s) {
  Vec r = Vec::Zero(2 * c.n);
  if (!c.plates) return r;
  const ring::PlatePair& pp = *c.plates;
  for (int j = 0; j < c.n; ++j) {
    const Vec2 p = plate_point(c, x, j);
    for (int plate = 0; plate < 2; ++plate) {
      const double sign = plate == 0 ? 1.0 : -1.0;
      if (pp.in_contact(pp.gap(plate, p.x(), p.y(), s)))
        r.segment<2>(2 * j) += c.l * pp.k * 0.5 * pp.travel * Vec2(sign * pp.d[0], sign * pp.d[1]);
    }
  }
  return r;
}

std::array<double, 2> plate_loads(const Chain& c, const Vec& x, double s) {
  std::array<double, 2> f{0.0, 0.0};
  if (!c.plates) return f;
  for (int j = 0; j < c.n; ++j) {
    const Vec2 p = plate_point(c, x, j);
    for (int plate = 0; plate < 2; ++plate) f[plate] += c.l * c.plates->pressure(c.plates->gap(plate, p.x(), p.y(), s));
  }
  return f;
}

std::array<double, 2> plate_contact_lengths(const Chain& c, const Vec& x, double s) {
  if (!c.plates) return {0.0, 0.0};
  std::vector<double> px(c.n), py(c.n);
  for (int j = 0; j < c.n; ++j) {
    const Vec2 p = plate_point(c, x, j);
    px[j] = p.x();
    py[j] = p.y();
  }
  return c.plates->contact_lengths(px, py, s);
}

Turn turn(const Chain& c, const Vec& x, int j, bool with_hessian) {
  const Vec2 a = c.at(x, j) - c.at(x, j - 1), b = c.at(x, j + 1) - c.at(x, j);
  Turn t;
  t.theta = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  const Vec2 ga = angle_gradient(a), gb = angle_gradient(b);
  // theta = angle(b) - angle(a); a = x_j - x_{j-1}, b = x_{j+1} - x_j.
  t.grad << ga, -ga - gb, gb;
  if (with_hessian) {
    const Eigen::Matrix2d Ha = angle_hessian(a), Hb = angle_hessian(b);
    t.hess.setZero();
    // - A^T Ha A with A = [-I, I, 0]; + B^T Hb B with B = [0, -I, I].
    t.hess.block<2, 2>(0, 0) -= Ha;
    t.hess.block<2, 2>(0, 2) += Ha;
    t.hess.block<2, 2>(2, 0) += Ha;
    t.hess.block<2, 2>(2, 2) -= Ha;
    t.hess.block<2, 2>(2, 2) += Hb;
    t.hess.block<2, 2>(2, 4) -= Hb;
    t.hess.block<2, 2>(4, 2) -= Hb;
    t.hess.block<2, 2>(4, 4) += Hb;
  }
  return t;
}

int dof(const Chain& c, int j, int i) {
  const int h = (((j - 1 + i / 2) % c.n) + c.n) % c.n;
  return 2 * h + i % 2;
}

void add_terms(const Terms& terms, const Vec& u, double hess_scale, Springs& s, HingeRotations hinges) {
  if (!terms.any_stiffness()) return;
  s.energy += terms.energy(u, hinges);
  terms.add_gradient(u, s.grad, hinges);
  if (hess_scale != 0.0) terms.add_hessian(u, hess_scale, s.hess, hinges);
}

std::array<double, 2> ground_force(const Eigen::SparseMatrix<double>& S, const Vec& mu, const Terms& terms,
                                   const Vec& u, int dofs_per_node) {
  Vec ground = Vec::Zero(u.size());
  if (S.rows() > 0) ground -= S.transpose() * mu;
  if (terms.any_stiffness()) {
    Vec g = Vec::Zero(u.size());
    terms.add_gradient(u, g);
    ground -= g;
  }
  std::array<double, 2> f{0.0, 0.0};
  for (Eigen::Index j = 0; j < u.size(); j += dofs_per_node) {
    f[0] += ground[j];
    f[1] += ground[j + 1];
  }
  return f;
}

Springs springs(const Chain& c, const Vec& q, double hess_scale, bool hinges) {
  const int N = 2 * c.n;
  const auto& hr = c.terms->hinge_rotations();
  const bool own = q.size() > N;
  if (own && q.size() != N + static_cast<Eigen::Index>(hr.size()))
    throw std::logic_error("lumped::springs: q has " + std::to_string(q.size()) + " values, not 2n (" +
                           std::to_string(N) + ") or 2n + hinge rotations (" + std::to_string(N + hr.size()) + ")");
  Springs s;
  s.grad = Vec::Zero(q.size());
  const Vec u = q.head(N) - c.rest;
  add_terms(*c.terms, u, hess_scale, s, own ? HingeRotations::unknowns : HingeRotations::condensed);
  if (own)
    for (std::size_t i = 0; i < hr.size(); ++i) {
      const int chi = N + static_cast<int>(i);
      for (const Terms::Split& sp : c.terms->split(u, i, q[chi], chi, hess_scale != 0.0))
        add_spring(sp.r, sp.k, &s.energy, &s.grad, hess_scale, &s.hess);
    }
  for (int j = 0; hinges && j < c.n; ++j) {
    if (!c.has_spring(j)) continue;
    const Turn t = turn(c, q, j, hess_scale != 0.0);
    const double e = t.theta - c.theta0;
    const ring::BilinearLaw::Point m = c.bending.at(j, e);
    s.energy += m.potential;
    for (int i = 0; i < 6; ++i) s.grad[dof(c, j, i)] += m.force * t.grad[i];
    if (hess_scale != 0.0) {
      // tangent grad grad^T + M Hess theta; inside the band M = k (e - e_p), written as the
      // elastic spring always was, k (grad grad^T + (e - e_p) Hess theta), so that an elastic
      // chain's tangent is bit for bit the same (the frontal count of unstable directions near a
      // bifurcation is sensitive to its rounding: bifurcation_test.cpp).
      // The fibre law has no single plastic rotation: its moment and tangent, always.
      const Eigen::Matrix<double, 6, 6> H =
          m.yielding || c.bending.fibre()
              ? Eigen::Matrix<double, 6, 6>(m.tangent * t.grad * t.grad.transpose() + m.force * t.hess)
                     : Eigen::Matrix<double, 6, 6>(m.tangent * (t.grad * t.grad.transpose() + (e - c.bending.plastic(j)) * t.hess));
      for (int i = 0; i < 6; ++i)
        for (int p = 0; p < 6; ++p) s.hess.emplace_back(dof(c, j, i), dof(c, j, p), hess_scale * H(i, p));
    }
  }
  return s;
}

std::vector<double> bending_strains(const Chain& c, const Vec& x) {
  std::vector<double> e(static_cast<std::size_t>(c.n));
  for (int j = 0; j < c.n; ++j)
    e[static_cast<std::size_t>(j)] = c.has_spring(j) ? turn(c, x, j, false).theta - c.theta0 : 0.0;
  return e;
}

Vec relaxed_rotations(const Chain& c, const Vec& x) {
  const int N = 2 * c.n;
  const auto& hr = c.terms->hinge_rotations();
  Vec chi(static_cast<Eigen::Index>(hr.size()));
  const Vec u = x.head(N) - c.rest;
  for (std::size_t i = 0; i < hr.size(); ++i) {
    // The split springs are quadratic in chi: one Newton step from chi = 0 is the minimum.
    double g = 0.0, h = 0.0;
    for (const Terms::Split& sp : c.terms->split(u, i, 0.0, N, false))
      for (std::size_t a = 0; a < sp.r.dofs.size(); ++a)
        if (sp.r.dofs[a] == N) {
          g += sp.k * sp.r.value * sp.r.grad[static_cast<Eigen::Index>(a)];
          h += sp.k * sp.r.grad[static_cast<Eigen::Index>(a)] * sp.r.grad[static_cast<Eigen::Index>(a)];
        }
    chi[static_cast<Eigen::Index>(i)] = -g / h;
  }
  return chi;
}

Springs tangent(const Chain& c, const ChainLoads& loads, const Vec& q, const Vec& lambda, double s, double scale,
                bool hinges) {
  Springs t = springs(c, q, scale, hinges);
  if (c.plates) {  // the statics' only (their q is x); s moves the plates
    Springs p;
    p.grad = Vec::Zero(2 * c.n);
    add_plates(c, q.head(2 * c.n), s, scale, p);
    t.energy += p.energy;
    t.grad.head(2 * c.n) += p.grad;
    t.hess.insert(t.hess.end(), p.hess.begin(), p.hess.end());
  }
  constraint_hessian(c, lambda, scale, t.hess);
  loads.add_hessian(q.head(2 * c.n), scale * s, t.hess);
  return t;
}

Vec constraints(const Chain& c, const Vec& x) {
  Vec g(c.rows());
  for (int j = 0; j < c.links(); ++j) g[j] = ((c.at(x, j + 1) - c.at(x, j)).squaredNorm() - c.l * c.l) / (2.0 * c.l);
  if (c.S.rows() > 0) g.tail(c.S.rows()) = c.S * (x - c.rest);
  return g;
}

void jacobian(const Chain& c, const Vec& x, int row_offset, double scale, bool transpose, Triplets& out) {
  auto put = [&](int r, int col, double v) {
    if (transpose) out.emplace_back(col, row_offset + r, scale * v);
    else out.emplace_back(row_offset + r, col, scale * v);
  };
  for (int j = 0; j < c.links(); ++j) {
    const Vec2 d = (c.at(x, j + 1) - c.at(x, j)) / c.l;
    const int a = 2 * j, b = 2 * ((j + 1) % c.n);
    put(j, a, -d.x());
    put(j, a + 1, -d.y());
    put(j, b, d.x());
    put(j, b + 1, d.y());
  }
  for (int col = 0; col < c.S.outerSize(); ++col)
    for (Sparse::InnerIterator it(c.S, col); it; ++it) put(c.links() + static_cast<int>(it.row()), col, it.value());
}

void constraint_hessian(const Chain& c, const Vec& lambda, double scale, Triplets& out) {
  for (int j = 0; j < c.links(); ++j) {
    const double w = scale * lambda[j] / c.l;
    const int a = 2 * j, b = 2 * ((j + 1) % c.n);
    for (int d = 0; d < 2; ++d) {
      out.emplace_back(a + d, a + d, w);
      out.emplace_back(b + d, b + d, w);
      out.emplace_back(a + d, b + d, -w);
      out.emplace_back(b + d, a + d, -w);
    }
  }
}

Sparse mass_matrix(const Chain& c, HingeRotations hinges) {
  const auto& hr = c.terms->hinge_rotations();
  const int N = 2 * c.n, Q = hinges == HingeRotations::unknowns ? N + static_cast<int>(hr.size()) : N;
  Triplets t;
  for (const Terms::Inertia& in : c.terms->inertia())
    for (int d = 0; d < 2; ++d) t.emplace_back(2 * in.node + d, 2 * in.node + d, in.mass);
  for (int j = 0; j < c.links(); ++j) {
    const int a = 2 * j, b = 2 * ((j + 1) % c.n);
    for (int d = 0; d < 2; ++d)
      for (int p : {a + d, b + d})
        for (int q : {a + d, b + d}) t.emplace_back(p, q, c.m / 4.0);
  }
  for (int i = 0; N + i < Q; ++i) t.emplace_back(N + i, N + i, hr[static_cast<std::size_t>(i)].inertia);
  Sparse M(Q, Q);
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

std::vector<int> load_hinges(const Chain& c, const ring::RingSpec& spec, const ring::Loads& loads,
                             const std::string& section) {
  std::vector<int> h;
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const ring::PointLoad& load = loads.points[i];
    const std::string key = loads.points.size() == 1 ? section + ".at" : section + ".loads[" + std::to_string(i + 1) + "].at";
    if (c.open) {
      h.push_back(node_at(spec, load.angle, c.n - 1, key));
      for (double p : spec.supports.pinned())
        if (node_at(spec, p, c.n - 1, "supports.pins") == h.back())
          throw std::invalid_argument("lumped: " + key + " acts at a pinned end of the arch");
      continue;
    }
    if (!ring::on_node(load.angle, c.anchor_deg, c.n))
      throw std::invalid_argument("lumped: " + key + " (=" + std::to_string(load.angle) + ") is not a hinge of the chain");
    h.push_back(c.hinge(load.angle));
    if (spec.supports.pin && h.back() == 0) throw std::invalid_argument("lumped: " + key + " acts at the pin");
  }
  return h;
}

}  // namespace lumped
