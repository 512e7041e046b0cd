// Arc-length continuation of the geometrically exact FE beam's statics
// (fem_reference/nonlinear.hpp, "Statics") against oracles outside it: the independent
// multibody chain (multibody/statics.hpp) and its Richardson extrapolation, the load
// stepping of the same beam where that alone works, the definition of a maximum, and
// closed-form geometry for the self-contact distance.
//
// The scene of the multibody test ContinuationPassesTheLimitPointOfAPressedArch: the
// paper's ring (R = 10 m, d = 0.12 m, E = 2.1e11 Pa) on a pin at 180 deg and a roller at
// 0 deg, pressed at its crown (90 deg) toward the centre: an arch with a limit point at
// P R^2 / EI ~ 7.61, past which the crown snaps down onto the bottom of the ring.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem_reference/nonlinear.hpp"
#include "fem_reference/self_contact.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"

namespace {

ring::RingSpec held_ring() {
  ring::RingSpec s = ringtest::pinned_ring();
  s.supports.roller = 0.0;
  return s;
}

/// P = p EI / R^2 at the crown, toward the centre; steps as the multibody test's.
ring::StaticOptions pressed_crown(const ring::RingSpec& spec, double p) {
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, 0.0}}};
  st.loads.points.at(0).force = {0.0, -p * spec.EI() / (spec.radius * spec.radius)};
  st.steps = std::max(1, static_cast<int>(4 * p));
  st.record = {90.0, 0.0, 270.0};
  return st;
}

ring::FemOptions fem_options(int degree, bool extensible) {
  ring::FemOptions o;
  o.elements = 40;
  o.degree = degree;
  o.extensible = extensible;
  return o;
}

std::string digits(double x) {
  std::ostringstream o;
  o << std::setprecision(10) << x;
  return o.str();
}

/// The message of the ring::NumericalError that `solve` throws ("" when it throws none).
template <class Solve>
std::string numerical_error(Solve&& solve) {
  try {
    solve();
  } catch (const ring::NumericalError& e) {
    return e.what();
  }
  return "";
}

double largest_load_factor(const fem::StaticPath& path) {
  double s = -1e300;
  for (const auto& p : path.points) s = std::max(s, p.load_factor);
  return s;
}

// At P R^2/EI = 8 load stepping cannot pass the limit point (it stops at load factor
// 0.9523 of 8 with 40 cubic elements); the continuation must carry the path through it:
// past the maximum the load falls while the crown keeps moving down, until the crown
// meets the bottom of the ring, which is reported as self-contact naming the limit. At
// P R^2/EI = 7, below the limit, load stepping reaches the full load.
TEST(FemContinuation, PassesTheLimitPointOfThePressedCrown) {
  const ring::RingSpec spec = held_ring();
  const ring::FemOptions o = fem_options(3, true);
  EXPECT_NO_THROW(fem::solve_static(spec, o, pressed_crown(spec, 7.0)));

  const ring::StaticOptions st = pressed_crown(spec, 8.0);
  const std::string w = numerical_error([&] { fem::solve_static(spec, o, st); });
  EXPECT_NE(w.find("past a limit point at load factor"), std::string::npos) << w;
  EXPECT_NE(w.find("touches itself"), std::string::npos) << w;

  const fem::StaticPath path = fem::trace_static(spec, o, st);
  ASSERT_FALSE(path.reached);
  EXPECT_TRUE(path.continuation);
  ASSERT_TRUE(std::isfinite(path.limit_load_factor));
  RecordProperty("limit_load_factor", digits(path.limit_load_factor));
  EXPECT_NE(path.failure.find("past a limit point at load factor"), std::string::npos) << path.failure;
  // The located limit is the maximum of the path: no accepted point above it (beyond
  // the corrector's 1e-12 in s), and the best accepted point just below it (the
  // located point lies inside the step that brackets it, so within one step's change).
  const double top = largest_load_factor(path);
  EXPECT_LE(top, path.limit_load_factor + 1e-12);
  EXPECT_GT(top, path.limit_load_factor - 1e-3);
  // Through the limit: after the maximum the crown goes on down while the load falls
  // by more than 5 % (measured: to 0.890 at contact).
  std::size_t at_top = 0;
  for (std::size_t k = 0; k < path.points.size(); ++k)
    if (path.points[k].load_factor == top) at_top = k;
  ASSERT_LT(at_top + 1, path.points.size());
  const auto& last = path.points.back();
  EXPECT_LT(last.load_factor, 0.95 * path.limit_load_factor);
  EXPECT_LT(last.displacement[1], path.points[at_top].displacement[1] - 1.0);
  for (std::size_t k = at_top + 1; k < path.points.size(); ++k)
    EXPECT_LT(path.points[k].displacement[1], path.points[k - 1].displacement[1]) << "point " << k;
}

