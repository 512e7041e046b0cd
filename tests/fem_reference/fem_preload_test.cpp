// Frequencies under load of the geometrically exact FE beam (fem_reference/preload.hpp,
// modes.preload = "static") against oracles outside the code under test:
//  - the FE's own unloaded modes (fem::compute_modes, the linear model's refined
//    eigen-solve: a different code path) and linear buckling (fem::compute_buckling,
//    itself checked against ring::closed_form::pinned_ring_critical_pressure in
//    fem_buckling_test.cpp): omega^2 falls from the unloaded value to zero, linearly, at
//    the critical pressure, as the multibody chain's does (tests/multibody/test_buckling.cpp,
//    FrequenciesUnderLoadFallToZeroAtTheCriticalPressure);
//  - the independent multibody chain's frequencies under load (multibody/statics.hpp), whose
//    error against the converged FE falls at the chain's order 2 (a test may link several
//    solvers; fem_reference itself never includes multibody);
//  - the FE's own convergence: order 2(p - 1) = 4 in the elements at p = 3, and a gain of
//    more than an order of magnitude per degree at fixed elements.
//
// The ring: the paper's (R = 10 m, solid circle d = 0.12 m, E = 2.1e11 Pa, rho = 7.8e3;
// tests/support/paper.hpp) on a pin at 270 deg and a roller at 90 deg. Two loads: a
// follower pressure at half its critical value (the membrane state: the inextensible
// equilibrium is the circle), and a squeeze of P = 3 EI/R^2 at 0 and 180 deg toward the
// centre, which bends the ring first (measured: the squeezed diameter shortens by 0.62 R,
// the other lengthens by 0.42 R).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem_reference/buckling.hpp"
#include "fem_reference/checks.hpp"
#include "fem_reference/modes.hpp"
#include "fem_reference/preload.hpp"
#include "multibody/statics.hpp"
#include "ring/closed_form.hpp"
#include "ring/errors.hpp"
#include "ring/sampling.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/preload.hpp"
#include "tests/support/close.hpp"

