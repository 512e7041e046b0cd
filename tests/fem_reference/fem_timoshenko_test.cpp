// The FE reference's Timoshenko ring (fem_reference/modes.hpp, "Timoshenko").
//
// Oracles:
//  - ring::closed_form::free_ring_timoshenko: the exact spectrum of the model the FE
//    discretizes (three branches per wave number; a foundation included), for free rings
//    of rectangular and circular section at depth/R = 1e-3, 0.1 and 0.3.
//  - Measured convergence orders: 2p for u, w, psi of degree p with the membrane and shear
//    strains projected onto P_{p-1} (a conforming mixed method, modes.hpp); the same fitted
//    order and constant at depth/R = 1e-3 and 0.1 is the absence of shear (and membrane)
//    locking. (Fully integrated, the same elements lock: at depth/R = 1e-3, p = 3, 32 cells
//    the k = 2 error is 7.8e-3 instead of 8.6e-8; docs/measured.md, "fem_reference: the
//    Timoshenko model".)
//  - The independent Euler-Bernoulli model (C0 interior penalty, rotary inertia on) as the
//    limit kGA -> infinity of a clamped ring with springs, a point mass and a foundation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem_reference/buckling.hpp"
#include "fem_reference/checks.hpp"
#include "fem_reference/modes.hpp"
#include "ring/closed_form.hpp"
#include "ring/sampling.hpp"
#include "support/convergence.hpp"

namespace {

/// Steel ring of radius 1 m, depth/R as given, Cowper's shear coefficient (nu = 0.3).
ring::RingSpec timoshenko_ring(double depth_over_R, bool rectangle) {
  ring::RingSpec s;
  s.radius = 1.0;
  s.E = 2.1e11;
  s.rho = 7.8e3;
  s.theory = ring::Theory::timoshenko;
  s.nu = 0.3;
  if (rectangle) {
    s.section.shape = ring::Section::Shape::rectangle;
    s.section.height = depth_over_R * s.radius;
    s.section.width = 0.05;
  } else {
    s.section.shape = ring::Section::Shape::circle;
    s.section.diameter = depth_over_R * s.radius;
  }
  return s;
}

/// One closed-form frequency with its wave number and branch (0 flexural, 1 extensional,
/// 2 shear: the closed form's ascending order).
struct Exact {
  double omega;
  int k, branch;
};

/// The free ring's closed-form spectrum, ascending, each k >= 1 twice (cos and sin waves),
/// without the rigid modes (spec.rigid_modes() of them: k = 0's and k = 1's lowest branch
/// when nothing holds the ring). k up to 400: far above any frequency asked for here.
std::vector<Exact> closed_form_spectrum(const ring::RingSpec& s) {
  std::vector<Exact> all;
  const bool free = s.rigid_modes() == 3;
  for (int k = 0; k <= 400; ++k) {
    const auto b = ring::closed_form::free_ring_timoshenko(s, k);
    for (int j = 0; j < 3; ++j) {
      if (free && k <= 1 && j == 0) continue;  // rotation (k = 0), translations (k = 1)
      all.push_back({b[j], k, j});
      if (k > 0) all.push_back({b[j], k, j});
    }
  }
  std::sort(all.begin(), all.end(), [](const Exact& a, const Exact& b) { return a.omega < b.omega; });
  return all;
}

/// Number of closed-form values up to and including the flexural branch of wave number k.
int count_through_flexural(const std::vector<Exact>& spectrum, int k) {
  int n = 0;
  for (const Exact& e : spectrum) {
    ++n;
    if (e.k == k && e.branch == 0 && n % 2 == 0) break;  // both waves of the pair
  }
  return n;
}

/// A number for RecordProperty (std::to_string would print 1e-12 as 0.000000).
std::string sci(double x) {
  std::ostringstream m;
  m.precision(3);
  m << std::scientific << x;
  return m.str();
}

std::string describe(const ring::RingSpec& s) {
  std::ostringstream m;
  m << (s.section.shape == ring::Section::Shape::rectangle ? "rectangle" : "circle") << ", depth/R = "
    << s.section.depth() / s.radius;
  return m.str();
}

// ---- Free rings against the closed form ----

class FemTimoshenkoFree : public ::testing::TestWithParam<std::tuple<double, bool>> {};

// Every elastic mode up to the flexural pair k = 10, in order, with whatever extensional and
// shear-branch modes fall below it (none for the thin rings; k = 0's breathing and
// shear-rotation modes and more at depth/R = 0.3), against the closed form.
// 40 cells of degree 8: a discretization error below 1e-11 (measured); tolerance 1e-9.
TEST_P(FemTimoshenkoFree, ModesThroughFlexuralK10MatchTheClosedForm) {
  const auto [depth, rectangle] = GetParam();
  const auto spec = timoshenko_ring(depth, rectangle);
  const auto exact = closed_form_spectrum(spec);
  const int count = count_through_flexural(exact, 10);
  ring::FemOptions o;
  o.elements = 40;
  o.degree = 8;
  const auto r = fem::compute_modes(spec, o, count);
  ASSERT_EQ(r.rigid_modes, 3);
  ASSERT_EQ(static_cast<int>(r.omega.size()), count);
  EXPECT_EQ(std::get<std::string>(r.model.at("theory")), "timoshenko");
  int other_branches = 0;
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const double err = std::abs(r.omega[i] - exact[i].omega) / exact[i].omega;
    worst = std::max(worst, err);
    other_branches += exact[i].branch != 0;
    EXPECT_LT(err, 1e-9) << describe(spec) << ": mode " << i + 1 << " (k = " << exact[i].k << ", branch "
                         << exact[i].branch << ") " << r.omega[i] << " vs " << exact[i].omega;
  }
  if (depth >= 0.3) {
    EXPECT_GE(other_branches, 2) << "the thick ring's count holds extensional/shear modes";
  }
  EXPECT_LT(r.max_residual.value(), 1e-9);
  RecordProperty("worst_relative_error", sci(worst));
  RecordProperty("non_flexural_modes", other_branches);
}

