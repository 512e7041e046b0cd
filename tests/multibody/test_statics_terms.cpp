// The O(n) statics (hinge positions, multibody/statics_natural.cpp) with every term and
// load of the dense statics: the foundation, translational and rotational springs, the
// clamp, further pins (attachments.hpp), several point loads, gravity, pressure of the
// three kinds (loading.hpp). Oracles: the dense path (segment angles: the same chain in
// other coordinates, a different assembly and solver), and at large n, where only the O(n)
// path runs, the closed forms of ring/closed_form.hpp at the chain's order-2 error.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "multibody/backend.hpp"
#include "multibody/checks.hpp"
#include "multibody/statics.hpp"
#include "ring/closed_form.hpp"
#include "tests/multibody/common.hpp"
#include "tests/support/convergence.hpp"

namespace {

using mbtest::chain_options;
using Method = ring::MultibodyOptions::Method;
using Kind = ring::Pressure::Kind;


/// A scene: the ring with its terms and the statics with its loads.
struct Scene {
  std::string name;
  ring::RingSpec spec;
  ring::StaticOptions statics;
};

/// P R^2 / EI = p for the paper's ring (N).
double force(double p) {
  const ring::RingSpec s = ringtest::free_ring();
  return p * s.EI() / (s.radius * s.radius);
}

ring::StaticOptions recorded(std::vector<ring::PointLoad> points, int steps = 8) {
  ring::StaticOptions st;
  st.loads.points = std::move(points);
  st.steps = steps;
  st.record = {0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0};
  return st;
}

/// One scene per new term of the O(n) statics, each load at P R^2/EI ~ 1 (displacements
/// ~0.1 R: the nonlinear terms matter). Every point is a hinge for n a multiple of 8.
std::vector<Scene> scenes(int n) {
  std::vector<Scene> out;
  {
    Scene s{"foundation and springs", ringtest::pinned_ring(180.0), recorded({{0.0, {-force(2.0), force(0.5)}}})};
    const double EI_R4 = s.spec.EI() / std::pow(s.spec.radius, 4);
    s.spec.foundation = {20.0 * EI_R4, 5.0 * EI_R4};
    s.spec.supports.springs = {{90.0, 30.0 * EI_R4 * s.spec.radius, 10.0 * EI_R4 * s.spec.radius, 0.0},
                               {315.0, 0.0, 50.0 * EI_R4 * s.spec.radius, 0.0}};
    out.push_back(s);
  }
  {
    // No pin: the foundation holds the rigid motions (hinge 0 free in the O(n) path).
    Scene s{"free ring on a foundation", ringtest::free_ring(),
            recorded({{0.0, {-force(2.0), force(0.5)}}, {180.0, {force(1.0), 0.0}}})};
    const double EI_R4 = s.spec.EI() / std::pow(s.spec.radius, 4);
    s.spec.foundation = {10.0 * EI_R4, 10.0 * EI_R4};
    s.statics.loads.pressure = {0.5 * ring::closed_form::critical_pressure(s.spec, Kind::follower), Kind::follower};
    out.push_back(s);
  }
  out.push_back({"several point loads", ringtest::pin_roller_ring(),
                 recorded({{0.0, {-force(1.5), 0.0}}, {90.0, {0.0, -force(1.0)}}, {135.0, {force(0.5), force(0.3)}}})});
  {
    // Hanging from its pin at 90 deg (no roller: gravity holds the rotation), a point mass
    // at the bottom weighs too.
    Scene s{"gravity, hanging", ringtest::pinned_ring(90.0), recorded({})};
    s.spec.masses = {{270.0, 200.0, 0.0}};
    s.statics.loads.gravity = {0.0, -9.81 * 0.2};
    out.push_back(s);
  }
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    Scene s{"pressure, " + ring::to_string(kind), ringtest::pin_270_roller_90(),
            recorded({{0.0, {-force(0.5), 0.0}}, {180.0, {force(0.5), 0.0}}})};
    s.statics.loads.pressure = {0.5 * ring::closed_form::critical_pressure(s.spec, kind), kind};
    out.push_back(s);
  }
  {
    Scene s{"further pins", ringtest::pinned_ring(180.0),
            recorded({{90.0, {0.0, -force(3.0)}}, {270.0, {force(1.0), 0.0}}})};
    // The last: hinge n - 2, the band's last (hinge n - 1, next to the pin, would make link
    // n - 1 a redundant row).
    s.spec.supports.pins = {0.0, 45.0, 180.0 - 720.0 / n};
    out.push_back(s);
  }
  {
    Scene s{"clamp and rotational springs", ringtest::pinned_ring(180.0), recorded({{90.0, {force(0.3), -force(0.6)}}})};
    const double K = s.spec.EI() / s.spec.radius;
    s.spec.supports.clamp = 180.0;
    s.spec.supports.springs = {{0.0, 0.0, 0.0, 3.0 * K}, {270.0, 5.0 * K / s.spec.radius, 0.0, 0.5 * K}};
    out.push_back(s);
  }
  return out;
}

