// The statics of one discretization as an equilibrium path from rest (static_path.hpp;
// the method is documented in nonlinear.hpp, "Statics").
#include "fem_reference/static_path.hpp"

#include <iomanip>
#include <sstream>

#include "fem_reference/newton.hpp"
#include "fem_reference/self_contact.hpp"

namespace fem::detail {
namespace {

/// Load stepping hands over to the continuation when a load level cannot be passed with
/// 1/2^kMaxHalvings of the requested increment.
constexpr int kMaxHalvings = 10;
/// The arc length adapts towards this many corrector iterations per step.
constexpr int kTargetIterations = 5;
/// A failed arc step halves the length; this many failures in a row end the path.
constexpr int kMaxArcHalvings = 30;
/// No value of q (displacements at the support points) moves more than this fraction
/// of the radius in one step: arc steps, so that the path is resolved (a maximum and a
/// minimum of the load factor are never skipped together in one step); load steps, so
/// that Newton started just below a limit point cannot land on a distant branch.
constexpr double kMaxArcMove = 0.1;
/// The limit point's bracket (in arc length) is narrowed to this fraction of the step
/// that contains it; the load factor there is then exact to ~|s''| (1e-6 len)^2.
constexpr double kLimitBracket = 1e-6;
constexpr int kMaxLimitEvaluations = 60;

std::string number(double x, int digits = 9) {
  std::ostringstream o;
  o << std::setprecision(digits) << x;
  return o.str();
}

/// Load stepping, then (if needed, or from the start) arc-length continuation, on one
/// RingModel. A small program in stages (run(): load_stepping(), continuation()); one
/// object traces one path.
class PathFollower {
 public:
  PathFollower(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st,
               const ContinuationOptions& continuation);
  StaticSolve run();

 private:
  struct State {
    Vector<double> q;
    double s = 0.0;
  };
  /// The path's unit tangent at a state, oriented forward, and ds/dtau along it (tau:
  /// the Euclidean length of the change of q, the arc length of the constraint).
  struct Tangent {
    Vector<double> t;
    double rate = 0.0;
  };

  int newton_at(Vector<double>& q, double s);
  /// Load stepping from the rest state; false when a load level cannot be passed.
  bool load_stepping(State& state, Vector<double>& last_step);
  /// Arc-length continuation from `state` in the direction `forward` (the last change
  /// of q) until the path reaches the full load or ends.
  void continuation(State state, const Vector<double>& forward);

  /// Fills B_ with [K(q) -F; w^T 0] and, if asked, r_ with grad V(q) - s F.
  void border(const Vector<double>& q, double s, const Vector<double>& w, bool residual);
  /// Solves [K -F; w^T 0] (t, ts) = (0, 1) at the state, w = `forward` normalized.
  bool tangent_at(const State& x, const Vector<double>& forward, Tangent& out);
  /// One arc step of length `len` from `from` along `tangent`: Newton on the bordered
  /// system; false (and `to` unusable) when it does not converge.
  bool arc_step(const State& from, const Tangent& tangent, double len, State& to, int& iterations);
  /// Narrows the first maximum of s between `from` (rate > 0) and the step of length
  /// `len` whose end has rate `rate_end` <= 0; returns the largest s met.
  double locate_limit(const State& from, const Tangent& tangent, double len, double s_end, double rate_end);

  /// Accepts the state reached from `from`: records it and checks the chord between the
  /// two deformed centrelines for self-contact. False when the ring touched itself.
  bool accept(const State& from, const State& to);
  std::vector<Point2> centreline(const Vector<double>& q) const { return model_.centreline(model_.expand(q), per_cell_); }
  void finish(const State& state);

