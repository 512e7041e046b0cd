// Forced nonlinear response of the chain (multibody/dynamics.hpp), the paper's section 5.
// Oracles: the linear modal superposition of the same chain from multibody::solve_modes
// (an independent linearization and eigensolver, validated by the modes tests), the static equilibrium of
// multibody::solve_static (a separate Newton path) for the damped late response,
// fitted time-step convergence orders, and the energy balance.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "multibody/chain.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/modes.hpp"
#include "multibody/statics.hpp"
#include "tests/support/close.hpp"
#include "tests/support/convergence.hpp"
#include "tests/multibody/common.hpp"
#include "tests/multibody/modal_superposition.hpp"

namespace {

using mbtest::sci;
using ringtest::pin_roller_ring;
using mbtest::Linear;
using mbtest::modal_superposition;
using mbtest::relative_deviation;
using mbtest::segments;

using Integrator = ring::ResponseOptions::Integrator;

/// The paper's scene as this project reconstructs it: n = 40, step force at C (0 deg) toward the
/// pin, dt = 0.01 s, t_end = 5 s, recorded points 0, 90, 180, 270 deg.
ring::ResponseOptions paper_scene(double force = 20e3, Integrator integrator = Integrator::newmark,
                                  double dt = 0.01, double t_end = 5.0) {
  ring::ResponseOptions r;
  r.loads.points = {{0.0, {0.0, 0.0}}};
  r.loads.points.at(0).force = {-force, 0.0};
  r.history.kind = ring::LoadHistory::Kind::step;
  r.dt = dt;
  r.t_end = t_end;
  r.integrator = integrator;
  r.rho_inf = 0.8;
  r.record = {0.0, 90.0, 180.0, 270.0};
  return r;
}

// Small load (P = 20 N, displacements ~3 mm on a 10 m ring): the geometric
// nonlinearity is ~3e-4 relative, so the response is the linear one of the same chain.
// Tolerance 0.5 % of the peak over 5 s (the specified agreement with the modal solution). It covers the
// integrators' phase error: at dt = 0.0025 s the relative period error of the lowest
// mode (w = 4.2 rad/s) is (w dt)^2/12 = 9e-6, ~1e-3 rad after 5 s.
class MultibodyDynamicsSmallLoad : public ::testing::TestWithParam<Integrator> {};

TEST_P(MultibodyDynamicsSmallLoad, EqualsLinearModalSuperposition) {
  const ring::RingSpec spec = pin_roller_ring();
  const ring::ResponseOptions r = paper_scene(20.0, GetParam(), 0.0025);
  const ring::TimeHistory th = multibody::respond(spec, segments(40), r);
  const Linear exact = modal_superposition(spec, 40, r, th.t, false);
  const Linear same = modal_superposition(spec, 40, r, th.t, true);
  // A tenth of the load: the linear part must scale away the deviation that is left.
  const ring::ResponseOptions r10 = paper_scene(2.0, GetParam(), 0.0025);
  const ring::TimeHistory th10 = multibody::respond(spec, segments(40), r10);
  const Linear same10 = modal_superposition(spec, 40, r10, th10.t, true);
  for (int p : {0, 1, 3}) {  // C, 90 and 270 deg; the pin (180 deg) does not move
    const double d_exact = relative_deviation(th, exact, p), d_same = relative_deviation(th, same, p);
    const double d_same10 = relative_deviation(th10, same10, p);
    const std::string tag = std::to_string(int(r.record[p]));
    RecordProperty("vs_exact_" + tag, sci(d_exact));
    RecordProperty("vs_same_integrator_" + tag, sci(d_same));
    RecordProperty("vs_same_integrator_2N_" + tag, sci(d_same10));
    // The specified agreement: 0.5 % of the peak against the exact modal solution. What
    // is left at dt = 0.0025 s is the integrators' error on the modes with w dt ~ 1 or
    // more (it falls like dt: 0.83 %, 0.43 %, 0.24 %, 0.14 % at dt = 0.01 .. 0.00125).
    EXPECT_LT(d_exact, 5e-3) << "point " << tag << " deg";
    // Against the same integrator applied mode by mode only the geometric nonlinearity
    // remains; its relative size grows like the load (first correction quadratic in the
    // displacement), measured 5.7e-4 at 20 N: bound 1e-3 at 20 N, and a tenth of the
    // load must leave a tenth of it (ratio 10, band 8..12 for the next-order terms).
    EXPECT_LT(d_same, 1e-3) << "point " << tag << " deg";
    EXPECT_GT(d_same / d_same10, 8.0) << "point " << tag << " deg";
    EXPECT_LT(d_same / d_same10, 12.0) << "point " << tag << " deg";
  }
}

// Other load histories, another hinge and an oblique force (the specified histories: step, ramp,
// half-sine, harmonic; loads at any hinge as a force vector): at 20 N the response is
// again the same integrator applied mode by mode, to the geometric nonlinearity
// (bound 1e-3 of the peak as above).
TEST_P(MultibodyDynamicsSmallLoad, HistoriesAndObliqueLoadsFollowTheModes) {
  const ring::RingSpec spec = pin_roller_ring();
  using Kind = ring::LoadHistory::Kind;
  for (Kind kind : {Kind::ramp, Kind::half_sine, Kind::harmonic}) {
    ring::ResponseOptions r = paper_scene(20.0, GetParam(), 0.005, 3.0);
    r.loads.points = {{45.0, {0.0, 0.0}}};  // a hinge of the 40-gon anchored at 180 deg
    r.loads.points.at(0).force = {-14.0, 14.0};
    r.history.kind = kind;
    r.history.period = 0.7;
    const ring::TimeHistory th = multibody::respond(spec, segments(40), r);
    const Linear same = modal_superposition(spec, 40, r, th.t, true);
    for (int p : {0, 1, 3}) {
      const double d = relative_deviation(th, same, p);
      RecordProperty("vs_same_" + ring::to_string(kind) + "_" + std::to_string(int(r.record[p])), sci(d));
      EXPECT_LT(d, 1e-3) << ring::to_string(kind) << ", point " << r.record[p] << " deg";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, MultibodyDynamicsSmallLoad,
                         ::testing::Values(Integrator::newmark, Integrator::generalized_alpha),
                         [](const auto& info) {
                           return info.param == Integrator::newmark ? "newmark" : "generalized_alpha";
                         });

}  // namespace

namespace {

/// Max over the recorded points and the common instants (every `stride_coarse` step of
/// `coarse`, every `stride_fine` of `fine`) of |u_coarse - u_fine|, m.
double history_difference(const ring::TimeHistory& coarse, const ring::TimeHistory& fine) {
  const size_t ratio = (fine.t.size() - 1) / (coarse.t.size() - 1);
  double d = 0.0;
  for (size_t p = 0; p < coarse.ux.size(); ++p)
    for (size_t i = 0; i < coarse.t.size(); ++i)
      d = std::max({d, std::abs(coarse.ux[p][i] - fine.ux[p][i * ratio]),
                    std::abs(coarse.uy[p][i] - fine.uy[p][i * ratio])});
  return d;
}

/// Successive differences d_k = max |u(dt_k) - u(dt_k / 2)| (all recorded points, all
/// instants of the coarser run) of the paper scene with the given integrator and t_end.
std::vector<double> successive_differences(Integrator integrator, double t_end,
                                           const std::vector<double>& dts,
                                           const ring::LoadHistory& history = {}, int n = 40) {
  const ring::RingSpec spec = pin_roller_ring();
  std::vector<ring::TimeHistory> runs;
  for (double dt : dts) {
    ring::ResponseOptions r = paper_scene(20e3, integrator, dt, t_end);
    r.history = history;
    runs.push_back(multibody::respond(spec, segments(n), r));
  }
  std::vector<double> d;
  for (size_t k = 0; k + 1 < runs.size(); ++k) d.push_back(history_difference(runs[k], runs[k + 1]));
  return d;
}

// Time-step convergence on the 20 kN paper scene (step load; displacements up to 3 m on
// the 10 m ring). The step excites all 37 modes of the chain, up to w_max = 432 rad/s
// (multibody::compute_modes), and the max-norm difference only reaches its asymptotic
// order 2 once those are resolved over the whole run: phase error w^3 dt^2 t / 12 << 1.
// From dt = 0.01 to 0.000625 over 5 s the measured orders are ~1 (1.01, 0.81, 1.02 for
// newmark), i.e. the pre-asymptotic range; so the fast test takes the first second of
// the scene (the first compression, C moving 2.6 m) with dt = 0.000625 .. 7.8e-5 s,
// where the observed order log2(d_k / d_{k+1}) is 2 within 0.2 (an order-1 scheme is 1 apart; the pre-asymptotic orders above are
// 0.8 to 1 apart) for the
// last two refinements. The full 5 s at dt down to 3.9e-5 s is in the stress suite.
class MultibodyDynamicsTimeStep : public ::testing::TestWithParam<Integrator> {};

TEST_P(MultibodyDynamicsTimeStep, ConvergesAtSecondOrder) {
  const std::vector<double> d =
      successive_differences(GetParam(), 1.0, {0.000625, 0.0003125, 0.00015625, 0.000078125});
  for (size_t k = 0; k < d.size(); ++k) RecordProperty("diff_" + std::to_string(k), sci(d[k]));
  // d[k] is the difference between dt_k and dt_{k+1}: its order in dt_k, two points at a time.
  const auto samples = ringtest::in_h({0.000625, 0.0003125, 0.00015625}, d);
  for (size_t k = 0; k + 1 < d.size(); ++k) {
    const auto pair = ringtest::subset(samples, {k, k + 1});
    RecordProperty("order_" + std::to_string(k), sci(ringtest::fit_order(pair).order));
    EXPECT_TRUE(ringtest::OrderNear(pair, 2.0, 0.2)) << "refinement " << k;
  }
  // Ceiling on the finest difference: 1e-4 m (1e-5 of R; measured 1.1e-5 m).
  EXPECT_LT(d.back(), 1e-4);
}

// At the scene's own dt the order shows on a chain whose modes the steps resolve: 12
// segments (w_max dt < 1 at dt = 0.01 s), 1 s, dt = 0.01 .. 0.00125 s. Two loads: a
// 20 kN half-sine of 0.5 s (smooth, starts at zero) and the 20 kN step, smooth for
// t > 0, whose start is where generalized-alpha's pseudo-acceleration differs from the
// consistent acceleration (a_0 = c qdd_0 / (c + w^2) per mode, dynamics.cpp). Fitted
// (least-squares) order of the successive differences: 2 within 0.1 (measured: half-sine
// 1.94 newmark, 1.96 generalized-alpha; step 1.99, 2.00; at n = 40 the half-sine's kinks at 0 and 0.5 s excite modes
// up to w dt ~ 4 and the order wanders between 1.1 and 1.9 over this range).
TEST_P(MultibodyDynamicsTimeStep, ResolvedChainConvergesAtSecondOrder) {
  ring::LoadHistory half_sine;
  half_sine.kind = ring::LoadHistory::Kind::half_sine;
  half_sine.period = 0.5;
  const std::vector<double> dts{0.01, 0.005, 0.0025, 0.00125};
  for (const ring::LoadHistory& history : {half_sine, ring::LoadHistory{}}) {
    const std::vector<double> d = successive_differences(GetParam(), 1.0, dts, history, 12);
    const std::string tag = ring::to_string(history.kind);
    for (size_t k = 0; k < d.size(); ++k) RecordProperty(tag + "_diff_" + std::to_string(k), sci(d[k]));
    const auto samples = ringtest::in_h({dts.begin(), dts.begin() + d.size()}, d);
    RecordProperty(tag + "_fitted_order", sci(ringtest::fit_order(samples).order));
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.1)) << tag;
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, MultibodyDynamicsTimeStep,
                         ::testing::Values(Integrator::newmark, Integrator::generalized_alpha),
                         [](const auto& info) {
                           return info.param == Integrator::newmark ? "newmark" : "generalized_alpha";
                         });

}  // namespace

namespace {

// The 20 kN scene as specified (dt = 0.01 s, 5 s), both integrators: constraints hold at
// every step (< 1e-10 m, the specified constraint tolerance), and the energy balance error is reported. Its
// bound: at dt = 0.01 it is below 1e-3 of the work done (measured 1.5e-4 for newmark;
// generalized-alpha dissipates the unresolved modes on purpose, measured 5.3e-4). For
// newmark the balance error is a truncation error of a second-order method, so it falls
// like dt^2 (checked with dt / 2: ratio 4, band 2.8..5.7, i.e. order 2 +- 0.5; measured
// 3.6). For generalized-alpha it is mostly the algorithmic dissipation of the modes
// above 1/dt, which falls more slowly (measured ratio 1.9), so only the bound applies.
class MultibodyDynamicsPaperScene : public ::testing::TestWithParam<Integrator> {};

TEST_P(MultibodyDynamicsPaperScene, ConstraintsHoldAndEnergyBalances) {
  const ring::RingSpec spec = pin_roller_ring();
  const ring::TimeHistory th = multibody::respond(spec, segments(40), paper_scene(20e3, GetParam()));
  ASSERT_EQ(th.t.size(), 501u);
  double worst_g = 0.0, worst_e = 0.0, max_w = 0.0;
  for (size_t i = 0; i < th.t.size(); ++i) {
    worst_g = std::max(worst_g, th.constraint_residual[i]);
    worst_e = std::max(worst_e, std::abs(th.energy_error[i]));
    max_w = std::max(max_w, th.work[i]);
    ASSERT_LT(th.constraint_residual[i], 1e-10) << "t = " << th.t[i];
  }
  const ring::TimeHistory half =
      multibody::respond(spec, segments(40), paper_scene(20e3, GetParam(), 0.005));
  double worst_e_half = 0.0;
  for (double e : half.energy_error) worst_e_half = std::max(worst_e_half, std::abs(e));
  RecordProperty("max_constraint_residual_m", sci(worst_g));
  RecordProperty("max_energy_error_J", sci(worst_e));
  RecordProperty("max_energy_error_dt_half_J", sci(worst_e_half));
  RecordProperty("max_work_J", sci(max_w));
  EXPECT_LT(worst_e, 1e-3 * max_w);
  if (GetParam() == Integrator::newmark) {
    EXPECT_GT(worst_e / worst_e_half, 2.8);
    EXPECT_LT(worst_e / worst_e_half, 5.7);
  }
  // The pin never moves and the roller keeps C on the line AC (y = 0).
  for (size_t i = 0; i < th.t.size(); ++i) {
    EXPECT_EQ(th.ux[2][i], 0.0);
    EXPECT_EQ(th.uy[2][i], 0.0);
    EXPECT_LT(std::abs(th.uy[0][i]), 1e-10);
  }
  // Snapshots for the paper's Figure 5: evenly spaced, every hinge.
  ASSERT_EQ(th.snapshot_t.size(), 6u);
  EXPECT_DOUBLE_EQ(th.snapshot_t.front(), 0.0);
  EXPECT_NEAR(th.snapshot_t.back(), 5.0, 1e-12);
  EXPECT_EQ(th.snapshot_x[3].size(), 40u);
}

INSTANTIATE_TEST_SUITE_P(Integrators, MultibodyDynamicsPaperScene,
                         ::testing::Values(Integrator::newmark, Integrator::generalized_alpha),
                         [](const auto& info) {
                           return info.param == Integrator::newmark ? "newmark" : "generalized_alpha";
                         });

// Damped response: with Rayleigh mass damping (a = 4 /s, about critical for the lowest
// mode, 2.5 rad/s) plus hinge dampers the ring settles, after 8 s, on the static
// equilibrium that multibody::solve_static finds by its own Newton path (tolerance 1e-4
// relative: the remaining transient decays like exp(-a t / 2) ~ 1e-7 of the motion, and
// the time-discretization error of a slow creep is far smaller). The energy balance then
// includes the dissipated energy; with newmark (no algorithmic dissipation) its error
// stays below 1e-3 of the largest work, as undamped.
TEST(MultibodyDynamics, DampedResponseSettlesOnTheStaticEquilibrium) {
  const ring::RingSpec spec = pin_roller_ring();
  ring::ResponseOptions r = paper_scene(20e3, Integrator::newmark, 0.01, 8.0);
  r.rayleigh_mass = 4.0;
  r.hinge_damping = 1e4;
  const ring::TimeHistory th = multibody::respond(spec, segments(40), r);
  ring::StaticOptions st;
  st.loads = r.loads;
  st.record = r.record;
  const ring::StaticResult eq = multibody::solve_static(spec, segments(40), st);
  for (size_t p = 0; p < r.record.size(); ++p) {
    EXPECT_TRUE(ringtest::IsClose(th.ux[p].back(), eq.displacements[p].ux, 1e-4, 1e-9)) << p;
    EXPECT_TRUE(ringtest::IsClose(th.uy[p].back(), eq.displacements[p].uy, 1e-4, 1e-9)) << p;
  }
  double worst_e = 0.0, max_w = 0.0;
  for (double e : th.energy_error) worst_e = std::max(worst_e, std::abs(e));
  for (double w : th.work) max_w = std::max(max_w, w);
  RecordProperty("max_energy_error_J", sci(worst_e));
  EXPECT_LT(worst_e, 1e-3 * max_w);
  EXPECT_LT(th.kinetic.back(), 1e-6 * th.work.back());
}

// Step rejection: a Newton budget of 2 iterations cannot converge a 0.01 s step of the
// 20 kN scene from rest, so steps are halved (and grown back); the history is still
// recorded on the requested grid, and it is at least as close as the plain run to a
// fine reference (dt = 0.000625 s): the sub-steps are smaller, not worse (margin 10 %).
// A budget of 1 iteration converges only steps so small that the predictor is already
// right; it must end in an IntegrationFailure that carries the partial history and
// names the time reached.
TEST(MultibodyDynamics, FailedStepsAreHalvedAndReported) {
  const ring::RingSpec spec = pin_roller_ring();
  const ring::ResponseOptions r = paper_scene(20e3, Integrator::newmark, 0.01, 0.5);
  multibody::IntegrationControls ctl;
  ctl.max_newton = 3;
  const ring::TimeHistory plain = multibody::respond(spec, segments(40), r);
  const ring::TimeHistory halved = multibody::respond(spec, segments(40), r, ctl);
  ASSERT_EQ(halved.t.size(), plain.t.size());
  int more = 0;
  for (size_t i = 1; i < plain.t.size(); ++i) more += halved.newton_iterations[i] > plain.newton_iterations[i];
  EXPECT_GT(more, 0);  // some steps did need sub-steps
  const ring::TimeHistory fine =
      multibody::respond(spec, segments(40), paper_scene(20e3, Integrator::newmark, 0.000625, 0.5));
  const double e_plain = std::abs(plain.ux[0].back() - fine.ux[0].back());
  const double e_halved = std::abs(halved.ux[0].back() - fine.ux[0].back());
  RecordProperty("error_plain_m", sci(e_plain));
  RecordProperty("error_halved_m", sci(e_halved));
  EXPECT_LT(e_halved, 1.1 * e_plain);
  ctl.max_newton = 1;
  ctl.min_dt_factor = 1e-3;
  try {
    multibody::respond(spec, segments(40), r, ctl);
    FAIL() << "expected IntegrationFailure";
  } catch (const multibody::IntegrationFailure& e) {
    EXPECT_EQ(e.reason(), multibody::IntegrationFailure::Reason::step_too_small);
    EXPECT_NE(std::string(e.what()).find("did not converge"), std::string::npos) << e.what();
    ASSERT_GE(e.partial().t.size(), 1u);
    EXPECT_LT(e.partial().t.size(), plain.t.size());
    EXPECT_EQ(e.t_reached(), e.partial().t.back());
    EXPECT_EQ(e.partial().ux[0].size(), e.partial().t.size());
  }
}

TEST(MultibodyDynamics, RejectsInputsThatCannotWork) {
  ring::RingSpec spec = pin_roller_ring();
  ring::ResponseOptions r = paper_scene();
  r.dt = 0.0;
  EXPECT_THROW(multibody::respond(spec, segments(40), r), std::invalid_argument);
  r = paper_scene();
  r.rho_inf = 1.5;
  EXPECT_THROW(multibody::respond(spec, segments(40), r), std::invalid_argument);
  r = paper_scene();
  r.record = {5.0};  // not a hinge
  EXPECT_THROW(multibody::respond(spec, segments(40), r), std::invalid_argument);
  r = paper_scene();
  EXPECT_THROW(multibody::respond(spec, segments(41), r), std::invalid_argument);  // roller off the hinges
  spec.supports.pin.reset();
  spec.supports.roller.reset();
  EXPECT_THROW(multibody::respond(spec, segments(40), r), std::invalid_argument);
}

}  // namespace
