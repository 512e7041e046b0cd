// The one Newton (paths/newton.hpp) against oracles outside it: a scalar equation whose root
// and whose quadratic convergence constant are known in closed form, systems that leave the
// basin, never settle or keep a stale matrix on purpose, and an elastic-plastic spring with
// kinematic hardening whose hysteresis loop has a closed-form area (internal variables,
// paths/internal.hpp, committed at accepted load levels only).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "paths/internal.hpp"
#include "paths/newton.hpp"

namespace {

/// f(x) = x^3 - 2 by full Newton, or with a matrix (the slope) kept from x = kept_at.
class Cubic : public paths::NewtonSystem {
 public:
  double x = 2.0;
  double slope = 0.0;        ///< the factored "matrix"
  bool have = false;         ///< a slope is kept from an earlier solve
  std::vector<bool> fresh;   ///< per linearization
  std::vector<double> iterates;
  double basin = HUGE_VAL;   ///< a correction above this leaves the basin

  bool has_matrix() const override { return have; }
  bool linearize(bool f) override {
    fresh.push_back(f);
    r_ = x * x * x - 2.0;
    if (f) slope = 3.0 * x * x;
    have = true;
    return true;
  }
  bool solve(paths::Correction& c) override {
    d_ = -r_ / slope;
    c.size = std::abs(d_);
    c.move = std::abs(d_) / basin;
    return true;
  }
  void apply() override {
    x += d_;
    iterates.push_back(x);
  }

