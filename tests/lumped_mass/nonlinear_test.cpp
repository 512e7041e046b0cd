// The nonlinear lumped-mass chain against oracles outside it: the multibody chain (the
// same physical model in segment angles: equal equilibria, and the same motion in
// continuous time without rotary inertia), the independent elastica of the diametrally
// loaded ring (tests/support/elastica.hpp), and the conservation laws of its integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "lumped_mass/nonlinear.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/elastica.hpp"
#include "support/paper.hpp"

namespace {

using ringtest::IsClose;

/// The paper's ring pinned at A (180 deg), roller at C (0 deg), as in section 5.
ring::RingSpec held_ring() {
  ring::RingSpec s = ringtest::pinned_ring();
  s.supports.roller = 0.0;
  return s;
}

ring::StaticOptions squeeze(double force) {
  ring::StaticOptions o;
  o.loads.points = {{0.0, {0.0, 0.0}}};
  o.loads.points.at(0).force = {-force, 0.0};
  o.steps = 20;
  o.record = {0.0, 90.0, 180.0, 270.0};
  return o;
}

ring::ResponseOptions step_load(double dt, double t_end) {
  ring::ResponseOptions r;
  r.loads.points = {{0.0, {0.0, 0.0}}};
  r.loads.points.at(0).force = {-20e3, 0.0};
  r.dt = dt;
  r.t_end = t_end;
  r.record = {0.0, 90.0, 180.0, 270.0};
  return r;
}

// Oracle: multibody::solve_static, written independently in segment angles. Both solve
// the same equilibrium equations to a Newton tolerance of ~1e-12 R, so the recorded
// displacements agree to 1e-9 relative (a bound with three decades of margin over the
// measured 1e-14), at 20 kN and at 60 kN (P R^2 / EI = 5.9, deep in the nonlinear range).
TEST(LumpedNonlinear, StaticsEqualTheMultibodyChain) {
  for (int n : {40, 80})
    for (double force : {20e3, 60e3}) {
      ring::LumpedOptions lo;
      lo.n = n;
      ring::MultibodyOptions mo;
      mo.n = n;
      mo.rotary_inertia = false;
      const auto a = lumped::solve_static(held_ring(), lo, squeeze(force));
      const auto b = multibody::solve_static(held_ring(), mo, squeeze(force));
      ASSERT_EQ(a.displacements.size(), b.displacements.size());
      const double scale = std::abs(b.displacements[0].ux);
      for (std::size_t p = 0; p < a.displacements.size(); ++p) {
        EXPECT_TRUE(IsClose(a.displacements[p].ux, b.displacements[p].ux, 0.0, 1e-9 * scale)) << n << " " << force;
        EXPECT_TRUE(IsClose(a.displacements[p].uy, b.displacements[p].uy, 0.0, 1e-9 * scale)) << n << " " << force;
      }
    }
}

/// The load factor named in "past a limit point at load factor X" (NaN when none).
double limit_in(const std::string& message) {
  const std::string key = "past a limit point at load factor ";
  const auto at = message.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(message.substr(at + key.size()));
}

// Oracle: the multibody chain again, past a limit point. The ring pressed at its crown
// (90 deg) toward the centre with P R^2 / EI = 8 is an arch that snaps through at a limit
// load factor (0.94 at n = 40) and then touches itself: both chains follow the path
// through the limit and report the contact, and the limit load factors, each located to
// ~1e-12 by the same driver on the same equilibrium equations, agree to 1e-9 (the
// Newton tolerance's effect on s near its maximum, with margin).
TEST(LumpedNonlinear, PassesTheLimitPointOfThePressedCrownAsTheMultibodyChainDoes) {
  const ring::RingSpec spec = held_ring();
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, 0.0}}};
  st.loads.points.at(0).force = {0.0, -8.0 * spec.EI() / (spec.radius * spec.radius)};
  st.steps = 32;
  st.record = {90.0};
  auto failure = [&](auto&& solve) -> std::string {
    try {
      solve();
    } catch (const ring::NumericalError& e) {
      return e.what();
    }
    return "";
  };
  ring::LumpedOptions lo;
  ring::MultibodyOptions mo;
  mo.rotary_inertia = false;
  const std::string a = failure([&] { lumped::solve_static(spec, lo, st); });
  const std::string b = failure([&] { multibody::solve_static(spec, mo, st); });
  EXPECT_NE(a.find("touches itself"), std::string::npos) << a;
  EXPECT_NEAR(limit_in(a), limit_in(b), 1e-9) << a << "\n" << b;
  EXPECT_NEAR(limit_in(a), 0.94, 0.01) << a;
}

