// Frequencies under load of the lumped chain (lumped_mass/preload.hpp, modes.preload =
// "static"). Oracles from outside the code under test:
//  - the chain's linear buckling (lumped::compute_buckling, itself checked against the closed
//    form ring::closed_form::pinned_ring_critical_pressure in buckling_test.cpp): under
//    follower pressure f lambda_1 the lowest omega^2 falls to zero at f = 1, linearly there;
//  - the chain's linear modes (lumped::compute_modes, model.cpp's assembly, not the nonlinear
//    chain's) at a vanishing load, with and without point masses;
//  - the multibody chain (multibody::compute_modes_under_load, segment angles, written
//    independently) without segment rotary inertia: the same discrete model in other
//    coordinates, under a uniform and under a bending load;
//  - the compound pendulum: a stiff ring hanging from its pin, turned 60 deg by gravity
//    against a rotational spring, whose lowest mode is the rigid swing with the point
//    inertia's J in full (the rotary mass about the deformed state, not about rest).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "common.hpp"
#include "lumped_mass/buckling.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/preload.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"
#include "support/preload.hpp"
#include "tests/support/close.hpp"

namespace {

using Kind = ring::Pressure::Kind;
constexpr double kPi = 3.14159265358979323846;

/// The lowest critical follower pressure of the chain (N/m) from its linear buckling.
double critical_follower(const ring::RingSpec& spec, int n) {
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, Kind::follower};
  b.count = 1;
  return lumped::compute_buckling(spec, lumptest::options(n, lumptest::kChain), b).factors[0];
}

ring::StaticOptions follower(double p) {
  ring::StaticOptions st;
  st.loads.pressure = {p, Kind::follower};
  return st;
}

std::string message(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument)";
}

// On a pin and a roller under follower pressure f lambda_1 the inextensible chain stays the
// n-gon (loads.hpp) and its tangent is K_0 + f lambda_1 K_1 (buckling.hpp), so the lowest
// omega^2 falls from the unloaded chain's to zero at f = 1: at f = 1e-9 it is the linear
// modes' to the two eigensolvers' rounding (1e-8 of omega^2: each solves its pencil to
// ~1e-12 at n = 40, the load moves omega^2 by 1e-9); near the zero the fall is linear
// (omega^2(0.999) / omega^2(0.99) = 0.1 to the curvature over 1 % of the load: 0.002, as the
// multibody test); the line through f = 0.5 and 0.75 meets zero within 2 % of f = 1 (the
// curvature that the supports' rigid motion adds through the mass to the n = 2 pair: the
// multibody chain's allowance, tests/multibody/test_buckling.cpp).
TEST(LumpedPreload, FrequenciesUnderLoadFallToZeroAtTheCriticalPressure) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::LumpedOptions o = lumptest::options(40, lumptest::kChain);
  const double critical = critical_follower(spec, 40);
  double residual = 0.0;  // over f <= 0.75 (below)
  auto omega2 = [&](double f) {
    const ring::ModalResult r = lumped::compute_modes_under_load(spec, o, follower(f * critical), 2);
    EXPECT_EQ(r.solver, "lumped");
    EXPECT_EQ(r.unknowns, 40 - 3);  // 40 hinges, 80 coordinates, 40 links, pin 2 rows, roller 1
    EXPECT_EQ(std::get<std::string>(r.model.at("preload")), "static");
    if (f <= 0.75) residual = std::max(residual, r.max_residual.value());
    return r.omega[0] * r.omega[0];
  };
  const double unloaded = std::pow(lumped::compute_modes(spec, o, 2).omega[0], 2);
  const double tiny = omega2(1e-9), near = omega2(0.99), nearer = omega2(0.999), a = omega2(0.5), b = omega2(0.75);
  const double zero = 0.75 + b / (a - b) * 0.25;  // where the line through f = 0.5, 0.75 meets 0
  std::printf("[lumped preload] n = 40: omega^2(1e-9)/unloaded - 1 = %.2e, omega^2(0.999)/omega^2(0.99) = %.4f, "
              "omega^2(0.5, 0.75)/unloaded = %.4f %.4f, line's zero at f = %.4f, max residual %.1e\n",
              tiny / unloaded - 1.0, nearer / near, a / unloaded, b / unloaded, zero, residual);
  EXPECT_TRUE(ringtest::IsClose(tiny, unloaded, 1e-8));
  EXPECT_LT(nearer / unloaded, 2e-3);
  EXPECT_NEAR(nearer / near, 0.1, 0.002);
  EXPECT_LT(b, a);
  EXPECT_NEAR(zero, 1.0, 0.02);
  // The residual of the shifted inverse on ker G: its rounding floor ~ eps ||T_r|| / omega^2
  // (ring/results.hpp) grows as omega^2 falls (6e-10 at f = 0.999), so it is bounded where
  // omega^2 is at least a quarter of the unloaded one: measured 2.3e-12; 1e-10.
  EXPECT_LT(residual, 1e-10);
  // Past the critical pressure the loaded ring has no (real) frequency.
  EXPECT_THROW(lumped::compute_modes_under_load(spec, o, follower(1.01 * critical), 2), ring::NumericalError);
}