INSTANTIATE_TEST_SUITE_P(DepthsAndSections, FemTimoshenkoFree,
                         ::testing::Combine(::testing::Values(1e-3, 0.1, 0.3), ::testing::Bool()));

// The foundation enters the closed form too: nothing is rigid, k = 0 and k = 1 are held.
TEST(FemTimoshenkoFoundation, HeldRingMatchesTheClosedFormFromKZero) {
  auto spec = timoshenko_ring(0.1, true);
  spec.foundation.radial = 3e8;       // N/m^2: k = 1 near the flexural k = 2
  spec.foundation.tangential = 1e8;
  ASSERT_EQ(spec.rigid_modes(), 0);
  const auto exact = closed_form_spectrum(spec);
  ring::FemOptions o;
  o.elements = 40;
  o.degree = 8;
  const int count = count_through_flexural(exact, 6);
  const auto r = fem::compute_modes(spec, o, count);
  ASSERT_EQ(r.rigid_modes, 0);
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    worst = std::max(worst, std::abs(r.omega[i] - exact[i].omega) / exact[i].omega);
    EXPECT_LT(std::abs(r.omega[i] - exact[i].omega) / exact[i].omega, 1e-9)
        << "mode " << i + 1 << " (k = " << exact[i].k << ", branch " << exact[i].branch << ") " << r.omega[i]
        << " vs " << exact[i].omega;
  }
  RecordProperty("worst_relative_error", sci(worst));
  RecordProperty("modes", count);
}

// The sampled k = 2 pair is the closed form's wave u = U sin 2t, w = W cos 2t (and its
// rotation by a quarter wave): the null vector of K - omega^2 M of the 3 x 3 closed form.
// Pins down the stations' sign conventions for the MAC pairing of the driver.
TEST(FemTimoshenkoFree, ShapeOfK2IsTheClosedFormWave) {
  const auto spec = timoshenko_ring(0.3, true);
  ring::FemOptions o;
  o.degree = 6;
  const auto r = fem::compute_modes(spec, o, 2);
  const double k = 2, R = spec.radius, lambda = std::pow(ring::closed_form::free_ring_timoshenko(spec, 2)[0], 2);
  // Rows 0 and 1 of K - lambda M on (U, W, P); their cross product is the null vector.
  const double a[3] = {k, 1, 0}, b[3] = {-1, -k, 1};
  const double M[3] = {spec.rhoA(), spec.rhoA(), spec.rhoI() / (R * R)};
  double row[2][3];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j)
      row[i][j] = (spec.EA() * a[i] * a[j] + spec.kGA() * b[i] * b[j]) / (R * R) - (i == j ? lambda * M[i] : 0.0);
  const double U = row[0][1] * row[1][2] - row[0][2] * row[1][1];
  const double W = row[0][2] * row[1][0] - row[0][0] * row[1][2];
  for (const auto& shape : r.shapes) {
    ring::ModeShape c, s;
    for (int st = 0; st < ring::kStations; ++st) {
      const double t = ring::station_angle(st) * M_PI / 180.0;
      c.radial.push_back(W * std::cos(k * t));
      c.tangential.push_back(U * std::sin(k * t));
      s.radial.push_back(W * std::sin(k * t));
      s.tangential.push_back(-U * std::cos(k * t));
    }
    EXPECT_GT(ring::mac(shape, c) + ring::mac(shape, s), 1.0 - 1e-9);  // discretization + sampling
  }
}

