// The multibody chain's nonlinear statics with ring.plastic (the resultant law at every hinge,
// multibody/bending.hpp) against the closed forms of the pinched elastic–plastic ring
// (tests/support/plastic_ring.hpp: limit analysis and the unit-load theorem), in both
// formulations multibody::solve_static chooses between: segment angles (dense) and hinge
// positions (O(n)).
//
// The scene (plastic_brief.md): the paper's ring, Mp = 1e-4 EI / R (the geometrically exact
// chain then deviates from the small-displacement closed forms by O(delta / R) ~ 1e-4
// relative), P* = 3.5 Mp / R inward at 90 and 270 deg (between first yield pi Mp / R and
// collapse 4 Mp / R), pin at 0 and roller at 180 (symmetric: no reactions), history [1, 0].
// The closing is the approach of the load points, uy(270) - uy(90).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

#include "multibody/buckling.hpp"
#include "multibody/chain.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/natural.hpp"
#include "multibody/static_equilibria.hpp"
#include "multibody/statics.hpp"
#include "paths/continuation.hpp"
#include "ring/errors.hpp"
#include "tests/support/close.hpp"
#include "tests/support/convergence.hpp"
#include "tests/support/plastic_ring.hpp"
#include "tests/multibody/common.hpp"
#include "tests/multibody/path_recorder.hpp"
#include "support/refusal.hpp"

