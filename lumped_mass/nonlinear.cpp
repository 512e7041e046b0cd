#include "lumped_mass/nonlinear.hpp"

#include "lumped_mass/chain.hpp"
#include "lumped_mass/checks.hpp"
#include "lumped_mass/frame.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/midpoint.hpp"
#include "lumped_mass/model.hpp"
#include "lumped_mass/stability.hpp"
#include "lumped_mass/terms.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "paths/continuation.hpp"
#include "paths/time_stepping.hpp"
#include "ring/energy_guard.hpp"
#include "ring/errors.hpp"

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Vec2 = Eigen::Vector2d;
using Sparse = Eigen::SparseMatrix<double>;

/// Distance from the point p to the segment [a, b]. O(1).
double point_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

/// Distance between the segments [a, b] and [c, d]: 0 when they cross, else the least of
/// the four endpoint-to-segment distances. O(1).
double segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
}

}  // namespace

Contact closest_nonadjacent(const Chain& c, const Vec& x) {
  const int gap = 2 + static_cast<int>(std::floor(2.0 * c.depth / c.l));
  const double cell = c.l + c.depth;
  std::unordered_map<long long, std::vector<int>> grid;
  auto key = [&](long long gx, long long gy) { return gx * 1000003LL + gy; };
  auto mid = [&](int j) -> Vec2 { return 0.5 * (c.at(x, j) + c.at(x, j + 1)); };
  const int links = c.links();
  for (int j = 0; j < links; ++j) {
    const Vec2 p = mid(j);
    grid[key(std::floor(p.x() / cell), std::floor(p.y() / cell))].push_back(j);
  }
  Contact best;
  if (2 * gap > c.n) return best;
  for (int j = 0; j < links; ++j) {
    const Vec2 p = mid(j);
    const long long gx = std::floor(p.x() / cell), gy = std::floor(p.y() / cell);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = grid.find(key(gx + dx, gy + dy));
        if (it == grid.end()) continue;
        for (int i : it->second) {
          // Along the chain: around the ring either way, along an arch (no closing link) one way.
          const int sep = c.open ? i - j : std::min((i - j + c.n) % c.n, (j - i + c.n) % c.n);
          if (i <= j || sep < gap) continue;
          const double d = segment_distance(c.at(x, j), c.at(x, j + 1), c.at(x, i), c.at(x, i + 1));
          if (d < best.distance) best = {d, j, i};
        }
      }
  }
  return best;
}

bool factor_bordered(Triplets t, int size, const Vec& b, const Vec& w, double ws,
                     Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>>& lu) {
  for (int i = 0; i < size; ++i) {
    if (b[i] != 0.0) t.emplace_back(i, size, b[i]);
    if (w[i] != 0.0) t.emplace_back(size, i, w[i]);
  }
  t.emplace_back(size, size, ws);
  Sparse A(size + 1, size + 1);
  A.setFromTriplets(t.begin(), t.end());
  lu.compute(A);
  return lu.info() == Eigen::Success;
}

std::string contact_where(const Chain& c, const Contact& k) {
  std::ostringstream s;
  s << "links " << k.i << " and " << k.j << " come within " << k.distance << " m (section depth " << c.depth << " m)";
  return s.str();
}

namespace {

std::vector<int> record_hinges(const Chain& c, const ring::RingSpec& spec, const std::vector<double>& record,
                               const std::string& key) {
  std::vector<int> h;
  for (double a : record) {
    if (c.open) {
      h.push_back(node_at(spec, a, c.n - 1, key));
      continue;
    }
    if (!ring::on_node(a, c.anchor_deg, c.n))
      throw std::invalid_argument("lumped: " + key + " angle " + std::to_string(a) + " is not a hinge of the chain");
    h.push_back(c.hinge(a));
  }
  return h;
}


}  // namespace

