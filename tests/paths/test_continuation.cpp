// The continuation driver (paths/continuation.hpp) against closed forms: a one-degree
// snap-through spring f(u) = u (u - 1)(u - 2) under the load s P. Its equilibrium path
// f(u) = s P has a maximum of the load at u = 1 - 1/sqrt(3), f = 2 / (3 sqrt(3)), a
// minimum at u = 1 + 1/sqrt(3), and rises again beyond: load stepping must stop at the
// maximum, the arc-length continuation carry the path through both turns to the full
// load, and the limit point come out at its closed-form value. A second unknown tied to
// the first by a multiplier checks that only the arc unknowns measure the arc.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <tuple>

#include "paths/continuation.hpp"
#include "ring/plastic.hpp"

namespace {

double f(double u) { return u * (u - 1.0) * (u - 2.0); }
double df(double u) { return 3.0 * u * u - 6.0 * u + 2.0; }

/// Unknowns (u, lambda) with R = (f(u) - s P + lambda, lambda - c u): the multiplier-like
/// second unknown carries c u, so the path is f(u) + c u = s P; only u measures the arc.
class Snap : public paths::Equilibrium {
 public:
  explicit Snap(double P, double c = 0.0) : P_(P), c_(c) {}
  std::function<bool(const paths::State&)> touches;  ///< contact hook: true at a state that touches
  std::vector<paths::State> accepted;
  bool inertia = false;  ///< says how many directions are unstable (f'(u) + c < 0)

  Eigen::Index size() const override { return 2; }
  Eigen::Index arc_size() const override { return 1; }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    const double u = x.z(0), lambda = x.z(1);
    r.resize(2);
    r << f(u) - x.s * P_ + lambda, lambda - c_ * u;
    B_ << df(u), 1.0, -P_,  //
        -c_, 1.0, 0.0,      //
        w(0), 0.0, ws;
    lu_.compute(B_);
    return std::abs(lu_.determinant()) > 1e-300;
  }
  bool solve(paths::Vector& y) override {
    y = lu_.solve(y);
    return y.allFinite();
  }
  double move(const paths::Vector& dz) const override { return std::abs(dz(0)) / 0.5; }
  bool converged(const paths::State&, const paths::Vector& dz, int) override { return dz.cwiseAbs().maxCoeff() <= 1e-13; }
  std::optional<int> unstable_directions(const paths::State& x) override {
    if (!inertia) return std::nullopt;
    return df(x.z(0)) + c_ < 0.0 ? 1 : 0;
  }
  std::optional<paths::Touch> accept(const paths::State& from, const paths::State& to) override {
    accepted.push_back(to);
    if (touches && touches(to)) return paths::Touch{1.0, "u passed " + std::to_string(to.z(0))};
    (void)from;
    return std::nullopt;
  }

 private:
  double P_, c_;
  Eigen::Matrix3d B_;
  Eigen::PartialPivLU<Eigen::Matrix3d> lu_;
};

paths::State rest() { return {paths::Vector::Zero(2), 0.0}; }

// The root of u^3 - 3 u^2 + 2 u = 1 beyond the minimum (Newton to round-off).
double far_root(double P) {
  double u = 2.5;
  for (int k = 0; k < 50; ++k) u -= (f(u) - P) / df(u);
  return u;
}

const double kLimit = 2.0 / (3.0 * std::sqrt(3.0));  // f at u = 1 - 1/sqrt(3)

