// The continuation driver (continuation.hpp): load stepping, arc-length continuation,
// the limit point, end events.
#include "paths/continuation.hpp"

#include "paths/newton.hpp"

#include <algorithm>
#include <functional>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace paths {
namespace {

/// The arc length adapts towards this many corrector iterations per step.
constexpr int kTargetIterations = 5;
/// A failed arc step halves the length; this many failures in a row end the path.
constexpr int kMaxArcHalvings = 30;
/// The limit point's bracket (in arc length) is narrowed to this fraction of the step
/// that contains it; the load factor there is then exact to ~|s''| (1e-6 len)^2.
constexpr double kLimitBracket = 1e-6;
constexpr int kMaxLimitEvaluations = 60;
/// A corrector's change of the load factor below this is converged (s is O(1)).
constexpr double kLoadTolerance = 1e-12;
/// A bifurcation on the load-stepping part is bisected to this fraction of its step.
constexpr double kBifurcationBracket = 1e-6;
/// Branch switching: the first step onto a branch moves this fraction of the basin; at
/// most this many switches per path.
constexpr double kBranchMove = 0.1;
constexpr std::size_t kMaxBranchSwitches = 4;

std::string number(double x, int digits = 9) {
  std::ostringstream o;
  o << std::setprecision(digits) << x;
  return o.str();
}

/// The path's unit tangent at a state (unit on the arc unknowns u), oriented forward,
/// and ds/dtau along it (tau: the arc length).
struct Tangent {
  Vector t;
  double rate = 0.0;
};

/// One path from rest: run() is load_stepping(), then continuation() if needed.
class Follower {
 public:
  /// The equilibrium at a fraction f of a step (its load, or its arc length): false when
  /// Newton does not find it.
  using Between = std::function<bool(double f, State& x)>;

  Follower(Equilibrium& eq, const Continuation& options)
      : eq_(eq), options_(options), N_(eq.size()), m_(eq.arc_size()), ds_(1.0 / std::max(1, options.steps)) {}

  Trace run(const State& rest) {
    State state = rest;
    out_.state = rest;
    unstable_ = eq_.unstable_directions(rest);
    Vector last_step;
    if (options_.from_start || !load_stepping(state, last_step)) {
      if (last_step.size() == 0 && !load_tangent(state, last_step)) {
        // No load step taken, and no load-raising direction dz/ds at the state itself.
        stall(state.s);
        return std::move(out_);
      }
      continuation(state, last_step);
    }
    while (out_.end == Trace::End::bifurcation && options_.branch_switch &&
           out_.branch_points.size() < kMaxBranchSwitches) {
      const State at = out_.state;
      State onto;
      if (!switch_branch(at, onto)) break;
      out_.branch_points.push_back(at.s);
      out_.end = Trace::End::reached;
      unstable_ = eq_.unstable_directions(onto);  // the branch's own count from here on
      ++out_.arc_steps;
      if (!accept(at, onto)) break;
      continuation(onto, onto.z - at.z);
    }
    return std::move(out_);
  }

  /// One arc step from the bifurcation `at` along the model's critical direction, landed
  /// on the branch (its chord at least half along the direction); false when none lands.
  bool switch_branch(const State& at, State& onto) {
    const std::optional<Vector> d = eq_.critical_direction(at);
    if (!d || d->size() != N_ || d->head(m_).norm() == 0.0) return false;
    Eigen::Index largest = 0;
    d->head(m_).cwiseAbs().maxCoeff(&largest);
    const double side = ((*d)(largest) > 0.0 ? 1.0 : -1.0) * (options_.branch_side < 0 ? -1.0 : 1.0);
    Tangent t{side * *d / d->head(m_).norm(), 0.0};
    double len = kBranchMove / std::max(eq_.move(t.t), 1e-300);
    Tangent ahead;
    for (int attempt = 0; attempt < 6; ++attempt, len *= 0.5) {
      int it = 0;
      if (!arc_step(at, t, len, onto, it, ahead)) continue;
      out_.iterations += it;
      if (std::abs((onto.z - at.z).head(m_).dot(t.t.head(m_))) >= 0.5 * len) return true;
    }
    return false;
  }