 private:
  double r_ = 0.0, d_ = 0.0;
};

const double kRoot = std::cbrt(2.0);

// Full Newton converges quadratically: e_{k+1} / e_k^2 -> f''(r) / (2 f'(r)) = 1 / r
// (the Taylor expansion of Newton's map), and stops at the first correction below the
// tolerance.
TEST(Newton, FullNewtonConvergesQuadraticallyToTheRoot) {
  Cubic f;
  paths::Rule rule;
  rule.tolerance = 1e-9;
  const paths::NewtonResult r = paths::newton(f, rule);
  ASSERT_TRUE(r.converged);
  EXPECT_FALSE(r.reused);
  EXPECT_NEAR(f.x, kRoot, 1e-15 * kRoot);
  for (bool fr : f.fresh) EXPECT_TRUE(fr);  // no reuse asked: every iteration is fresh
  // The last two errors big enough to measure show the constant 1 / r (within 5 %: the
  // next Taylor term is O(e)).
  int checked = 0;
  for (std::size_t k = 0; k + 1 < f.iterates.size(); ++k) {
    const double e0 = f.iterates[k] - kRoot, e1 = f.iterates[k + 1] - kRoot;
    if (std::abs(e0) > 1e-2 || std::abs(e1) < 1e-12) continue;
    EXPECT_NEAR(e1 / (e0 * e0), 1.0 / kRoot, 0.05 / kRoot) << "k = " << k;
    ++checked;
  }
  EXPECT_GE(checked, 1);
  // The correction that stopped it was below the tolerance, the one before it was not.
  const std::size_t n = f.iterates.size();
  ASSERT_GE(n, 2u);
  EXPECT_LE(std::abs(f.iterates[n - 1] - f.iterates[n - 2]), 1e-9);
  EXPECT_EQ(r.iterations, static_cast<int>(n));
}

// The basin: a first correction of x = 2 -> 1.42 (0.58) leaves a basin of 0.1, and a fresh
// matrix cannot be refreshed: the solve fails at once, the iterate untouched.
TEST(Newton, ACorrectionBeyondTheBasinFailsAtOnce) {
  Cubic f;
  f.basin = 0.1;
  const paths::NewtonResult r = paths::newton(f, {});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_EQ(f.x, 2.0);
}

// The cap: a system that never settles fails after exactly the cap's iterations.
TEST(Newton, ASystemThatNeverSettlesFailsAtTheCap) {
  struct Never : Cubic {
    paths::Verdict settle(bool, const paths::Correction&) override { return paths::Verdict::iterate; }
  } f;
  paths::Rule rule;
  rule.cap = 7;
  EXPECT_EQ(paths::newton(f, rule).iterations, 7);
  EXPECT_FALSE(paths::newton(f, rule).converged);
  Never g;
  EXPECT_EQ(paths::newton(g, {}).iterations, paths::kNewtonCap);
}

// Jacobian reuse: a slope kept from x = 3 (27, against 3 r^2 = 4.76 at the root) serves the
// first iteration only, which the solve reports; the second is fresh, and the solve then
// converges as full Newton does. Without reuse the kept slope is never used.
TEST(Newton, AKeptMatrixServesTheFirstIterationAndIsThenRefreshed) {
  Cubic f;
  f.slope = 27.0;
  f.have = true;
  f.x = 1.3;
  paths::Rule rule;
  rule.tolerance = 1e-12;
  rule.reuse = true;
  const paths::NewtonResult r = paths::newton(f, rule);
  ASSERT_TRUE(r.converged);
  EXPECT_TRUE(r.reused);
  ASSERT_GE(f.fresh.size(), 2u);
  EXPECT_FALSE(f.fresh[0]);
  EXPECT_TRUE(f.fresh[1]);
  // A matrix kept within the solve contracts by q <= 1/8 per iteration (else it is
  // refreshed), so the error after a last correction below the tolerance is at most
  // tolerance q / (1 - q) < tolerance.
  EXPECT_NEAR(f.x, kRoot, rule.tolerance);

  Cubic g;
  g.slope = 27.0;
  g.have = true;
  g.x = 1.3;
  rule.reuse = false;
  EXPECT_FALSE(paths::newton(g, rule).reused);
  EXPECT_TRUE(g.fresh[0]);
}

// A kept matrix whose correction leaves the basin is dropped and the iteration repeated
// with a fresh one (counted), instead of failing: slope 0.5 kept, x = 1.3: the kept
// correction -(2.197 - 2) / 0.5 = -0.39 is beyond a basin of 0.2, the fresh one
// (-0.039) is not.
TEST(Newton, AKeptMatrixThatLeavesTheBasinIsRefreshedNotFailed) {
  Cubic f;
  f.slope = 0.5;
  f.have = true;
  f.x = 1.3;
  f.basin = 0.2;
  paths::Rule rule;
  rule.tolerance = 1e-12;
  rule.reuse = true;
  const paths::NewtonResult r = paths::newton(f, rule);
  ASSERT_TRUE(r.converged);
  EXPECT_FALSE(f.fresh[0]);
  EXPECT_TRUE(f.fresh[1]);
  EXPECT_EQ(f.iterates.size() + 1, static_cast<std::size_t>(r.iterations));  // the repeat applied nothing
  EXPECT_NEAR(f.x, kRoot, rule.tolerance);  // modified Newton's bound, as above
}

/// A spring of stiffness k with linear kinematic hardening (plastic modulus H, yield force
/// Fy) under a force F: k (u - up) = F, the plastic displacement up and the back force b
/// (= H up) its internal variables, found by the return mapping from the committed ones.
class PlasticSpring : public paths::NewtonSystem {
 public:
  struct State {
    double up = 0.0;
  };
  PlasticSpring(double k, double H, double Fy) : k_(k), H_(H), Fy_(Fy) {}
  paths::InternalVariables<State> plastic;
  double u = 0.0, force = 0.0;
  bool fail_next = false;  ///< the next solve fails after its first iteration (a rejected level)