TEST(Continuation, PassesBothTurnsOfASnapThroughToTheFullLoad) {
  Snap snap(1.0);
  const paths::Continuation options{20};
  const paths::Trace t = paths::follow(snap, rest(), options);
  ASSERT_EQ(t.end, paths::Trace::End::reached) << paths::failure_message(t, options);
  EXPECT_TRUE(t.continuation);
  // Load stepping stops within one halved increment (1/20 / 2^10) below the limit.
  EXPECT_LE(t.stepping_stopped, kLimit);
  EXPECT_GT(t.stepping_stopped, kLimit - 0.05);
  // The limit's bracket is 1e-6 of a step (~0.1): s there within |s''| (1e-7)^2 ~ 1e-13;
  // 1e-10 allows the corrector's 1e-13 tolerance.
  EXPECT_NEAR(t.limit, kLimit, 1e-10);
  // The equilibrium there: u = 1 - 1/sqrt(3), to the bracket's 1e-6 of an arc step (< 0.5:
  // the model's basin) in u, where s is flat.
  ASSERT_TRUE(t.limit_state.has_value());
  EXPECT_EQ(t.limit_state->s, t.limit);
  EXPECT_NEAR(t.limit_state->z(0), 1.0 - 1.0 / std::sqrt(3.0), 1e-6);
  EXPECT_DOUBLE_EQ(t.state.s, 1.0);
  EXPECT_NEAR(t.state.z(0), far_root(1.0), 1e-12);  // Newton at s = 1: 1e-13 correction
  // Every accepted point is on the path (the corrector's tolerance, 1e-13 on u).
  for (const auto& x : snap.accepted) EXPECT_NEAR(f(x.z(0)), x.s, 1e-11) << "u = " << x.z(0);
  EXPECT_GT(t.arc_steps, 0);
  EXPECT_EQ(t.steps, static_cast<int>(snap.accepted.size()));
}

TEST(Continuation, LoadSteppingAloneBelowTheLimitLoad) {
  Snap snap(0.3);  // below the maximum 0.385: twenty plain load steps
  const paths::Trace t = paths::follow(snap, rest(), {20});
  ASSERT_EQ(t.end, paths::Trace::End::reached);
  EXPECT_FALSE(t.continuation);
  EXPECT_EQ(t.steps, 20);
  EXPECT_TRUE(std::isnan(t.limit));
  double u = 0.0;  // the root below the maximum
  for (int k = 0; k < 50; ++k) u -= (f(u) - 0.3) / df(u);
  EXPECT_NEAR(t.state.z(0), u, 1e-12);
}

TEST(Continuation, FromRestTheSameEquilibrium) {
  Snap a(1.0), b(1.0);
  paths::Continuation arc{20};
  arc.from_start = true;
  const paths::Trace stepped = paths::follow(a, rest(), {20}), traced = paths::follow(b, rest(), arc);
  ASSERT_EQ(traced.end, paths::Trace::End::reached);
  EXPECT_EQ(traced.stepping_stopped, 0.0);
  EXPECT_NEAR(traced.state.z(0), stepped.state.z(0), 1e-12);
  EXPECT_NEAR(traced.limit, kLimit, 1e-10);
}

// Only u measures the arc: a multiplier unknown that carries c u changes the path to
// f(u) + c u = s P (limit at df = -c) but not the arc lengths' meaning.
TEST(Continuation, MultipliersAreNotPartOfTheArc) {
  const double c = 0.5, P = 1.0;
  Snap snap(P, c);
  const paths::Trace t = paths::follow(snap, rest(), {20});
  ASSERT_EQ(t.end, paths::Trace::End::reached);
  const double u1 = 1.0 - std::sqrt((1.0 - c) / 3.0);  // 3u^2 - 6u + 2 + c = 0
  EXPECT_NEAR(t.limit, (f(u1) + c * u1) / P, 1e-10);
  EXPECT_NEAR(t.state.z(1), c * t.state.z(0), 1e-12);
}

TEST(Continuation, ContactEndsThePathAsAResult) {
  Snap snap(1.0);
  snap.touches = [](const paths::State& x) { return x.z(0) > 1.2; };
  const paths::Continuation options{20};
  const paths::Trace t = paths::follow(snap, rest(), options);
  ASSERT_EQ(t.end, paths::Trace::End::contact);
  EXPECT_NEAR(t.limit, kLimit, 1e-10);  // the touch is past the maximum
  EXPECT_LT(t.end_load, kLimit);
  const std::string m = paths::failure_message(t, options);
  EXPECT_NE(m.find("past a limit point at load factor 0.3849"), std::string::npos) << m;
  EXPECT_NE(m.find("touches itself"), std::string::npos) << m;
}

