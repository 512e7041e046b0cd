// The time-stepping driver (paths/time_stepping.hpp) against oracles outside it: a linear
// oscillator m x'' + k x = F g(t) stepped by the average-acceleration rule, whose discrete
// solution from rest under a constant force is known in closed form,
//   x_k = F / k (1 - cos(Omega t_k)),  tan(Omega dt / 2) = omega dt / 2
// (the rule's period elongation; Hughes, The Finite Element Method, 9.3), and steppers
// that refuse steps, ask for a retry, blow up, touch or gain energy on purpose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "paths/time_stepping.hpp"
#include "ring/errors.hpp"
#include "support/paper.hpp"

namespace {

using Reason = ring::IntegrationFailure::Reason;

/// m = 1 kg, k = omega^2, force F from rest; a0 = F / m. `refuse(t, h)` rejects a step.
class Oscillator : public paths::Stepper {
 public:
  Oscillator(double omega, double force) : k_(omega * omega), F_(force) { a_ = F_; }
  std::function<paths::StepOutcome(double t, double h)> refuse;  ///< an outcome not converged rejects
  std::vector<double> steps;                                      ///< every accepted sub-step
  double gain = 1.0;                                              ///< velocity factor per step

  paths::StepOutcome try_step(double t, double h) override {
    if (refuse) {
      const paths::StepOutcome o = refuse(t, h);
      if (!o.converged) return o;
    }
    // Average acceleration, beta = 1/4, gamma = 1/2: one linear solve.
    const double beta = 0.25, gamma = 0.5;
    const double xhat = x_ + h * v_ + (0.5 - beta) * h * h * a_;
    x1_ = (F_ + xhat / (beta * h * h)) / (k_ + 1.0 / (beta * h * h));
    a1_ = (x1_ - xhat) / (beta * h * h);
    v1_ = gain * (v_ + h * ((1.0 - gamma) * a_ + gamma * a1_));
    h_ = h;
    return {true, false, 1, 1.0};
  }
  void accept(double) override {
    work_ += F_ * (x1_ - x_);
    x_ = x1_;
    v_ = v1_;
    a_ = a1_;
    steps.push_back(h_);
  }
  bool finite() const override { return std::isfinite(x_) && std::isfinite(v_); }
  paths::Sample sample() const override {
    paths::Sample s;
    s.ux = {x_};
    s.uy = {0.0};
    s.kinetic = 0.5 * v_ * v_;
    s.strain = 0.5 * k_ * x_ * x_;
    s.work = work_;
    return s;
  }
  void shape(std::vector<double>& x, std::vector<double>& y) const override {
    x = {x_};
    y = {0.0};
  }
  std::optional<std::string> contact() const override {
    if (x_ > touch) return "x = " + std::to_string(x_);
    return std::nullopt;
  }
  double touch = std::numeric_limits<double>::infinity();
  double x() const { return x_; }

 private:
  double k_, F_;
  double x_ = 0.0, v_ = 0.0, a_ = 0.0, x1_ = 0.0, v1_ = 0.0, a1_ = 0.0, h_ = 0.0, work_ = 0.0;
};

paths::Grid grid(double dt, double t_end) {
  paths::Grid g;
  g.dt = dt;
  g.t_end = t_end;
  g.who = "test";
  return g;
}

TEST(TimeStepping, RecordsTheDiscreteClosedFormOnTheGrid) {
  const double omega = 2.0, F = 3.0, dt = 0.05;
  Oscillator o(omega, F);
  const ring::TimeHistory h = paths::integrate(o, grid(dt, 10.0), {90.0});
  ASSERT_EQ(h.t.size(), 201u);
  const double Omega = 2.0 / dt * std::atan(0.5 * omega * dt);
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    EXPECT_EQ(h.t[k], dt * double(k));  // on the grid, exactly
    // Round-off of 200 recursive steps of a bounded solution: 1e-12 of F / k.
    EXPECT_NEAR(h.ux[0][k], F / (omega * omega) * (1.0 - std::cos(Omega * h.t[k])), 1e-12) << k;
    // The rule conserves the energy of a linear system: T + V - W at round-off.
    EXPECT_NEAR(h.energy_error[k], 0.0, 1e-12) << k;
  }
  EXPECT_EQ(h.snapshot_t.size(), 6u);  // the default: 0, 2, 4, 6, 8, 10 s
  EXPECT_DOUBLE_EQ(h.snapshot_t[1], 2.0);
  EXPECT_EQ(o.steps.size(), 200u);  // no sub-steps where every step converges
}

// The progress callback (ResponseOptions::progress, passed on by every solver): the
// fraction of t_end, increasing, at most ~200 calls, ending at 1; the record is the same.
TEST(TimeStepping, ReportsTheFractionOfTheRunAtMostAbout200Times) {
  for (const double t_end : {1.0, 100.0}) {
    Oscillator plain(2.0, 3.0), watched(2.0, 3.0);
    paths::Grid g = grid(0.05, t_end);
    const ring::TimeHistory a = paths::integrate(plain, g, {90.0});
    std::vector<double> seen;
    g.progress = [&](double f) { seen.push_back(f); };
    const ring::TimeHistory b = paths::integrate(watched, g, {90.0});
    EXPECT_EQ(a.ux, b.ux);
    ASSERT_FALSE(seen.empty());
    EXPECT_LE(seen.size(), 201u) << t_end;
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_GT(seen.front(), 0.0);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    if (t_end == 1.0) {
      EXPECT_EQ(seen.size(), 20u);  // 20 steps: every one
    }
  }
}