  bool linearize(bool) override {
    // Return mapping from the committed state: trial force k (u - up), yield where
    // |trial - b| > Fy; the consistent tangent k H / (k + H) there.
    const State& c = plastic.committed();
    const double trial = k_ * (u - c.up), b = H_ * c.up;
    const double excess = std::abs(trial - b) - Fy_;
    State& t = plastic.trial();
    t = c;
    tangent_ = k_;
    if (excess > 0.0) {
      t.up = c.up + std::copysign(excess / (k_ + H_), trial - b);
      tangent_ = k_ * H_ / (k_ + H_);
    }
    r_ = k_ * (u - t.up) - force;
    return true;
  }
  bool solve(paths::Correction& c) override {
    d_ = -r_ / tangent_;
    c.size = std::abs(d_);
    c.move = 0.0;
    return true;
  }
  void apply() override { u += d_; }
  paths::Verdict settle(bool small, const paths::Correction&) override {
    if (fail_next) {
      fail_next = false;
      return paths::Verdict::failed;
    }
    return small ? paths::Verdict::converged : paths::Verdict::iterate;
  }

 private:
  double k_, H_, Fy_, tangent_ = 0.0, r_ = 0.0, d_ = 0.0;
};

// Fully reversed force cycles 0 -> F -> -F -> F -> ... in load levels, each solved by the
// one Newton, the internal variables committed at converged levels only. The stabilized
// loop of a bilinear kinematic-hardening spring is a parallelogram: its plastic branches
// move up by 2 (F - Fy) / H, at forces b + Fy and b - Fy, so the area (the dissipation per
// cycle) is 4 Fy (F - Fy) / H (Lubliner, Plasticity Theory, 1.4 and 3.3, the 1-D model). A
// failed Newton solve at every tenth level, discarded and retried, changes nothing.
TEST(Newton, InternalVariablesCommittedPerLevelGiveTheHysteresisLoopArea) {
  const double k = 1000.0, H = 250.0, Fy = 10.0, F = 25.0;
  PlasticSpring s(k, H, Fy);
  paths::Rule rule;
  rule.tolerance = 1e-14;
  auto level = [&](double force, bool fail_first) {
    s.force = force;
    if (fail_first) {
      s.fail_next = true;
      const double u0 = s.u;
      EXPECT_FALSE(paths::newton(s, rule).converged);
      s.plastic.discard();
      s.u = u0;
    }
    const paths::NewtonResult r = paths::newton(s, rule);
    EXPECT_TRUE(r.converged) << "at F = " << force;
    // The spring is piecewise linear: Newton is exact in one correction per branch.
    EXPECT_LE(r.iterations, 3);
    s.plastic.commit();
  };
  // The path: 100 levels per half cycle; the work of the force by the trapezoidal rule,
  // exact on the elastic branches and O(dF^2) on the plastic ones (the tangent changes
  // within one level).
  const int per = 200;
  std::vector<double> forces;
  for (int i = 1; i <= per / 2; ++i) forces.push_back(F * i / (per / 2));
  for (int cycle = 0; cycle < 3; ++cycle) {
    for (int i = 1; i <= per; ++i) forces.push_back(F - 2.0 * F * i / per);
    for (int i = 1; i <= per; ++i) forces.push_back(-F + 2.0 * F * i / per);
  }
  double work = 0.0, u_prev = 0.0, f_prev = 0.0, work_cycle_start = 0.0;
  std::vector<double> loop_work;
  for (std::size_t i = 0; i < forces.size(); ++i) {
    level(forces[i], i % 10 == 5);
    work += 0.5 * (forces[i] + f_prev) * (s.u - u_prev);
    u_prev = s.u;
    f_prev = forces[i];
    if (i + 1 >= per / 2 && (i + 1 - per / 2) % (2 * per) == 0) {
      loop_work.push_back(work - work_cycle_start);
      work_cycle_start = work;
    }
  }
  const double area = 4.0 * Fy * (F - Fy) / H;  // 2.4 J
  ASSERT_EQ(loop_work.size(), 4u);  // the first entry is the initial loading
  for (std::size_t c = 1; c < loop_work.size(); ++c)  // stable from the first cycle (symmetric cycles)
    EXPECT_NEAR(loop_work[c], area, 1e-3 * area) << "cycle " << c;
  // Back at F = +F after whole cycles: the back force is F - Fy.
  EXPECT_NEAR(H * s.plastic.committed().up, F - Fy, 1e-9 * F);
}

}  // namespace