/// The two chains' preloaded omega, mode by mode; returns the largest relative difference.
double worst_against_multibody(const ring::RingSpec& spec, const ring::StaticOptions& st, int n, int count,
                               double tol, const char* what) {
  ring::MultibodyOptions mo;
  mo.n = n;
  mo.rotary_inertia = false;  // the lumped chain's links carry their mass at the midpoint only
  mo.method = ring::MultibodyOptions::Method::dense;
  const ring::ModalResult mb = multibody::compute_modes_under_load(spec, mo, st, count);
  const ring::ModalResult lm = lumped::compute_modes_under_load(spec, lumptest::options(n, lumptest::kChain), st, count);
  EXPECT_EQ(lm.unknowns, mb.unknowns) << what;
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    worst = std::max(worst, ringtest::rel(lm.omega[i], mb.omega[i]));
    EXPECT_TRUE(ringtest::IsClose(lm.omega[i], mb.omega[i], tol)) << what << ", mode " << i + 1;
  }
  std::printf("[lumped preload vs multibody] n = %d, %s: %d modes, max rel. diff %.2e (lowest omega %.6f rad/s); "
              "seconds lumped %.3f, multibody %.3f; residuals %.1e, %.1e\n",
              n, what, count, worst, lm.omega[0], lm.seconds, mb.seconds, lm.max_residual.value(), mb.max_residual.value());
  return worst;
}

// The lumped chain (hinge positions, link lengths as constraints) and the multibody chain
// without segment rotary inertia (segment angles, closure constraints) are one discrete
// model: the same n-gon, masses rho A l at the link midpoints, springs EI/l at the hinges
// (their unloaded modes agree to 1e-9: vs_multibody_test.cpp). With multibody.rotary_inertia
// = true the links would also carry m l^2 / 12, a model difference of O((pi/n)^2). So
// their frequencies about the same loaded equilibrium must agree up to the rounding of each
// solver's statics (hinges to ~1e-12 R) and pencil. Cases: (a) follower pressure at half its
// critical value (the n-gon, prestressed); (b) two opposite point loads P R^2/EI = 2 on the
// diameter 0-180 deg, which bend the ring far into the nonlinear range (the elastica's
// diametral problem, loads_test.cpp), plus a dead pressure at a quarter of the follower's
// critical value. All 37 modes at n = 40.
// Measured: (a) 5.2e-12, (b) 1.6e-11 at most over the 37 modes (the highest modes: the
// shifted inverse loses (omega_k / omega_1)^2 eps, vs_multibody_test.cpp). Tolerance 1e-9: the
// bound of the unloaded comparison (vs_multibody_test.cpp), far below any model difference
// (the segments' rotary inertia would move omega by ~1e-3).
TEST(LumpedPreload, EqualsTheMultibodyChainUnderUniformAndBendingLoads) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const int n = 40;
  const double critical = critical_follower(spec, n);
  worst_against_multibody(spec, follower(0.5 * critical), n, n - 3, 1e-9, "follower 0.5 critical");

  const double P = 2.0 * spec.EI() / (spec.radius * spec.radius);
  ring::StaticOptions bend;
  bend.loads.points = {{0.0, {-P, 0.0}}, {180.0, {P, 0.0}}};
  bend.loads.pressure = {0.25 * critical, Kind::dead};
  bend.steps = 20;
  worst_against_multibody(spec, bend, n, n - 3, 1e-9, "squeeze P R^2/EI = 2 + dead 0.25 critical");
}