namespace {

/// The chain's equilibrium grad V(x) + G(x)^T lambda + s grad P(x) = 0, c(x) = 0 for the
/// continuation driver (paths/continuation.hpp), P the loads' potential (loads.hpp).
/// Unknowns z = (x, lambda), lambda in units of `scale` = EI / l^3 (the constraint rows and
/// columns scaled to the stiffness, so that the KKT matrix is balanced for the LU's
/// pivoting); the bordered KKT matrix [A + s Hess P, grad P; w^T ws] by one sparse LU (its
/// pattern: the band, the closing corners, the border's row and column; the border column
/// is full once a pressure or gravity acts).
///
/// ring.plastic: the hinge springs' law (bending.hpp) lives in this equilibrium's own copy of
/// the chain, whose states accept() commits; every linearization and stability count between
/// two accepted equilibria is the return map from the last committed states. An elastic
/// chain is not copied (its law has no state): the statics' memory is what it was.
class ChainStatics : public paths::Equilibrium {
 public:
  ChainStatics(const Chain& c, const ChainLoads& loads, double scale, double radius, InertiaRoute route)
      : own_(c.bending.plastic() ? std::optional<Chain>(c) : std::nullopt),
        c_(own_ ? *own_ : c),
        L_(loads),
        N_(2 * c.n),
        E_(c.plates ? 1 : 0),
        S_(2 * c.n + E_ + c.rows()),
        scale_(scale),
        radius_(radius),
        route_(route) {}
  ChainStatics(const ChainStatics&) = delete;  // c_ may refer to own_
  ChainStatics& operator=(const ChainStatics&) = delete;
  Eigen::Index size() const override { return S_; }
  /// The positions, and with [plates] their advance a (below): a ring that has sprung back clear
  /// of the plates on unloading stands still while s falls, and an arc measured on the positions
  /// alone could not step on.
  Eigen::Index arc_size() const override { return N_ + E_; }
  bool linearize(const paths::State& s, const paths::Vector& w, double ws, paths::Vector& r) override {
    const Vec x = s.z.head(N_), lambda = multipliers(s.z);
    const Springs sp = tangent(c_, L_, x, lambda * scale_, s.s, 1.0);
    Triplets t = sp.hess;
    const int M = N_ + E_;  // the first multiplier's row
    jacobian(c_, x, M, scale_, true, t);
    jacobian(c_, x, M, scale_, false, t);
    Triplets gt;
    jacobian(c_, x, 0, 1.0, true, gt);
    Sparse GT(N_, S_ - M);
    GT.setFromTriplets(gt.begin(), gt.end());
    r.resize(S_);
    const Vec gP = L_.gradient(x);
    // A driven point (static.displacement): its rows S (x - rest) - s drive, whose change with
    // s is the load column's constraint part (constraint_rate); no loads act then (gP = 0).
    const Vec rate = constraint_rate(c_);
    r.head(N_) = sp.grad + GT * (lambda * scale_) + s.s * gP;
    r.tail(S_ - M) = scale_ * (constraints(c_, x) + s.s * rate);
    Vec b = Vec::Zero(S_), wz = Vec::Zero(S_);
    b.head(N_) = gP;
    b.tail(S_ - M) = scale_ * rate;
    if (c_.plates) {
      // Their penalty is in sp (tangent()), its change with s in the load column; and the
      // plates' advance a = s travel / 2 is an unknown of its own (row N_: scale (a - s travel / 2)),
      // which the arc measures with the positions.
      b.head(N_) += plate_rate(c_, x, s.s);
      const double half = 0.5 * c_.plates->travel;
      r[N_] = scale_ * (s.z[N_] - s.s * half);
      t.emplace_back(N_, N_, scale_);
      b[N_] = -scale_ * half;
    }
    wz.head(M) = w.head(M);
    return factor_bordered(std::move(t), S_, b, wz, ws, lu_) && r.allFinite();
  }
  bool solve(paths::Vector& y) override {
    y = lu_.solve(y).eval();
    return y.allFinite();
  }
  /// The largest change of a link's direction, |dx_{j+1} - dx_j| / l (rad, to first
  /// order), against half a radian: a rigid motion moves nothing, and the bound does not
  /// shrink with the links.
  double move(const paths::Vector& dz) const override {
    double turn = 0.0;
    for (int j = 0; j < c_.links(); ++j) {
      const int k = (j + 1) % c_.n;
      turn = std::max(turn, std::hypot(dz[2 * k] - dz[2 * j], dz[2 * k + 1] - dz[2 * j + 1]) / c_.l);
    }
    return turn / 0.5;
  }
  /// No hinge moved by more than 1e-12 R, or (from the third iteration) the correction,
  /// below 1e-9 R, did not shrink: Newton is at the rounding floor of a nearly singular
  /// tangent. Near a bifurcation the residual's rounding (eps times the link forces) is
  /// amplified along the buckling mode by the inverse of its eigenvalue: within 1e-6 of the
  /// critical load at n = 40 the corrections wander between 2e-12 and 2e-10 R without
  /// converging (measured), and the bifurcation's bisection could not get closer. Regular
  /// Newton contracts quadratically down to 1e-12 R and never stalls above it. And the links
  /// hold to 1e-10 R.
  bool converged(const paths::State& s, const paths::Vector& dz, int iteration) override {
    const double step = dz.head(N_).cwiseAbs().maxCoeff();
    const bool stalled = iteration >= 3 && step >= last_step_ && step <= 1e-9 * radius_;
    last_step_ = step;
    return (step <= 1e-12 * radius_ || stalled) &&
           constraints(c_, s.z.head(N_)).head(c_.n).cwiseAbs().maxCoeff() <= 1e-10 * radius_;
  }
  /// Commits the hinges' bending states at `to` and adds the step's work of the loads, then
  /// records `to` (and, first, `from`: rest) when recording, then the self-contact check.
  std::optional<paths::Touch> accept(const paths::State& from, const paths::State& to) override {
    if (recording_ && path_.empty()) path_.push_back(path_point(from.s, from.z));
    // The work of the loads s P: the trapezoidal rule over the step, -(s_a + s_b) / 2 (P(x_b) -
    // P(x_a)), exact for a path linear in s; O(ds^2) otherwise (the energy identity's quadrature).
    work_ -= 0.5 * (from.s + to.s) * (L_.potential(to.z.head(N_)) - L_.potential(from.z.head(N_)));
    // A driven point: the rig's work, the trapezoidal rule on reaction . d(displacement), the
    // displacement s drive linear in s (exact where the reaction is linear in s).
    if (c_.driven >= 0) {
      const std::array<double, 2> a = reaction(from.z, from.s), b = reaction(to.z, to.s);
      work_ += 0.5 * (to.s - from.s) * ((a[0] + b[0]) * c_.drive.x() + (a[1] + b[1]) * c_.drive.y());
    }
    // [plates]: each plate's work, its total pressure times its own advance s travel / 2, by
    // the same trapezoidal rule.
    if (c_.plates) {
      const std::array<double, 2> a = plate_loads(c_, from.z.head(N_), from.s), b = plate_loads(c_, to.z.head(N_), to.s);
      work_ += 0.5 * (to.s - from.s) * 0.5 * c_.plates->travel * (a[0] + a[1] + b[0] + b[1]);
    }
    if (own_) own_->bending.commit(bending_strains(c_, to.z.head(N_)));
    if (recording_) path_.push_back(path_point(to.s, to.z));
    const Contact k = closest_nonadjacent(c_, to.z.head(N_));
    if (k.distance >= c_.depth) return std::nullopt;
    return paths::Touch{1.0, contact_where(c_, k) + "; the chain model does not include contact"};
  }
  /// The multipliers of z (links, then the support rows), in units of scale_.
  Vec multipliers(const paths::Vector& z) const { return z.tail(S_ - N_ - E_); }
  /// The bending law with the committed states (bending.hpp).
  const Bending& bending() const { return c_.bending; }
  /// What accept() changes (the committed bending states, the work, the recorded path), kept so
  /// that a leg that fails can be tried again from where it began (follow_legs).
  struct Saved {
    std::optional<Bending> bending;
    double work;
    std::size_t points;
  };
  Saved save() const { return {own_ ? std::optional<Bending>(own_->bending) : std::nullopt, work_, path_.size()}; }
  void restore(const Saved& k) {
    if (own_ && k.bending) own_->bending = *k.bending;
    work_ = k.work;
    path_.resize(std::min(path_.size(), k.points));
  }
  /// The work of the loads along the accepted path so far, J.
  double work() const { return work_; }
  /// The closest approach of links at least the contact gap apart (accept's check) minus
  /// the section depth, for the driver to locate the touch within a step: O(n) (the grid).
  /// Infinite while no such pair has its midpoints in neighbouring cells (l + depth).
  std::optional<double> clearance(const paths::State& s) override {
    return closest_nonadjacent(c_, s.z.head(N_)).distance - c_.depth;
  }
  /// The tangent's least stable direction on ker G in the positions, multipliers zero
  /// (stability.hpp): dense, O(n^3), up to n = 200; none above (no branch switching there:
  /// the path ends at the bifurcation).
  std::optional<paths::Vector> critical_direction(const paths::State& s) override {
    const std::optional<Vec> d =
        least_stable_direction(c_, L_, s.z.head(N_), multipliers(s.z) * scale_, s.s, route_);
    if (!d) return std::nullopt;
    paths::Vector dz = paths::Vector::Zero(S_);
    dz.head(N_) = *d;
    return dz;
  }
  /// Records every accepted equilibrium (ring::PathPoint) at these hinges from now on.
  void record_path(std::vector<int> hinges) {
    record_ = std::move(hinges);
    recording_ = true;
  }
  /// The recorded path, rest first.
  const std::vector<ring::PathPoint>& path() const { return path_; }
  /// The path point of an equilibrium (the located limit point), at the recorded hinges.
  ring::PathPoint point_of(const paths::State& x) const { return path_point(x.s, x.z); }
  /// The force the rig applies on the ring at the driven point (static.displacement), N:
  /// minus the multipliers of its rows, S's last two (the residual's G^T lambda is the force the
  /// constraint needs from the ring). [plates]: the force of the plate at plates.axis on the
  /// ring, its total pressure along -d_0. 0 without either.
  std::array<double, 2> reaction(const paths::Vector& z, double s) const {
    if (c_.plates) {
      const double f = plate_loads(c_, z.head(N_), s)[0];
      return {-f * c_.plates->d[0], -f * c_.plates->d[1]};
    }
    if (c_.driven < 0) return {0.0, 0.0};
    return {-scale_ * z[S_ - 2], -scale_ * z[S_ - 1]};
  }
  /// The inertia of the tangent on the constraints' tangent space (stability.hpp): dense
  /// O(n^3) up to n = 200, O(n) frontal LDL^T of the KKT matrix up to n = 10^4, none above.
  std::optional<int> unstable_directions(const paths::State& s) override {
    return lumped::unstable_directions(c_, L_, s.z.head(N_), multipliers(s.z) * scale_, s.s, scale_, route_);
  }

