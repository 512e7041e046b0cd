// The one energy rule of the forced responses (ring/energy_guard.hpp) on histories made
// up here, against the rule as the header documents it: a gain above 1 % of the largest
// work plus the round-off bound fails, a loss never does, a run at round-off never does.
// The bound itself is recomputed here from the documented formula, term by term.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ring/energy_guard.hpp"
#include "support/close.hpp"
#include "support/paper.hpp"

namespace {

using ring::EnergyGuard;

constexpr double kEps = std::numeric_limits<double>::epsilon();

ring::RingSpec paper() {
  ring::RingSpec s = ringtest::pinned_ring();
  s.supports.roller = 0.0;
  return s;
}

/// r of the header for k steps of length h at load factor 1 (no variation), n pieces,
/// force |F|, largest T + V `stored` and largest |W| `work`.
double documented_bound(const ring::RingSpec& s, int n, double F, double h, long k, double stored, double work) {
  const double dx = 16.0 * kEps * s.radius;
  const double M = s.rhoA() * 2.0 * M_PI * s.radius;
  const double L = 2.0 * M_PI * s.radius;
  const double dv = 2.0 * dx / h;
  const double E1 = 0.5 * M * dv * dv + 8.0 * std::pow(double(n), 4) * s.EI() * dx * dx / (L * L * L);
  return F * dx * 2.0 + k * E1 + 2.0 * k * std::sqrt(stored * E1) + kEps * (k + 4.0) * (stored + work);
}

EnergyGuard after_steps(const ring::RingSpec& s, int n, double F, double h, long k) {
  EnergyGuard g(s, n, F);
  g.start(0.0, 0.0, 0.0);
  for (long i = 0; i < k; ++i) g.step(h, 1.0);
  return g;
}

TEST(EnergyGuard, AGainAboveOnePercentOfTheWorkFailsAndBelowItPasses) {
  const ring::RingSpec s = paper();
  // 1000 J of work, 500 steps: the round-off bound is ~1e-4 J, far below 1 % (10 J).
  EnergyGuard g = after_steps(s, 40, 2e4, 0.01, 500);
  const EnergyGuard::Verdict below = g.check(600.0, 409.0, 1000.0);  // +9 J
  EXPECT_FALSE(below.gained);
  EXPECT_NEAR(below.gain, 9.0, 1e-9);
  EXPECT_LT(below.roundoff, 1e-3);
  EnergyGuard h = after_steps(s, 40, 2e4, 0.01, 500);
  const EnergyGuard::Verdict above = h.check(600.0, 411.0, 1000.0);  // +11 J
  EXPECT_TRUE(above.gained);
  EXPECT_DOUBLE_EQ(above.work, 1000.0);
}

TEST(EnergyGuard, ALossNeverFails) {
  const ring::RingSpec s = paper();
  EnergyGuard g = after_steps(s, 40, 2e4, 0.01, 100);
  // Damping or numerical dissipation: 800 J of the 1000 J of work gone.
  const EnergyGuard::Verdict v = g.check(100.0, 100.0, 1000.0);
  EXPECT_FALSE(v.gained);
  EXPECT_DOUBLE_EQ(v.gain, -800.0);
  // All of it gone, the largest work still the scale.
  EXPECT_FALSE(g.check(0.0, 0.0, 1000.0).gained);
}

TEST(EnergyGuard, TheLargestWorkSoFarIsTheScaleSoALaterSmallWorkDoesNotTightenIt) {
  const ring::RingSpec s = paper();
  EnergyGuard g = after_steps(s, 40, 2e4, 0.01, 100);
  EXPECT_FALSE(g.check(500.0, 500.0, 1000.0).gained);
  // The load's point came back (work 10 J) while 9 J of the earlier 1000 J are still
  // stored: a gain of 9 J, below 1 % of the largest work.
  EXPECT_FALSE(g.check(10.0, 9.0, 10.0).gained);
}

TEST(EnergyGuard, ARunAtRoundOffPassesAndTheBoundIsNeverZero) {
  const ring::RingSpec s = paper();
  // The cases that were refused as valid input: no work at all (a load the roller reacts; 1e-300 N), and the
  // measured rounding energies of the chains (T + V ~ 4e-19 J after 200 steps, n = 40).
  for (double F : {2e4, 1e-300, 0.0}) {
    EnergyGuard g = after_steps(s, 40, F, 0.01, 200);
    const EnergyGuard::Verdict v = g.check(2e-19, 2e-19, 0.0);
    EXPECT_FALSE(v.gained) << F;
    EXPECT_GT(v.roundoff, 0.0) << F;
  }
  // ... and with the work itself at round-off (W = -1.1e-10 J for T = 5.9e-13 J after a
  // step of 1e-9 s: multibody, response.dt = 1e-9, the roller's rounding).
  EnergyGuard g = after_steps(s, 40, 2e4, 1e-9, 1);
  EXPECT_FALSE(g.check(5.9e-13, 3e-23, -1.07e-10).gained);
}

TEST(EnergyGuard, TheStartsOwnRoundingIsNotAGain) {
  const ring::RingSpec s = paper();
  EnergyGuard g(s, 40, 2e4);
  g.start(0.0, 1e3, 0.0);  // a made-up rest strain, to see that it is subtracted
  g.step(0.01, 1.0);
  const EnergyGuard::Verdict v = g.check(0.0, 1e3, 0.0);
  EXPECT_FALSE(v.gained);
  EXPECT_DOUBLE_EQ(v.gain, 0.0);
}

TEST(EnergyGuard, ANonFiniteBalanceFails) {
  const ring::RingSpec s = paper();
  EnergyGuard g = after_steps(s, 40, 2e4, 0.01, 1);
  EXPECT_TRUE(g.check(std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0).gained);
  EnergyGuard h = after_steps(s, 40, 2e4, 0.01, 1);
  EXPECT_TRUE(h.check(std::numeric_limits<double>::infinity(), 0.0, 1.0).gained);
}

TEST(EnergyGuard, TheBoundIsTheDocumentedFormula) {
  const ring::RingSpec s = paper();
  for (int n : {40, 10000})
    for (double h : {0.01, 1e-9}) {
      EnergyGuard g = after_steps(s, n, 2e4, h, 300);
      const EnergyGuard::Verdict v = g.check(700.0, 300.0, 900.0);
      const double r = documented_bound(s, n, 2e4, h, 300, 1000.0, 900.0);
      EXPECT_TRUE(ringtest::IsClose(v.roundoff, r, 1e-12)) << n << " " << h << ": " << v.roundoff << " vs " << r;
      EXPECT_DOUBLE_EQ(v.allowed(), 0.01 * 900.0 + v.roundoff);
    }
}

TEST(EnergyGuard, TheWorksRoundingGrowsWithTheLoadFactorsVariation) {
  const ring::RingSpec s = paper();
  // f = 0, 1, 0, 1: max |f| = 1, variation 3: |F| dx (2 + 3) instead of |F| dx 2.
  EnergyGuard g(s, 40, 2e4);
  g.start(0.0, 0.0, 0.0);
  for (double f : {0.0, 1.0, 0.0, 1.0}) g.step(0.01, f);
  EnergyGuard c = after_steps(s, 40, 2e4, 0.01, 4);
  const double dx = 16.0 * kEps * s.radius;
  EXPECT_TRUE(ringtest::IsClose(g.check(0.0, 0.0, 0.0).roundoff - c.check(0.0, 0.0, 0.0).roundoff, 2e4 * dx * 3.0,
                                1e-9));
}

TEST(EnergyGuard, TheMessageNamesTheGainTheScalesAndTheTime) {
  EnergyGuard::Verdict v;
  v.gained = true;
  v.gain = 12.5;
  v.work = 1000.0;
  v.roundoff = 1e-6;
  const std::string m = ring::describe(v, 0.25);
  for (const char* part : {"12.5 J", "1 %", "1000 J", "1e-06 J", "t = 0.25 s", "gains energy"})
    EXPECT_NE(m.find(part), std::string::npos) << part << " not in: " << m;
}

}  // namespace
