// static.path for the lumped chain: the equilibrium path through a bifurcation (branch
// switching along the tangent's least stable direction) to the ring's touch, which ends the
// path as a result (paths/continuation.hpp; lumped_mass/nonlinear.cpp, ChainStatics).
//
// Oracles: the multibody chain (multibody::solve_static, dense), the same discrete model in
// segment angles followed by the same driver, its touch (centre lines of non-neighbouring
// links one section depth apart) located by the same bisection to 1e-6 of a step; the
// chain's own linear buckling (lumped::compute_buckling) for the branch point, as
// tests/multibody/test_buckling.cpp does for the multibody chain.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common.hpp"
#include "lumped_mass/buckling.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"
#include "support/mirror.hpp"

namespace {

using Kind = ring::Pressure::Kind;

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

// The collapse ends in contact as a result, where the multibody chain's does. Both follow
// the path by load steps of at most 1/20 of the load (the driver's load stepping, which
// reaches the touch here: the load rises along the whole path) and bisect the step that
// crosses the touch to 1e-6 of it, so their touch loads may differ by up to 2 x 1e-6 x 0.05
// = 1e-7 when their step sequences differ (the Newton tolerance, 1e-12 R, adds nothing
// visible). Measured: 1e-16 at n = 40, 80, 160 (the same steps; touch loads 0.858812,
// 0.865835, 0.867591, the multibody values of the scene); with the pressure exactly
// 6 EI/R^3 the n = 160 step sequences differ and the loads 8e-9. n = 40 is the case where
// links cross between hinges (l = 1.57 m, 13 depths): a test on hinge distances alone, as
// the lumped statics had, found that touch at 0.986.
TEST(LumpedPath, TheCollapseEndsInContactWhereTheMultibodyChainsDoes) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  for (int n : {40, 80, 160}) {
    SCOPED_TRACE(n);
    const ring::StaticResult r =
        lumped::solve_static(spec, lumptest::options(n, lumptest::kChain), ringtest::collapse_statics());
    ring::MultibodyOptions o;
    o.n = n;
    o.method = ring::MultibodyOptions::Method::dense;
    const ring::StaticResult m = multibody::solve_static(spec, o, ringtest::collapse_statics());
    ASSERT_TRUE(starts_with(r.end, "contact: links")) << r.end;
    // The located touch: the links one depth apart, from below (the bisection keeps the
    // touching end of its bracket), to the message's 6 digits.
    double d = 0.0;
    ASSERT_EQ(std::sscanf(r.end.c_str() + r.end.find("within "), "within %lf", &d), 1) << r.end;
    EXPECT_LE(d, spec.section.depth()) << r.end;
    EXPECT_NEAR(d, spec.section.depth(), 2e-6) << r.end;
    ASSERT_TRUE(starts_with(m.end, "contact")) << m.end;
    EXPECT_NEAR(r.end_load, m.end_load, 1e-7);
    EXPECT_EQ(r.branch_points.size(), m.branch_points.size());
    ASSERT_GT(r.path.size(), 5u);
    EXPECT_EQ(r.path.front().load_factor, 0.0);
    EXPECT_NEAR(r.path.front().ovalisation, 0.0, 1e-14);  // rest: the regular polygon (round-off)
    EXPECT_DOUBLE_EQ(r.path.back().load_factor, r.end_load);
    // The last path point is the touching equilibrium the result reports.
    ASSERT_EQ(r.path.back().displacements.size(), 2u);
    EXPECT_EQ(r.path.back().displacements[0].ux, r.displacements[0].ux);
    EXPECT_EQ(r.path.back().displacements[1].ux, r.displacements[1].ux);
    // The same ovalisation (same definition, same shape): 8e-9 apart in load at n = 160.
    EXPECT_NEAR(r.path.back().ovalisation, m.path.back().ovalisation, 1e-6);
    EXPECT_GT(r.path.back().ovalisation, 1.5);  // opposite sides nearly meet
  }
}

// A simple bifurcation (dead pressure at 1.5 lambda_1: the out-of-phase shape alone) is
// passed by branch switching: the path leaves at the critical load of the chain's linear
// buckling (1 / 1.5 of the load; the bracket: 1e-4, measured 3e-7) and goes on to the touch.
TEST(LumpedPath, ThePathSwitchesOntoTheBranchAtASimpleBifurcation) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::LumpedOptions o = lumptest::options(40, lumptest::kChain);
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, Kind::dead};
  b.count = 1;
  ring::StaticOptions st;
  st.loads.pressure = {1.5 * lumped::compute_buckling(spec, o, b).factors[0], Kind::dead};
  st.path = true;
  st.record = {0.0, 180.0};
  const ring::StaticResult r = lumped::solve_static(spec, o, st);
  ASSERT_EQ(r.branch_points.size(), 1u) << r.end;
  EXPECT_NEAR(r.branch_points[0], 1.0 / 1.5, 1e-4);
  EXPECT_TRUE(starts_with(r.end, "contact")) << r.end;
  // From the other side of the pitchfork (static.branch = "negative"; the ring and the load
  // are symmetric about the y axis): the same path mirrored, the same touch.
  // The touch is bisected to 1e-6 of the arc step on either side, each with its own
  // rounding (measured: 6e-9 and 9e-9 of the load in the two chains, 3e-10 and 4e-10 of |u|).
  ringtest::expect_the_other_side_mirrors(
      r, st, [&](const ring::StaticOptions& s) { return lumped::solve_static(spec, o, s); }, 1e-7, 1e-8);
}

// Above the dense count's limit (2n > 400 unknowns) there is no critical direction, hence
// no branch switching: the same path ends at the bifurcation, a NumericalError as without
// static.path.
TEST(LumpedPath, AboveTheDenseLimitThePathEndsAtTheBifurcation) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::LumpedOptions o = lumptest::options(202, lumptest::kChain);
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, Kind::dead};
  b.count = 1;
  ring::StaticOptions st;
  st.loads.pressure = {1.5 * lumped::compute_buckling(spec, o, b).factors[0], Kind::dead};
  st.path = true;
  try {
    lumped::solve_static(spec, o, st);
    ADD_FAILURE() << "no bifurcation reported";
  } catch (const ring::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("between load factors "), std::string::npos) << e.what();
  }
}

}  // namespace
