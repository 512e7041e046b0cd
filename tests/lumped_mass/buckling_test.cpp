// Linear buckling of the lumped chain (lumped_mass/buckling.hpp).
//
// Oracle: ring::closed_form::pinned_ring_critical_pressure, the continuum critical pressures
// of a thin inextensible ring on a pin and a roller (the Fourier analysis of
// ring/closed_form.hpp, not this code): follower 3 EI/R^3 (the n = 2 pair, a double
// factor: with or without the rotation the supports impose), central 4.5 EI/R^3, dead
// 3.27125 EI/R^3 (the out-of-phase even harmonics coupled through the rotation), and, for
// dead pressure, Levy's 4 EI/R^3 of the n = 2 shape in phase with the pin (a translation
// only, which dead pressure does not resist) as the second factor.
// The chain's discretization error is O(1/n^2) (a central scheme: lumped_mass/README.md), so
// the error against the continuum must shrink at a fitted order 2 over n = 40, 80, 160.
// Shapes: the radial n = 2 harmonic about the pin, cos 2 (theta - pin) (in phase) against
// sin 2 (theta - pin) (out of phase); the supports' rigid motion adds no radial n = 2.
// Also: the registry's entry against the direct call (the one CLI-free cross check of the
// wiring) and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include "common.hpp"
#include "compare/registry.hpp"
#include "lumped_mass/buckling.hpp"
#include "ring/errors.hpp"
#include "ring/closed_form.hpp"
#include "tests/support/close.hpp"
#include "tests/support/convergence.hpp"

namespace {

using Kind = ring::Pressure::Kind;

ring::BucklingOptions pressure(Kind kind, int count) {
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, kind};  // 1 N/m: the factors are the critical pressures in N/m
  b.count = count;
  return b;
}

const char* name(Kind k) { return k == Kind::follower ? "follower" : k == Kind::central ? "central" : "dead"; }

/// The radial n = 2 harmonic of a shape about the pin at `pin` degrees: (cos, sin) coefficients.
std::pair<double, double> second_harmonic(const ring::ModeShape& m, double pin) {
  double a = 0.0, b = 0.0;
  for (int k = 0; k < ring::kStations; ++k) {
    const double t = 2.0 * (ring::station_angle(k) - pin) * 3.14159265358979323846 / 180.0;
    a += m.radial[k] * std::cos(t);
    b += m.radial[k] * std::sin(t);
  }
  return {2.0 * a / ring::kStations, 2.0 * b / ring::kStations};
}

std::string message(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument)";
}

struct Case {
  Kind kind;
  double second;   ///< lambda_2 of the continuum in EI/R^3 (0: not checked, see the file comment)
  double ceiling;  ///< largest relative error of lambda_1 and lambda_2 accepted at n = 160 (see below)
};

class LumpedBuckling : public ::testing::TestWithParam<Case> {};

// lambda_1 (and lambda_2 where the continuum's is known) -> the continuum's critical
// pressures at order 2. The fit over 40, 80, 160 sees the O(h^4) remainder at n = 40; 0.1 is
// the convergence suite's allowance for it (convergence_test.cpp). Ceilings: about twice the
// largest error measured at n = 160 (printed: follower 5.1e-4 for both of its pair, central
// 2.6e-4, dead 2.9e-4 and 3.9e-4 for lambda_2).
TEST_P(LumpedBuckling, PinRollerPressureConvergesAtOrderTwo) {
  const Case c = GetParam();
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const double unit = spec.EI() / std::pow(spec.radius, 3);
  const double exact = ring::closed_form::pinned_ring_critical_pressure(spec, c.kind);
  const std::vector<int> ns{40, 80, 160};
  std::vector<double> err1, err2;
  for (int n : ns) {
    const ring::BucklingResult r = lumped::compute_buckling(spec, lumptest::options(n, lumptest::kChain), pressure(c.kind, 2));
    ASSERT_EQ(r.factors.size(), 2u);
    EXPECT_EQ(r.solver, "lumped");
    EXPECT_EQ(r.unknowns, n - 3);  // n hinges, 2n coordinates, n links, pin 2 rows, roller 1
    ASSERT_EQ(r.shapes.size(), 2u);
    for (const ring::ModeShape& m : r.shapes) {  // ModeShape's scaling
      double largest = 0.0;
      for (int k = 0; k < ring::kStations; ++k)
        largest = std::max({largest, std::abs(m.radial[k]), std::abs(m.tangential[k])});
      EXPECT_TRUE(ringtest::IsClose(largest, 1.0, 1e-14));  // 1e-14: the scaling's rounding
    }
    err1.push_back(ringtest::rel(r.factors[0], exact));
    if (c.second > 0.0) err2.push_back(ringtest::rel(r.factors[1], c.second * unit));
  }
  const auto lambda1 = ringtest::in_n(ns, err1);  // the order in h = 2 pi R / n
  const double p1 = ringtest::fit_order(lambda1).order;
  std::printf("[lumped buckling %s] lambda_1 rel. errors n = 40, 80, 160: %.3e %.3e %.3e  fitted order %.3f\n",
              name(c.kind), err1[0], err1[1], err1[2], p1);
  EXPECT_TRUE(ringtest::OrderNear(lambda1, 2.0, 0.1, c.ceiling)) << name(c.kind) << ", lambda_1";
  if (c.second > 0.0) {
    const auto lambda2 = ringtest::in_n(ns, err2);
    const double p2 = ringtest::fit_order(lambda2).order;
    std::printf("[lumped buckling %s] lambda_2 rel. errors n = 40, 80, 160: %.3e %.3e %.3e  fitted order %.3f\n",
                name(c.kind), err2[0], err2[1], err2[2], p2);
    EXPECT_TRUE(ringtest::OrderNear(lambda2, 2.0, 0.1, c.ceiling)) << name(c.kind) << ", lambda_2";
  }
}