// A Newton at the full load that cannot start from the point interpolated across it (here:
// the model refuses to linearize at s = 1 farther than 1e-7 of the load from its path, as a
// stiff contact or a plastic plateau may) is retried from a shorter arc step, which lands
// nearer the crossing, until it meets the full load; the path never runs on past s = 1.
class FussyAtFullLoad : public Snap {
 public:
  using Snap::Snap;
  int refused = 0;
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    if (x.s == 1.0 && std::abs(f(x.z(0)) - 1.0) > 1e-7) {
      ++refused;
      return false;
    }
    return Snap::linearize(x, w, ws, r);
  }
};
TEST(Continuation, AFullLoadNewtonThatFailsShortensTheStepInsteadOfRunningPastIt) {
  FussyAtFullLoad snap(1.0);
  const paths::Trace t = paths::follow(snap, rest(), paths::Continuation{20});
  ASSERT_EQ(t.end, paths::Trace::End::reached);
  EXPECT_GT(snap.refused, 0);  // the interpolated point was refused at least once
  EXPECT_EQ(t.end_load, 1.0);
  EXPECT_NEAR(t.state.z(0), far_root(1.0), 1e-10);
  for (const auto& x : snap.accepted) EXPECT_LE(x.s, 1.0) << x.z(0);
}

// A load that stops acting (u = min(s, 1/2): a ring sprung back clear of the plates that
// drove it) leaves an end that does not depend on s (dz/ds = 0). That is no jump over a limit
// point: load stepping goes on to the full load instead of halving its step to nothing.
class Released : public paths::Equilibrium {
 public:
  Eigen::Index size() const override { return 1; }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    const bool acting = x.s < 0.5;
    r.resize(1);
    r << x.z(0) - std::min(x.s, 0.5);
    B_ << 1.0, acting ? -1.0 : 0.0, w(0), ws;
    lu_.compute(B_);
    return std::abs(lu_.determinant()) > 1e-300;
  }
  bool solve(paths::Vector& y) override {
    y = lu_.solve(y);
    return y.allFinite();
  }
  double move(const paths::Vector& dz) const override { return std::abs(dz(0)); }
  bool converged(const paths::State&, const paths::Vector& dz, int) override { return std::abs(dz(0)) <= 1e-14; }
  std::optional<paths::Touch> accept(const paths::State&, const paths::State&) override { return std::nullopt; }

 private:
  Eigen::Matrix2d B_;
  Eigen::PartialPivLU<Eigen::Matrix2d> lu_;
};
TEST(Continuation, ALoadThatStopsActingIsNoJumpOverALimitPoint) {
  Released released;
  const paths::Trace t = paths::follow(released, {paths::Vector::Zero(1), 0.0}, paths::Continuation{8});
  ASSERT_EQ(t.end, paths::Trace::End::reached);
  EXPECT_FALSE(t.continuation);
  EXPECT_DOUBLE_EQ(t.state.z(0), 0.5);
}

TEST(Continuation, ReportsAPathThatDoesNotComeBackWithinTheArcStepBound) {
  Snap snap(1.0);
  paths::Continuation options{20};
  options.max_arc_steps = 3;
  const paths::Trace t = paths::follow(snap, rest(), options);
  ASSERT_EQ(t.end, paths::Trace::End::arc_steps_exhausted);
  EXPECT_EQ(t.arc_steps, 3);
  EXPECT_NE(paths::failure_message(t, options).find("within 3 arc-length steps"), std::string::npos);
}

}  // namespace