 private:
  /// Newton at the fixed load factor x.s from x.z (updated). Iterations, or -1. With
  /// `dzds`, also dz/ds at the solution, from the last factorization.
  int newton_at(State& x, Vector* dzds) {
    const Vector start = x.z, w = Vector::Zero(m_);
    int iteration = 0;
    NewtonFunctions system;
    system.linearize_at = [&](bool) {
      ++iteration;
      return eq_.linearize(x, w, 1.0, r_);
    };
    system.solve_for = [&](Correction& c) {
      y_.resize(N_ + 1);
      y_.head(N_) = -r_;
      y_(N_) = 0.0;
      if (!eq_.solve(y_)) return false;
      c.move = eq_.move(x.z + y_.head(N_) - start);  // above 1: left the basin
      return true;
    };
    system.apply_correction = [&] { x.z += y_.head(N_); };
    system.settle_at = [&](bool, const Correction&) {
      return eq_.converged(x, y_.head(N_), iteration) ? Verdict::converged : Verdict::iterate;
    };
    const NewtonResult result = newton(system, Rule{});
    if (!result.converged) eq_.reject();
    if (!result.converged || (dzds && !solve_unit(*dzds))) return -1;
    return result.iterations;
  }

  /// The last factorization applied to (0, 1): the tangent of its border.
  bool solve_unit(Vector& t) {
    y_.setZero(N_ + 1);
    y_(N_) = 1.0;
    if (!eq_.solve(y_)) return false;
    t = y_;
    return true;
  }

  /// dz/ds at the equilibrium x (one factorization with the border of a fixed load).
  bool load_tangent(const State& x, Vector& dzds) {
    if (!eq_.linearize(x, Vector::Zero(m_), 1.0, r_) || !solve_unit(dzds)) return false;
    dzds.conservativeResize(N_);
    return true;
  }

  /// A solution y of a bordered system whose border was w (w . y_u = y_s's row) as the
  /// path's unit tangent: normalized on u, rate = ds/dtau.
  bool to_tangent(const Vector& y, Tangent& out) const {
    const double norm = y.head(m_).norm();
    if (!std::isfinite(norm) || !std::isfinite(y(N_)) || norm == 0.0) return false;
    out.t = y.head(N_) / norm;
    out.rate = y(N_) / norm;
    return true;
  }

  /// The tangent at x oriented by `forward` (its u part): one factorization.
  bool tangent_at(const State& x, const Vector& forward, Tangent& out) {
    const Vector w = forward.head(m_).normalized();
    Vector y;
    return eq_.linearize(x, w, 0.0, r_) && solve_unit(y) && to_tangent(y, out);
  }

  /// One arc step of length `len` from `from` along `tangent` (the corrector of the
  /// header); false (`to` unusable) when it does not converge. On success the last
  /// factorization's border is the chord: `ahead` is the tangent at `to`, oriented by it.
  bool arc_step(const State& from, const Tangent& tangent, double len, State& to, int& iterations, Tangent& ahead) {
    to.z = from.z + len * tangent.t;
    to.s = from.s + len * tangent.rate;
    const Vector predicted = to.z.head(m_);
    int iteration = 0;
    NewtonFunctions system;
    system.linearize_at = [&](bool) {
      ++iteration;
      const Vector d = (to.z.head(m_) - from.z.head(m_)) / len;
      if (!eq_.linearize(to, d, 0.0, r_)) return false;
      y_.resize(N_ + 1);
      y_.head(N_) = -r_;
      y_(N_) = -0.5 * len * (d.squaredNorm() - 1.0);
      return true;
    };
    system.solve_for = [&](Correction& c) {
      if (!eq_.solve(y_) || !std::isfinite(to.s + y_(N_))) return false;
      // A corrector that moves a whole step away from the predicted point has left it
      // for another part of the path (or of the sphere): the step is too long.
      c.move = (to.z.head(m_) + y_.head(m_) - predicted).norm() / len;
      return true;
    };
    system.apply_correction = [&] {
      to.z += y_.head(N_);
      to.s += y_(N_);
    };
    system.settle_at = [&](bool, const Correction&) {
      return eq_.converged(to, y_.head(N_), iteration) && std::abs(y_(N_)) <= kLoadTolerance ? Verdict::converged
                                                                                               : Verdict::iterate;
    };
    const NewtonResult result = newton(system, Rule{});
    iterations = result.iterations;
    if (!result.converged) {
      eq_.reject();
      return false;
    }
    Vector y;
    return solve_unit(y) && to_tangent(y, ahead);
  }