namespace {

using Method = ring::MultibodyOptions::Method;

constexpr double kMpScale = 1e-4;  ///< Mp R / EI (the brief's ring)
constexpr double kPeak = 3.5;      ///< P* R / Mp

ring::RingSpec ring_with(double Mp) {
  ring::RingSpec spec = ringtest::pinned_ring(0.0);
  spec.supports.roller = 180.0;
  ring::Plastic p;
  p.moment = Mp;
  spec.plastic = p;
  return spec;
}

double plastic_moment() {
  const ring::RingSpec s = ringtest::free_ring();
  return kMpScale * s.EI() / s.radius;
}

ringtest::PinchedPlasticRing oracle() {
  const ring::RingSpec s = ringtest::free_ring();
  return {s.radius, s.EI(), plastic_moment()};
}

/// The pinch P = factor Mp / R at 90 and 270, the path along `history`.
ring::StaticOptions pinch(double factor, std::vector<double> history, int steps = 20) {
  return ringtest::pinch(factor * plastic_moment() / ringtest::free_ring().radius, std::move(history), steps);
}

/// The same limit analysis as plastic_ring.hpp, one step further: with hinges under the loads
/// (M0 = Mp), a quarter's end rotations vanish by symmetry, so its elastic rotation
/// (R / EI) int_0^{pi/2} M dtheta = (R / EI)(pi Mp / 2 - P R / 2) and half the hinge's plastic
/// rotation cancel: theta_p = (R / EI)(P R - pi Mp) for P in [P_y, P_c] (zero at P_y). Each of
/// the two hinges dissipates Mp theta_p on the monotone leg; unloading is elastic.
double plastic_rotation(const ringtest::PinchedPlasticRing& r, double P) {
  return r.R / r.EI * (P * r.R - M_PI * r.Mp);
}
double dissipation(const ringtest::PinchedPlasticRing& r, double P) { return 2.0 * r.Mp * plastic_rotation(r, P); }

double closing(const ring::StaticResult& r) { return r.displacements.at(1).uy - r.displacements.at(0).uy; }

const char* name(Method m) { return m == Method::dense ? "angles (dense)" : "hinge positions (O(n))"; }

// ---- convergence of the closing at the peak and after unloading ----

class PinchedPlastic : public ::testing::TestWithParam<Method> {};

TEST_P(PinchedPlastic, ClosingResidualDissipationAndPlasticRotationConvergeToTheClosedForms) {
  const ringtest::PinchedPlasticRing ring = oracle();
  const double P = kPeak * ring.Mp / ring.R;
  const ring::RingSpec spec = ring_with(ring.Mp);
  const std::vector<int> ns = {16, 32, 64, 128};
  std::vector<double> peak_errors, residual_errors, dissipation_errors, rotation_errors;
  for (int n : ns) {
    const ring::MultibodyOptions o = mbtest::chain_options(n, GetParam());
    const ring::StaticResult peak = multibody::solve_static(spec, o, pinch(kPeak, {1.0}));
    const ring::StaticResult after = multibody::solve_static(spec, o, pinch(kPeak, {1.0, 0.0}));
    peak_errors.push_back(ringtest::rel(closing(peak), ring.closing(P)));
    residual_errors.push_back(ringtest::rel(closing(after), ring.residual_closing(P)));
    dissipation_errors.push_back(ringtest::rel(after.dissipated, dissipation(ring, P)));
    // plastic_curvature is the hinge's plastic rotation over l = 2 pi R / n (results.hpp).
    rotation_errors.push_back(
        ringtest::rel(after.plastic_curvature * 2.0 * M_PI * ring.R / n, plastic_rotation(ring, P)));
    EXPECT_EQ(after.dissipated, peak.dissipated);  // the unloading leg is elastic
    EXPECT_GT(after.dissipated, 0.0);
    EXPECT_GT(after.plastic_curvature, 0.0);
    std::cout << name(GetParam()) << " n = " << n << ": peak closing " << closing(peak) << " (closed form "
              << ring.closing(P) << ", rel. error " << peak_errors.back() << "), residual " << closing(after)
              << " (closed form " << ring.residual_closing(P) << ", rel. error " << residual_errors.back()
              << "), dissipated " << after.dissipated << " J, plastic curvature " << after.plastic_curvature
              << " 1/m\n";
  }
  const ringtest::Order peak = ringtest::fit_order(ringtest::in_n(ns, peak_errors));
  const ringtest::Order residual = ringtest::fit_order(ringtest::in_n(ns, residual_errors));
  std::cout << name(GetParam()) << ": peak closing order " << peak.order << " +- " << peak.standard_error
            << ", residual closing order " << residual.order << " +- " << residual.standard_error << "\n";
  const ringtest::Order d = ringtest::fit_order(ringtest::in_n(ns, dissipation_errors));
  const ringtest::Order t = ringtest::fit_order(ringtest::in_n(ns, rotation_errors));
  std::cout << name(GetParam()) << ": dissipation order " << d.order << " +- " << d.standard_error
            << " (finest error " << d.finest_error << "), plastic rotation order " << t.order << " +- "
            << t.standard_error << " (finest error " << t.finest_error << ")\n";
  RecordProperty("peak_order", mbtest::sci(peak.order));
  RecordProperty("residual_order", mbtest::sci(residual.order));
  // The elastic chain's order 2 holds with the plastic hinge under the load (a hinge of the
  // chain sits there, where the continuum's hinge forms). Measured (multibody/README.md,
  // "Plastic statics"): peak 1.96 +- 0.02, residual 2.10 +- 0.04 in both formulations; 0.2
  // leaves room for the O(delta / R) ~ 1e-4 geometric deviation, which the finest errors
  // (1.1e-3 and 8.6e-4 at n = 128) approach; ceilings: those errors and 40 % more.
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, peak_errors), 2.0, 0.2, 1.6e-3));
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, residual_errors), 2.0, 0.2, 1.2e-3));
  // Measured 2.12 +- 0.04 for both (D = 2 Mp theta_p: the same relative error), finest
  // 7.7e-4; the same allowance and ceiling rule.
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, dissipation_errors), 2.0, 0.2, 1.1e-3));
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, rotation_errors), 2.0, 0.2, 1.1e-3));
}

INSTANTIATE_TEST_SUITE_P(BothFormulations, PinchedPlastic, ::testing::Values(Method::dense, Method::sparse));

// The recorded path (dense: static.path) carries the committed law: the dissipation never
// falls, is zero until the first yield and ends at the result's.
TEST(PlasticStatics, PathPointsCarryTheDissipation) {
  const ringtest::PinchedPlasticRing ring = oracle();
  ring::StaticOptions st = pinch(kPeak, {1.0, 0.0});
  st.path = true;
  const ring::StaticResult r = multibody::solve_static(ring_with(ring.Mp), mbtest::chain_options(32, Method::dense), st);
  ASSERT_GT(r.path.size(), 2u);
  EXPECT_EQ(r.path.front().dissipated, 0.0);
  for (std::size_t i = 1; i < r.path.size(); ++i) {
    EXPECT_GE(r.path[i].dissipated, r.path[i - 1].dissipated) << "point " << i;
    EXPECT_GE(r.path[i].plastic_curvature, r.path[i - 1].plastic_curvature) << "point " << i;
    // Below first yield (s P* < P_y, the chain's to O(1/n^2): 5 % margin) nothing yields.
    if (i < r.path.size() / 2 && r.path[i].load_factor * kPeak < 0.95 * M_PI) EXPECT_EQ(r.path[i].dissipated, 0.0);
  }
  EXPECT_EQ(r.path.back().dissipated, r.dissipated);
  EXPECT_EQ(r.path.back().plastic_curvature, r.plastic_curvature);
}