namespace {

// With the model's inertia known, the snap-through's two limit points each change the count
// of unstable directions by one, which the limit explains: the path still reaches the full
// load, and no bifurcation is reported.
TEST(Continuation, LimitPointsAreNotBifurcations) {
  Snap snap(1.0);
  snap.inertia = true;
  const paths::Continuation options{20};
  const paths::Trace t = paths::follow(snap, rest(), options);
  ASSERT_EQ(t.end, paths::Trace::End::reached) << paths::failure_message(t, options);
  EXPECT_NEAR(t.limit, kLimit, 1e-10);
}

/// Perfect pitchforks: R_i = (a_i - s b_i) u_i + u_i^3, i = 1, 2, whose trivial path u = 0
/// loses stability at s = a_i / b_i while the branches u_i^2 = s b_i - a_i leave it; the
/// load does no work on the trivial path (dR/ds = 0 there), as a uniform pressure on an
/// inextensible ring.
class Pitchfork : public paths::Equilibrium {
 public:
  Pitchfork(Eigen::Vector2d a, Eigen::Vector2d b) : a_(a), b_(b) {}
  Eigen::Index size() const override { return 2; }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    const Eigen::Vector2d u = x.z;
    r = (a_ - x.s * b_).cwiseProduct(u) + u.cwiseProduct(u).cwiseProduct(u);
    Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 2; ++i) {
      B(i, i) = a_(i) - x.s * b_(i) + 3.0 * u(i) * u(i);
      B(i, 2) = -b_(i) * u(i);
      B(2, i) = w(i);
    }
    B(2, 2) = ws;
    lu_.compute(B);
    return std::abs(lu_.determinant()) > 1e-300;
  }
  bool solve(paths::Vector& y) override {
    y = lu_.solve(y);
    return y.allFinite();
  }
  double move(const paths::Vector& dz) const override { return dz.cwiseAbs().maxCoeff() / 0.5; }
  bool converged(const paths::State&, const paths::Vector& dz, int) override { return dz.cwiseAbs().maxCoeff() <= 1e-13; }
  std::optional<paths::Touch> accept(const paths::State&, const paths::State&) override { return std::nullopt; }
  std::optional<int> unstable_directions(const paths::State& x) override {
    int k = 0;
    for (int i = 0; i < 2; ++i) k += a_(i) - x.s * b_(i) + 3.0 * x.z(i) * x.z(i) < 0.0 ? 1 : 0;
    return k;
  }
  /// The least stable unit direction, given with a negative sign (the eigenvector's sign is
  /// arbitrary: the driver must fix the side by its own rule, not by this one).
  std::optional<paths::Vector> critical_direction(const paths::State& x) override {
    Eigen::Vector2d d = (a_ - x.s * b_).array() + 3.0 * x.z.array().square();
    Eigen::Index i = 0;
    d.minCoeff(&i);
    return paths::Vector(-Eigen::Vector2d::Unit(i));
  }

 private:
  Eigen::Vector2d a_, b_;
  Eigen::PartialPivLU<Eigen::Matrix3d> lu_;
};

// A simple crossing at s = 1/4 and a double one at s = 1/2 (two directions at once, which
// the determinant's sign would not see): the path ends at the bifurcation, bracketed to
// 1e-6 of the load step (1/20) by bisection, with the count of directions lost.
TEST(Continuation, BifurcationsEndThePathLocatedToTheBracket) {
  const paths::Continuation options{20};
  for (const auto& [b, at, lost] : {std::tuple{Eigen::Vector2d(4.0, 2.0), 0.25, 1},
                                    std::tuple{Eigen::Vector2d(2.0, 2.0), 0.5, 2}}) {
    Pitchfork p(Eigen::Vector2d(1.0, 1.0), b);
    const paths::Trace t = paths::follow(p, {paths::Vector::Zero(2), 0.0}, options);
    ASSERT_EQ(t.end, paths::Trace::End::bifurcation) << paths::failure_message(t, options);
    EXPECT_LE(t.bifurcation_low, at);
    EXPECT_GE(t.bifurcation_high, at);
    EXPECT_LE(t.bifurcation_high - t.bifurcation_low, 1e-6 * 0.05);
    EXPECT_EQ(t.unstable_after - t.unstable_before, lost);
    EXPECT_NE(paths::failure_message(t, options).find("bifurcation"), std::string::npos);
  }
}