  /// Whether `now` unstable directions at an equilibrium reached from `from` differ from the
  /// last accepted count. At rest (load factor 0) the true count is 0, an unloaded ring's
  /// stiffness being positive semidefinite: rigid motions that only the load holds (a ring
  /// hanging from its pin) are neutral there, and rounding may count them as unstable (the
  /// FE beam's frontal inertia did, and stopped the shipped hanging ring at load factor
  /// 1e-7). So a fall in the count on a step from rest is the load taking hold of them, not
  /// a branch point: it becomes the count, and no change.
  bool count_changed(const State& from, int now) {
    if (from.s == 0.0 && now < *unstable_) unstable_ = now;
    return now != *unstable_;
  }

  /// Records the accepted `to`; false (and the trace ended) when the ring touched itself
  /// or the path passed a bifurcation. `limits`: limit points passed between them (each
  /// explains a change of one unstable direction); `between`: the equilibria inside the
  /// step, for locating a touch; `known`: the unstable directions at `to`, if counted.
  bool accept(const State& from, const State& to, int limits = 0, const Between* between = nullptr,
              std::optional<int> known = std::nullopt) {
    ++out_.steps;
    if (between)
      if (const std::optional<double> c = eq_.clearance(to); c && *c < 0.0) {
        touched(from, to, *between);
        return false;
      }
    if (const auto touch = eq_.accept(from, to)) {
      out_.end = Trace::End::contact;
      out_.end_load = from.s + touch->at * (to.s - from.s);
      out_.contact = touch->where;
      out_.state = from;
      return false;
    }
    if (unstable_) {
      const std::optional<int> now = known ? known : eq_.unstable_directions(to);
      if (now && count_changed(from, *now) && std::abs(*now - *unstable_) > limits) {
        bifurcation(from, to, *now);
        return false;
      }
      unstable_ = now;
    }
    out_.state = to;
    return true;
  }

  /// Ends the path where the ring first touches itself between the accepted `from` (clear)
  /// and `to` (overlapping): bisection on the fraction of the step, `between` giving the
  /// equilibrium there, to kBifurcationBracket; the touching equilibrium is the result.
  void touched(const State& from, const State& to, const Between& between) {
    double lo = 0.0, hi = 1.0;
    State x, touching = to;
    while (hi - lo > kBifurcationBracket && between(0.5 * (lo + hi), x)) {
      const std::optional<double> c = eq_.clearance(x);
      if (!c) break;
      if (*c < 0.0) {
        hi = 0.5 * (lo + hi);
        touching = x;
      } else {
        lo = 0.5 * (lo + hi);
      }
    }
    const auto touch = eq_.accept(from, touching);
    out_.end = Trace::End::contact;
    out_.end_load = touching.s;
    out_.contact = touch ? touch->where : "the ring touches itself";
    out_.state = touching;
  }

  /// Ends the path at a bifurcation between the accepted `from` and `to` (where the count
  /// of unstable directions is `after`). On load stepping (`bisect`) the bracket is then
  /// bisected on the load factor to kBifurcationBracket of an increment, each level solved
  /// by Newton from the bracket's lower end (on the followed branch), or, where Newton
  /// misses its tolerance beside the singular point, taken between the two ends by linear
  /// interpolation (its inertia differs from the equilibrium's only within the bracket).
  void bifurcation(const State& from, const State& to, int after, bool bisect = false) {
    out_.end = Trace::End::bifurcation;
    out_.unstable_before = *unstable_;
    out_.unstable_after = after;
    State lo = from, hi = to;
    while (bisect && hi.s - lo.s > kBifurcationBracket * ds_) {
      State mid{lo.z, 0.5 * (lo.s + hi.s)};
      if (const int it = newton_at(mid, nullptr); it >= 0) out_.iterations += it;
      else mid = {0.5 * (lo.z + hi.z), 0.5 * (lo.s + hi.s)};
      const std::optional<int> k = eq_.unstable_directions(mid);
      if (!k) break;
      (*k == *unstable_ ? lo : hi) = mid;
    }
    out_.bifurcation_low = lo.s;
    out_.bifurcation_high = hi.s;
    out_.end_load = lo.s;
    out_.state = lo;
  }

  void reached(const State& x) {
    out_.end = Trace::End::reached;
    out_.end_load = x.s;
    out_.state = x;
  }

  void stall(double s) {
    out_.end = Trace::End::stalled;
    out_.end_load = s;
  }