 private:
  std::optional<Chain> own_;  ///< ring.plastic: a copy, whose bending states are this path's
  const Chain& c_;            ///< own_, or the caller's elastic chain
  const ChainLoads& L_;
  const int N_, E_, S_;  ///< positions; 1 with [plates] (their advance a), else 0; all unknowns
  const double scale_, radius_;
  const InertiaRoute route_;
  double work_ = 0.0;  ///< the loads' work along the accepted path, J
  double last_step_ = INFINITY;  ///< the Newton correction before (converged's memory)
  Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> lu_;
  std::vector<int> record_;  ///< the hinges a path point reports
  bool recording_ = false;
  std::vector<ring::PathPoint> path_;

  /// The path point of the unknowns z = (x, lambda) at load factor s: the recorded hinges'
  /// displacements and the ovalisation (largest - smallest distance between opposite
  /// hinges k and k + n/2) / rho, rho the circumradius: the multibody chain's definition
  /// (multibody/statics.cpp, StaticEquilibrium::path_point).
  ring::PathPoint path_point(double s, const Vec& z) const {
    const Vec x = z.head(N_);
    ring::PathPoint pt;
    pt.load_factor = s;
    pt.reaction = reaction(z, s);
    pt.contact_length = plate_contact_lengths(c_, x, s);
    for (int k : record_) {
      const Vec2 u = c_.at(x, k) - c_.at(c_.rest, k);
      pt.displacements.push_back({ring::wrap_degrees(c_.anchor_deg + c_.step_deg * k), u.x(), u.y()});
    }
    double most = 0.0, least = c_.open ? 0.0 : INFINITY;  // an arch has no opposite hinges: 0
    for (int k = 0; !c_.open && k < (c_.n + 1) / 2; ++k) {
      const double d = (c_.at(x, k) - c_.at(x, k + c_.n / 2)).norm();
      most = std::max(most, d);
      least = std::min(least, d);
    }
    pt.ovalisation = (most - least) / c_.rho;
    pt.dissipated = c_.bending.dissipated();
    pt.plastic_curvature = c_.bending.plastic_curvature();
    for (int k = 0; k < c_.n; k += ring::path_shape_stride(c_.n)) {
      const Vec2 p = c_.at(x, k);
      pt.node_x.push_back(p.x());
      pt.node_y.push_back(p.y());
    }
    return pt;
  }
};

/// [plates] on a plastic ring (follow_statics says why): the path leg by leg (without a history
/// the one leg to the full load), each by arc length from its start; a leg that withdraws the
/// plates and does not come through so is tried again from its start by load stepping. The
/// traces joined as paths::follow joins a history's legs (its counts the legs' sums, the rest
/// the last leg's).
paths::Trace follow_legs(ChainStatics& eq, const paths::State& rest, paths::Continuation policy) {
  const std::vector<double> ends = policy.history.empty() ? std::vector<double>{1.0} : policy.history;
  paths::Trace all;
  all.state = rest;
  for (const double b : ends) {
    const double a = all.state.s;
    if (b == a) continue;
    policy.history = {b};
    policy.from_start = true;
    const ChainStatics::Saved saved = eq.save();
    paths::Trace t = paths::follow(eq, all.state, policy);
    if (t.end != paths::Trace::End::reached && t.end != paths::Trace::End::contact && b < a) {
      eq.restore(saved);
      policy.from_start = false;
      t = paths::follow(eq, all.state, policy);
    }
    // The driver ends a leg at its end only through a Newton at it from the step across it;
    // when that misses, it follows the path on (the tube ran so from s = 1 to a self-contact at
    // 1.83): a touch beyond the leg's end is that, not a result.
    if (t.end == paths::Trace::End::contact && (b - a) * (t.end_load - b) > 0.0)
      throw ring::NumericalError("lumped statics: the path crossed load factor " + std::to_string(b) +
                                 " without converging there, and went on to " + std::to_string(t.end_load) +
                                 " (" + t.contact + ")");
    t.steps += all.steps;
    t.arc_steps += all.arc_steps;
    t.iterations += all.iterations;
    t.continuation = t.continuation || all.continuation;
    if (!std::isnan(all.limit)) {
      t.limit = all.limit;
      t.limit_state = all.limit_state;
    }
    t.branch_points.insert(t.branch_points.begin(), all.branch_points.begin(), all.branch_points.end());
    all = std::move(t);
    if (all.end != paths::Trace::End::reached) return all;
  }
  all.end = paths::Trace::End::reached;
  all.end_load = all.state.s;
  return all;
}

}  // namespace