namespace {

using Kind = ring::Pressure::Kind;

ring::FemOptions fem_options(int elements, int degree, bool extensible) {
  ring::FemOptions o;
  o.elements = elements;
  o.degree = degree;
  o.extensible = extensible;
  return o;
}

/// A follower pressure of f times `critical` (N/m).
ring::StaticOptions follower(double f, double critical) {
  ring::StaticOptions st;
  st.loads.pressure = {f * critical, Kind::follower};
  return st;
}

/// P = p EI / R^2 at 0 and 180 deg, both toward the centre (vertices of 4k elements).
ring::StaticOptions squeeze(const ring::RingSpec& spec, double p) {
  const double P = p * spec.EI() / (spec.radius * spec.radius);
  ring::StaticOptions st;
  st.loads.points = {{0.0, {-P, 0.0}}, {180.0, {P, 0.0}}};
  return st;
}

/// x in scientific notation, 4 digits (the recorded measurements).
std::string sci(double x) {
  std::ostringstream o;
  o << std::scientific << std::setprecision(3) << x;
  return o.str();
}


// As the multibody test: follower pressure f times the FE's own critical pressure (16
// cubic elements, extensible: 6418.05 N/m, 3.0 EI/R^3 up to the extensible correction and
// the discretization). The extensible beam first shrinks by the hoop strain (not exactly
// the circle of the inextensible closed forms), so T(q*, 1) is not exactly K_0 + f K_1;
// the zero still comes at the bifurcation of the path.
//  - f = 1e-9: the unloaded modes of the linear model (a different code path: the refined
//    LAPACK solve of ring_model.hpp) to 1e-8. Measured -9.4e-10, -9.9e-10, -4.0e-10,
//    -3.7e-10 for modes 1-4: the load's own first-order change, -f (d omega^2/df) / omega^2
//    ~ -f (the n = 2 pair) and -0.4 f (n = 3), plus the tangent's round-off (~1e-10 here);
//  - near the zero the fall is linear: omega^2(0.999) / omega^2(0.99) = 0.1 (measured
//    0.10039; the multibody chain's bound 0.002), omega^2(0.999) below 2e-3 of the
//    unloaded (measured 1.09e-3);
//  - the line through f = 0.5 and 0.75 meets zero within 0.02 of f = 1 (measured 1.0115;
//    the chain's bound: the curvature that the supports' rigid motion adds, through the
//    mass, to the n = 2 pair).
TEST(FemPreload, FrequenciesUnderLoadFallToZeroAtTheCriticalPressure) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::FemOptions o = fem_options(16, 3, true);
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, Kind::follower};
  b.count = 1;
  const double critical = fem::compute_buckling(spec, o, b).factors[0];
  const ring::ModalResult unloaded = fem::compute_modes(spec, o, 4);
  const ring::ModalResult tiny = fem::compute_modes_under_load(spec, o, follower(1e-9, critical), 4);
  ASSERT_EQ(tiny.omega.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const double ratio = std::pow(tiny.omega[k] / unloaded.omega[k], 2);
    RecordProperty("omega2_ratio_minus_1_mode_" + std::to_string(k + 1), sci(ratio - 1.0));
    EXPECT_NEAR(ratio, 1.0, 1e-8) << "mode " << k + 1;
    // The shapes too: the same mode (MAC 1 to the square of the frequencies' agreement).
    EXPECT_GT(ring::mac(tiny.shapes[k], unloaded.shapes[k]), 1.0 - 1e-8) << "mode " << k + 1;
  }
  auto omega2 = [&](double f) {
    const double w = fem::compute_modes_under_load(spec, o, follower(f, critical), 1).omega[0];
    return w * w;
  };
  const double w2 = std::pow(unloaded.omega[0], 2);
  RecordProperty("ratio_0999_099", sci(omega2(0.999) / omega2(0.99)));
  EXPECT_LT(omega2(0.999) / w2, 2e-3);
  EXPECT_NEAR(omega2(0.999) / omega2(0.99), 0.1, 0.002);
  const double a = omega2(0.5), c = omega2(0.75);
  EXPECT_LT(c, a);
  const double zero = 0.75 + c / (a - c) * 0.25;  // where the line through the two meets 0
  RecordProperty("zero", sci(zero));
  EXPECT_NEAR(zero, 1.0, 0.02) << a / w2 << " " << c / w2;
}

// The result's contract: solver, model, unknowns, the residual in the FE's dual norm
// (refined pairs: measured 5.7e-12 here; 1e-9 is the bound of a refined pair, far below the
// 1e-4 at which the refinement fails), and shapes at the common stations held by the
// supports (both displacements zero at the pin, the tangential one at the roller, whose
// line is the diameter through the pin; to the sampling's round-off).
TEST(FemPreload, ResultNamesTheModelAndHoldsTheSupports) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::ModalResult r = fem::compute_modes_under_load(spec, fem_options(16, 3, true), squeeze(spec, 1.0), 3);
  EXPECT_EQ(r.solver, "fem");
  EXPECT_EQ(std::get<std::string>(r.model.at("preload")), "static");
  EXPECT_EQ(std::get<long long>(r.model.at("elements")), 16);
  EXPECT_EQ(std::get<long long>(r.model.at("degree")), 3);
  EXPECT_TRUE(std::get<bool>(r.model.at("extensible")));
  EXPECT_EQ(r.unknowns, 109);  // 16 cells x (4 + 3) DoFs - 3 supported
  EXPECT_EQ(r.rigid_modes, 0);
  EXPECT_EQ(r.residual_norm, fem::kDualResidualNorm);
  RecordProperty("max_residual", sci(r.max_residual.value()));
  EXPECT_LT(r.max_residual.value(), 1e-9);
  EXPECT_GT(r.seconds, 0.0);
  ASSERT_EQ(r.shapes.size(), 3u);
  for (const ring::ModeShape& shape : r.shapes) {
    ASSERT_EQ(shape.radial.size(), static_cast<std::size_t>(ring::kStations));
    double largest = 0.0;
    for (int i = 0; i < ring::kStations; ++i)
      largest = std::max({largest, std::abs(shape.radial[i]), std::abs(shape.tangential[i])});
    EXPECT_NEAR(largest, 1.0, 1e-12);
    const int pin = ring::kStations * 270 / 360, roller = ring::kStations * 90 / 360;
    EXPECT_NEAR(shape.radial[pin], 0.0, 1e-12);
    EXPECT_NEAR(shape.tangential[pin], 0.0, 1e-12);
    EXPECT_NEAR(shape.tangential[roller], 0.0, 1e-12);
  }
}