// extensible = false (the penalty EA -> beta EI / R^2 and the extrapolation in 1/beta of
// modes.hpp) against the closed form's inextensible limit, derived here: eps = 0 on
// u = U sin kt, w = W cos kt is W = -k U, which leaves (U, P) with
//   K = kGA/R^2 [c^2 c; c 1] + EI k^2/R^4 e2 e2^T (c = k^2 - 1), M = diag(rho A (1 + k^2), rho I / R^2)
// (the shear strain (-U - k W + P)/R = (c U + P)/R). Roots of the 2 x 2 pencil without
// cancellation: the product det K / det M = kGA EI k^2 c^2 / (R^6 det M) and the larger
// root. k = 0 and 1 keep the rigid rotation and translation (det K = 0).
std::vector<Exact> inextensible_spectrum(const ring::RingSpec& s) {
  std::vector<Exact> all;
  const double R = s.radius, a = s.kGA() / (R * R), e = s.EI() / std::pow(R, 4);
  for (int k = 0; k <= 400; ++k) {
    const double kk = k, c = kk * kk - 1.0;
    const double m1 = s.rhoA() * (1.0 + kk * kk), m2 = s.rhoI() / (R * R);
    const double k11 = a * c * c, k22 = a + e * kk * kk, det = a * e * kk * kk * c * c;
    const double b = k11 * m2 + k22 * m1;
    const double high = (b + std::sqrt(std::max(b * b - 4.0 * m1 * m2 * det, 0.0))) / (2.0 * m1 * m2);
    const double low = det / (m1 * m2 * high);
    for (int j = 0; j < 2; ++j) {
      if (k <= 1 && j == 0) continue;  // rigid
      const double omega = std::sqrt(j == 0 ? low : high);
      all.push_back({omega, k, j == 0 ? 0 : 2});
      if (k > 0) all.push_back({omega, k, j == 0 ? 0 : 2});
    }
  }
  std::sort(all.begin(), all.end(), [](const Exact& x, const Exact& y) { return x.omega < y.omega; });
  return all;
}

TEST(FemTimoshenkoFree, InextensibleLimitMatchesTheConstrainedClosedForm) {
  const auto spec = timoshenko_ring(0.1, true);
  const auto exact = inextensible_spectrum(spec);
  const int count = count_through_flexural(exact, 8);
  ring::FemOptions o;
  o.elements = 40;
  o.degree = 8;
  o.extensible = false;
  const auto r = fem::compute_modes(spec, o, count);
  EXPECT_FALSE(std::get<bool>(r.model.at("extensible")));
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const double err = std::abs(r.omega[i] - exact[i].omega) / exact[i].omega;
    worst = std::max(worst, err);
    // 1e-8 as the Euler model's inextensible test: the extrapolation leaves O(beta^-2)
    EXPECT_LT(err, 1e-8) << "mode " << i + 1 << " (k = " << exact[i].k << ", branch " << exact[i].branch << ") "
                         << r.omega[i] << " vs " << exact[i].omega;
  }
  // and the extensible ring is measurably softer: the oracle is not the extensible one
  const double extensible = ring::closed_form::free_ring_timoshenko(spec, 2)[0];
  EXPECT_GT(std::abs(exact[0].omega - extensible) / extensible, 1e3 * std::max(worst, 1e-12));
  RecordProperty("worst_relative_error", sci(worst));
}