TEST(TimeStepping, HalvesRefusedStepsAndRegrowsAfterTwoSuccesses) {
  const double omega = 2.0, F = 3.0, dt = 0.05;
  Oscillator o(omega, F);
  // Steps longer than 0.3 dt never converge between t = 1 and t = 2.
  o.refuse = [&](double t, double h) -> paths::StepOutcome {
    if (t >= 1.0 - 1e-12 && t < 2.0 - 1e-12 && h > 0.3 * dt) return {false, false, 3, 0.0};
    return {true, false, 0, 0.0};
  };
  const ring::TimeHistory h = paths::integrate(o, grid(dt, 4.0), {90.0});
  ASSERT_EQ(h.t.size(), 81u);
  for (std::size_t k = 0; k < h.t.size(); ++k) EXPECT_EQ(h.t[k], dt * double(k));
  // Inside the window every sub-step is dt / 4; outside, the full step comes back at once
  // after two successes (grid steps are never longer than dt).
  for (double s : o.steps) EXPECT_LE(s, dt * (1 + 1e-12));
  const auto quarter = std::count_if(o.steps.begin(), o.steps.end(), [&](double s) { return std::abs(s - 0.25 * dt) < 1e-12; });
  EXPECT_EQ(quarter, 4 * 20);
  // Within the rule's error at these steps ((omega dt)^2 / 12 relative in the phase).
  const double exact = F / (omega * omega) * (1.0 - std::cos(omega * 4.0));
  EXPECT_NEAR(h.ux[0].back(), exact, 0.01 * F / (omega * omega));
  // Refused steps' Newton iterations are counted at their grid point.
  EXPECT_GT(h.newton_iterations[30], h.newton_iterations[10]);
}

TEST(TimeStepping, RetriesOnceAtTheSameSizeBeforeHalving) {
  Oscillator o(2.0, 3.0);
  bool first = true;
  o.refuse = [&](double, double) -> paths::StepOutcome {
    if (first) {
      first = false;
      return {false, true, 1, 0.0};  // stale Newton matrix: try again
    }
    return {true, false, 0, 0.0};
  };
  paths::integrate(o, grid(0.05, 1.0), {90.0});
  EXPECT_EQ(o.steps.size(), 20u);  // never halved
}

TEST(TimeStepping, FailsWithThePartialHistoryWhenTheStepCannotShrinkFurther) {
  Oscillator o(2.0, 3.0);
  o.refuse = [&](double t, double) -> paths::StepOutcome {
    if (t >= 0.5 - 1e-12) return {false, false, 2, 0.0};
    return {true, false, 0, 0.0};
  };
  try {
    paths::integrate(o, grid(0.05, 1.0), {90.0});
    FAIL() << "expected an IntegrationFailure";
  } catch (const ring::IntegrationFailure& e) {
    EXPECT_EQ(e.reason(), Reason::step_too_small);
    EXPECT_NEAR(e.t_reached(), 0.5, 1e-12);
    EXPECT_EQ(e.partial().t.size(), 11u);  // 0, 0.05, ..., 0.5
    EXPECT_NE(std::string(e.what()).find("test: Newton did not converge at t = 0.5"), std::string::npos) << e.what();
  }
}

TEST(TimeStepping, ANonFiniteStateAndContactFail) {
  Oscillator blows(2.0, std::numeric_limits<double>::infinity());
  try {
    paths::integrate(blows, grid(0.05, 1.0), {90.0});
    FAIL();
  } catch (const ring::IntegrationFailure& e) {
    EXPECT_EQ(e.reason(), Reason::not_finite);
  }
  Oscillator touches(2.0, 3.0);
  touches.touch = 1.0;  // x = 0.75 (1 - cos 2t) passes 1 m at t = acos(-1/3) / 2 = 0.955 s
  try {
    paths::integrate(touches, grid(0.05, 2.0), {90.0});
    FAIL();
  } catch (const ring::IntegrationFailure& e) {
    EXPECT_EQ(e.reason(), Reason::self_contact);
    EXPECT_NEAR(e.t_reached(), 0.95, 1e-12);  // the last grid point before the contact
    EXPECT_NE(std::string(e.what()).find("touches itself"), std::string::npos);
  }
}

TEST(TimeStepping, TheEnergyGuardCatchesAGainAndPassesTheConservingRule) {
  // The guard's scales come from a ring; the oscillator's energies are of order 1 J,
  // far above its round-off bound.
  const ring::RingSpec spec = ringtest::pinned_ring();
  {
    Oscillator o(2.0, 3.0);
    ring::EnergyGuard guard(spec, 40, 3.0);
    paths::Grid g = grid(0.05, 10.0);
    g.guard = &guard;
    EXPECT_NO_THROW(paths::integrate(o, g, {90.0}));
  }
  Oscillator o(2.0, 3.0);
  o.gain = 1.01;  // 1 % more velocity every step: energy from nowhere
  ring::EnergyGuard guard(spec, 40, 3.0);
  paths::Grid g = grid(0.05, 10.0);
  g.guard = &guard;
  try {
    paths::integrate(o, g, {90.0});
    FAIL();
  } catch (const ring::IntegrationFailure& e) {
    EXPECT_EQ(e.reason(), Reason::energy_growth);
    EXPECT_LT(e.t_reached(), 2.0);
  }
}

}  // namespace