// Oracle: the inextensible elastica (shooting, RK4 with 20000 steps: error < 1e-12).
// The chain is a central discretization of the rod, so its error falls as n^-2: the
// fitted order over n = 40, 80, 160 must lie within 0.1 of 2 (measured 2.00; errors
// 2.0e-2, 4.9e-3, 1.2e-3 at P R^2/EI = 2), and Richardson's (4 u_160 - u_80) / 3 must
// remove that term: within 1e-5 of the elastica (measured below 1e-6).
TEST(LumpedNonlinear, StaticsConvergeToTheElasticaAtSecondOrder) {
  const ring::RingSpec spec = held_ring();
  const double p = 2.0;  // P R^2 / EI
  const double force = p * spec.EI() / (spec.radius * spec.radius);
  const double exact = elastica::diametral(p).along * spec.radius;
  std::vector<double> n_values = {40, 80, 160}, along, errors;
  for (double n : n_values) {
    ring::LumpedOptions lo;
    lo.n = static_cast<int>(n);
    const auto r = lumped::solve_static(spec, lo, squeeze(force));
    along.push_back(-r.displacements[0].ux);
    errors.push_back(std::abs(along.back() - exact) / exact);
  }
  // The order from the coarsest and the finest n (two points).
  const auto samples = ringtest::in_n(std::vector<double>{n_values[0], n_values[2]}, {errors[0], errors[2]});
  RecordProperty("fitted_order", std::to_string(ringtest::fit_order(samples).order));
  EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.1)) << "errors " << errors[0] << " " << errors[1] << " " << errors[2];
  const double richardson = (4.0 * along[2] - along[1]) / 3.0;
  EXPECT_TRUE(IsClose(richardson, exact, 1e-5));
}

// Oracle: the multibody chain without rotary inertia is the same system in continuous
// time, integrated by another second-order scheme (Newmark on segment angles). Their
// difference at equal dt must then vanish at order 2 (fitted over dt = 0.01, 0.005,
// 0.0025 s, within 0.2; measured 2.0). A smooth load (half-sine, 1 s) so that the
// chain's highest modes, which no dt here resolves, stay unexcited; t = 1 s, the loaded
// point and the point at 90 deg.
TEST(LumpedNonlinear, ResponseConvergesToTheMultibodyChainAtSecondOrder) {
  ring::MultibodyOptions mo;
  mo.rotary_inertia = false;
  std::vector<double> dts = {0.01, 0.005, 0.0025}, diff0, diff90;
  double u0 = 0.0;
  for (double dt : dts) {
    auto r = step_load(dt, 1.0);
    r.history.kind = ring::LoadHistory::Kind::half_sine;
    r.history.period = 1.0;
    const auto a = lumped::respond(held_ring(), ring::LumpedOptions{}, r);
    const auto b = multibody::respond(held_ring(), mo, r);
    ASSERT_NEAR(a.t.back(), 1.0, 1e-12);
    diff0.push_back(std::abs(a.ux[0].back() - b.ux[0].back()));
    diff90.push_back(std::abs(a.uy[1].back() - b.uy[1].back()));
    u0 = std::abs(b.ux[0].back());
  }
  for (const auto* d : {&diff0, &diff90}) {
    // The order in dt from the first and the last step (two points).
    const auto samples = ringtest::in_h({dts[0], dts[2]}, {(*d)[0], (*d)[2]});
    RecordProperty("fitted_order", std::to_string(ringtest::fit_order(samples).order));
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.2)) << (*d)[0] << " " << (*d)[1] << " " << (*d)[2];
  }
  EXPECT_LT(diff0[2], 1e-4 * u0);  // measured 8e-6 relative
}