namespace detail {

StaticState follow_statics(const Chain& c, const ChainLoads& loads, const ring::RingSpec& spec,
                           const ring::StaticOptions& statics, const std::vector<int>* record, InertiaRoute route,
                           const std::string& who) {
  const int N = 2 * c.n, R = c.rows();
  const double scale = spec.EI() / (c.l * c.l * c.l);
  ChainStatics eq(c, loads, scale, spec.radius, route);
  paths::State rest{paths::Vector::Zero(eq.size()), 0.0};
  rest.z.head(N) = c.rest;
  // static.path: the path through bifurcations (branch switching) to the touch, which is a
  // result; every other early end still fails.
  paths::Continuation policy;
  policy.steps = statics.steps;
  policy.history = statics.history;
  // A driven plastic chain: arc-length continuation from rest. Load stepping starts each
  // Newton solve at the last equilibrium with only the driven rows moved, and its first
  // iterate spreads the step over the hinges elastically; on the collapse plateau that
  // yields the neighbours of the mechanism's hinges as well, and a perfectly plastic hinge's
  // zero tangent then makes a mechanism of the iterate (a correction of 0.16 m on the paper
  // ring at n = 32, measured): the increments were cut to a closing of ~3e-6 R, thousands of
  // steps to a closing of R. The arc's predictor follows the path's tangent, which on the
  // plateau is the mechanism's own motion: a few dozen steps (measured).
  // [plates] on a plastic ring the same: load stepping with the fibre law (the tube of
  // scenes/tube-crushing.toml, n = 80, 40 steps) crawled at 1/256 of an increment from load
  // factor 0.11 to 0.17 (1200 levels), and the arc it then handed over to took 12 iterations
  // per step on the flattened ring; its Newton at s = 1, from the point interpolated between
  // 0.979 and 1.003, left the basin, and the driver then followed the path on past the full
  // load (to the self-contact at 1.83, 12 s). From rest by arc length: 56 steps, the Newton at
  // s = 1 in 3 iterations, 0.3 s (measured). A leg that withdraws the plates runs by arc length
  // too (the tube's [1, 0.98]: 97 equilibria, 0.5 s; load stepped, 2284 and 11 s, the same
  // force, measured), but the resultant law's [1, 0.9] stalled so at 0.9999, where the ring
  // springs back clear of the plates and many nodes leave them at once; load stepping passes
  // that in one step, so such a leg is tried again by it (follow_legs).
  policy.from_start = c.driven >= 0 && c.bending.plastic();
  if (record) {
    policy.branch_switch = true;
    policy.branch_side = statics.branch_side;
    eq.record_path(*record);
  }
  StaticState st;
  st.trace = c.plates && c.bending.plastic() ? follow_legs(eq, rest, policy) : paths::follow(eq, rest, policy);
  const bool touched = record && st.trace.end == paths::Trace::End::contact;
  if (st.trace.end != paths::Trace::End::reached && !touched)
    throw ring::NumericalError(who + ": " + paths::failure_message(st.trace, policy));
  st.x = st.trace.state.z.head(N);
  st.lambda = st.trace.state.z.tail(R) * scale;
  if (record) st.path = eq.path();
  if (record && st.trace.limit_state) st.limits.push_back(eq.point_of(*st.trace.limit_state));
  st.dissipated = eq.bending().dissipated();
  st.plastic_curvature = eq.bending().plastic_curvature();
  st.work = eq.work();
  const double s_end = st.trace.state.s;
  st.reaction = eq.reaction(st.trace.state.z, s_end);
  st.stored = eq.bending().stored(bending_strains(c, st.x)) + c.terms->energy(st.x - c.rest);
  if (c.plates) {
    Springs p;
    p.grad = Vec::Zero(N);
    add_plates(c, st.x, s_end, 0.0, p);
    st.stored += p.energy;
    st.contact_length = plate_contact_lengths(c, st.x, s_end);
  }
  return st;
}

}  // namespace detail