// Branch switching onto either side of a pitchfork (static.branch): the path leaves the
// trivial one at s = a_1 / b_1 = 1/4 and reaches the full load on the branch the closed
// form gives, u_1^2 = s b_1 - a_1 = 3, u_2 = 0, with u_1 > 0 on the positive side (the
// direction's largest unknown positive, whatever the sign the model gave it) and u_1 < 0
// on the negative: one path seen from either side, mirrored. Newton's 1e-13 on the
// corrections leaves ~1e-12 on u.
TEST(Continuation, BranchSwitchingFollowsEitherSideOfAPitchfork) {
  for (int side : {1, -1}) {
    paths::Continuation options{20};
    options.branch_switch = true;
    options.branch_side = side;
    Pitchfork p(Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(4.0, 0.5));
    const paths::Trace t = paths::follow(p, {paths::Vector::Zero(2), 0.0}, options);
    ASSERT_EQ(t.end, paths::Trace::End::reached) << paths::failure_message(t, options);
    ASSERT_EQ(t.branch_points.size(), 1u);
    EXPECT_NEAR(t.branch_points[0], 0.25, 1e-6 * 0.05);
    EXPECT_DOUBLE_EQ(t.state.s, 1.0);
    EXPECT_NEAR(t.state.z(0), side * std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(t.state.z(1), 0.0, 1e-12);
  }
}

// A rigid motion that only the load holds (a ring hanging from its pin): R = s c u + u^3, the
// path u = 0, the tangent s c neutral at rest. At rest the model counts the neutral
// direction as unstable, as the FE beam's frontal inertia did by rounding (it stopped the
// shipped hanging ring at load factor 1e-7 with "regains stability ... a bifurcation").
// The fall of the count on the first step from rest is the load taking hold of it: the
// path reaches the full load; a count that rises at rest would still be a branch point
// (BifurcationsEndThePathLocatedToTheBracket).
class Hanging : public paths::Equilibrium {
 public:
  Eigen::Index size() const override { return 1; }
  Eigen::Index arc_size() const override { return 1; }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    const double u = x.z(0);
    r.resize(1);
    r << x.s * kC * u + u * u * u;
    B_ << x.s * kC + 3.0 * u * u, -kC * u,  //
        w(0), ws;
    lu_.compute(B_);
    return std::abs(lu_.determinant()) > 1e-300;
  }
  bool solve(paths::Vector& y) override {
    y = lu_.solve(y);
    return y.allFinite();
  }
  double move(const paths::Vector& dz) const override { return std::abs(dz(0)) / 0.5; }
  bool converged(const paths::State&, const paths::Vector& dz, int) override { return dz.cwiseAbs().maxCoeff() <= 1e-13; }
  std::optional<int> unstable_directions(const paths::State& x) override {
    return x.s * kC + 3.0 * x.z(0) * x.z(0) <= 0.0 ? 1 : 0;  // the neutral rest counted unstable
  }
  std::optional<paths::Touch> accept(const paths::State&, const paths::State&) override { return std::nullopt; }

 private:
  static constexpr double kC = 2.0;
  Eigen::Matrix2d B_;
  Eigen::PartialPivLU<Eigen::Matrix2d> lu_;
};

TEST(Continuation, ALoadThatTakesHoldOfANeutralRestIsNoBifurcation) {
  Hanging hanging;
  const paths::Continuation options{10};
  const paths::Trace t = paths::follow(hanging, {paths::Vector::Zero(1), 0.0}, options);
  ASSERT_EQ(t.end, paths::Trace::End::reached) << paths::failure_message(t, options);
  EXPECT_DOUBLE_EQ(t.state.s, 1.0);
  EXPECT_EQ(t.state.z(0), 0.0);
  EXPECT_FALSE(t.continuation);
}

