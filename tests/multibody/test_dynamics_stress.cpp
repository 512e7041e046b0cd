// Stress tests of the forced response (label `stress`, each well under 60 s in Release):
// long runs, fine time steps, and a load that makes the ring pass through itself.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "multibody/dynamics.hpp"
#include "tests/multibody/common.hpp"
#include "support/convergence.hpp"
#include "support/study.hpp"

namespace {

using mbtest::sci;
using ringtest::pin_roller_ring;

using Integrator = ring::ResponseOptions::Integrator;

ring::ResponseOptions paper_scene(double force, Integrator integrator, double dt, double t_end) {
  ring::ResponseOptions r;
  r.loads.points = {{0.0, {0.0, 0.0}}};
  r.loads.points.at(0).force = {-force, 0.0};
  r.dt = dt;
  r.t_end = t_end;
  r.integrator = integrator;
  r.rho_inf = 0.8;
  r.record = {0.0, 90.0, 180.0, 270.0};
  return r;
}

ring::MultibodyOptions n40() {
  ring::MultibodyOptions o;
  o.n = 40;
  return o;
}

// 10^5 steps (1000 s) of the 20 kN scene with generalized-alpha (rho_inf = 0.8): no
// blow-up. Oracles: the constraints hold at every step (< 1e-10 m, the specified constraint tolerance); the
// mechanical energy never exceeds the work of the load plus 0.1 % (the integrator only
// dissipates; the 0.1 % covers the balance error measured at dt = 0.01, 5e-4); the
// displacements stay below the geometric bound 2 R of a ring that cannot pass through
// itself (a run that did would stop with IntegrationFailure).
TEST(MultibodyDynamicsStress, GeneralizedAlphaRunsTenToTheFiveSteps) {
  const ring::RingSpec spec = pin_roller_ring();
  const ring::TimeHistory th =
      multibody::respond(spec, n40(), paper_scene(20e3, Integrator::generalized_alpha, 0.01, 1000.0));
  ASSERT_EQ(th.t.size(), 100001u);
  double worst_g = 0.0, worst_u = 0.0, worst_excess = -1e300;
  int max_it = 0;
  for (size_t i = 0; i < th.t.size(); ++i) {
    worst_g = std::max(worst_g, th.constraint_residual[i]);
    for (size_t p = 0; p < th.ux.size(); ++p)
      worst_u = std::max(worst_u, std::hypot(th.ux[p][i], th.uy[p][i]));
    worst_excess = std::max(worst_excess, th.kinetic[i] + th.strain[i] - th.work[i]);
    max_it = std::max(max_it, th.newton_iterations[i]);
  }
  double max_w = 0.0;
  for (double w : th.work) max_w = std::max(max_w, w);
  RecordProperty("max_constraint_residual_m", sci(worst_g));
  RecordProperty("max_energy_excess_J", sci(worst_excess));
  RecordProperty("final_energy_error_J", sci(th.energy_error.back()));
  RecordProperty("max_newton_iterations", max_it);
  EXPECT_LT(worst_g, 1e-10);
  EXPECT_LT(worst_excess, 1e-3 * max_w);
  EXPECT_LT(worst_u, 2.0 * spec.radius);
}

// The paper scene (step load, newmark) at time steps small enough to resolve all 37
// modes of the chain (w_max = 432 rad/s) over the whole run: dt = 3.125e-4 .. 3.9e-5 s.
// The observed order of the successive max-norm differences must reach 2 +- 0.2 (the
// band of the time-step tests, test_dynamics.cpp) over the last two refinements (measured 1.85 and 1.99 over the whole 5 s; 0.86
// one level coarser). The suite integrates the first second, the study (bench/studies.sh)
// the 5 s of the scene. Checked at the suite's length: Newmark's gamma = 0.6 instead of 1/2
// (first order, integrators.cpp) fails it (orders 0.65 and 0.75).
TEST(MultibodyDynamicsStress, NewmarkFullSceneReachesSecondOrder) {
  const ring::RingSpec spec = pin_roller_ring();
  const double t_end = ringtest::study_size(1.0, 5.0);
  const std::vector<double> dts{3.125e-4, 1.5625e-4, 7.8125e-5, 3.90625e-5};
  std::vector<ring::TimeHistory> runs;
  for (double dt : dts)
    runs.push_back(multibody::respond(spec, n40(), paper_scene(20e3, Integrator::newmark, dt, t_end)));
  std::vector<double> d;
  for (size_t k = 0; k + 1 < runs.size(); ++k) {
    const auto &c = runs[k], &f = runs[k + 1];
    double m = 0.0;
    for (size_t p = 0; p < c.ux.size(); ++p)
      for (size_t i = 0; i < c.t.size(); ++i)
        m = std::max({m, std::abs(c.ux[p][i] - f.ux[p][2 * i]), std::abs(c.uy[p][i] - f.uy[p][2 * i])});
    d.push_back(m);
  }
  // d[k] is the difference between dt_k and dt_{k+1}: its order in dt_k, two points at a time.
  const auto samples = ringtest::in_h({dts[0], dts[1], dts[2]}, d);
  for (size_t k = 0; k + 1 < d.size(); ++k) {
    const auto pair = ringtest::subset(samples, {k, k + 1});
    RecordProperty("order_" + std::to_string(k), sci(ringtest::fit_order(pair).order));
    EXPECT_TRUE(ringtest::OrderNear(pair, 2.0, 0.2)) << "refinement " << k;
  }
}

// A step force of 150 kN (P R^2/EI = 7; the static elastica reaches C ~ A near P R^2/EI
// = 7.5, and the dynamic overshoot doubles the static deflection) drives C into the
// far side of the ring within a second. The chain has no contact model, so the
// integration must stop with a clear IntegrationFailure, not return a ring that has
// passed through itself.
TEST(MultibodyDynamicsStress, SelfContactIsReportedAsAFailure) {
  const ring::RingSpec spec = pin_roller_ring();
  for (Integrator integrator : {Integrator::newmark, Integrator::generalized_alpha}) {
    try {
      multibody::respond(spec, n40(), paper_scene(150e3, integrator, 0.01, 5.0));
      ADD_FAILURE() << "expected IntegrationFailure (self contact)";
    } catch (const multibody::IntegrationFailure& e) {
      EXPECT_EQ(e.reason(), multibody::IntegrationFailure::Reason::self_contact) << e.what();
      EXPECT_NE(std::string(e.what()).find("touches itself"), std::string::npos) << e.what();
      EXPECT_GT(e.t_reached(), 0.0);
      EXPECT_LT(e.t_reached(), 5.0);
      ASSERT_FALSE(e.partial().t.empty());
      EXPECT_EQ(e.partial().t.back(), e.t_reached());
    }
  }
}

}  // namespace