INSTANTIATE_TEST_SUITE_P(Pressures, LumpedBuckling,
                         ::testing::Values(Case{Kind::follower, 3.0, 1e-3}, Case{Kind::central, 0.0, 5e-4},
                                           Case{Kind::dead, 4.0, 8e-4}),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(name(i.param.kind)); });

// Follower pressure: the n = 2 shape costs the same with or without the rotation the supports
// impose, so the lowest factor is a double pair. Its two members agree to the rounding floor
// eps (R/l)^4 of the assembled tangent (lumped_mass/buckling.hpp; measured 2.3e-10 at n = 160):
// 1e-8 allows 40 times that, far below the discretization error 5e-4 that would separate
// them if the pair were not a pair.
TEST(LumpedBuckling, FollowerPairIsDouble) {
  const ring::BucklingResult r =
      lumped::compute_buckling(ringtest::pin_270_roller_90(), lumptest::options(160, lumptest::kChain), pressure(Kind::follower, 3));
  EXPECT_TRUE(ringtest::IsClose(r.factors[1], r.factors[0], 1e-8));
  EXPECT_GT(r.factors[2] / r.factors[0], 2.0);  // the next wave number, 8 EI/R^3 in the limit
}

// Dead pressure: lambda_1 is the shape out of phase with the pin (its radial n = 2 harmonic
// a pure sin 2 (theta - pin), coupled through the supports' rotation), lambda_2 Levy's shape
// in phase (a pure cos 2 (theta - pin), a translation only). By the symmetry of the supports
// about the pin-roller diameter the other harmonic vanishes to rounding: measured 1e-10 of the
// leading one at n = 160; 1e-8 allows for it.
TEST(LumpedBuckling, DeadPressureShapesOutOfAndInPhaseWithThePin) {
  const double pin = 270.0;
  const ring::BucklingResult r =
      lumped::compute_buckling(ringtest::pin_270_roller_90(), lumptest::options(160, lumptest::kChain), pressure(Kind::dead, 2));
  const auto [a1, b1] = second_harmonic(r.shapes[0], pin);
  const auto [a2, b2] = second_harmonic(r.shapes[1], pin);
  EXPECT_LT(std::abs(a1), 1e-8 * std::abs(b1)) << "lambda_1: cos " << a1 << ", sin " << b1;
  EXPECT_LT(std::abs(b2), 1e-8 * std::abs(a2)) << "lambda_2: cos " << a2 << ", sin " << b2;
}

