// Nonlinear statics of the chain (multibody/statics.hpp) against an independent
// reference: the inextensible elastica ring squeezed along a diameter, by shooting on
// its ODE (tests/support/elastica.hpp), and its linear limit (Roark, Table 9.2 case 1,
// ring::closed_form::diametral_load).
//
// The scene: the paper's ring pinned at A (180 deg), roller at C (0 deg) on the line AC,
// a force P at C pointing at A. The pin's reaction is -P along AC, so this is the ring
// squeezed by two opposite forces P along the diameter AC. The shortening of AC is
// -ux(C); the lengthening of the perpendicular diameter is uy(90) - uy(270).
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "multibody/statics.hpp"
#include "ring/closed_form.hpp"
#include "ring/errors.hpp"
#include "tests/support/elastica.hpp"
#include "tests/support/close.hpp"
#include "tests/support/convergence.hpp"
#include "tests/multibody/common.hpp"

namespace {

using mbtest::sci;
using ringtest::pin_roller_ring;

struct Diametral {
  double along, across;
};

/// The diametral load p = P R^2 / EI at C toward the pin, recorded at 0, 90, 180, 270 deg.
ring::StaticOptions diametral_load(double p, int steps = 20) {
  const ring::RingSpec spec = pin_roller_ring();
  ring::StaticOptions st;
  st.loads.points = {{0.0, {0.0, 0.0}}};
  st.loads.points.at(0).force = {-p * spec.EI() / (spec.radius * spec.radius), 0.0};
  st.steps = steps;
  st.record = {0.0, 90.0, 180.0, 270.0};
  return st;
}

/// The ring on its pin and roller pressed at its crown (90 deg) toward the centre with
/// p = P R^2 / EI, recorded at the crown.
ring::StaticOptions pressed_crown(double p, int steps) {
  const ring::RingSpec spec = pin_roller_ring();
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, 0.0}}};
  st.record = {90.0};
  st.loads.points.at(0).force = {0.0, -p * spec.EI() / (spec.radius * spec.radius)};
  st.steps = steps;
  return st;
}

ring::MultibodyOptions chain_options(int n, ring::MultibodyOptions::Method method) {
  ring::MultibodyOptions o;
  o.n = n;
  o.method = method;
  return o;
}

/// Chain result for p = P R^2 / EI with n segments, in units of R.
Diametral chain_diametral(double p, int n, int steps = 20,
                          ring::MultibodyOptions::Method method = ring::MultibodyOptions::Method::automatic) {
  const ring::RingSpec spec = pin_roller_ring();
  const ring::StaticResult r = multibody::solve_static(spec, chain_options(n, method), diametral_load(p, steps));
  return {-r.displacements[0].ux / spec.radius,
          (r.displacements[1].uy - r.displacements[3].uy) / spec.radius};
}

class MultibodyStaticsElastica : public ::testing::TestWithParam<double> {};

// Second-order convergence in 1/n to the elastica at P R^2/EI = 0.5, 1, 2, 5. The chain
// replaces the ring by an inscribed polygon of equal perimeter with concentrated hinge
// springs: a midpoint-type discretization of the elastica, so its error is O(1/n^2).
// The reference is converged to ~1e-14 (RK4 with 20000 steps, checked by doubling in
// development), far below the chain's errors (>1e-5 at n = 320).
TEST_P(MultibodyStaticsElastica, ConvergesAtSecondOrderInOneOverN) {
  const double p = GetParam();
  const elastica::DiametralResult ref = elastica::diametral(p);
  const std::vector<int> ns{40, 80, 160, 320};
  std::vector<double> e_along, e_across;
  for (int n : ns) {
    const Diametral d = chain_diametral(p, n);
    e_along.push_back(std::abs(d.along - ref.along));
    e_across.push_back(std::abs(d.across - ref.across));
  }
  const auto along = ringtest::in_n(ns, e_along), across = ringtest::in_n(ns, e_across);  // the order in 1/n
  RecordProperty("order_along", sci(ringtest::fit_order(along).order));
  RecordProperty("order_across", sci(ringtest::fit_order(across).order));
  RecordProperty("err_along_n40", sci(e_along.front() / ref.along));
  RecordProperty("err_along_n320", sci(e_along.back() / ref.along));
  // Expected order 2; 0.2 is the band the chain's statics were specified to meet, for every
  // load up to P R^2/EI = 5 with the fit starting at n = 40.
  EXPECT_TRUE(ringtest::OrderNear(along, 2.0, 0.2)) << "along";
  EXPECT_TRUE(ringtest::OrderNear(across, 2.0, 0.2)) << "across";
  // Ceiling on the finest error: 1 % of the n = 40 error times (40/320)^2 margin 2, i.e.
  // the finest run sits on the asymptote, not just the slope.
  EXPECT_LT(e_along.back(), 2.0 * e_along.front() / 64.0);
  EXPECT_LT(e_across.back(), 2.0 * e_across.front() / 64.0);
}