// Where load stepping alone reaches the full load (P R^2/EI = 7, the crown moving
// 7.4 m), arc-length continuation from rest must reach the same equilibrium. Both end
// with Newton converged to 1e-12 R (1e-11 m) on the same discrete equations, so they
// agree to 1e-9 of the displacement, far above that.
TEST(FemContinuation, SameEquilibriumWithAndWithoutTheContinuation) {
  const ring::RingSpec spec = held_ring();
  const ring::FemOptions o = fem_options(3, true);
  const ring::StaticOptions st = pressed_crown(spec, 7.0);
  const fem::StaticPath stepped = fem::trace_static(spec, o, st);
  fem::ContinuationOptions from_rest;
  from_rest.from_start = true;
  const fem::StaticPath traced = fem::trace_static(spec, o, st, from_rest);
  ASSERT_TRUE(stepped.reached) << stepped.failure;
  ASSERT_TRUE(traced.reached) << traced.failure;
  EXPECT_FALSE(stepped.continuation);
  EXPECT_TRUE(traced.continuation);
  EXPECT_GT(traced.arc_steps, 0);
  EXPECT_TRUE(std::isnan(traced.limit_load_factor));  // the limit (7.61) lies beyond 7
  for (std::size_t i = 0; i < st.record.size(); ++i) {
    const auto& a = stepped.result.displacements[i];
    const auto& b = traced.result.displacements[i];
    const double scale = std::hypot(stepped.result.displacements[0].ux, stepped.result.displacements[0].uy);
    EXPECT_LT(std::hypot(a.ux - b.ux, a.uy - b.uy), 1e-9 * scale) << "at " << st.record[i] << " deg";
  }
}

/// The multibody chain's limit load factor at n segments, from its message ("past a
/// limit point at load factor X": 6 significant digits).
double chain_limit(const ring::RingSpec& spec, const ring::StaticOptions& st, int n) {
  ring::MultibodyOptions o;
  o.n = n;
  const std::string w = numerical_error([&] { multibody::solve_static(spec, o, st); });
  const std::string key = "past a limit point at load factor ";
  const auto at = w.find(key);
  if (at != std::string::npos) return std::stod(w.substr(at + key.size()));
  ADD_FAILURE() << "the chain with n = " << n << " met no limit point: " << w;
  return std::nan("");
}

// The limit load against an independent solver. The rigid-segment chain is
// inextensible, so the FE beam is too (fem.extensible = false; the extensible beam's
// limit is 2.4e-5 lower, measured: 0.9517406 against 0.9517637 of P).
//  - Chain: n = 80, 160, 320 (measured 0.948794, 0.951021, 0.951578; successive
//    differences shrink by 4.00: second order in 1/n), Richardson (4 s(2n) - s(n)) / 3
//    from (80, 160) and from (160, 320). Their difference bounds the O(1/n^4) left, and
//    each value carries the message's rounding, 5e-7 relative, which the Richardson
//    weights (4 + 1)/3 turn into at most 8.4e-7.
//  - FE: 40 elements, p = 5 against p = 6 (p-convergence: 1.4e-5 at p = 4, 2.6e-8 at
//    p = 5, measured), their difference bounds p = 5's error.
// Tolerance: twice the sum of these three, against the measured agreement ~1e-7.
TEST(FemContinuation, LimitLoadAgreesWithTheMultibodyChain) {
  const ring::RingSpec spec = held_ring();
  const ring::StaticOptions st = pressed_crown(spec, 8.0);
  const double s80 = chain_limit(spec, st, 80), s160 = chain_limit(spec, st, 160), s320 = chain_limit(spec, st, 320);
  // The two-point order of the successive differences (of one sign: a monotone approach).
  EXPECT_GT((s160 - s80) * (s320 - s160), 0.0) << s80 << " " << s160 << " " << s320;
  EXPECT_TRUE(ringtest::OrderNear(
      ringtest::in_n(std::vector<int>{80, 160}, {std::abs(s160 - s80), std::abs(s320 - s160)}), 2.0, 0.1))
      << s80 << " " << s160 << " " << s320;
  const double coarse = (4.0 * s160 - s80) / 3.0, fine = (4.0 * s320 - s160) / 3.0;
  const double rounding = 5.0 / 3.0 * 5e-7 * fine;

  const fem::StaticPath p5 = fem::trace_static(spec, fem_options(5, false), st);
  const fem::StaticPath p6 = fem::trace_static(spec, fem_options(6, false), st);
  ASSERT_TRUE(std::isfinite(p5.limit_load_factor)) << p5.failure;
  ASSERT_TRUE(std::isfinite(p6.limit_load_factor)) << p6.failure;
  const double fe = p5.limit_load_factor, fe_error = std::abs(p6.limit_load_factor - fe);

  const double tolerance = 2.0 * (std::abs(fine - coarse) + rounding + fe_error);
  RecordProperty("chain_richardson", digits(fine));
  RecordProperty("fem_p5", digits(fe));
  RecordProperty("difference", digits(std::abs(fe - fine)));
  RecordProperty("tolerance", digits(tolerance));
  EXPECT_NEAR(fe, fine, tolerance) << "chain (80, 160, 320): " << s80 << " " << s160 << " " << s320
                                   << "; FE p = 5, 6: " << fe << " " << p6.limit_load_factor;
  // And the limit is where the multibody test says: P R^2/EI ~ 7.5 of the full 8.
  EXPECT_NEAR(8.0 * fe, 7.6, 0.1);
}