// Springs, a point mass with rotary inertia and a foundation enter the loaded tangent and
// mass as they enter the linear model's K and M: at a vanishing load the modes are the
// linear model's (compute_modes) to 1e-9 (the refined pairs' round-off at this size is
// ~1e-10; measured 7.5e-11 at most).
TEST(FemPreload, TermsAtAVanishingLoadAreTheLinearModes) {
  ring::RingSpec spec = ringtest::pin_270_roller_90();
  spec.masses = {{45.0, 0.05 * spec.rho * spec.A() * 2.0 * M_PI * spec.radius, 20.0}};  // 5 % of the ring
  spec.supports.springs = {{180.0, 1e4, 2e4, 5e5}};
  spec.foundation = {30.0, 10.0};
  const ring::FemOptions o = fem_options(16, 3, true);
  const ring::ModalResult linear = fem::compute_modes(spec, o, 4);
  ring::StaticOptions st;
  st.loads.pressure = {1e-6, Kind::follower};
  const ring::ModalResult loaded = fem::compute_modes_under_load(spec, o, st, 4);
  for (int k = 0; k < 4; ++k) {
    RecordProperty("difference_mode_" + std::to_string(k + 1), sci(loaded.omega[k] / linear.omega[k] - 1));
    EXPECT_TRUE(ringtest::IsClose(loaded.omega[k], linear.omega[k], 1e-9)) << k + 1;
  }
}

/// The two loads of the comparison with the chain.
enum class Load { pressure, squeeze };
void PrintTo(Load l, std::ostream* os) { *os << (l == Load::pressure ? "pressure" : "squeeze"); }

ring::StaticOptions load_of(Load l, const ring::RingSpec& spec) {
  // Half the inextensible ring's critical follower pressure 3 EI/R^3 (closed form).
  return l == Load::pressure ? follower(0.5, ring::closed_form::pinned_ring_critical_pressure(spec, Kind::follower))
                             : squeeze(spec, 3.0);
}

class FemPreloadAgainstTheChain : public ::testing::TestWithParam<Load> {};

// The multibody chain converges to the inextensible ring, so its oracle is the inextensible
// FE (fem.extensible = false, the extrapolation in 1/beta) at 16 elements of degree 8,
// converged to its round-off: measured changes of 1e-7 between degrees 6, 8, 10, 12 (the
// inextensible penalty's rounding of the assembled tangent, preload.hpp), far below the
// chain's error at n = 160 (>= 3.6e-5). The chain's error falls at its order 2 (the
// O((l/R)^2) of the rigid segments): measured ratios 3.99-4.00 per halving for all four
// modes and both loads; fitted over n = 40, 80, 160, each mode within 0.1 of 2 (the
// chain's own order bands are 0.15-0.2; the FE's noise moves the fit by < 0.01), and the
// error at n = 160 below 1.5e-3 (measured at most 1.18e-3, the squeeze's third mode).
TEST_P(FemPreloadAgainstTheChain, ChainErrorFallsAtOrderTwo) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::StaticOptions st = load_of(GetParam(), spec);
  const int count = 4;
  const ring::ModalResult fe = fem::compute_modes_under_load(spec, fem_options(16, 8, false), st, count);
  ring::MultibodyOptions o;
  o.method = ring::MultibodyOptions::Method::dense;
  const std::vector<int> sizes{40, 80, 160};
  std::vector<std::vector<double>> errors(count);
  for (int n : sizes) {
    o.n = n;
    const ring::ModalResult chain = multibody::compute_modes_under_load(spec, o, st, count);
    for (int k = 0; k < count; ++k) errors[k].push_back(ringtest::rel(chain.omega[k], fe.omega[k]));
  }
  for (int k = 0; k < count; ++k) {
    const auto samples = ringtest::in_n(sizes, errors[k]);  // the order in 1 / size
    RecordProperty("order_mode_" + std::to_string(k + 1), sci(ringtest::fit_order(samples).order));
    RecordProperty("error_n160_mode_" + std::to_string(k + 1), sci(errors[k].back()));
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.1, 1.5e-3)) << "mode " << k + 1;
  }
}