INSTANTIATE_TEST_SUITE_P(Loads, MultibodyStaticsElastica, ::testing::Values(0.5, 1.0, 2.0, 5.0));

// The elastica reference itself, at small load, against the linear closed form (the
// nonlinear correction is O(p): along/p changes by 0.0176 per unit p, so at p = 1e-4
// the relative difference is ~1.2e-5; tolerance 3e-5).
TEST(MultibodyStaticsElastica, ReferenceHasTheLinearLimit) {
  const double p = 1e-4;
  const auto ref = elastica::diametral(p);
  EXPECT_TRUE(ringtest::IsClose(ref.along / p, M_PI / 4 - 2 / M_PI, 3e-5));
  EXPECT_TRUE(ringtest::IsClose(ref.across / p, 2 / M_PI - 0.5, 3e-5));
}

// Linear limit of the chain: P = 20 N (p ~ 1e-3) at n = 320 against Roark. The chain's
// discretization error at n = 320 is ~1e-5 relative (see the convergence test) and the
// nonlinear correction ~1e-4 relative at this p; tolerance 5e-4.
TEST(MultibodyStatics, SmallLoadGivesTheLinearRingFormulas) {
  const ring::RingSpec spec = pin_roller_ring();
  const double P = 20.0;
  const auto lin = ring::closed_form::diametral_load(spec, P);
  const double p = P * spec.radius * spec.radius / spec.EI();
  const Diametral d = chain_diametral(p, 320, 1);
  EXPECT_TRUE(ringtest::IsClose(d.along * spec.radius, lin.along, 5e-4));
  EXPECT_TRUE(ringtest::IsClose(d.across * spec.radius, lin.across, 5e-4));
}

// The loaded ring is symmetric about AC: the points at 90 and 270 deg mirror each other
// (oracle: the geometry), and the pin does not move.
TEST(MultibodyStatics, DeformedShapeIsSymmetricAboutTheLoadLine) {
  const ring::RingSpec spec = pin_roller_ring();
  ring::MultibodyOptions o;
  o.n = 40;
  ring::StaticOptions st;
  st.loads.points = {{0.0, {0.0, 0.0}}};
  st.loads.points.at(0).force = {-20e3, 0.0};
  st.record = {0.0, 90.0, 180.0, 270.0};
  const auto r = multibody::solve_static(spec, o, st);
  // Round-off of a Newton solution converged to 1e-12 rad on a 10 m ring: 1e-9 m.
  EXPECT_NEAR(r.displacements[1].ux, r.displacements[3].ux, 1e-9);
  EXPECT_NEAR(r.displacements[1].uy, -r.displacements[3].uy, 1e-9);
  EXPECT_NEAR(r.displacements[0].uy, 0.0, 1e-9);  // the roller keeps C on AC
  EXPECT_NEAR(r.displacements[2].ux, 0.0, 1e-12);  // the pin
  EXPECT_NEAR(r.displacements[2].uy, 0.0, 1e-12);
  EXPECT_EQ(r.steps, 20);
  EXPECT_GT(r.newton_iterations, r.steps);
  EXPECT_EQ(static_cast<int>(r.node_x.size()), 40);
}