  /// Load stepping from the state; false when a load level cannot be passed (the state
  /// is then the last equilibrium and `last_step` the change of z into it).
  bool load_stepping(State& state, Vector& last_step) {
    double step = ds_;
    State trial;
    Vector dzds;
    std::optional<State> beyond;  ///< the last level found past a change of stability
    int beyond_count = 0;
    while (state.s < 1.0 - 1e-14) {
      trial.z = state.z;
      trial.s = std::min(1.0, state.s + step);
      const int it = newton_at(trial, &dzds);
      // A step whose end, looked at in the direction of the step, has the load falling
      // has jumped over a limit point onto the path beyond it: like a failed Newton, it
      // is cut. (A step that moves nothing, under a zero load or a load the model carries
      // without deforming, as a uniform pressure on an inextensible ring, jumped nowhere:
      // a change of 1e-10 of the Newton basin is round-off.)
      // An end that does not depend on the load (dz/ds = 0: a ring that springs back clear of
      // the plates that drove it) has no limit point to have jumped over.
      const Vector change = trial.z - state.z;
      const bool moved = eq_.move(change) > 1e-10;
      const bool jumped = it >= 0 && moved && dzds.head(m_).squaredNorm() > 0.0 &&  // dz/ds only where Newton converged
                          !(change.head(m_).dot(dzds.head(m_)) > 0.0);
      if (it < 0 || jumped) {
        if (beyond) {
          // Beside the branch point the tangent is nearly singular and Newton may miss its
          // tolerance: shorter tries (not halves, which could meet the point again) until
          // the step is the bracket's width; the bracket is then up to the nearest level
          // seen past it.
          step *= 0.37;
          if (step > kBifurcationBracket * ds_) continue;
          bifurcation(state, *beyond, beyond_count, true);
          return true;
        }
        step *= 0.5;
        if (step < ds_ / (1 << options_.max_halvings)) return false;
        continue;
      }
      // A level whose stability differs from the last one's holds a bifurcation, or Newton
      // jumped to another branch near one: approached by halving the increment (each try
      // from the accepted equilibrium, so on its branch) until it is kBifurcationBracket
      // of an increment, where accept() ends the path at it.
      const std::optional<int> count = unstable_ ? eq_.unstable_directions(trial) : std::nullopt;
      if (count && count_changed(state, *count) && step > kBifurcationBracket * ds_) {
        beyond = trial;
        beyond_count = *count;
        step *= 0.5;
        continue;
      }
      out_.iterations += it;
      const State from = state;
      state = trial;
      last_step = change;
      const Between at_load = [&](double f, State& x) {
        x = {from.z, from.s + f * (state.s - from.s)};
        return newton_at(x, nullptr) >= 0;
      };
      if (!accept(from, state, 0, &at_load, count)) return true;
      step = std::min(ds_, 2.0 * step);
    }
    reached(state);
    return true;
  }