// Conservation: constraint forces act at the midpoint, so with quadratic link
// constraints they do no work and the links keep their length to round-off
// (1e-12 R per step); the undamped balance T + V - W is off only by the midpoint rule's
// O(dt^2) error on the spring energy (measured 1e-6 of the work at dt = 0.01 over the
// paper's 2 s; bound 1e-4).
TEST(LumpedNonlinear, EnergyBalanceAndConstraintsOnThePapersScene) {
  const auto h = lumped::respond(held_ring(), ring::LumpedOptions{}, step_load(0.01, 2.0));
  double max_work = 0.0, max_error = 0.0, max_residual = 0.0;
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    max_work = std::max(max_work, std::abs(h.work[k]));
    max_error = std::max(max_error, std::abs(h.energy_error[k]));
    max_residual = std::max(max_residual, h.constraint_residual[k]);
  }
  RecordProperty("energy_error_over_work", std::to_string(max_error / max_work));
  EXPECT_LT(max_error, 1e-4 * max_work);
  EXPECT_LT(max_residual, 1e-10 * 10.0);
  EXPECT_EQ(h.solver, "lumped");
  EXPECT_EQ(h.snapshot_t.size(), 6u);
}

// Damping only removes energy: with Rayleigh and hinge damping the dissipated energy is
// positive and the peak of the loaded point is below the undamped one.
TEST(LumpedNonlinear, DampingDissipates) {
  auto r = step_load(0.01, 2.0);
  const auto free = lumped::respond(held_ring(), ring::LumpedOptions{}, r);
  r.rayleigh_mass = 0.5;
  r.hinge_damping = 1e5;
  const auto damped = lumped::respond(held_ring(), ring::LumpedOptions{}, r);
  double peak_free = 0.0, peak_damped = 0.0;
  for (std::size_t k = 0; k < free.t.size(); ++k) {
    peak_free = std::max(peak_free, std::abs(free.ux[0][k]));
    peak_damped = std::max(peak_damped, std::abs(damped.ux[0][k]));
  }
  EXPECT_LT(peak_damped, peak_free);
  const std::size_t last = damped.t.size() - 1;
  // T + V + D - W = error: with D > 0 the stored energy T + V lies below the work.
  EXPECT_LT(damped.kinetic[last] + damped.strain[last], damped.work[last]);
}

// Inputs that can never work are std::invalid_argument (exit 2 through the driver).
TEST(LumpedNonlinear, RejectsWhatItCannotDo) {
  ring::LumpedOptions frame;
  frame.variant = ring::LumpedOptions::Variant::frame;
  // The lumped frame's statics are taken (the corotational frame, frame_test.cpp); its
  // rotations are massless, so it has no response.
  EXPECT_THROW(lumped::respond(held_ring(), frame, step_load(0.01, 0.1)), std::invalid_argument);
  auto r = step_load(0.01, 0.1);
  r.integrator = ring::ResponseOptions::Integrator::generalized_alpha;
  EXPECT_THROW(lumped::respond(held_ring(), ring::LumpedOptions{}, r), std::invalid_argument);
  auto off = squeeze(1e3);
  off.loads.points = {{5.0, {0.0, 0.0}}};  // not a hinge of the 40-link chain
  EXPECT_THROW(lumped::solve_static(held_ring(), ring::LumpedOptions{}, off), std::invalid_argument);
  ring::RingSpec no_roller = held_ring();
  no_roller.supports.roller.reset();
  EXPECT_THROW(lumped::solve_static(no_roller, ring::LumpedOptions{}, squeeze(1e3)), std::invalid_argument);
}

}  // namespace