TEST(MultibodyStatics, RejectsInputsThatCannotWork) {
  ring::RingSpec spec = pin_roller_ring();
  ring::MultibodyOptions o;
  ring::StaticOptions st;
  st.loads.points = {{0.0, {-1e3, 0.0}}};
  st.steps = 0;
  EXPECT_THROW(multibody::solve_static(spec, o, st), std::invalid_argument);
  st.steps = 5;
  st.loads.points = {{4.0, {-1e3, 0.0}}};  // not a hinge of the 40-gon anchored at 180 deg
  EXPECT_THROW(multibody::solve_static(spec, o, st), std::invalid_argument);
  st.loads.points = {{0.0, {-1e3, 0.0}}};
  spec.supports.roller.reset();
  EXPECT_THROW(multibody::solve_static(spec, o, st), std::invalid_argument);
}

// A load far beyond self-contact: the static path must stop with a clear report.
TEST(MultibodyStatics, SelfContactIsReportedNotSolvedThrough) {
  const ring::RingSpec spec = pin_roller_ring();
  ring::MultibodyOptions o;
  ring::StaticOptions st;
  st.loads.points = {{0.0, {0.0, 0.0}}};
  // p = 40: the elastica's C would pass through A (shortening > 2R) long before this.
  st.loads.points.at(0).force = {-40.0 * spec.EI() / (spec.radius * spec.radius), 0.0};
  st.steps = 40;
  try {
    multibody::solve_static(spec, o, st);
    FAIL() << "expected a NumericalError";
  } catch (const ring::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("touches itself"), std::string::npos) << e.what();
  }
}

}  // namespace

namespace {

// A load at the top (90 deg) pushing toward the centre: the ring on its pin and roller
// is an arch pressed at its crown. Below P R^2/EI ~ 7.5 plain load stepping converges
// (checked at 7). At 8 load stepping stops at a limit point (measured: load factor 0.94
// of 8); the arc-length continuation must carry the path through it instead of giving
// up there. Past the limit the load falls while the top snaps down (measured: contact at
// load factor 0.87 < 0.94, so the load did pass a maximum) onto the bottom of the ring:
// a self-contact, which must be reported as such, naming the limit point.
TEST(MultibodyStatics, ContinuationPassesTheLimitPointOfAPressedArch) {
  const ring::RingSpec spec = pin_roller_ring();
  const ring::MultibodyOptions o;
  EXPECT_NO_THROW(multibody::solve_static(spec, o, pressed_crown(7.0, 28)));
  try {
    multibody::solve_static(spec, o, pressed_crown(8.0, 32));
    FAIL() << "expected a NumericalError (self-contact past the limit point)";
  } catch (const ring::NumericalError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("limit point"), std::string::npos) << w;
    EXPECT_NE(w.find("touches itself"), std::string::npos) << w;
  }
}

}  // namespace

