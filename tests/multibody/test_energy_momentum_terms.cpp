// The energy-momentum integrator (multibody/energy_momentum.hpp) with the ring's terms beyond
// the paper (point masses, a further pin, an elastic support with kx, ky and kr, the Winkler
// foundation) and every load (several point loads, gravity, pressure of the three kinds).
// Oracles outside the scheme's code: the undamped energy balance, with the terms' energy
// evaluated from their own definitions (attachments.hpp) and the loads' work; the further
// pin's rows; and the dense Newmark chain (segment angles, the terms pulled back through the
// chain's kinematics: another formulation and another scheme), to which it converges at
// order 2 in dt.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "multibody/dynamics.hpp"
#include "tests/multibody/common.hpp"
#include "tests/support/convergence.hpp"
#include "tests/support/paper.hpp"

namespace {

using Integrator = ring::ResponseOptions::Integrator;
using Kind = ring::Pressure::Kind;
using mbtest::sci;

/// The paper's ring (pin at 180 deg, roller at 0 deg) with a 500 kg mass at 90 deg and a
/// 300 kg one at 45 deg (no inertia), a further pin at 270 deg, a support at 135 deg with kx,
/// ky = EI / R^3 and kr = EI / R, and a foundation (radial EI / R^4, tangential half of it).
ring::RingSpec with_terms() {
  ring::RingSpec s = ringtest::pin_roller_ring();
  const double EI = s.EI(), R = s.radius;
  s.masses = {{90.0, 500.0, 0.0}, {45.0, 300.0, 0.0}};
  s.supports.pins = {270.0};
  s.supports.springs = {{135.0, EI / (R * R * R), EI / (R * R * R), EI / R}};
  s.foundation.radial = EI / (R * R * R * R);
  s.foundation.tangential = 0.5 * s.foundation.radial;
  return s;
}

/// Two point loads (2 kN at 0 deg toward the pin, 1 kN at 225 deg outward), gravity g/10
/// along -y and a pressure of `kind` at a tenth of the thin ring's critical 3 EI / R^3, as a
/// half-sine pulse of 1 s; dt = 0.01 s; recorded at 0, 90 and 270 deg (the further pin).
ring::ResponseOptions every_load(Integrator integrator, Kind kind, double t_end) {
  ring::ResponseOptions r = mbtest::forced_scene(integrator, t_end);
  const ring::RingSpec s = with_terms();
  r.loads.points = {{0.0, {-2000.0, 0.0}}, {225.0, {-707.1, -707.1}}};
  r.loads.gravity = {0.0, -0.981};
  r.loads.pressure = {0.3 * s.EI() / std::pow(s.radius, 3), kind};
  r.history.kind = ring::LoadHistory::Kind::half_sine;
  r.history.period = 1.0;
  r.record = {0.0, 90.0, 270.0};
  return r;
}

std::string name(Kind k) { return k == Kind::follower ? "follower" : (k == Kind::dead ? "dead" : "central"); }

class MultibodyEnergyMomentumTerms : public ::testing::TestWithParam<Kind> {};

// The undamped balance T + V - W holds by construction for any dt (energy_momentum.hpp): the
// point masses sit in the constant mass, the quadratic terms' midpoint gradient is their
// discrete gradient, kr's angle takes the springs' correction, and W is the loads' work at the
// midpoint. So the paper scene's bound holds (1e-9 of the largest work: Newton's 1e-12 R and
// round-off; test_energy_momentum.cpp), at dt = 0.01 and at the coarse 0.05, over the pulse and
// 1 s of free vibration after it. The further pin holds to the positions' round-off (1e-12 R).
TEST_P(MultibodyEnergyMomentumTerms, ConservesTheEnergyBalanceWithEveryTermAndLoad) {
  const ring::RingSpec spec = with_terms();
  for (double dt : {0.01, 0.05}) {
    ring::ResponseOptions r = every_load(Integrator::energy_momentum, GetParam(), 2.0);
    r.dt = dt;
    const ring::TimeHistory h = multibody::respond(spec, mbtest::segments(40), r);
    ASSERT_NEAR(h.t.back(), 2.0, 1e-12);
    const mbtest::Balance b = mbtest::balance(h);
    double pin = 0.0;
    for (std::size_t k = 0; k < h.t.size(); ++k) pin = std::max(pin, std::hypot(h.ux[2][k], h.uy[2][k]));
    RecordProperty("balance_" + name(GetParam()) + "_dt" + sci(dt), sci(b.worst / b.work));
    EXPECT_LT(b.worst, 1e-9 * b.work) << name(GetParam()) << ", dt = " << dt;
    EXPECT_GT(b.work, 0.0);
    EXPECT_LT(pin, 1e-12 * spec.radius);
  }
}

// Oracle: the dense Newmark chain (segment angles; the masses through the kinetic energy's
// constants, the springs and foundation pulled back, the loads' potential in the angles:
// attachments.hpp, loading.hpp) integrates the same chain in continuous time, so at equal dt
// the two histories differ by the schemes' O(dt^2) only: fitted order 2 +- 0.2 over dt =
// 0.01, 0.005, 0.0025 s at t = 1 s (the end of the pulse), at the loaded hinge and the heavier
// mass; the finest difference below 1e-4 of the displacement (the tolerances of
// test_response_attachments.cpp's comparison with the lumped chain). Without the segments'
// rotary inertia, whose own rotation modes no dt here resolves (test_energy_momentum.cpp).
TEST_P(MultibodyEnergyMomentumTerms, ConvergesToTheDenseNewmarkChainInDt) {
  const ring::RingSpec spec = with_terms();
  ring::MultibodyOptions mo = mbtest::dense_chain(40);
  mo.rotary_inertia = false;
  const std::vector<double> dts{0.01, 0.005, 0.0025};
  std::vector<double> diff0, diff90;
  double u0 = 0.0;
  for (double dt : dts) {
    ring::ResponseOptions em = every_load(Integrator::energy_momentum, GetParam(), 1.0), nm = em;
    nm.integrator = Integrator::newmark;
    em.dt = nm.dt = dt;
    const ring::TimeHistory a = multibody::respond(spec, mo, em);
    const ring::TimeHistory b = multibody::respond(spec, mo, nm);
    ASSERT_NEAR(a.t.back(), 1.0, 1e-12);
    ASSERT_NEAR(b.t.back(), 1.0, 1e-12);
    diff0.push_back(std::hypot(a.ux[0].back() - b.ux[0].back(), a.uy[0].back() - b.uy[0].back()));
    diff90.push_back(std::hypot(a.ux[1].back() - b.ux[1].back(), a.uy[1].back() - b.uy[1].back()));
    u0 = std::hypot(b.ux[0].back(), b.uy[0].back());
  }
  for (const auto* d : {&diff0, &diff90}) {
    // The order in dt from the first and the last step (two points).
    const auto samples = ringtest::in_h({dts[0], dts[2]}, {(*d)[0], (*d)[2]});
    RecordProperty(std::string(d == &diff0 ? "order_0_" : "order_90_") + name(GetParam()),
                   sci(ringtest::fit_order(samples).order));
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.2)) << (*d)[0] << " " << (*d)[1] << " " << (*d)[2];
  }
  RecordProperty("finest_relative_0_" + name(GetParam()), sci(diff0[2] / u0));
  EXPECT_LT(diff0[2], 1e-4 * u0);
}

INSTANTIATE_TEST_SUITE_P(Pressures, MultibodyEnergyMomentumTerms,
                         ::testing::Values(Kind::follower, Kind::dead, Kind::central),
                         [](const ::testing::TestParamInfo<Kind>& i) { return name(i.param); });

// A point inertia's hinge rotation is an unknown of the angle paths only: refused by name.
TEST(MultibodyEnergyMomentumTermsRefusal, RefusesAPointInertia) {
  ring::RingSpec spec = with_terms();
  spec.masses.front().inertia = 10.0;
  try {
    multibody::respond(spec, mbtest::segments(40), every_load(Integrator::energy_momentum, Kind::dead, 0.1));
    FAIL() << "a point inertia was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("masses[].inertia"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("energy-momentum"), std::string::npos) << e.what();
  }
}

}  // namespace