// ---- No locking: the same order and constant, thin and thick ----

class FemTimoshenkoLocking : public ::testing::TestWithParam<int> {};

// k = 2 flexural error against the closed form on 4 meshes (3 refinements), for depth/R = 1e-3
// and 0.1: fitted order 2p for both (|rate - 2p| < 0.2, the convergence suite's bound),
// the two rates within 0.1 of each other and the errors within a factor 2: a locking
// element's error grows like (R/depth)^2 at fixed h and its pre-asymptotic rate differs.
TEST_P(FemTimoshenkoLocking, SameFittedOrderAtDepthOverR1em3And1em1) {
  const int p = GetParam();
  // In the asymptotic range and above the ~1e-12 round-off floor (measured: p = 4 at 64
  // cells is 2e-13, so p = 4 refines by 3/2).
  const std::vector<int> meshes = p <= 3 ? std::vector<int>{12, 24, 48, 96} : std::vector<int>{8, 12, 18, 27};
  std::array<double, 2> rate{}, finest{};
  const std::array<double, 2> depths{1e-3, 0.1};
  for (int d = 0; d < 2; ++d) {
    const auto spec = timoshenko_ring(depths[d], true);
    const double exact = ring::closed_form::free_ring_timoshenko(spec, 2)[0];
    std::vector<double> h, e;
    for (int n : meshes) {
      ring::FemOptions o;
      o.elements = n;
      o.degree = p;
      const auto r = fem::compute_modes(spec, o, 2);
      h.push_back(2 * M_PI / n);
      e.push_back(std::abs(r.omega[0] - exact) / exact);
    }
    const auto samples = ringtest::in_h(h, e);
    rate[d] = ringtest::fit_order(samples).order;
    finest[d] = e.back();
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0 * p, 0.2)) << "depth/R = " << depths[d] << ", p = " << p;
  }
  EXPECT_NEAR(rate[0], rate[1], 0.1) << "orders " << rate[0] << " (depth/R = 1e-3) and " << rate[1] << " (0.1), p = " << p;
  EXPECT_LT(finest[0], 2.0 * finest[1]) << "finest errors " << finest[0] << " (1e-3) and " << finest[1] << " (0.1)";
  EXPECT_LT(finest[1], 2.0 * finest[0]) << "finest errors " << finest[0] << " (1e-3) and " << finest[1] << " (0.1)";
  EXPECT_LT(finest[0], 1e-4);  // ceiling: the constant must not hide a wrong model
  RecordProperty("rate_thin", sci(rate[0]));
  RecordProperty("finest_thin", sci(finest[0]));
  RecordProperty("rate_thick", sci(rate[1]));
  RecordProperty("finest_thick", sci(finest[1]));
}

INSTANTIATE_TEST_SUITE_P(Degrees, FemTimoshenkoLocking, ::testing::Values(2, 3, 4));

// ---- Supports and point terms ----

/// A clamped ring with every term of the linear model: pin and clamp at 0 deg, a spring
/// (kx, ky, kr) at 120 deg, a point mass with rotary inertia at 240 deg, a foundation. The
/// terms scale with the ring (EI, rho A), so that they matter as much at every depth.
ring::RingSpec clamped_ring(double depth_over_R) {
  ring::RingSpec s = timoshenko_ring(depth_over_R, true);
  const double R = s.radius, EI = s.EI(), ring_mass = 2 * M_PI * R * s.rhoA();
  s.supports.pin = 0.0;
  s.supports.clamp = 0.0;
  s.supports.springs.push_back({120.0, 20 * EI / (R * R * R), 10 * EI / (R * R * R), 0.5 * EI / R});
  s.masses.push_back({240.0, 0.1 * ring_mass, 0.1 * ring_mass * 0.01 * R * R});
  s.foundation.radial = 20 * EI / std::pow(R, 4);
  s.foundation.tangential = 10 * EI / std::pow(R, 4);
  return s;
}

/// The paper's supports on a Timoshenko ring, and one more pin: pin at 180 deg, roller at
/// 0 deg (on the line through both), a further pin at 90 deg. Nothing rigid.
ring::RingSpec roller_ring(double depth_over_R) {
  ring::RingSpec s = timoshenko_ring(depth_over_R, true);
  s.supports.pin = 180.0;
  s.supports.roller = 0.0;
  s.supports.pins = {90.0};
  return s;
}