// ---- an elastic path dissipates nothing; a huge Mp is the elastic ring ----

TEST(PlasticStatics, BelowFirstYieldNothingIsDissipated) {
  const ringtest::PinchedPlasticRing ring = oracle();
  const double below = 0.9 * ring.first_yield() * ring.R / ring.Mp;  // P = 0.9 P_y
  for (Method m : {Method::dense, Method::sparse}) {
    ring::StaticOptions st = pinch(below, {1.0, 0.0});
    st.path = m == Method::dense;  // the path's points on the dense path (check_static)
    const ring::StaticResult r = multibody::solve_static(ring_with(ring.Mp), mbtest::chain_options(32, m), st);
    EXPECT_EQ(r.dissipated, 0.0) << name(m);
    EXPECT_EQ(r.plastic_curvature, 0.0) << name(m);
    for (const ring::PathPoint& p : r.path) EXPECT_EQ(p.dissipated, 0.0);
    // Unloaded along an elastic path: back at rest (Newton's tolerance 1e-12 R, times a few).
    EXPECT_LT(std::abs(closing(r)), 1e-11 * ring.R) << name(m);
  }
}

TEST(PlasticStatics, HugePlasticMomentIsTheElasticRing) {
  ring::RingSpec elastic = ring_with(1.0);
  elastic.plastic.reset();
  for (Method m : {Method::dense, Method::sparse}) {
    const ring::MultibodyOptions o = mbtest::chain_options(32, m);
    const ring::StaticResult a = multibody::solve_static(ring_with(1e30), o, pinch(kPeak, {1.0}));
    const ring::StaticResult b = multibody::solve_static(elastic, o, pinch(kPeak, {1.0}));
    // The law never leaves its band: the same arithmetic (ring/plastic.hpp: k (e - 0)).
    for (std::size_t i = 0; i < b.node_x.size(); ++i) {
      EXPECT_EQ(a.node_x[i], b.node_x[i]) << name(m) << " hinge " << i;
      EXPECT_EQ(a.node_y[i], b.node_y[i]) << name(m) << " hinge " << i;
    }
    EXPECT_EQ(a.dissipated, 0.0);
  }
}

// ---- the energy balance: work of the loads = elastic energy + dissipated ----


struct Balance {
  double work, stored, dissipated;
};

/// The loads' work along the accepted path (trapezoidal in the steps: P s linear in s,
/// the displacement between two equilibria taken as straight), the elastic energy at its
/// end (the committed states: bending.hpp, stored) and the dissipated work.
Balance balance(Method m, int n, double factor, std::vector<double> history, int steps) {
  const ring::RingSpec spec = ring_with(plastic_moment());
  const ring::StaticOptions st = pinch(factor, std::move(history), steps);
  const multibody::Chain chain(spec, mbtest::chain_options(n, m), 90.0);
  const ringtest::PinchBalance p = ringtest::pinch_balance(spec, chain, m == Method::dense, st);
  EXPECT_TRUE(p.reached);
  return {p.work, p.stored, p.dissipated};
}