class MultibodyStaticsTerms : public ::testing::TestWithParam<int> {};

// The two backends solve the same chain in different coordinates with different code:
// their equilibria agree to the Newton tolerances (1e-12 R on positions, 1e-12 rad on the
// angles: ~1e-11 m on a 10 m ring against displacements ~1 m), bound 1e-9 relative to the
// largest displacement, the precedent of test_statics.cpp (BothPathsGiveTheSameEquilibrium).
// Every hinge's position is compared, not only the recorded points. Measured: 3e-16 to 3e-14
// relative for every scene at n = 40, 120, 200, the further pins' 1e-13 to 9e-13.
TEST_P(MultibodyStaticsTerms, BothBackendsGiveTheSameEquilibrium) {
  const int n = GetParam();
  for (const Scene& s : scenes(n)) {
    SCOPED_TRACE(s.name);
    ring::StaticResult dense, on;
    try {
      dense = multibody::solve_static(s.spec, chain_options(n, Method::dense), s.statics);
      on = multibody::solve_static(s.spec, chain_options(n, Method::sparse), s.statics);
    } catch (const std::exception& e) {
      ADD_FAILURE() << s.name << ", n = " << n << ": " << e.what();
      continue;
    }
    double scale = 0.0, diff = 0.0;
    for (const auto& d : dense.displacements) scale = std::max(scale, std::hypot(d.ux, d.uy));
    ASSERT_EQ(dense.node_x.size(), on.node_x.size());
    for (size_t k = 0; k < dense.node_x.size(); ++k)
      diff = std::max(diff, std::hypot(dense.node_x[k] - on.node_x[k], dense.node_y[k] - on.node_y[k]));
    EXPECT_GT(scale, 1e-3 * s.spec.radius) << s.name << ": a visible deformation";
    EXPECT_LT(diff, 1e-9 * scale) << s.name << ", n = " << n << ": largest displacement " << scale;
  }
}

INSTANTIATE_TEST_SUITE_P(N, MultibodyStaticsTerms, ::testing::Values(40, 120, 200));

}  // namespace

namespace {

const std::vector<int> kLarge{1000, 2000, 4000, 10000};

// At large n only the O(n) path runs ("auto" takes it from n = 1000 for every term): the
// ring hanging from its pin at 90 deg under its own weight against the thin ring's series
// (closed_form.hpp, Roark's 0.4674 and 0.4292 q R^4/EI). A roller at 270 deg, on the line
// of symmetry, carries nothing (the symmetric solution keeps that point on the line) but
// removes the rotation about the pin that only gravity's weak moment holds, which in hinge
// positions costs the solve digits. The sag is 1e-7 R: the nonlinear part, -0.4 sag / R
// relative (measured), stays below 1.5 % of the chain's O(1/n^2) error at n = 10^4.
// Measured: sag errors 3.14e-5, 7.83e-6, 1.93e-6, 2.79e-7 (e n^2 = 31.4 .. 27.9, the dense
// chain's 1.2e-3 at n = 160 of test_loading.cpp, 30.7, continued), across 2.08e-5 .. 2.08e-7.
TEST(MultibodyStaticsTermsLargeN, HangingRingMeetsTheSelfWeightSeriesAtOrderTwo) {
  ring::RingSpec spec = ringtest::pinned_ring(90.0);
  spec.supports.roller = 270.0;
  const ring::StaticOptions st = mbtest::hanging_statics(spec, 1e-7);
  const auto exact = ring::closed_form::hanging_ring_self_weight(spec, -st.loads.gravity[1]);
  std::vector<double> sag, across;
  for (int n : kLarge) {
    ASSERT_EQ(multibody::backend(chain_options(n, Method::automatic), spec, st.loads, multibody::Analysis::statics),
              multibody::Backend::banded);
    const ring::StaticResult r = multibody::solve_static(spec, chain_options(n, Method::automatic), st);
    sag.push_back(std::abs(-r.displacements[2].uy - exact.sag) / exact.sag);
    across.push_back(std::abs(r.displacements[1].ux - r.displacements[0].ux - exact.across) / exact.across);
  }
  RecordProperty("sag_error_n10000", mbtest::sci(sag.back()));
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(kLarge, sag), 2.0, 0.1, 4e-7)) << "sag";  // ceiling: 31 / n^2 = 3.1e-7
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(kLarge, across), 2.0, 0.1)) << "across";
}