// Limit kGA -> infinity: the Timoshenko ring becomes the Euler-Bernoulli ring with the
// cross-section's rotary inertia (psi -> phi = (u - w')/R; kr and J act on psi and on the
// Euler model's {phi}). omega^2(s) = omega^2_EB + c / s + O(s^-2) in the shear coefficient s:
// extrapolated from s and 2 s. Oracle: the Euler model (an independent discretization:
// C0 interior penalty for w, no psi), 36 cells of degree 8 both.
// Also the roller ring (pins and the roller's oblique constraint).
TEST(FemTimoshenkoClamped, StiffShearLimitIsTheEulerRingWithRotaryInertia) {
  const int count = 12;
  for (const bool clamped : {true, false}) {
    const ring::RingSpec base = clamped ? clamped_ring(0.05) : roller_ring(0.05);
    ring::RingSpec euler = base;
    euler.theory = ring::Theory::euler_bernoulli;
    ring::FemOptions o;
    o.elements = 36;
    o.degree = 8;
    o.rotary_inertia = true;
    const auto eb = fem::compute_modes(euler, o, count);
    ring::RingSpec t = base;
    const double s0 = 1e3 * t.kappa();
    t.shear_coefficient = s0;
    const auto t1 = fem::compute_modes(t, o, count);
    t.shear_coefficient = 2 * s0;
    const auto t2 = fem::compute_modes(t, o, count);
    ASSERT_EQ(eb.rigid_modes, 0);
    ASSERT_EQ(t1.rigid_modes, 0);
    double worst = 0.0;
    for (int i = 0; i < count; ++i) {
      const double limit = std::sqrt(2 * t2.omega[i] * t2.omega[i] - t1.omega[i] * t1.omega[i]);
      worst = std::max(worst, std::abs(limit - eb.omega[i]) / eb.omega[i]);
      EXPECT_LT(std::abs(limit - eb.omega[i]) / eb.omega[i], 1e-9)
          << (clamped ? "clamped" : "roller") << " ring, mode " << i + 1 << ": extrapolated " << limit
          << " (s: " << t1.omega[i] << ", 2s: " << t2.omega[i] << ") vs Euler-Bernoulli " << eb.omega[i];
      // and the finite-kGA ring is softer than the Euler limit (shear adds flexibility)
      EXPECT_LT(t1.omega[i], eb.omega[i] * (1 + 1e-12));
    }
    RecordProperty(clamped ? "clamped_worst_relative_difference" : "roller_worst_relative_difference", sci(worst));
  }
}

// The clamped ring with every term at Cowper's kappa: no closed form, so the order. Oracle:
// the model's converged reference (fem.reference, tolerance 1e-12). Fitted order 2p over
// 12, 24, 48, 96 cells at p = 3 for the 8 lowest modes' largest error; depth/R = 1e-3 and 0.1.
TEST(FemTimoshenkoClamped, OrderTwoPWithEveryTerm) {
  const int p = 3, count = 8;
  for (double depth : {1e-3, 0.1}) {
    const auto spec = clamped_ring(depth);
    ring::FemOptions ref;
    ref.elements = 12;
    ref.reference = true;
    ref.tolerance = 1e-12;
    const auto exact = fem::compute_modes(spec, ref, count);
    std::vector<double> h, e;
    for (int n : {12, 24, 48, 96}) {
      ring::FemOptions o;
      o.elements = n;
      o.degree = p;
      const auto r = fem::compute_modes(spec, o, count);
      double worst = 0.0;
      for (int i = 0; i < count; ++i) worst = std::max(worst, std::abs(r.omega[i] - exact.omega[i]) / exact.omega[i]);
      h.push_back(2 * M_PI / n);
      e.push_back(worst);
    }
    const auto samples = ringtest::in_h(h, e);
    const double rate = ringtest::fit_order(samples).order;
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0 * p, 0.3, 1e-5)) << "depth/R = " << depth;
    RecordProperty(depth < 0.01 ? "rate_thin" : "rate_thick", sci(rate));
    RecordProperty(depth < 0.01 ? "finest_thin" : "finest_thick", sci(e.back()));
  }
}

// ---- The converged reference ----