// What cannot work is refused before anything is computed, naming the key.
TEST(LumpedBuckling, Refusals) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::BucklingOptions follower = pressure(Kind::follower, 2);
  // Every variant buckles: the Euler frames on their corotational tangent (frame.hpp), at
  // order 2 to the thin ring's 3 EI/R^3 like the chain (FramesBuckleAtTheClosedForm below).
  EXPECT_NO_THROW(lumped::check_buckling(spec, lumptest::options(40, lumptest::kFrame), follower));
  // The chain is the Euler-Bernoulli model of either ring.theory (checks.hpp check_theory):
  // taken on a Timoshenko ring, as the Timoshenko frame is (frame_test.cpp measures it).
  ring::RingSpec thick = spec;
  thick.theory = ring::Theory::timoshenko;
  EXPECT_NO_THROW(lumped::check_buckling(thick, lumptest::options(40, lumptest::kChain), follower));
  EXPECT_NO_THROW(
      lumped::check_buckling(thick, lumptest::options(40, ring::LumpedOptions::Variant::timoshenko_frame), follower));
  // A ring on its pin alone turns freely at rest: K_0 is singular.
  EXPECT_NE(message([&] {
              lumped::check_buckling(ringtest::pinned_ring(270.0), lumptest::options(40, lumptest::kChain), follower);
            }).find("supports.roller"),
            std::string::npos);
  EXPECT_NE(message([&] {
              lumped::check_buckling(spec, lumptest::options(40, lumptest::kChain), ring::BucklingOptions{});
            }).find("buckling.loads"),
            std::string::npos);
  // More factors than the loads have (modal::critical_factors names buckling.count): an
  // outward pressure of any kind puts the links in tension and the ring never buckles (no
  // positive factor: in the continuum every p_n of ring/closed_form.hpp is positive, so -1 N/m
  // has none), and the chain on a pin and a roller has only n - 3 = 37 factors in all.
  for (Kind kind : {Kind::follower, Kind::central, Kind::dead}) {
    ring::BucklingOptions outward = pressure(kind, 1);
    outward.loads.pressure.value = -1.0;
    EXPECT_NE(message([&] { lumped::compute_buckling(spec, lumptest::options(40, lumptest::kChain), outward); })
                  .find("buckling.count"),
              std::string::npos)
        << name(kind);
  }
  EXPECT_NE(message([&] {
              lumped::compute_buckling(spec, lumptest::options(40, lumptest::kChain), pressure(Kind::follower, 38));
            }).find("buckling.count"),
            std::string::npos);
}

// The registry's entry is this solver (CLI-free): a scene with [buckling] runs
// lumped::compute_buckling with its ring, options and loads, and a frame is refused by
// check_scene as an input error naming the lumped section.
TEST(LumpedBuckling, RegistryEntryIsTheSolver) {
  const std::string scene = "\n" + ringtest::paper_ring_toml() + R"([supports]
pin = 270.0
roller = 90.0
[lumped]
n = 40
[buckling]
solvers = ["lumped"]
pressure = { value = 1.0, kind = "dead" }
count = 3
)";
  const ring::Scene s = cmp::parse_scene(scene, "buckling.toml");
  cmp::check_scene(s);
  const ring::BucklingResult via_registry = cmp::solver("lumped").buckling(s);
  const ring::BucklingResult direct =
      lumped::compute_buckling(ringtest::pin_270_roller_90(), lumptest::options(40, lumptest::kChain), pressure(Kind::dead, 3));
  ASSERT_EQ(via_registry.factors.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(via_registry.factors[i], direct.factors[i]);  // the same computation
  EXPECT_EQ(via_registry.solver, "lumped");

  const ring::Scene frame = cmp::parse_scene(scene, "buckling.toml", {"lumped.variant=frame"});
  EXPECT_NO_THROW(cmp::check_scene(frame));
}

// The Euler frames (the corotational frame with the Hermite element, frame.hpp) under follower
// pressure: order 2 to the closed form 3 EI/R^3 of the thin ring on a pin and a roller, as
// the chain (above); the extensible frame's hoop strain moves it by O(I/(A R^2)) = 9e-6 here.
TEST(LumpedBuckling, FramesBuckleAtTheClosedForm) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const double exact = ring::closed_form::pinned_ring_critical_pressure(spec, Kind::follower);
  for (const auto variant : {lumptest::kFrame, lumptest::kConsistent}) {
    const std::vector<int> ns{40, 80, 160};
    std::vector<double> err;
    for (int n : ns)
      err.push_back(std::abs(lumped::compute_buckling(spec, lumptest::options(n, variant), pressure(Kind::follower, 1))
                                 .factors.at(0) / exact - 1.0));
    EXPECT_LT(err[2], 1e-3) << ring::to_string(variant);
    for (int i = 0; i + 1 < 3; ++i)  // each refinement's two-point order
      EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{ns[i], ns[i + 1]}, {err[i], err[i + 1]}), 2.0, 0.15))
          << ring::to_string(variant);
  }
}

}  // namespace