// Two opposite forces along a diameter of a ring under half its critical pressure of each
// kind (each kind's load stiffness), against the Fourier series about the pressurized
// circle (closed_form.hpp), as test_loading.cpp's SqueezeUnderPressureMeetsTheSeriesOfEachKind
// at n = 40 .. 160, here at n = 1000 .. 10^4 on the O(n) path. P = 1e-7 EI/R^2 keeps the
// series' linearity to ~1e-7 (P = 1e-6 showed 2e-7 more at n = 10^4; 1e-8 meets the solve's
// round-off). Measured e n^2: follower 40.5 .. 42.1, dead 37.4 .. 40.8, central 32.7 .. 35.5.
TEST(MultibodyStaticsTermsLargeN, SqueezeUnderPressureMeetsTheSeriesAtOrderTwo) {
  ring::RingSpec spec = ringtest::pin_270_roller_90();
  const double P = 1e-7 * spec.EI() / (spec.radius * spec.radius);
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    const ring::Pressure pressure{0.5 * ring::closed_form::critical_pressure(spec, kind), kind};
    const double exact = ring::closed_form::diametral_load_under_pressure(spec, P, pressure).along;
    ring::StaticOptions st;
    st.loads.points = {{0.0, {-P, 0.0}}, {180.0, {P, 0.0}}};
    st.loads.pressure = pressure;
    st.steps = 4;
    st.record = {0.0, 180.0};
    std::vector<double> err;
    for (int n : kLarge) {
      const ring::StaticResult r = multibody::solve_static(spec, chain_options(n, Method::automatic), st);
      err.push_back(std::abs(r.displacements[1].ux - r.displacements[0].ux - exact) / exact);
    }
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(kLarge, err), 2.0, 0.1, 5e-7))  // ceiling: 42 / n^2
        << ring::to_string(kind);
  }
}

// The tyre's case: a free ring on a foundation under a small radial point load against the
// inextensional Fourier series (mbtest::foundation_point_load_series), as test_attachments.cpp's
// StaticsOnAFoundationConvergeToTheFourierSeries at n = 80 .. 320, here at n = 1000 .. 10^4 on
// the O(n) path. The equilibrium's nonlinear part is -0.12 w/R relative (measured), above the
// chain's error at large n for any load the solve resolves (w(F = 1 N) = 5.6e-6 R: -7e-7), so
// the linear part is taken by Richardson in the load, (4 u(F) - u(2F)) / 2, exact for
// u = a F + b F^2. F = 10 N (w ~ 6e-5 R) keeps the O(F^3) part and the solve's ~1e-12 R below
// 1 % of the chain's error. Measured e n^2 = 11.47, 11.47, 11.47, 11.45 at n = 1000, 2000,
// 4000, 10^4.
TEST(MultibodyStaticsTermsLargeN, FreeRingOnAFoundationMeetsTheFourierSeriesAtOrderTwo) {
  ring::RingSpec spec = ringtest::free_ring();
  spec.foundation = {500.0, 300.0};
  const double F = 10.0;
  const double exact = mbtest::foundation_point_load_series(spec, F);
  std::vector<double> err;
  for (int n : kLarge) {
    double u[2];
    for (int i : {0, 1}) {
      const ring::StaticOptions st = recorded({{0.0, {(i + 1) * F, 0.0}}}, 1);
      ASSERT_EQ(multibody::backend(chain_options(n, Method::automatic), spec, st.loads, multibody::Analysis::statics),
                multibody::Backend::banded);
      u[i] = multibody::solve_static(spec, chain_options(n, Method::automatic), st).displacements[0].ux;
    }
    err.push_back(std::abs((4 * u[0] - u[1]) / 2 - exact) / exact);
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(kLarge, err), 2.0, 0.05, 1.2e-7));  // ceiling: 11.5 / n^2
}