namespace {

using Method = ring::MultibodyOptions::Method;

// The O(n) path (hinge positions, multibody.method = "sparse") and the dense path
// (segment angles, arc-length capable) solve the same chain in different coordinates with
// different code: their equilibria must agree to the Newton tolerances (1e-12 R on
// positions, 1e-9 rad on angles -> ~1e-8 m on a 10 m ring; bound 1e-9 relative to the
// largest displacement; measured <= 1e-12 m on displacements of ~10 m).
TEST(MultibodyStaticsSparse, BothPathsGiveTheSameEquilibrium) {
  const ring::RingSpec spec = pin_roller_ring();
  for (int n : {40, 160})
    for (double p : {1.0, 5.0}) {
      const auto st = diametral_load(p);
      const auto dense = multibody::solve_static(spec, chain_options(n, Method::dense), st);
      const auto on = multibody::solve_static(spec, chain_options(n, Method::sparse), st);
      ASSERT_EQ(dense.displacements.size(), on.displacements.size());
      double scale = 0.0, diff = 0.0;
      for (size_t i = 0; i < dense.displacements.size(); ++i) {
        const auto &a = dense.displacements[i], &b = on.displacements[i];
        scale = std::max(scale, std::hypot(a.ux, a.uy));
        diff = std::max(diff, std::hypot(a.ux - b.ux, a.uy - b.uy));
      }
      EXPECT_LT(diff, 1e-9 * scale) << "n = " << n << ", p = " << p;
      EXPECT_EQ(on.steps, 20);
      EXPECT_EQ(static_cast<int>(on.node_x.size()), n);
    }
}

// n = 10^4 on the O(n) path (the dense path would need ~10^12 flops per iteration):
// the chain keeps converging to the elastica at second order up to there, i.e. neither
// the round-off of the larger system nor the Newton stopping rule shows (measured at
// p = 5: relative error of the shortening 2.79e-4 (n = 320), 4.36e-6 (2560), 2.86e-7
// (10^4), order 2.00 and 2.00). Order 2 +- 0.05 from 2560 to 10^4 bounds a spurious
// error of ~1e-8 relative. Full Newton contracts quadratically, so a load step needs a
// handful of iterations whatever n: at most 6 per step on average (a count; measured
// 4.8 at n = 2560, 5.6 at 10^4, where one or two more reach the round-off floor).
TEST(MultibodyStaticsSparse, TenThousandSegmentsConvergeToTheElasticaAtSecondOrder) {
  const double p = 5.0;
  const elastica::DiametralResult ref = elastica::diametral(p);
  const ring::RingSpec spec = pin_roller_ring();
  const std::vector<int> ns{2560, 10000};
  std::vector<double> e_along, e_across;
  for (int n : ns) {
    const auto r = multibody::solve_static(spec, chain_options(n, Method::automatic), diametral_load(p));
    e_along.push_back(std::abs(-r.displacements[0].ux / spec.radius - ref.along) / ref.along);
    e_across.push_back(
        std::abs((r.displacements[1].uy - r.displacements[3].uy) / spec.radius - ref.across) / ref.across);
    EXPECT_EQ(r.steps, 20);
    EXPECT_LE(r.newton_iterations, 6 * r.steps) << "n = " << n;
  }
  RecordProperty("err_along_n10000", sci(e_along.back()));
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, e_along), 2.0, 0.05)) << "along";  // two points
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, e_across), 2.0, 0.05)) << "across";
  EXPECT_EQ(multibody::backend(chain_options(10000, Method::automatic), multibody::Analysis::statics),
            multibody::Backend::banded);
  EXPECT_EQ(multibody::backend(chain_options(40, Method::automatic), multibody::Analysis::statics),
            multibody::Backend::dense);
}

// The load factor of the limit point named in a "past a limit point at load factor X"
// message (NaN when it names none).
double limit_in(const std::string& message) {
  const std::string key = "past a limit point at load factor ";
  const auto at = message.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(message.substr(at + key.size()));
}

std::string static_failure(const ring::MultibodyOptions& o, const ring::StaticOptions& st) {
  try {
    multibody::solve_static(pin_roller_ring(), o, st);
  } catch (const ring::NumericalError& e) {
    return e.what();
  }
  return "";
}

// The O(n) path follows the pressed crown through its limit point as the dense path does
// (ContinuationPassesTheLimitPointOfAPressedArch): the same chain in other coordinates,
// so the same limit load factor (each located to ~1e-12 by the continuation driver; the
// two paths' equilibria agree to 1e-9 relative, see BothPathsGiveTheSameEquilibrium) and
// the same end, self-contact past the limit. At n = 2000 (past the crossover, where a
// dense Newton iteration costs seconds) the same end, and the limit within the chain's
// discretization error of the extrapolated n -> infinity value 0.9517637
// (tests/fem_reference/fem_continuation_test.cpp, LimitLoadAgreesWithTheMultibodyChain):
// second order, measured 0.9517447 at n = 1000 and 0.9517590 at n = 2000 (error 4.7e-6,
// a quarter of n = 1000's), so 1e-5 bounds it.
TEST(MultibodyStaticsSparse, ContinuationPassesTheLimitPointAsTheDensePathDoes) {
  const std::string dense = static_failure(chain_options(40, Method::dense), pressed_crown(8.0, 32));
  const std::string on = static_failure(chain_options(40, Method::sparse), pressed_crown(8.0, 32));
  for (const std::string& w : {dense, on}) {
    EXPECT_NE(w.find("limit point"), std::string::npos) << w;
    EXPECT_NE(w.find("touches itself"), std::string::npos) << w;
  }
  EXPECT_NEAR(limit_in(on), limit_in(dense), 1e-9) << on << "\n" << dense;
  const std::string fine = static_failure(chain_options(2000, Method::automatic), pressed_crown(8.0, 32));
  EXPECT_NE(fine.find("touches itself"), std::string::npos) << fine;
  EXPECT_NEAR(limit_in(fine), 0.9517637, 1e-5) << fine;
}

}  // namespace