// Timings at n = 160 (printed for the docs) and the same agreement on the lowest ten modes.
// Tolerance 1e-8: the lumped tangent's rounding floor grows as eps (R/l)^4 (buckling.hpp:
// 2e-10 at n = 160); measured 1.2e-10.
TEST(LumpedPreload, EqualsTheMultibodyChainAtN160) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  worst_against_multibody(spec, follower(0.5 * critical_follower(spec, 160)), 160, 10, 1e-8, "follower 0.5 critical");
}

// Point masses: their translational mass is the chain's constant mass matrix, their rotary
// inertia J rides on the tangent's rotation at their hinge (terms.hpp). At a vanishing load
// the preloaded modes are the linear model's with the same masses (model.cpp's assembly of J
// at rest), to the eigensolvers' rounding as above.
TEST(LumpedPreload, PointMassesAtAVanishingLoadAreTheLinearModes) {
  ring::RingSpec spec = ringtest::pin_270_roller_90();
  const double ring_mass = 2.0 * kPi * spec.radius * spec.rhoA();
  spec.masses = {{0.0, 0.1 * ring_mass, 0.05 * ring_mass * spec.radius * spec.radius},
                 {135.0, 0.05 * ring_mass, 0.0}};
  const ring::LumpedOptions o = lumptest::options(40, lumptest::kChain);
  const int count = 6;
  const ring::ModalResult loaded =
      lumped::compute_modes_under_load(spec, o, follower(1e-9 * critical_follower(spec, 40)), count);
  const ring::ModalResult linear = lumped::compute_modes(spec, o, count);
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const double a = loaded.omega[i] * loaded.omega[i], b = linear.omega[i] * linear.omega[i];
    worst = std::max(worst, ringtest::rel(a, b));
    EXPECT_TRUE(ringtest::IsClose(a, b, 1e-8)) << "mode " << i + 1;
  }
  std::printf("[lumped preload point masses] f = 1e-9: omega^2 against the linear modes, max rel. diff %.2e\n", worst);
}

// The compound pendulum. The ring pinned at 0 deg, a rotational spring kr at the pin, a point
// inertia J = I_O / 2 there, gravity g = (0, -g0): the ring swings about the pin by alpha,
// with kr alpha = M g0 rho cos alpha (M the ring's mass, rho the n-gon's circumradius: its
// centre of mass at the centre), and its lowest mode is the rigid swing,
//   omega^2 = (kr + M g0 rho sin alpha) / (I_O + J),   I_O = n m (rho^2 + (rho cos(pi/n))^2)
// (the midpoint masses m = rho A l about the pin: sum |y_j - pin|^2 with sum y_j = 0); kr is
// chosen for alpha = 60 deg. J acts on the rotation of the tangent, which turns with the ring
// by alpha: the mass about the deformed state counts J in full, where one taken at rest would
// count J cos^2 alpha (omega^2 a third too high). The chain departs from the rigid body by
// O(g0): its sag and the swing's coupling to bending ((omega / omega_bending)^2), and the
// hinge's own rotation that carries J (terms.hpp; kr ~ g0); measured +1.1e-5 (+1.6e-5 with J
// condensed on the chord rotation) of
// omega^2 at g0 = 3e-3 m/s^2 and twice that at 2 g0. Richardson's 2 r(g0) - r(2 g0) removes
// it: measured 2.9e-8 left (2.4e-8 condensed) (the O(g0^2) remainder and the rounding of omega^2 ~ 5e-5 of the
// shift, which grows as 1/g0: 2e-6 at g0 = 1e-5). Tolerance 5e-7.
double pendulum_ratio(double g0) {
  ring::RingSpec spec = ringtest::pinned_ring(0.0);
  const int n = 40;
  const double l = 2.0 * kPi * spec.radius / n, rho = l / (2.0 * std::sin(kPi / n)), m = spec.rhoA() * l;
  const double M = n * m, I_O = n * m * (rho * rho + std::pow(rho * std::cos(kPi / n), 2));
  const double alpha = kPi / 3.0;
  const double kr = M * g0 * rho * std::cos(alpha) / alpha;
  const double J = 0.5 * I_O;
  spec.supports.springs = {{0.0, 0.0, 0.0, kr}};
  spec.masses = {{0.0, 0.0, J}};
  ring::StaticOptions st;
  st.loads.gravity = {0.0, -g0};
  const ring::ModalResult r = lumped::compute_modes_under_load(spec, lumptest::options(n, lumptest::kChain), st, 1);
  const double exact = (kr + M * g0 * rho * std::sin(alpha)) / (I_O + J);
  return r.omega[0] * r.omega[0] / exact;
}