// A bounded number of arc steps: with 5 allowed the path passes the limit (found in the
// first steps after load stepping stops) but cannot come back; the message names the
// limit and the bound.
TEST(FemContinuation, ReportsAPathThatDoesNotReturnWithinTheArcStepBound) {
  const ring::RingSpec spec = held_ring();
  fem::ContinuationOptions few;
  few.max_arc_steps = 5;
  const fem::StaticPath path = fem::trace_static(spec, fem_options(3, true), pressed_crown(spec, 8.0), few);
  ASSERT_FALSE(path.reached);
  EXPECT_EQ(path.arc_steps, 5);
  EXPECT_NE(path.failure.find("past a limit point at load factor"), std::string::npos) << path.failure;
  EXPECT_NE(path.failure.find("within 5 arc-length steps"), std::string::npos) << path.failure;
  ring::FemOptions reference = fem_options(3, true);
  reference.reference = true;
  EXPECT_THROW(fem::trace_static(spec, reference, pressed_crown(spec, 8.0)), std::invalid_argument);
}

// A zero load leaves the ring at rest: load steps that move nothing have no direction
// for the check that a step jumped over a limit point, and must not count as jumps.
TEST(FemContinuation, ZeroLoadStaysAtRest) {
  const ring::RingSpec spec = held_ring();
  const auto r = fem::solve_static(spec, fem_options(3, true), pressed_crown(spec, 0.0));
  for (const auto& d : r.displacements) {
    EXPECT_EQ(d.ux, 0.0);
    EXPECT_EQ(d.uy, 0.0);
  }
}

// The self-contact distance on closed polygons with a known answer (geometry): a
// stadium of two parallel straight sides 0.1 apart joined by half circles, and a figure
// eight, whose edges cross at its waist.
TEST(FemSelfContact, ClosestApproachOfKnownLoops) {
  using fem::detail::Point2;
  const double kPi = std::acos(-1.0);
  std::vector<Point2> stadium;
  const double r = 0.05;  // half the gap between the straight sides
  for (int k = 0; k < 100; ++k) stadium.push_back({-1.0 + 0.02 * k, -r});
  for (int k = 0; k < 20; ++k) stadium.push_back({1.0 + r * std::sin(kPi * k / 20), -r * std::cos(kPi * k / 20)});
  for (int k = 0; k < 100; ++k) stadium.push_back({1.0 - 0.02 * k, r});
  for (int k = 0; k < 20; ++k) stadium.push_back({-1.0 - r * std::sin(kPi * k / 20), r * std::cos(kPi * k / 20)});
  // Edges at least 40 apart: the straight sides face each other; nothing else is closer.
  const auto a = fem::detail::closest_approach(stadium, 40, 0.12);
  ASSERT_GE(a.first, 0);
  EXPECT_NEAR(a.distance, 2 * r, 1e-12);
  // Only pairs closer than the reach count.
  EXPECT_EQ(fem::detail::closest_approach(stadium, 40, 0.05).first, -1);

  std::vector<Point2> eight;
  for (int k = 0; k < 400; ++k) {
    const double t = 2 * kPi * (k + 0.5) / 400;  // no vertex at the waist: two edges cross there
    eight.push_back({std::sin(t), std::sin(t) * std::cos(t)});
  }
  const auto b = fem::detail::closest_approach(eight, 20, 0.1);
  ASSERT_GE(b.first, 0);
  EXPECT_EQ(b.distance, 0.0);
  EXPECT_EQ(fem::detail::segment_gap({0, 0}, {1, 0}, {0.5, -1}, {0.5, 1}), 0.0);
  EXPECT_NEAR(fem::detail::segment_gap({0, 0}, {1, 0}, {2, 1}, {3, 1}), std::sqrt(2.0), 1e-15);
}

}  // namespace