  const ring::RingSpec& spec_;
  const ring::StaticOptions& st_;
  const ContinuationOptions& options_;
  const RingModel model_;
  const unsigned int N_;
  const unsigned int loaded_;
  const Vector<double> F_;
  const double ds_;        ///< the requested load increment 1 / steps
  const double depth_;     ///< section depth: the self-contact distance
  unsigned int per_cell_ = 2;  ///< centreline points per cell (spacing <= depth / 2)
  int min_gap_ = 2;            ///< centreline edges closer along the ring are neighbours
  SparseMatrix<double> K_;
  SparsityPattern bordered_pattern_;
  SparseMatrix<double> B_;
  Vector<double> r_;
  std::vector<Point2> last_centreline_;
  StaticSolve out_;
};

PathFollower::PathFollower(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st,
                           const ContinuationOptions& continuation)
    : spec_(spec),
      st_(st),
      options_(continuation),
      model_(spec, setup),
      N_(model_.n_free()),
      loaded_(model_.vertex_of(st.load.angle)),
      F_(model_.vertex_force(loaded_, st.load.force)),
      ds_(1.0 / std::max(1, st.steps)),
      depth_(spec.section.depth()),
      K_(model_.sparsity()) {
  // Centreline points at most depth / 2 apart along the rest ring (chord sag of a part
  // bent to radius rho: spacing^2 / (8 rho), far below the depth); edges whose nearest
  // ends are at least 2 depths apart along the ring are "not neighbours": bending alone
  // would need a radius below the depth to bring those within a depth of each other.
  const double cell_arc = 2.0 * kPi * spec.radius / model_.cells();
  per_cell_ = std::max(2u, static_cast<unsigned int>(std::ceil(cell_arc / (0.5 * depth_))));
  const double spacing = cell_arc / per_cell_;
  min_gap_ = 1 + static_cast<int>(std::ceil(2.0 * depth_ / spacing));
  // The bordered pattern: K's, plus a full last row and column.
  DynamicSparsityPattern dsp(N_ + 1, N_ + 1);
  for (auto e = model_.sparsity().begin(); e != model_.sparsity().end(); ++e) dsp.add(e->row(), e->column());
  for (unsigned int i = 0; i <= N_; ++i) {
    dsp.add(i, N_);
    dsp.add(N_, i);
  }
  bordered_pattern_.copy_from(dsp);
  B_.reinit(bordered_pattern_);
  out_.unknowns = N_;
  out_.depth = depth_;
}

int PathFollower::newton_at(Vector<double>& q, double s) {
  return newton(
      q, spec_.radius,
      [&](const Vector<double>& x, Vector<double>& r) -> SparseMatrix<double>& {
        model_.beam_energy(x, &r, &K_);
        r.add(-s, F_);
        return K_;
      },
      kMaxArcMove * spec_.radius);
}

void PathFollower::border(const Vector<double>& q, double s, const Vector<double>& w, bool residual) {
  model_.beam_energy(q, residual ? &r_ : nullptr, &B_);  // K in the top-left block, border zeroed
  for (unsigned int i = 0; i < N_; ++i) {
    B_.set(i, N_, -F_[i]);
    B_.set(N_, i, w[i]);
  }
  if (residual) r_.add(-s, F_);
}

bool PathFollower::tangent_at(const State& x, const Vector<double>& forward, Tangent& out) {
  Vector<double> w = forward;
  w /= w.l2_norm();
  border(x.q, x.s, w, false);
  SparseDirectUMFPACK lu;
  try {
    lu.initialize(B_);
  } catch (const std::exception&) {
    return false;
  }
  Vector<double> z(N_ + 1);
  z[N_] = 1.0;
  lu.solve(z);
  out.t.reinit(N_);
  for (unsigned int i = 0; i < N_; ++i) out.t[i] = z[i];
  const double norm = out.t.l2_norm();
  if (!std::isfinite(norm) || !std::isfinite(z[N_]) || norm == 0.0) return false;
  out.t /= norm;
  out.rate = z[N_] / norm;
  return true;
}

bool PathFollower::arc_step(const State& from, const Tangent& tangent, double len, State& to, int& iterations) {
  // Predictor along the tangent; corrector: Newton on grad V(q) - s F = 0 together with
  // the cylindrical constraint c = (|q - q0|^2 - len^2) / (2 len) = 0 (Crisfield 1981,
  // no load term in the arc), q and s unknown. Its Jacobian is the bordered matrix
  // [K -F; (q - q0)^T / len 0], regular at a limit point (where K alone is singular), so
  // it is factorized as a whole (UMFPACK) rather than by block elimination with K^-1.
  to.q = from.q;
  to.q.add(len, tangent.t);
  to.s = from.s + len * tangent.rate;
  const Vector<double> predicted = to.q;
  Vector<double> d(N_), rhs(N_ + 1);
  SparseDirectUMFPACK lu;
  for (iterations = 1; iterations <= kMaxNewton; ++iterations) {
    d = to.q;
    d -= from.q;
    d /= len;
    border(to.q, to.s, d, true);
    for (unsigned int i = 0; i < N_; ++i) rhs[i] = -r_[i];
    rhs[N_] = -0.5 * len * (d.norm_sqr() - 1.0);
    if (!std::isfinite(rhs.l2_norm())) return false;
    try {
      lu.initialize(B_);
    } catch (const std::exception&) {
      return false;
    }
    lu.solve(rhs);
    double move = 0.0;
    for (unsigned int i = 0; i < N_; ++i) {
      to.q[i] += rhs[i];
      move = std::max(move, std::abs(rhs[i]));
    }
    to.s += rhs[N_];
    if (!std::isfinite(move) || !std::isfinite(to.s)) return false;
    // A corrector that moves a whole step away from the predicted point has left it
    // for another part of the path (or of the sphere): the step is too long.
    d = to.q;
    d -= predicted;
    if (d.l2_norm() > len) return false;
    if (move <= 1e-12 * spec_.radius && std::abs(rhs[N_]) <= 1e-12) return true;
  }
  return false;
}

bool PathFollower::accept(const State& from, const State& to) {
  ++out_.steps;
  const Vector<double> full = model_.expand(to.q);
  out_.path.push_back({to.s, model_.vertex_displacement(full, loaded_)});
  std::vector<Point2> next = model_.centreline(full, per_cell_);
  // The deformed centreline moves between the two equilibria; checking only the ends
  // could miss a part passing through another, so the chord between them is checked at
  // sub-steps that move no point by more than depth / 2 (two parts then close in by at
  // most a depth per sub-step, and a crossing counts as distance 0).
  double move = 0.0;
  for (std::size_t k = 0; k < next.size(); ++k)
    move = std::max(move, std::hypot(next[k][0] - last_centreline_[k][0], next[k][1] - last_centreline_[k][1]));
  const int substeps = std::max(1, static_cast<int>(std::ceil(move / (0.5 * depth_))));
  std::vector<Point2> at(next.size());
  for (int j = 1; j <= substeps; ++j) {
    const double w = static_cast<double>(j) / substeps;
    for (std::size_t k = 0; k < next.size(); ++k)
      for (int c = 0; c < 2; ++c) at[k][c] = last_centreline_[k][c] + w * (next[k][c] - last_centreline_[k][c]);
    const Approach a = closest_approach(at, min_gap_, depth_);
    if (a.first >= 0 && a.distance < depth_) {
      const double pin = spec_.supports.pin.value_or(0.0);
      auto angle = [&](int edge) { return ring::wrap_degrees(pin + (edge + 0.5) * 360.0 / at.size()); };
      out_.end = StaticSolve::End::contact;
      out_.end_load = from.s + w * (to.s - from.s);
      out_.contact = "the centreline near " + number(angle(a.first), 4) + " deg and near " +
                     number(angle(a.second), 4) + " deg (rest positions) " +
                     (a.distance == 0.0 ? std::string("crosses itself")
                                        : "comes within " + number(a.distance, 4) + " m of itself");
      return false;
    }
  }
  last_centreline_ = std::move(next);
  return true;
}

void PathFollower::finish(const State& state) {
  const Vector<double> full = model_.expand(state.q);
  for (double a : st_.record) out_.record.push_back(model_.vertex_displacement(full, model_.vertex_of(a)));
  for (unsigned int k = 0; k < model_.cells(); ++k) {
    const auto X = model_.vertex_position(k);
    const auto u = model_.vertex_displacement(full, k);
    out_.node_x.push_back(X[0] + u[0]);
    out_.node_y.push_back(X[1] + u[1]);
  }
  out_.end = StaticSolve::End::reached;
  out_.end_load = state.s;
}

bool PathFollower::load_stepping(State& state, Vector<double>& last_step) {
  double step = ds_;
  Vector<double> trial;
  while (state.s < 1.0 - 1e-14) {
    const State from = state;
    const double s_next = std::min(1.0, state.s + step);
    trial = state.q;
    const int it = newton_at(trial, s_next);
    // A step whose end, looked at in the direction of the step, has the load falling has
    // jumped over a limit point onto the path beyond it: like a failed Newton, it is cut.
    // (A step that moves nothing, under a zero load, has no direction and jumped nowhere.)
    Vector<double> change = trial;
    change -= state.q;
    Tangent ahead;
    const bool jumped = it >= 0 && change.l2_norm() > 0.0 && (!tangent_at({trial, s_next}, change, ahead) || ahead.rate <= 0.0);
    if (it < 0 || jumped) {
      step *= 0.5;
      if (step < ds_ / (1 << kMaxHalvings)) return false;
      continue;
    }
    last_step = std::move(change);
    state.q = trial;
    state.s = s_next;
    out_.iterations += it;
    if (!accept(from, state)) return true;
    step = std::min(ds_, 2.0 * step);
  }
  finish(state);
  return true;
}

double PathFollower::locate_limit(const State& from, const Tangent& tangent, double len, double s_end,
                                  double rate_end) {
  // Regula falsi with the Illinois modification on the rate ds/dtau as a function of the
  // arc length tau from `from`: each evaluation is an arc step of length tau and the
  // tangent there. ds/dtau is smooth and crosses zero linearly at a limit point.
  double lo = 0.0, hi = len, r_lo = tangent.rate, r_hi = rate_end, best = std::max(from.s, s_end);
  int side = 0;
  State x;
  Tangent tx;
  Vector<double> chord;
  auto evaluate = [&](double tau) {
    int it = 0;
    if (!arc_step(from, tangent, tau, x, it)) return false;
    chord = x.q;
    chord -= from.q;
    if (!tangent_at(x, chord, tx)) return false;
    out_.iterations += it;
    return true;
  };
  for (int k = 0; k < kMaxLimitEvaluations && hi - lo > kLimitBracket * len; ++k) {
    double tau = (lo * r_hi - hi * r_lo) / (r_hi - r_lo);
    if (!(tau > lo && tau < hi)) tau = 0.5 * (lo + hi);
    // A step inside a converged one should converge; if not, bisect instead.
    if (!evaluate(tau)) {
      tau = 0.5 * (lo + hi);
      if (!evaluate(tau)) break;
    }
    best = std::max(best, x.s);
    if (tx.rate > 0.0) {
      lo = tau;
      r_lo = tx.rate;
      if (side == 1) r_hi *= 0.5;
      side = 1;
    } else {
      hi = tau;
      r_hi = tx.rate;
      if (side == -1) r_lo *= 0.5;
      side = -1;
    }
  }
  return best;
}

void PathFollower::continuation(State state, const Vector<double>& forward) {
  out_.continuation = true;
  out_.stepping_stopped = state.s;
  Tangent tangent;
  if (!tangent_at(state, forward, tangent)) {
    out_.end = StaticSolve::End::stalled;
    out_.end_load = state.s;
    return;
  }
  // First length: the last load step's change of q, or (from rest) the arc that raises
  // the load by one increment along the tangent.
  double len = out_.path.size() > 1 ? forward.l2_norm() : ds_ / std::max(std::abs(tangent.rate), 1e-300);
  len = std::min(len, kMaxArcMove * spec_.radius);
  int halvings = 0;
  State next;
  Vector<double> chord;
  while (out_.arc_steps < options_.max_arc_steps) {
    int it = 0;
    if (!arc_step(state, tangent, len, next, it)) {
      if (++halvings > kMaxArcHalvings) {
        out_.end = StaticSolve::End::stalled;
        out_.end_load = state.s;
        return;
      }
      len *= 0.5;
      continue;
    }
    halvings = 0;
    out_.iterations += it;
    if (state.s < 1.0 && next.s >= 1.0) {
      // The path crosses the full load: Newton at s = 1 from the interpolated point.
      State full;
      full.q = state.q;
      const double w = (1.0 - state.s) / (next.s - state.s);
      full.q.sadd(1.0 - w, w, next.q);
      full.s = 1.0;
      const int f = newton_at(full.q, 1.0);
      if (f >= 0) {
        out_.iterations += f;
        ++out_.arc_steps;
        if (accept(state, full)) finish(full);
        return;
      }
    }
    ++out_.arc_steps;
    if (!accept(state, next)) return;
    chord = next.q;
    chord -= state.q;
    Tangent ahead;
    if (!tangent_at(next, chord, ahead)) {
      out_.end = StaticSolve::End::stalled;
      out_.end_load = next.s;
      return;
    }
    if (std::isnan(out_.limit) && tangent.rate > 0.0 && ahead.rate <= 0.0)
      out_.limit = locate_limit(state, tangent, len, next.s, ahead.rate);
    // The next length: towards kTargetIterations corrector iterations (at most doubled
    // or halved), shorter (down to half) after a load change above one requested
    // increment, and no value of q moved by more than kMaxArcMove R.
    double scale = std::clamp(std::sqrt(static_cast<double>(kTargetIterations) / it), 0.5, 2.0);
    const double load_change = std::abs(next.s - state.s);
    if (load_change > 0.0) scale = std::min(scale, std::max(0.5, ds_ / load_change));
    scale = std::min(scale, kMaxArcMove * spec_.radius / chord.linfty_norm());
    len *= scale;
    state = std::move(next);
    tangent = std::move(ahead);
  }
  out_.end = StaticSolve::End::arc_steps_exhausted;
  out_.end_load = state.s;
}

StaticSolve PathFollower::run() {
  State state;
  state.q.reinit(N_);
  out_.path.push_back({0.0, {0.0, 0.0}});
  last_centreline_ = centreline(state.q);
  Vector<double> last_step;
  if (!options_.from_start && load_stepping(state, last_step)) return std::move(out_);
  // From rest the load-raising direction is F itself (F^T K^-1 F > 0 while K is
  // positive definite); otherwise the last load step's.
  continuation(state, last_step.size() ? last_step : F_);
  return std::move(out_);
}

}  // namespace

StaticSolve trace_path(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st,
                       const ContinuationOptions& continuation) {
  return PathFollower(spec, setup, st, continuation).run();
}

std::string failure_message(const StaticSolve& s, const ContinuationOptions& continuation) {
  std::string m = "fem statics: ";
  if (!std::isnan(s.limit)) m += "past a limit point at load factor " + number(s.limit) + ", the equilibrium path (arc-length continuation) ";
  switch (s.end) {
    case StaticSolve::End::contact:
      m += std::string(std::isnan(s.limit) ? "" : "reaches self-contact: ") + "the ring touches itself at load factor " +
           number(s.end_load) + ": " + s.contact + " (section depth " + number(s.depth, 6) + " m); the beam model does not include contact";
      break;
    case StaticSolve::End::arc_steps_exhausted:
      m += std::string(std::isnan(s.limit) ? "load stepping stopped at load factor " + number(s.stepping_stopped) + " and the arc-length continuation " : "") +
           "did not come back to the full load within " + std::to_string(continuation.max_arc_steps) +
           " arc-length steps (reached load factor " + number(s.end_load) + ")";
      break;
    case StaticSolve::End::stalled:
      m += std::string(std::isnan(s.limit) ? "load stepping stopped at load factor " + number(s.stepping_stopped) + " and the arc-length continuation " : "") +
           "stalled at load factor " + number(s.end_load) + " (the arc length was halved " +
           std::to_string(kMaxArcHalvings) + " times without a converged step)";
      break;
    case StaticSolve::End::reached:
      m += "reached the full load";
      break;
  }
  return m;
}

}  // namespace fem::detail
