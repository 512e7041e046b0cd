// Displacement control (static.displacement) on an arch (ring.arc): the lumped chain's open form
// (model.hpp) pinned at both ends of the semicircle [0, 180] deg, its crown (90 deg) driven.
// Oracle: the same chain's load-controlled path with a load at the crown, another formulation of
// the same equilibrium (a load scaled by the load factor instead of a moving target on two more
// constraint rows): the crown driven to where the load took it needs the load as its reaction,
// and the load equal to the driven reaction takes the crown to the driven displacement, to
// Newton's tolerance. Elastic, and plastic (resultant law, perfectly plastic) between first
// yield and collapse, as the ring's (displacement_test.cpp, AgreesWithTheLoadControlledPinch) and
// the multibody chain's arch (tests/multibody/test_driven_statics.cpp); and the plastic peak
// against the two-hinged arch's limit analysis, 8 Mp / R (derived below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "common.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "ring/analysis.hpp"
#include "tests/support/paper.hpp"

namespace {

using lumptest::kChain;

constexpr int kN = 32;  ///< links; 90 and 45 deg are nodes (180 / 32 = 5.625 deg)

/// The paper's section on the semicircle [0, 180], pinned at both ends; plastic with Mp = mp EI / R.
ring::RingSpec pinned_arch(std::optional<double> mp = std::nullopt) {
  ring::RingSpec s = ringtest::free_ring();
  s.arc = ring::Arc{0.0, 180.0};
  s.supports.pin = 0.0;
  s.supports.pins = {180.0};
  if (mp) {
    s.plastic = ring::Plastic{};
    s.plastic->moment = *mp * s.EI() / s.radius;
  }
  return s;
}

/// The crown loaded by (0, -P), recorded at 90 and 45 deg.
ring::StaticResult loaded(const ring::RingSpec& spec, double P) {
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -P}}};
  st.record = {90.0, 45.0};
  st.steps = 20;
  return lumped::solve_static(spec, lumptest::options(kN, kChain), st);
}

/// The crown driven to (ux, uy), recorded at 90 and 45 deg.
lumped::StaticDetail driven(const ring::RingSpec& spec, double ux, double uy) {
  ring::StaticOptions st;
  st.displacement = ring::StaticOptions::Displacement{90.0, {ux, uy}};
  st.record = {90.0, 45.0};
  st.steps = 20;
  return lumped::solve_static_detail(spec, lumptest::options(kN, kChain), st);
}

// Elastic: the crown load P R^2 / EI = 1, on the symmetric branch (the pinned semicircle's
// lowest critical crown load is several times that, DaDeppo & Schmidt's family of
// arch_test.cpp), then the crown driven to where it went. Both solves stop at corrections of
// 1e-12 R (nonlinear.hpp); the reaction's error is the crown stiffness (~P / |uy|) times that,
// ~1e-10 of P here: bound 1e-8 P. The crown's x is free under the load and held by the drive: zero
// by the symmetry about 90 deg (the nodes are symmetric), so its reaction is zero to the same
// bound. The point at 45 deg, which neither path prescribes, agrees to 1e-8 of the crown's travel.
// No loads act on the driven arch: the pins' multipliers (ground_force) balance the rig.
TEST(DrivenArch, AgreesWithTheLoadControlledPath) {
  const ring::RingSpec spec = pinned_arch();
  const double P = spec.EI() / (spec.radius * spec.radius);
  const ring::StaticResult byload = loaded(spec, P);
  const double ux = byload.displacements.at(0).ux, uy = byload.displacements.at(0).uy;
  const lumped::StaticDetail d = driven(spec, ux, uy);
  const ring::StaticResult& bydrive = d.result;
  std::printf("[ driven arch ] crown (%.6e, %.6e) m under P = %.9e N: reaction (%.3e, %.12e) N\n", ux, uy, P,
              bydrive.reaction[0], bydrive.reaction[1]);
  ASSERT_LT(uy, 0.0);
  EXPECT_GT(std::abs(uy) / spec.radius, 1e-2) << "the test should be nonlinear";
  EXPECT_NEAR(-bydrive.reaction[1], P, 1e-8 * P);
  EXPECT_NEAR(bydrive.reaction[0], 0.0, 1e-8 * P);
  EXPECT_NEAR(bydrive.displacements.at(1).ux, byload.displacements.at(1).ux, 1e-8 * std::abs(uy));
  EXPECT_NEAR(bydrive.displacements.at(1).uy, byload.displacements.at(1).uy, 1e-8 * std::abs(uy));
  EXPECT_NEAR(d.ground_force[0], -bydrive.reaction[0], 1e-8 * P);
  EXPECT_NEAR(d.ground_force[1], -bydrive.reaction[1], 1e-8 * P);
}