// The FE's own convergence against a finer FE (32 elements of degree 8, extensible: its
// round-off ~1e-8, preload.hpp) under p-refinement on 16 elements: from degree 2 to 5 the
// worst of four modes gains more than 30 times per degree (measured 53-192 for both
// loads: the h^(2(p-1)) of the pencil at h = 2 pi / 16, plus the falling constants) and
// ends below 1e-6 (measured 8.2e-8 pressure, 2.7e-7 squeeze).
TEST_P(FemPreloadAgainstTheChain, FeGainsOverAnOrderOfMagnitudePerDegree) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::StaticOptions st = load_of(GetParam(), spec);
  const ring::ModalResult fine = fem::compute_modes_under_load(spec, fem_options(32, 8, true), st, 4);
  double previous = 0.0;
  for (int p = 2; p <= 5; ++p) {
    const ring::ModalResult r = fem::compute_modes_under_load(spec, fem_options(16, p, true), st, 4);
    double worst = 0.0;
    for (int k = 0; k < 4; ++k) worst = std::max(worst, ringtest::rel(r.omega[k], fine.omega[k]));
    RecordProperty("error_degree_" + std::to_string(p), sci(worst));
    if (p > 2) {
      EXPECT_GT(previous / worst, 30.0) << "degree " << p;
    }
    previous = worst;
  }
  EXPECT_LT(previous, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Loads, FemPreloadAgainstTheChain, ::testing::Values(Load::pressure, Load::squeeze),
                         [](const auto& info) { return info.param == Load::pressure ? "pressure" : "squeeze"; });

// Order 2(p - 1) = 4 in the elements at p = 3 (the modes' and buckling's order: a
// consistent symmetric interior-penalty pencil), under half the critical pressure, on 16,
// 32, 64 elements against 32 of degree 8: measured errors 5.8e-4, 3.7e-5, 2.3e-6 (mode 1),
// fitted 3.98-4.00 for the four modes; the 0.2 is the FE convergence tests' bound.
TEST(FemPreload, ConvergesAtOrderFourInTheElementsAtDegreeThree) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::StaticOptions st = load_of(Load::pressure, spec);
  const ring::ModalResult fine = fem::compute_modes_under_load(spec, fem_options(32, 8, true), st, 4);
  const std::vector<int> sizes{16, 32, 64};
  std::vector<std::vector<double>> errors(4);
  for (int n : sizes) {
    const ring::ModalResult r = fem::compute_modes_under_load(spec, fem_options(n, 3, true), st, 4);
    for (int k = 0; k < 4; ++k) errors[k].push_back(ringtest::rel(r.omega[k], fine.omega[k]));
  }
  for (int k = 0; k < 4; ++k) {
    const auto samples = ringtest::in_n(sizes, errors[k]);  // the order in 1 / size
    RecordProperty("order_mode_" + std::to_string(k + 1), sci(ringtest::fit_order(samples).order));
    EXPECT_TRUE(ringtest::OrderNear(samples, 4.0, 0.2)) << "mode " << k + 1;
  }
}