// The trapezoidal work is exact for a response linear in s between two equilibria (the
// elastic steps, and the plastic ones: the yielded hinges hold Mp, the rest is linear), up to
// the O(delta / R) geometry. Its one error is the step [s0, s1] in which the hinges yield at
// s_y: the closing's slope in s jumps there from a = elastic_closing(P*) to
// b = (2 R^2 / EI) pi P* R / 8 (plastic_ring.hpp), and the trapezoid misses
// P* (b - a) (s1 - s_y)(s_y - s0) / 2 <= P* (b - a) ds^2 / 8 of the work. The balance must
// hold within that bound (10 % more for the chain's O(1/n^2) compliances at n = 32, 1.6 %);
// measured: 7 %, 13 % and 26 % of it at 20, 40 and 80 steps (the defect falls like ds, as
// ds^2 times the yield's fraction of its step, which grows here), the same in both
// formulations (multibody/README.md).
TEST(PlasticStatics, WorkOfTheLoadsIsStoredPlusDissipated) {
  const ringtest::PinchedPlasticRing ring = oracle();
  const double P = kPeak * ring.Mp / ring.R;
  const double a = ring.elastic_closing(P), b = 2.0 * ring.R * ring.R / ring.EI * M_PI * P * ring.R / 8.0;
  for (Method m : {Method::dense, Method::sparse})
    for (const std::vector<double>& history : {std::vector<double>{1.0}, std::vector<double>{1.0, 0.0}})
      for (int steps : {20, 40, 80}) {
        const Balance e = balance(m, 32, kPeak, history, steps);
        const double defect = std::abs(e.work - e.stored - e.dissipated), ds = 1.0 / steps;
        const double bound = 1.1 * P * (b - a) * ds * ds / 8.0;
        std::cout << name(m) << " history to " << history.back() << ", " << steps << " steps: work " << e.work
                  << " J, stored " << e.stored << " J, dissipated " << e.dissipated << " J, |defect| " << defect
                  << " J, bound " << bound << " J\n";
        EXPECT_GT(e.dissipated, 0.0);
        EXPECT_LE(defect, bound) << name(m) << ", " << steps << " steps";
      }
}

// Elastic throughout (P = 0.9 P_y): nothing dissipated, and the trapezoid has no kink to
// miss: the balance holds to the trapezoid's error on the geometrically nonlinear path,
// O(ds^2 delta / R) relative: ds^2 delta / R = 1.1e-7 here (ds = 1/20, delta / R = 4.2e-5 at
// 0.9 P_y); measured 2.7e-8 in both formulations.
TEST(PlasticStatics, ElasticPathStoresTheWork) {
  const ringtest::PinchedPlasticRing ring = oracle();
  const double below = 0.9 * ring.first_yield() * ring.R / ring.Mp;
  for (Method m : {Method::dense, Method::sparse}) {
    const Balance e = balance(m, 32, below, {1.0}, 20);
    std::cout << name(m) << " elastic: work " << e.work << " J, stored " << e.stored << " J, rel. defect "
              << std::abs(e.work - e.stored) / e.work << "\n";
    EXPECT_EQ(e.dissipated, 0.0);
    const double ds = 1.0 / 20.0, closing_over_R = ring.elastic_closing(below * ring.Mp / ring.R) / ring.R;
    EXPECT_TRUE(ringtest::IsClose(e.work, e.stored, ds * ds * closing_over_R)) << name(m);
  }
}

// ---- refusals ----

TEST(PlasticStatics, TimoshenkoChainRefusesThePlasticLawNamingTheKey) {
  ring::RingSpec spec = ring_with(plastic_moment());
  spec.theory = ring::Theory::timoshenko;
  spec.nu = 0.3;
  try {
    multibody::solve_static(spec, mbtest::chain_options(16, Method::dense), pinch(kPeak, {1.0}));
    FAIL() << "no refusal";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "ring.plastic");
  }
}

// What the chain cannot take yet refuses by key before it computes (the scene reader refuses
// these too; the library's own checks hold for a caller that builds the spec itself). The
// response takes the plastic law with every integrator and backend (test_plastic_response.cpp)
// but on the Timoshenko chain, which refuses it.
TEST(PlasticStatics, ResponseBucklingAndModesUnderLoadRefuseThePlasticLaw) {
  const ring::RingSpec spec = ring_with(plastic_moment());
  const ring::MultibodyOptions o = mbtest::chain_options(16, Method::dense);
  ring::ResponseOptions response;
  response.loads = pinch(kPeak, {}).loads;
  ring::RingSpec timoshenko = spec;
  timoshenko.theory = ring::Theory::timoshenko;
  timoshenko.nu = 0.3;
  EXPECT_EQ(ringtest::refused_key([&] { multibody::respond(timoshenko, o, response); }), "ring.plastic");
  ring::BucklingOptions buckling;
  buckling.loads = pinch(kPeak, {}).loads;
  EXPECT_EQ(ringtest::refused_key([&] { multibody::compute_buckling(spec, o, buckling); }), "ring.plastic");
  EXPECT_EQ(ringtest::refused_key([&] { multibody::compute_modes_under_load(spec, o, pinch(kPeak, {1.0}), 2); }), "ring.plastic");
}

}  // namespace