StaticDetail solve_static_detail(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                 const ring::StaticOptions& statics, InertiaRoute route) {
  const auto t0 = std::chrono::steady_clock::now();
  check_static(spec, options, statics);
  if (options.variant != ring::LumpedOptions::Variant::chain) return frame_static(spec, options, statics);
  Chain c = make_chain(spec, options);
  const Sparse supports = c.S;  // the ground's rows (ground_force), without a driven point's
  if (statics.displacement)
    drive(c, c.hinge(statics.displacement->at),
          Vec2(statics.displacement->value[0], statics.displacement->value[1]));
  if (statics.plates) hold_plates(c, spec, *statics.plates);
  const auto at = load_hinges(c, spec, statics.loads, "static");
  const auto rec = record_hinges(c, spec, statics.record, "static.record");
  const int N = 2 * c.n, R = c.rows();
  const ChainLoads loads(statics.loads, c.rest, c.l, mass_matrix(c), at, c.open);
  const detail::StaticState st =
      detail::follow_statics(c, loads, spec, statics, statics.path ? &rec : nullptr, route, "lumped statics");
  const paths::Trace& path = st.trace;
  const bool touched = statics.path && path.end == paths::Trace::End::contact;
  const Vec& x = st.x;
  StaticDetail detail;
  ring::StaticResult& out = detail.result;
  if (statics.path) {
    out.path = st.path;
    out.branch_points = path.branch_points;
    out.limit_points = st.limits;
    out.end = touched ? "contact: " + path.contact : statics.history.empty() ? "full load" : "end of the history";
    out.end_load = path.end_load;  // the touch, or the full load (a history: its last factor)
  }
  out.steps = path.steps;
  out.newton_iterations = path.iterations;
  out.dissipated = st.dissipated;
  out.plastic_curvature = st.plastic_curvature;
  detail.work = st.work;
  detail.stored = st.stored;
  detail.limit = path.limit;
  for (std::size_t p = 0; p < rec.size(); ++p) {
    const Vec2 u = c.at(x, rec[p]) - c.at(c.rest, rec[p]);
    out.displacements.push_back({statics.record[p], u.x(), u.y()});
  }
  for (int j = 0; j < c.n; ++j) {
    out.node_x.push_back(x[2 * j]);
    out.node_y.push_back(x[2 * j + 1]);
  }
  detail.ground_force = ground_force(supports, st.lambda.segment(c.links(), supports.rows()), *c.terms, x - c.rest, 2);
  out.reaction = st.reaction;
  out.contact_length = st.contact_length;
  if (statics.plates) {  // the no-slide rows' and the centre row's multipliers, S's last three
    detail.no_slide = {st.lambda[c.rows() - 3], st.lambda[c.rows() - 2]};
    detail.centre = st.lambda[c.rows() - 1];
    detail.plate_loads = plate_loads(c, x, path.state.s);
  }
  out.solver = "lumped";
  out.unknowns = N + R + (c.plates ? 1 : 0);  // [plates]: their advance (ChainStatics)
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return detail;
}

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                const ring::StaticOptions& statics) {
  return solve_static_detail(spec, options, statics).result;
}