// Plastic (Mp = 1e-4 EI / R, the ring tests' value): the crown driven down by 2.5e-5 R, past
// first yield (dissipation > 0) and below collapse (reaction 7.55 Mp / R, the peak 8.02 at
// c = 2.8e-5 R at n = 32: measured with the path on), then the crown loaded by the
// driven reaction. The hinges' states follow each path's own steps, but a perfectly plastic
// hinge below the plateau has one equilibrium for a monotone load: the crowns agree to the Newton
// tolerance over the plastic tangent, bound 1e-6 of the travel (the ring's, displacement_test.cpp).
TEST(DrivenArch, PlasticAgreesWithTheLoadControlledPath) {
  const ring::RingSpec spec = pinned_arch(1e-4);
  const double c = 2.5e-5 * spec.radius;
  const lumped::StaticDetail d = driven(spec, 0.0, -c);
  const double P = -d.result.reaction[1];
  const ring::StaticResult byload = loaded(spec, P);
  std::printf(
      "[ driven arch ] plastic crown %.6e m: reaction %.12e N (%.4f Mp / R), dissipated %.3e J, loaded crown "
      "%.12e m\n",
      c, P, P * spec.radius / spec.plastic->moment, d.result.dissipated, byload.displacements.at(0).uy);
  EXPECT_GT(d.result.dissipated, 0.0);
  EXPECT_NEAR(byload.displacements.at(0).uy, -c, 1e-6 * c);
  EXPECT_NEAR(byload.displacements.at(0).ux, 0.0, 1e-6 * c);
}

// The collapse of the two-hinged semicircle under a crown load (limit analysis, small
// displacements, Mp = R = 1): the thrust H and the vertical reactions P / 2 give the moment
// M(phi) = (P / 2)(1 - cos phi) - H sin phi from a support (phi = 0) to the crown (phi = 90 deg).
// The mechanism hinges at the crown (M = Mp: H = P / 2 - 1) and where M is least,
// P / 2 - sqrt((P / 2)^2 + H^2) = -Mp: with a = P / 2, 2 a^2 - 2 a + 1 = (a + 1)^2, a = 4:
//   P_c = 8 Mp / R, the side hinges at phi* = atan(2 H / P) = 36.87 deg.
// The driven chain (n = 64, path on, to c = 0.01 R) peaks there and then falls with the
// mechanism's geometry. Bound on |peak / P_c - 1|, 1e-3: the polygon's lever (hinges on the
// circumradius, (pi/n)^2 / 3 = 8.0e-4 as the ring's, displacement_test.cpp), the side hinge at the
// nearest node, 0.31 deg from phi* (M is flat there: 5 Mp (0.0054 rad)^2 / 2 = 7e-5 of P_c), and
// the elastic offset O(Mp R / EI) = 1e-4. Measured 1.2e-4 (n = 32: 2.5e-3, its nearest node
// 2.5 deg from phi*). And the energy identity along that path (measured: defect 6.2e-6 J of
// 1.68 J, bound 4.1e-5 J).
TEST(DrivenArch, PlasticPeakIsTheTwoHingedArchsCollapseLoad) {
  const ring::RingSpec spec = pinned_arch(1e-4);
  const double Pc = 8.0 * spec.plastic->moment / spec.radius;
  ring::StaticOptions st;
  st.displacement = ring::StaticOptions::Displacement{90.0, {0.0, -0.01 * spec.radius}};
  st.record = {90.0};
  st.steps = 40;
  st.path = true;
  const lumped::StaticDetail d = lumped::solve_static_detail(spec, lumptest::options(64, kChain), st);
  ASSERT_FALSE(d.result.path.empty());
  double peak = 0.0;
  for (const ring::PathPoint& p : d.result.path) peak = std::max(peak, -p.reaction[1]);
  const double last = -d.result.reaction[1];
  std::printf(
      "[ driven arch ] plastic peak %.9e N = %.6f Mp / R (8: limit analysis), at 0.01 R %.6f Mp / R, "
      "dissipated %.3e J\n",
      peak, peak * spec.radius / spec.plastic->moment, last * spec.radius / spec.plastic->moment, d.result.dissipated);
  EXPECT_NEAR(peak / Pc, 1.0, 1e-3);
  EXPECT_LT(last, peak);  // the mechanism's geometry softens it past the peak
  EXPECT_GT(d.result.dissipated, 0.0);
  // The rig's work (the solver's trapezoid over its accepted steps) = stored + dissipated. The
  // trapezoid is exact where P(u) is linear within a step; its error in a step of travel du over
  // which P's slope varies by dk is at most du^2 dk / 8. dk is bounded by the change of the chord
  // slopes of the neighbouring steps (a kink inside a step, at first yield or at the peak, shows as
  // the difference of its neighbours' chords; the first step from rest by its own chord against
  // the next).
  const std::vector<ring::PathPoint>& path = d.result.path;
  std::vector<double> du, slope;
  for (std::size_t i = 1; i < path.size(); ++i) {
    du.push_back(path[i - 1].displacements[0].uy - path[i].displacements[0].uy);
    slope.push_back((path[i - 1].reaction[1] - path[i].reaction[1]) / du.back());
  }
  double bound = 0.0;
  for (std::size_t i = 0; i < du.size(); ++i) {
    const double before = slope[i > 0 ? i - 1 : 0], after = slope[std::min(i + 1, du.size() - 1)];
    bound += du[i] * du[i] / 8.0 *
             std::max({std::abs(after - before), std::abs(slope[i] - before), std::abs(after - slope[i])});
  }
  const double defect = d.work - d.stored - d.result.dissipated;
  std::printf("[ driven arch ] work %.9e J, stored + dissipated %.9e J: defect %.3e J, bound %.3e J\n", d.work,
              d.stored + d.result.dissipated, defect, bound);
  EXPECT_LT(std::abs(defect), bound);
}

}  // namespace