// The ring on a foundation with translational springs, pinned (with a roller at the load)
// and free (a tyre: the foundation alone holds it, under follower pressure too): the first
// two scenes, P R^2/EI ~ 2, nonlinear equilibria without a closed form, converge at order 2
// up to n = 16000: the successive differences of the displacements fall by 4 (measured
// 3.99995 to 4.00038), so neither the solve's round-off nor the stopping rule shows (4 +- 0.1:
// order 2 +- 0.04).
TEST(MultibodyStaticsTermsLargeN, RingsOnAFoundationConvergeAtOrderTwoToSixteenThousand) {
  for (int which : {0, 1}) {
    Scene s = scenes(8)[which];
    SCOPED_TRACE(s.name);
    if (which == 0) s.spec.supports.roller = 0.0;
    s.statics.steps = 4;
    s.statics.record = {0.0, 90.0};
    std::vector<double> along, crown;
    for (int n : {2000, 4000, 8000, 16000}) {
      const ring::StaticResult r = multibody::solve_static(s.spec, chain_options(n, Method::automatic), s.statics);
      along.push_back(r.displacements[0].ux);
      crown.push_back(r.displacements[1].uy);
    }
    for (const std::vector<double>* u : {&along, &crown})
      for (int i = 0; i + 2 < 4; ++i) {
        const double ratio = ((*u)[i + 1] - (*u)[i]) / ((*u)[i + 2] - (*u)[i + 1]);
        EXPECT_NEAR(ratio, 4.0, 0.1) << "differences " << (*u)[i + 1] - (*u)[i] << ", " << (*u)[i + 2] - (*u)[i + 1];
      }
  }
}

}  // namespace

namespace {

// The statics' backend rule (backend.hpp): "auto" takes the O(n) path from the crossover
// for every term and load, stays dense for the Timoshenko chain and for static.path = true
// (branch switching takes the dense tangent's eigenvectors); a forced "sparse" refuses
// those two, naming the key.
TEST(MultibodyStaticsTermsBackend, AutoTakesTheOnPathForEveryTermAndRefusesOnlyWhatItLacks) {
  Scene s = scenes(8)[1];  // the free ring on a foundation under follower pressure
  const ring::MultibodyOptions at = chain_options(multibody::sparse_crossover(multibody::Analysis::statics),
                                                  Method::automatic);
  EXPECT_EQ(multibody::backend(at, s.spec, s.statics), multibody::Backend::banded);
  EXPECT_EQ(multibody::backend(chain_options(999, Method::automatic), s.spec, s.statics), multibody::Backend::dense);
  s.statics.path = true;
  EXPECT_EQ(multibody::backend(at, s.spec, s.statics), multibody::Backend::dense);
  auto refusal = [](const ring::RingSpec& spec, const ring::StaticOptions& st) -> std::string {
    try {
      multibody::check_static(spec, chain_options(40, Method::sparse), st);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(refusal(s.spec, s.statics).find("static.path"), std::string::npos) << refusal(s.spec, s.statics);
  s.statics.path = false;
  EXPECT_EQ(refusal(s.spec, s.statics), "");
  s.spec.theory = ring::Theory::timoshenko;
  EXPECT_EQ(multibody::backend(at, s.spec, s.statics), multibody::Backend::dense);
  EXPECT_NE(refusal(s.spec, s.statics).find("ring.theory"), std::string::npos) << refusal(s.spec, s.statics);
}

}  // namespace