namespace {

/// The discrete gradient of a link's direction angle between its vectors v0 and v1: the
/// midpoint gradient angle_gradient(v_m) (terms.hpp) scaled so that its product with v1 - v0
/// is the angle turned, atan2(v0 x v1, v0 . v1), exactly. The midpoint gradient's own product
/// is v0 x v1 / |v_m|^2 (= 2 tan(phi / 2) for equal lengths), so the scale is
/// atan2(c, d) |v_m|^2 / c (c = v0 x v1, d = v0 . v1), by its series atan(t) / t = 1 - t^2 / 3
/// (error below t^4 / 5 < 2e-17) for |t| = |c / d| < 1e-4 (d > 0). O(1).
Vec2 angle_discrete_gradient(const Vec2& v0, const Vec2& v1) {
  const Vec2 vm = 0.5 * (v0 + v1);
  const double c = v0.x() * v1.y() - v0.y() * v1.x(), d = v0.dot(v1);
  const double scale = d > 0.0 && std::abs(c) < 1e-4 * d ? (1.0 - (c / d) * (c / d) / 3.0) * vm.squaredNorm() / d
                                                         : std::atan2(c, d) * vm.squaredNorm() / c;
  return scale * angle_gradient(vm);
}

/// The chain's midpoint step (midpoint.hpp): a Newton solve on the constrained midpoint
/// equations, the loads' force, the damping and the springs at the step's midpoint. The
/// unknowns q = (x, chi): the hinge positions, then the rotation chi of every hinge with a point
/// inertia (Terms::hinge_rotations: the linear modes' unknowns, model.cpp), whose mass is J and
/// whose springs are the hinge's split springs (chain.hpp, springs(); the kr of such a hinge
/// acts on chi, not condensed). The mass on q is constant (the midpoint masses, the point
/// masses, J on chi). The hinge dampers act on the rate of each turning angle.
///
/// ring.plastic: the hinges' states are internal variables. Every Newton iterate evaluates the
/// law from the states committed at the last accepted step (bending.hpp: the return map), and
/// commit() commits them at an accepted step only (PlasticSteps calls it after the driver's
/// accept); a rejected or halved attempt leaves nothing behind. The hinge moment of the step is
/// then not the law at the midpoint but a discrete gradient (Gonzalez 1996), in two layers:
///  - on the rotation: M_d = (Psi(e_1) - Psi(e_0)) / (e_1 - e_0), Psi the law's incremental
///    potential from the committed state (ring/plastic.hpp, Point::potential), e_0 the
///    committed rotation (the step's start) and e_1 the trial one; and
///  - on the positions: the turning angle's discrete gradient D theta (the two links'
///    angle_discrete_gradient), whose product with q_1 - q_0 is theta(q_1) - theta(q_0) exactly.
/// The hinge then does the work M_d D theta . (q_1 - q_0) = Psi(e_1) - Psi(e_0) over the step,
/// exactly. What that means with dissipation: Psi is not a stored energy but the step's
/// incremental potential, and Psi(e_1) - Psi(e_0) is the stored energy's change plus the
/// plastic work that the commit at e_1 counts (the return map is backward Euler: exact for the
/// piecewise linear law); so the discrete gradient spends exactly on the hinges what they store
/// and dissipate, and kinetic + stored + dissipated - work is exact to the Newton tolerance
/// (with the midpoint rule's exact kinetic energy, the links' quadratic constraints, linear
/// support rows and dead point loads; a foundation, a follower pressure and the hinge dampers
/// keep the midpoint rule's O(h^2)). Elastic, the discrete gradient is not the midpoint
/// rule's k e(q_m) grad theta(q_m): the elastic chain keeps that (its responses stay what they
/// were), so Mp -> infinity differs from it by the two second-order rules' O(h^2), not by
/// round-off. Newton's matrix for the hinge is dM_d/de_1 D theta grad theta(q_1)^T +
/// M_d Hess theta(q_m) / 2 (the scale of D theta's own derivative, O(phi) for a link turning
/// by phi in the step, left out: Newton stays fast for the small turns of a step).
class ChainStepper : public detail::MidpointStepper {
 public:
  ChainStepper(const Chain& c, const ring::ResponseOptions& r, double radius, const ChainLoads& loads, Sparse M,
               Sparse C, std::vector<int> rec, Vec rest)
      : MidpointStepper(r, std::move(M), std::move(C), std::move(rest), c.rows()),
        own_(c.bending.plastic() ? std::optional<Chain>(c) : std::nullopt), c_(own_ ? *own_ : c), radius_(radius),
        L_(loads), rec_(std::move(rec)), ch_(r.hinge_damping), rhs_(q_.size() + c.rows()), d_(q_.size() + c.rows()) {}
  ChainStepper(const ChainStepper&) = delete;  // c_ may refer to own_
  ChainStepper& operator=(const ChainStepper&) = delete;

  /// ring.plastic: commits the hinges' states at the accepted state (after the driver's
  /// accept, which made the step's end the state). O(n states).
  void commit() {
    if (own_) own_->bending.commit(bending_strains(c_, q_.head(2 * c_.n)));
  }
  /// The plastic work of the committed steps, J.
  double plastic_work() const { return c_.bending.dissipated(); }

  void shape(std::vector<double>& x, std::vector<double>& y) const override {
    paths::interleaved_shape(q_, c_.n, x, y);
  }

  std::optional<std::string> contact() const override {
    const Contact k = closest_nonadjacent(c_, q_.head(2 * c_.n));
    if (k.distance >= c_.depth) return std::nullopt;
    return contact_where(c_, k);
  }

