// Stress tests of the O(n) forced-response path (label `stress`, each
// well under 60 s in Release): n = 10^4 with the constraints at round-off every step,
// and sparse against dense at n = 1280, beyond the validation suite's n = 160.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "multibody/dynamics.hpp"
#include "tests/support/close.hpp"
#include "tests/multibody/common.hpp"

namespace {

using mbtest::sci;
using ringtest::pin_roller_ring;

using Integrator = ring::ResponseOptions::Integrator;
using Method = ring::MultibodyOptions::Method;

ring::ResponseOptions paper_scene(Integrator integrator, double t_end = 5.0) {
  return mbtest::forced_scene(integrator, t_end);
}

ring::MultibodyOptions opts(int n, Method m) {
  ring::MultibodyOptions o;
  o.n = n;
  o.method = m;
  return o;
}

// n = 10^4 (the largest size the path is specified for): 20 steps of the 20 kN scene (the start, the hardest part:
// the step load's local response needs step halving) on both integrators. Oracles:
// constraint residual < 1e-10 m at every step (the specified constraint tolerance), finite energies, and
// the energy balance: T + V never exceeds the work of the load by more than 1 % of it
// (newmark: trapezoidal rule, measured 0; generalized-alpha only dissipates since its
// pseudo-acceleration starts from the Newton matrix, measured 0: T + V - W < 0 after
// t = 0; with the consistent start it gained energy here and stopped, energy_growth).
// A run that fails anyway (IntegrationFailure) has its partial history checked too.
multibody::IntegrationFailure::Reason run_or_partial(const ring::MultibodyOptions& o, const ring::ResponseOptions& r,
                                                     ring::TimeHistory& th) {
  try {
    th = multibody::respond(pin_roller_ring(), o, r);
  } catch (const multibody::IntegrationFailure& f) {
    th = f.partial();
    return f.reason();
  }
  return static_cast<multibody::IntegrationFailure::Reason>(-1);
}

TEST(MultibodySparseDynamicsStress, TenThousandSegments) {
  for (Integrator integ : {Integrator::generalized_alpha, Integrator::newmark}) {
    ring::TimeHistory th;
    const auto reason = run_or_partial(opts(10000, Method::sparse), paper_scene(integ, 0.2), th);
    EXPECT_EQ(static_cast<int>(reason), -1) << "the run stopped with an IntegrationFailure";
    ASSERT_EQ(th.t.size(), 21u);
    double worst_g = 0.0, excess = -1e300, max_w = 0.0;
    int iterations = 0;
    for (size_t i = 0; i < th.t.size(); ++i) {
      worst_g = std::max(worst_g, th.constraint_residual[i]);
      excess = std::max(excess, th.kinetic[i] + th.strain[i] - th.work[i]);
      max_w = std::max(max_w, th.work[i]);
      iterations += th.newton_iterations[i];
      ASSERT_TRUE(std::isfinite(th.kinetic[i]) && std::isfinite(th.strain[i]));
    }
    const std::string tag = integ == Integrator::newmark ? "newmark_" : "generalized_alpha_";
    RecordProperty(tag + "max_constraint_residual_m", sci(worst_g));
    RecordProperty(tag + "max_energy_excess_J", sci(excess));
    RecordProperty(tag + "newton_iterations", iterations);
    EXPECT_LT(worst_g, 1e-10);
    EXPECT_LE(excess, 0.01 * max_w);
    EXPECT_GT(max_w, 0.0);
  }
}

// Sparse against dense at n = 1280 for 10 steps (dense: O(n^3), ~0.5 s per step).
// Tolerance: one Newton tolerance, 1e-8 of the peak displacement (see
// test_dynamics_sparse.cpp). Both paths must end alike (both finish, or both fail at the
// same step with the same history).
TEST(MultibodySparseDynamicsStress, SparseEqualsDenseAt1280) {
  for (Integrator integ : {Integrator::generalized_alpha, Integrator::newmark}) {
    const ring::ResponseOptions r = paper_scene(integ, 0.1);
    ring::TimeHistory d, s;
    EXPECT_EQ(run_or_partial(opts(1280, Method::dense), r, d), run_or_partial(opts(1280, Method::sparse), r, s));
    ASSERT_EQ(d.t.size(), s.t.size());
    double peak = 0.0, diff = 0.0;
    for (size_t p = 0; p < d.ux.size(); ++p)
      for (size_t i = 0; i < d.t.size(); ++i) {
        peak = std::max(peak, std::hypot(d.ux[p][i], d.uy[p][i]));
        diff = std::max(diff, std::hypot(d.ux[p][i] - s.ux[p][i], d.uy[p][i] - s.uy[p][i]));
      }
    RecordProperty(integ == Integrator::newmark ? "newmark_rel_diff" : "generalized_alpha_rel_diff",
                   sci(diff / peak));
    EXPECT_LE(diff, 1e-8 * peak);
    for (size_t i = 0; i < d.t.size(); ++i) {
      EXPECT_LT(s.constraint_residual[i], 1e-10);
      EXPECT_EQ(s.newton_iterations[i], d.newton_iterations[i]) << i;
    }
  }
}

}  // namespace