  /// Narrows the first maximum of s between `from` (rate > 0) and the step of length
  /// `len` whose end has rate `rate_end` <= 0; returns the largest s met.
  double locate_limit(const State& from, const Tangent& tangent, double len, const State& end, double rate_end) {
    // Regula falsi with the Illinois modification on the rate ds/dtau as a function of
    // the arc length tau from `from`: each evaluation is an arc step of length tau and
    // the tangent there. ds/dtau is smooth and crosses zero linearly at a limit point.
    double lo = 0.0, hi = len, r_lo = tangent.rate, r_hi = rate_end, best = std::max(from.s, end.s);
    out_.limit_state = from.s >= end.s ? from : end;
    int side = 0;
    State x;
    Tangent tx;
    auto evaluate = [&](double tau) {
      int it = 0;
      if (!arc_step(from, tangent, tau, x, it, tx)) return false;
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
      if (x.s > best) {
        best = x.s;
        out_.limit_state = x;
      }
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

  /// Arc-length continuation from `state` in the direction `forward` (a change of z)
  /// until the path reaches the full load or ends.
  void continuation(State state, const Vector& forward) {
    if (!out_.continuation) out_.stepping_stopped = state.s;
    out_.continuation = true;
    Tangent tangent;
    if (!tangent_at(state, forward, tangent)) {
      stall(state.s);
      return;
    }
    // First length: the last load step's change, or (from rest) the arc that raises the
    // load by one increment along the tangent; within the model's basin.
    double len = out_.steps > 0 ? forward.head(m_).norm() : ds_ / std::max(std::abs(tangent.rate), 1e-300);
    if (const double m = eq_.move(len * tangent.t); m > 1.0) len /= m;
    int halvings = 0;
    State next;
    Tangent ahead;
    while (out_.arc_steps < options_.max_arc_steps) {
      int it = 0;
      if (!arc_step(state, tangent, len, next, it, ahead)) {
        if (++halvings > kMaxArcHalvings) {
          stall(state.s);
          return;
        }
        len *= 0.5;
        continue;
      }
      if (state.s < 1.0 && next.s >= 1.0) {
        // The path crosses the full load: Newton at s = 1 from the interpolated point.
        const double w = (1.0 - state.s) / (next.s - state.s);
        State full{state.z + w * (next.z - state.z), 1.0};
        const int f = newton_at(full, nullptr);
        if (f >= 0) {
          out_.iterations += it + f;
          ++out_.arc_steps;
          if (accept(state, full, limit_between(tangent.rate, ahead.rate))) reached(full);
          return;
        }
        // Never step past the full load without meeting it (the path would run on beyond
        // it): a shorter step lands nearer the crossing, where the interpolation is better.
        if (++halvings > kMaxArcHalvings) {
          stall(state.s);
          return;
        }
        len *= 0.5;
        continue;
      }
      halvings = 0;
      out_.iterations += it;
      ++out_.arc_steps;
      const Between along = [&](double f, State& x) {
        int iterations = 0;
        Tangent unused;
        return arc_step(state, tangent, f * len, x, iterations, unused);
      };
      if (!accept(state, next, limit_between(tangent.rate, ahead.rate), &along)) return;
      if (std::isnan(out_.limit) && tangent.rate > 0.0 && ahead.rate <= 0.0)
        out_.limit = locate_limit(state, tangent, len, next, ahead.rate);
      // The next length: towards kTargetIterations corrector iterations (at most doubled
      // or halved), shorter (down to half) after a load change above one increment, and
      // a chord within the model's basin.
      double scale = std::clamp(std::sqrt(static_cast<double>(kTargetIterations) / it), 0.5, 2.0);
      const double load_change = std::abs(next.s - state.s);
      if (load_change > 0.0) scale = std::min(scale, std::max(0.5, ds_ / load_change));
      scale = std::min(scale, 1.0 / eq_.move(next.z - state.z));
      len *= scale;
      state = std::move(next);
      tangent = std::move(ahead);
    }
    out_.end = Trace::End::arc_steps_exhausted;
    out_.end_load = state.s;
  }

  /// 1 when ds/dtau changes sign between two tangents (a limit point between them).
  static int limit_between(double rate_from, double rate_to) { return (rate_from > 0.0) != (rate_to > 0.0) ? 1 : 0; }

  Equilibrium& eq_;
  const Continuation& options_;
  std::optional<int> unstable_;  ///< unstable directions of the last accepted equilibrium
  const Eigen::Index N_, m_;
  const double ds_;  ///< the requested load increment 1 / steps
  Vector r_, y_;
  Trace out_;
};

/// One leg of a load history, from load factor a to b, as an equilibrium of its own with the
/// leg's factor t = (s - a) / (b - a) running from 0 to 1, so that the driver above follows
/// it unchanged. Its bordered Jacobian is the model's with the load column scaled by b - a:
/// B' = B diag(1, ..., 1, b - a) when the model is asked for the corner ws / (b - a), so a
/// solve is the model's with its last value divided by b - a.
class Leg final : public Equilibrium {
 public:
  Leg(Equilibrium& eq, double a, double b) : eq_(eq), a_(a), d_(b - a) {}
  State model(const State& x) const { return {x.z, a_ + d_ * x.s}; }
  State leg(const State& x) const { return {x.z, (x.s - a_) / d_}; }
  double load(double t) const { return a_ + d_ * t; }

  Eigen::Index size() const override { return eq_.size(); }
  Eigen::Index arc_size() const override { return eq_.arc_size(); }
  bool linearize(const State& x, const Vector& w, double ws, Vector& r) override {
    return eq_.linearize(model(x), w, ws / d_, r);
  }
  bool solve(Vector& y) override {
    if (!eq_.solve(y)) return false;
    y[y.size() - 1] /= d_;
    return true;
  }
  double move(const Vector& dz) const override { return eq_.move(dz); }
  bool converged(const State& x, const Vector& dz, int iteration) override {
    return eq_.converged(model(x), dz, iteration);
  }
  std::optional<Touch> accept(const State& from, const State& to) override { return eq_.accept(model(from), model(to)); }
  void reject() override { eq_.reject(); }
  std::optional<int> unstable_directions(const State& x) override { return eq_.unstable_directions(model(x)); }
  std::optional<double> clearance(const State& x) override { return eq_.clearance(model(x)); }
  std::optional<Vector> critical_direction(const State& x) override { return eq_.critical_direction(model(x)); }

 private:
  Equilibrium& eq_;
  const double a_, d_;
};

/// The legs of options.history one after the other, each a path of its own from where the
/// last ended; the trace's load factors are the model's, its counts the legs' sums.
Trace follow_history(Equilibrium& eq, const State& rest, const Continuation& options) {
  Continuation leg_options = options;
  leg_options.history.clear();
  Trace all;
  all.state = rest;
  double a = rest.s;
  for (const double b : options.history) {
    if (b == a) continue;
    Leg leg(eq, a, b);
    Trace t = Follower(leg, leg_options).run(leg.leg(all.state));
    all.end = t.end;
    all.state = leg.model(t.state);
    all.steps += t.steps;
    all.arc_steps += t.arc_steps;
    all.iterations += t.iterations;
    all.continuation = all.continuation || t.continuation;
    if (std::isnan(all.limit) && !std::isnan(t.limit)) {
      all.limit = leg.load(t.limit);
      if (t.limit_state) all.limit_state = leg.model(*t.limit_state);
    }
    all.stepping_stopped = leg.load(t.stepping_stopped);
    all.end_load = leg.load(t.end_load);
    all.contact = t.contact;
    all.bifurcation_low = leg.load(t.bifurcation_low);
    all.bifurcation_high = leg.load(t.bifurcation_high);
    all.unstable_before = t.unstable_before;
    all.unstable_after = t.unstable_after;
    for (const double p : t.branch_points) all.branch_points.push_back(leg.load(p));
    if (t.end != Trace::End::reached) return all;
    a = b;
  }
  all.end = Trace::End::reached;
  all.end_load = a;
  return all;
}

}  // namespace

Trace follow(Equilibrium& eq, const State& rest, const Continuation& options) {
  if (!options.history.empty()) return follow_history(eq, rest, options);
  return Follower(eq, options).run(rest);
}

std::string failure_message(const Trace& t, const Continuation& options) {
  const bool limit = !std::isnan(t.limit);
  std::string m;
  if (limit) m = "past a limit point at load factor " + number(t.limit) + ", the equilibrium path (arc-length continuation) ";
  const std::string stopped =
      limit ? "" : "load stepping stopped at load factor " + number(t.stepping_stopped) + " and the arc-length continuation ";
  switch (t.end) {
    case Trace::End::contact:
      m += std::string(limit ? "reaches self-contact: " : "") + "the ring touches itself at load factor " +
           number(t.end_load) + ": " + t.contact;
      break;
    case Trace::End::arc_steps_exhausted:
      m += stopped + "did not come back to the full load within " + std::to_string(options.max_arc_steps) +
           " arc-length steps (reached load factor " + number(t.end_load) + ")";
      break;
    case Trace::End::stalled:
      m += stopped + "stalled at load factor " + number(t.end_load) + " (the arc length was halved " +
           std::to_string(kMaxArcHalvings) + " times without a converged step)";
      break;
    case Trace::End::bifurcation: {
      const int k = t.unstable_after - t.unstable_before;
      m += std::string(limit ? "meets " : "") + "a bifurcation point between load factors " +
           number(t.bifurcation_low) + " and " + number(t.bifurcation_high) + ": the tangent stiffness " +
           (k > 0 ? "loses " : "regains ") + "stability in " + std::to_string(std::abs(k)) + " direction" +
           (std::abs(k) == 1 ? "" : "s") + " without a limit point, so another equilibrium path branches off there "
           "(the ring buckles) and the one followed is " + (k > 0 ? "unstable" : "not the only one") +
           " beyond it; [buckling] estimates where";
      if (std::abs(k) >= 2)
        m += "; it loses " + std::to_string(std::abs(k)) + " at once, as a symmetric ring does whose buckled shape may "
             "turn freely: a small load that selects the shape (an imperfection) lets the path follow one";
      break;
    }
    case Trace::End::reached: m += "reached the full load"; break;
  }
  return m;
}

}  // namespace paths