 private:
  // The Newton system of the step (paths/newton.hpp) on (q1_, mu1_): the KKT matrix
  // A d = -(residual, scale g) by sparse LU. A correction that moves a hinge by half a link
  // or more (a hinge rotation by half a radian: l chi counts as a displacement) has left the
  // basin; converged when it moves nothing by more than 1e-11 R and the links then hold to
  // 1e-10 R (R: the ring's radius), failed when they do not.
  paths::Rule rule() const override {
    paths::Rule r;
    r.tolerance = 1e-11 * radius_;
    return r;
  }
  bool linearize(bool) override {
    const double hh = step_size(), factor = load_factor();
    const int N = 2 * c_.n, R = c_.rows(), Q = static_cast<int>(q_.size());
    scale_ = 2.0 / (hh * hh) * c_.m;  // balances the constraint rows
    const Vec qm = 0.5 * (q_ + q1_), vm = (q1_ - q_) / hh;
    const Vec xm = qm.head(N), x1 = q1_.head(N);
    const bool plastic = c_.bending.plastic();
    Springs sp = tangent(c_, L_, qm, mu1_ * scale_, factor, 0.5, !plastic);
    if (plastic) add_discrete_hinges(sp);
    Triplets trip = sp.hess;
    jacobian(c_, xm, Q, scale_, true, trip);
    jacobian(c_, x1, Q, scale_, false, trip);
    Vec res = (2.0 / (hh * hh)) * (M_ * (q1_ - q_ - hh * v_)) + sp.grad;
    res.head(N) += factor * L_.gradient(xm);
    if (damped_) res += C_ * vm;
    if (ch_ > 0)
      for (int j = 0; j < c_.n; ++j) {
        if (!c_.has_spring(j)) continue;
        const Turn tm_ = turn(c_, xm, j, false);
        const double rate = (turn(c_, x1, j, false).theta - turn(c_, q_, j, false).theta) / hh;
        for (int i = 0; i < 6; ++i) {
          res[dof(c_, j, i)] += ch_ * rate * tm_.grad[i];
          for (int p = 0; p < 6; ++p)
            trip.emplace_back(dof(c_, j, i), dof(c_, j, p), ch_ / hh * tm_.grad[i] * tm_.grad[p]);
        }
      }
    Triplets gt;
    jacobian(c_, xm, 0, 1.0, true, gt);
    Sparse GT(Q, R);
    GT.setFromTriplets(gt.begin(), gt.end());
    res += GT * (mu1_ * scale_);
    Sparse A(Q + R, Q + R);
    A.setFromTriplets(trip.begin(), trip.end());
    Sparse Mt = (2.0 / (hh * hh)) * M_;
    if (damped_) Mt += C_ / hh;
    Mt.conservativeResize(Q + R, Q + R);
    A += Mt;
    rhs_.resize(Q + R);
    rhs_.head(Q) = -res;
    rhs_.tail(R) = -scale_ * constraints(c_, x1);
    // Solved at once (full Newton): the LU lives only here, as the memory estimate counts it.
    Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> lu;
    lu.compute(A);
    if (lu.info() != Eigen::Success || !rhs_.allFinite()) return false;
    d_ = lu.solve(rhs_);
    return true;
  }
  /// ring.plastic: the hinges' discrete gradient of the step from q_ to q1_ (class comment)
  /// added to sp's gradient, and its derivative on q1_ to sp's triplets. O(n states).
  void add_discrete_hinges(Springs& sp) const {
    const Vec qm = 0.5 * (q_ + q1_);
    for (int j = 0; j < c_.n; ++j) {
      if (!c_.has_spring(j)) continue;
      const Turn t0 = turn(c_, q_, j, false), t1 = turn(c_, q1_, j, false), tm = turn(c_, qm, j, true);
      const double e0 = t0.theta - c_.theta0, e1 = t1.theta - c_.theta0, de = e1 - e0;
      const ring::BilinearLaw::Point p1 = c_.bending.at(j, e1);
      double M = 0.0, dM = 0.0;
      // Below a relative 1e-8 the difference quotient would lose ~eps / 1e-8 of M to the
      // potentials' cancellation; there the law at the mean rotation (its error against the
      // quotient is the law's curvature times de^2, below eps of Psi).
      if (std::abs(de) > 1e-8 * (std::abs(e0) + std::abs(e1))) {
        M = (p1.potential - c_.bending.at(j, e0).potential) / de;
        dM = (p1.force - M) / de;
      } else {
        const ring::BilinearLaw::Point pm = c_.bending.at(j, 0.5 * (e0 + e1));
        M = pm.force;
        dM = 0.5 * pm.tangent;
      }
      const Vec2 a0 = c_.at(q_, j) - c_.at(q_, j - 1), a1 = c_.at(q1_, j) - c_.at(q1_, j - 1);
      const Vec2 b0 = c_.at(q_, j + 1) - c_.at(q_, j), b1 = c_.at(q1_, j + 1) - c_.at(q1_, j);
      const Vec2 ga = angle_discrete_gradient(a0, a1), gb = angle_discrete_gradient(b0, b1);
      Eigen::Matrix<double, 6, 1> D;
      D << ga, -ga - gb, gb;  // as turn()'s gradient: theta = angle(b) - angle(a)
      for (int i = 0; i < 6; ++i) {
        sp.grad[dof(c_, j, i)] += M * D[i];
        for (int p = 0; p < 6; ++p)
          sp.hess.emplace_back(dof(c_, j, i), dof(c_, j, p), dM * D[i] * t1.grad[p] + 0.5 * M * tm.hess(i, p));
      }
      sp.energy += p1.potential;
    }
  }
  bool solve(paths::Correction& k) override {
    const int N = 2 * c_.n, Q = static_cast<int>(q_.size());
    if (!d_.allFinite()) return false;
    k.size = d_.head(N).cwiseAbs().maxCoeff();
    if (Q > N) k.size = std::max(k.size, c_.l * d_.segment(N, Q - N).cwiseAbs().maxCoeff());
    k.move = k.size / (0.5 * c_.l);
    return true;
  }
  void apply() override {
    const Eigen::Index Q = q_.size();
    q1_ += d_.head(Q);
    mu1_ += d_.tail(d_.size() - Q);
  }
  paths::Verdict settle(bool small, const paths::Correction&) override {
    if (!small) return paths::Verdict::iterate;
    return constraints(c_, q1_.head(2 * c_.n)).head(c_.n).cwiseAbs().maxCoeff() <= 1e-10 * radius_
               ? paths::Verdict::converged
               : paths::Verdict::failed;
  }