/// fem.reference from `elements` x `degree` on the free ring of depth/R `depth`: its 20 lowest
/// frequencies against the closed form within 1e-9 (fem.tolerance's default); the result.
ring::ModalResult expect_reference_reaches_the_closed_form(double depth, int elements, int degree) {
  const auto spec = timoshenko_ring(depth, true);
  const auto exact = closed_form_spectrum(spec);
  const int count = 20;
  ring::FemOptions o;
  o.elements = elements;
  o.degree = degree;
  o.reference = true;
  const auto r = fem::compute_modes(spec, o, count);
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const double err = std::abs(r.omega[i] - exact[i].omega) / exact[i].omega;
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-9) << "depth/R " << depth << ", mode " << i + 1 << " (k = " << exact[i].k << ", branch "
                         << exact[i].branch << ")";
  }
  ::testing::Test::RecordProperty("worst_relative_error", sci(worst));
  return r;
}

// fem.reference on a free thick ring (depth/R = 0.3): the closed form to 1e-9, through the
// same p/h loop as the Euler model (fem.tolerance 1e-9, its default).
TEST(FemTimoshenkoReference, ThickFreeRingReachesTheClosedFormTo1em9) {
  const auto r = expect_reference_reaches_the_closed_form(0.3, 8, 2);
  EXPECT_TRUE(std::get<bool>(r.model.at("reference")));
  EXPECT_GT(std::get<long long>(r.model.at("refinements")), 0);
  EXPECT_LE(r.error_estimate, 1e-9);
}

// The thin end (depth/R = 1e-3, kGA R^2 / EI ~ 1e6) from 40 cells: the raw pairs carry the
// shear stiffness's round-off (eps kGA / lambda), so unrefined changes never fell below the
// tolerance; the loop raised p to 16 and stopped with exit 3 ("too coarse to represent the
// rigid modes") after 28 s. Refined pairs from the first step reach the closed form.
TEST(FemTimoshenkoReference, ThinFreeRingFrom40CellsReachesTheClosedFormTo1em9) {
  const auto r = expect_reference_reaches_the_closed_form(1e-3, 40, 4);
  // Converged in a few degrees, as the Euler ring does (it took p to 16 before).
  EXPECT_LE(std::get<long long>(r.model.at("degree")), 10);
}

// ---- Output and refusals ----

TEST(FemTimoshenkoOutput, VtuCarriesTheRotation) {
  const auto dir = std::filesystem::temp_directory_path() / "ringvib_fem_timoshenko_vtu";
  std::filesystem::create_directories(dir);
  ring::FemOptions o;
  o.elements = 8;
  const std::string file = fem::write_vtu(timoshenko_ring(0.1, false), o, 2, dir.string());
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("rotation_1_omega_"), std::string::npos);
  EXPECT_NE(text.str().find("displacement_2_omega_"), std::string::npos);
  std::filesystem::remove_all(dir);
}

void expect_refused(const std::function<void()>& f, const std::string& words) {
  try {
    f();
    ADD_FAILURE() << "not refused: " << words;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

// The polygon refuses the Timoshenko theory by name. The nonlinear statics, response,
// linear buckling and modes under load take it (the Reissner beam, fem_reissner_test.cpp).
TEST(FemTimoshenkoInput, PolygonRefusesByNameTheNonlinearAnalysesAccept) {
  auto spec = timoshenko_ring(0.1, true);
  ring::FemOptions polygon;
  polygon.geometry = ring::FemOptions::Geometry::polygon;
  expect_refused([&] { fem::check_modes(spec, polygon); }, "fem.geometry");
  expect_refused([&] { fem::compute_modes(spec, polygon, 4); }, "timoshenko");
  spec.supports.pin = 180.0;
  spec.supports.roller = 0.0;
  const ring::FemOptions o;
  ring::StaticOptions st;
  st.loads.points.push_back({90.0, {0.0, -1.0}});
  ring::ResponseOptions rs;
  rs.loads.points.push_back({90.0, {0.0, -1.0}});
  EXPECT_NO_THROW(fem::check_static(spec, o, st));
  EXPECT_NO_THROW(fem::check_response(spec, o, rs));
  ring::BucklingOptions b;
  b.loads = st.loads;
  EXPECT_NO_THROW(fem::check_buckling(spec, o, b));
  EXPECT_NO_THROW(fem::check_preloaded_modes(spec, o, st));
}

}  // namespace