/// An elastic–plastic spring (ring/plastic.hpp, kinematic hardening) under the force s F:
/// its state committed at every accepted equilibrium, as a solver's hinges are.
class PlasticSpring : public paths::Equilibrium {
 public:
  PlasticSpring(double F) : F_(F) {}
  ring::BilinearLaw law{100.0, 1.0, 0.1, ring::Plastic::Rule::kinematic};
  ring::PlasticState state;
  std::vector<paths::State> accepted;

  Eigen::Index size() const override { return 1; }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    const ring::BilinearLaw::Point p = law.at(state, x.z(0));
    r.resize(1);
    r << p.force - x.s * F_;
    B_ << p.tangent, -F_, w(0), ws;
    lu_.compute(B_);
    return std::abs(lu_.determinant()) > 1e-300;
  }
  bool solve(paths::Vector& y) override {
    y = lu_.solve(y);
    return y.allFinite();
  }
  double move(const paths::Vector& dz) const override { return std::abs(dz(0)) / 0.5; }
  bool converged(const paths::State&, const paths::Vector& dz, int) override { return std::abs(dz(0)) <= 1e-13; }
  std::optional<paths::Touch> accept(const paths::State&, const paths::State& to) override {
    state = law.commit(state, to.z(0));
    accepted.push_back(to);
    return std::nullopt;
  }

 private:
  double F_;
  Eigen::Matrix2d B_;
  Eigen::PartialPivLU<Eigen::Matrix2d> lu_;
};

// A load history through a plastic spring: loading past yield (force 2, yield 1), unloading
// to zero, reversed loading and reloading. Closed forms of the bilinear law (k = 100, h = 0.1,
// H = h k / (1 - h)): at force f > Y the strain is Y/k + (f - Y)/(h k); unloading is elastic,
// so the residual strain is the plastic strain (1 - h)(f - Y)/(h k); kinematic hardening
// makes the reversed load -2 yield at f - 2Y = 0 (the Bauschinger effect), so at -2 the
// strain is the mirror image of +2's.
TEST(Continuation, ALoadHistoryVisitsEachFactorInTurnThroughAPlasticSpring) {
  PlasticSpring spring(2.0);
  paths::Continuation o;
  o.steps = 8;
  o.history = {1.0, 0.0, -1.0, 1.0};
  const paths::Trace t = paths::follow(spring, {paths::Vector::Zero(1), 0.0}, o);
  ASSERT_EQ(t.end, paths::Trace::End::reached) << paths::failure_message(t, o);
  EXPECT_DOUBLE_EQ(t.state.s, 1.0);
  const double k = 100.0, h = 0.1, Y = 1.0, f = 2.0;
  const double peak = Y / k + (f - Y) / (h * k), residual = (1.0 - h) * (f - Y) / (h * k);
  // Four legs 0 -> 1 -> 0 -> -1 -> 1 of `steps` = 8 increments each: 32 steps.
  ASSERT_EQ(spring.accepted.size(), 32u);
  const auto at = [&](std::size_t i) { return spring.accepted[i - 1]; };
  EXPECT_DOUBLE_EQ(at(8).s, 1.0);
  EXPECT_NEAR(at(8).z(0), peak, 1e-12);
  EXPECT_DOUBLE_EQ(at(16).s, 0.0);
  EXPECT_NEAR(at(16).z(0), residual, 1e-12);
  EXPECT_DOUBLE_EQ(at(24).s, -1.0);
  EXPECT_NEAR(at(24).z(0), -peak, 1e-12);
  EXPECT_NEAR(t.state.z(0), peak, 1e-12);
  EXPECT_EQ(t.steps, 32);
}

}  // namespace