  double potential(const Vec& q) const override { return L_.potential(q.head(2 * c_.n)); }
  double strain(const Vec& q) const override { return springs(c_, q, 0.0).energy; }
  double constraint_residual(const Vec& q) const override {
    return constraints(c_, q.head(2 * c_.n)).head(c_.n).cwiseAbs().maxCoeff();
  }
  void record(const Vec& q, paths::Sample& out) const override {
    for (int h : rec_) {
      const Vec2 u = c_.at(q, h) - c_.at(c_.rest, h);
      out.ux.push_back(u.x());
      out.uy.push_back(u.y());
    }
  }
  double own_dissipation(const Vec& q0, const Vec& q1, double hh) const override {
    double d = 0.0;
    if (ch_ > 0)
      for (int j = 0; j < c_.n; ++j) {
        if (!c_.has_spring(j)) continue;
        const double rate = (turn(c_, q1, j, false).theta - turn(c_, q0, j, false).theta) / hh;
        d += hh * ch_ * rate * rate;
      }
    return d;
  }

  std::optional<Chain> own_;  ///< ring.plastic: a copy, whose hinge states are this response's
  const Chain& c_;            ///< own_, or the caller's elastic chain
  const double radius_;
  const ChainLoads& L_;
  const std::vector<int> rec_;
  const double ch_;
  double scale_ = 0.0;                                   ///< the constraint rows' scale of the step
  /// -(residual, scale g) and the correction, allocated once with the stepper: allocated
  /// among the step's matrices they left glibc's heap 8 MB higher at n = 10^4 (measured by
  /// ru_maxrss; the live memory was the same).
  Vec rhs_, d_;
};

/// ring.plastic: the chain's steps (ChainStepper) with the hinges' states committed at every
/// accepted step (after the midpoint rule's accept, which the driver calls) and their plastic
/// work reported as paths::Sample::plastic (the driver records it as the history's
/// `dissipated` and counts it in energy_error and the energy guard). A rejected attempt
/// (paths::Stepper::reject) has nothing to discard: the Newton evaluates the law from the
/// committed states only.
class PlasticSteps : public paths::Stepper {
 public:
  explicit PlasticSteps(ChainStepper& s) : s_(s) {}
  paths::StepOutcome try_step(double t, double h) override { return s_.try_step(t, h); }
  void accept(double t) override {
    s_.accept(t);
    s_.commit();
  }
  void reject() override { s_.reject(); }
  bool finite() const override { return s_.finite(); }
  paths::Sample sample() const override {
    paths::Sample out = s_.sample();
    out.plastic = s_.plastic_work();
    return out;
  }
  void shape(std::vector<double>& x, std::vector<double>& y) const override { s_.shape(x, y); }
  std::optional<std::string> contact() const override { return s_.contact(); }

 private:
  ChainStepper& s_;
};

}  // namespace

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                          const ring::ResponseOptions& r) {
  const auto t0 = std::chrono::steady_clock::now();
  check_response(spec, options, r);
  if (options.variant != ring::LumpedOptions::Variant::chain) return frame_respond(spec, options, r);
  const Chain c = make_chain(spec, options);
  const auto at = load_hinges(c, spec, r.loads, "response");
  const auto rec = record_hinges(c, spec, r.record, "response.record");
  const int N = 2 * c.n, R = c.rows();
  const Sparse M = mass_matrix(c);
  const ChainLoads loads(r.loads, c.rest, c.l, M, at, c.open);
  // The unknowns q = (x, chi) (ChainStepper): J on every hinge rotation chi.
  const auto& hr = c.terms->hinge_rotations();
  const int Q = N + static_cast<int>(hr.size());
  Vec rest = Vec::Zero(Q);
  rest.head(N) = c.rest;
  const Sparse Mq = mass_matrix(c, HingeRotations::unknowns);
  // Rayleigh damping C = a M + b K0, M the mass on q, K0 the Hessian of the springs and terms
  // at rest (no link forces there), the hinge rotations' split springs included.
  ChainStepper stepper(c, r, spec.radius, loads, Mq,
                       detail::rayleigh_damping(r, Mq, [&] { return springs(c, rest, 1.0).hess; }), rec, rest);
  if (!c.bending.plastic()) {
    ring::TimeHistory h = detail::integrate_midpoint(stepper, spec, c.n, r, "lumped response", Q + R);
    h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return h;
  }
  PlasticSteps plastic(stepper);
  ring::TimeHistory h = detail::integrate_midpoint(plastic, spec, c.n, r, "lumped response", Q + R);
  h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}

namespace detail {

ring::TimeHistory integrate_midpoint(paths::Stepper& stepper, const ring::RingSpec& spec, int nodes,
                                     const ring::ResponseOptions& r, const std::string& who, int unknowns) {
  ring::EnergyGuard guard(spec, nodes, ring::load_scale(spec, r.loads));
  paths::Grid grid;
  grid.dt = r.dt;
  grid.t_end = r.t_end;
  grid.guard = &guard;
  grid.who = who;
  grid.progress = r.progress;
  ring::TimeHistory h = paths::integrate(stepper, grid, r.record);
  h.solver = "lumped";
  h.unknowns = unknowns;
  return h;
}

}  // namespace detail

}  // namespace lumped