TEST(LumpedPreload, AStiffRingHangingFromItsPinSwingsAsACompoundPendulum) {
  const double g0 = 3e-3;
  const double one = pendulum_ratio(g0), two = pendulum_ratio(2.0 * g0);
  const double extrapolated = 2.0 * one - two;
  std::printf("[lumped preload pendulum] omega^2 / rigid - 1 = %.2e (g0), %.2e (2 g0), extrapolated %.2e; J taken "
              "at rest would give %.2e\n",
              one - 1.0, two - 1.0, extrapolated - 1.0, 1.5 / (1.0 + 0.5 * 0.25) - 1.0);
  EXPECT_NEAR(extrapolated, 1.0, 5e-7);
}

// What cannot work is refused before anything is computed, naming the key.
TEST(LumpedPreload, Refusals) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::StaticOptions st = follower(1.0);
  // The lumped frame's rotations are massless; the consistent frame is taken (frame_test.cpp).
  EXPECT_NE(message([&] { lumped::check_preloaded_modes(spec, lumptest::options(40, lumptest::kFrame), st); })
                .find("lumped.variant = \"frame\" lumps no rotary inertia"),
            std::string::npos);
  EXPECT_NO_THROW(lumped::check_preloaded_modes(spec, lumptest::options(40, lumptest::kConsistent), st));
  // The solver calls the same check first.
  EXPECT_NE(message([&] { lumped::compute_modes_under_load(spec, lumptest::options(40, lumptest::kFrame), st, 2); })
                .find("lumped.variant"),
            std::string::npos);
  EXPECT_NE(message([&] {
              lumped::check_preloaded_modes(spec, lumptest::options(lumped::kMaxPreloadHinges + 1, lumptest::kChain), st);
            }).find("lumped.n"),
            std::string::npos);
  // The statics' own refusals: a ring on its pin alone turns about it under pressure.
  EXPECT_NE(message([&] {
              lumped::check_preloaded_modes(ringtest::pinned_ring(270.0), lumptest::options(40, lumptest::kChain), st);
            }).find("supports.roller"),
            std::string::npos);
  // More modes than the chain has: n - 3 = 37 on a pin and a roller.
  EXPECT_NE(message([&] { lumped::compute_modes_under_load(spec, lumptest::options(40, lumptest::kChain), st, 38); })
                .find("modes.count"),
            std::string::npos);
  EXPECT_NE(message([&] { lumped::compute_modes_under_load(spec, lumptest::options(40, lumptest::kChain), st, 0); })
                .find("modes.count"),
            std::string::npos);
}


// Frequencies under load against the closed form: the free ring on a foundation under a
// follower pressure (support/preload.hpp), at the chain's O(1/n^2) (the multibody chain's
// numbers to 1e-12, the same discrete model: 7.7e-4 at most, 1.85e-3 in the slope).
TEST(LumpedPreload, MeetsTheClosedFormOfTheRingOnAFoundation) {
  const ring::LumpedOptions o = lumptest::options(80, lumptest::kChain);
  ringtest::expect_the_closed_form_under_pressure(
      [&](const ring::RingSpec& s, const ring::StaticOptions& st, int count) {
        return lumped::compute_modes_under_load(s, o, st, count);
      },
      1e-3, 3e-3);
}

}  // namespace