// Past the critical pressure the path from rest ends at the bifurcation (the statics'
// inertia count, located at 0.990099 of 1.01 times the critical pressure): a
// ring::NumericalError saying the loaded ring is at or past a critical load. (Farther past
// it the path can land on the ring's stable, rising post-buckled branch instead, where the
// tangent counts no unstable direction again, and the modes there are a result: at 1.05 with
// 20 load steps, measured omega = 0.54 and 0.87 rad/s.)
TEST(FemPreload, PastTheCriticalPressureIsANumericalError) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::FemOptions o = fem_options(8, 3, true);
  try {
    (void)fem::compute_modes_under_load(spec, o, follower(1.01, 6490.44), 2);  // 6490.44: 8 cubic elements' critical
    ADD_FAILURE() << "no error past the critical pressure";
  } catch (const ring::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("at or past a critical load"), std::string::npos) << e.what();
  }
}

// static.path only shapes the statics' report: the modes about the full load's equilibrium
// are the same with it.
TEST(FemPreload, StaticPathIsIgnored) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  ring::StaticOptions st = squeeze(spec, 1.0);
  const double plain = fem::compute_modes_under_load(spec, fem_options(8, 3, true), st, 1).omega[0];
  st.path = true;
  st.record = {0.0};
  EXPECT_EQ(fem::compute_modes_under_load(spec, fem_options(8, 3, true), st, 1).omega[0], plain);
}

// ---- Refusals (std::invalid_argument naming the key) --------------------------------------

void expect_refusal(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st, int count,
                    const std::string& key) {
  try {
    fem::check_preloaded_modes(spec, o, st);
    (void)fem::compute_modes_under_load(spec, o, st, count);
    ADD_FAILURE() << "not refused: " << key;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(FemPreload, RefusesWhatCannotWork) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::FemOptions o = fem_options(16, 3, true);
  const ring::StaticOptions st = squeeze(spec, 1.0);
  ring::FemOptions reference = o;
  reference.reference = true;
  expect_refusal(spec, reference, st, 2, "fem.reference");
  ring::FemOptions inertia = o;
  inertia.rotary_inertia = true;
  expect_refusal(spec, inertia, st, 2, "fem.rotary_inertia");
  expect_refusal(ringtest::pinned_ring(270.0), o, st, 2, "rigid motion");
  ring::StaticOptions off = st;
  off.loads.points = {{100.0, {0.0, -1.0}}};
  expect_refusal(spec, o, off, 2, "static.at");
  ring::FemOptions polygon = o;
  polygon.geometry = ring::FemOptions::Geometry::polygon;
  expect_refusal(spec, polygon, st, 2, "fem.geometry");
  expect_refusal(spec, o, st, 0, "count");
  expect_refusal(spec, o, st, 110, "count");  // 109 unknowns
  // 200 elements of degree 8: 3397 unknowns, above kDenseBucklingLimit (refused before the statics).
  expect_refusal(spec, fem_options(200, 8, true), st, 2, "fem.elements");
}


// Frequencies under load against the closed form: the free ring on a foundation under a
// follower pressure (support/preload.hpp); the inextensible beam (fem.extensible = false,
// the closed form's model) on 16 elements of degree 6: measured 3.7e-7 at most (the rotation
// k = 0, the inextensible extrapolation's O(beta^-2)), 3e-8 in the slope.
TEST(FemPreload, MeetsTheClosedFormOfTheRingOnAFoundation) {
  ring::FemOptions o;
  o.elements = 16;
  o.degree = 6;
  o.extensible = false;
  ringtest::expect_the_closed_form_under_pressure(
      [&](const ring::RingSpec& s, const ring::StaticOptions& st, int count) {
        return fem::compute_modes_under_load(s, o, st, count);
      },
      1e-6, 1e-6);
}

}  // namespace
