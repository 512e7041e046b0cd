// static.path for the FE beam: the equilibrium path through the bifurcation (branch
// switching along the tangent's least stable direction on the free unknowns) to the
// ring's touch, which ends the path as a result (paths/continuation.hpp;
// fem_reference/static_path.cpp, BeamEquilibrium), as the chains' do
// (tests/lumped_mass/path_test.cpp, tests/multibody/test_buckling.cpp).
//
// Oracle: the chains' touch load of scenes/ring-collapse.toml (centrelines of non-
// neighbouring parts one section depth apart): multibody n = 160 0.867591, n = 320
// 0.868029, converging at order 2 to 0.868175 (Richardson from those two). The FE beam is
// extensible (the chains are not). Measured touch loads of the FE (ringvib static with
// static.solvers = ["fem"]): 40 cubic elements 0.868359 (+2.1e-4 relative to 0.868175),
// 80 cubic 0.868182, 40 of degree 4 0.868175, 80 of degree 4 0.868173 (-2e-6): the
// scene's 40 cubic elements' offset is their discretization error; converged, the FE and the
// chains touch at the same load to a few 1e-6 (extensibility included).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "fem_reference/buckling.hpp"
#include "fem_reference/nonlinear.hpp"
#include "ring/errors.hpp"
#include "support/mirror.hpp"
#include "support/paper.hpp"

namespace {

using Kind = ring::Pressure::Kind;

ring::FemOptions scene_fem() {
  ring::FemOptions o;
  o.elements = 40;
  o.degree = 3;
  return o;
}

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

constexpr double kMultibody160 = 0.867591;
constexpr double kMultibody320 = 0.868029;
constexpr double kChainsExtrapolated = kMultibody320 + (kMultibody320 - kMultibody160) / 3.0;  // order 2

TEST(FemPath, TheCollapseEndsInContactNearTheChainsTouch) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::StaticResult r = fem::solve_static(spec, scene_fem(), ringtest::collapse_statics());
  std::printf("end: %s\nend load %.8f, branch points %zu, path points %zu, steps %d, Newton %d, %.2f s\n"
              "relative to multibody n = 320 (%.6f): %.3e; to the chains' extrapolation (%.6f): %.3e\n",
              r.end.c_str(), r.end_load, r.branch_points.size(), r.path.size(), r.steps, r.newton_iterations,
              r.seconds, kMultibody320, (r.end_load - kMultibody320) / kMultibody320, kChainsExtrapolated,
              (r.end_load - kChainsExtrapolated) / kChainsExtrapolated);
  for (double b : r.branch_points) std::printf("branch point %.8f\n", b);
  ASSERT_TRUE(starts_with(r.end, "contact: the centreline")) << r.end;
  EXPECT_GT(r.end_load, 0.5);  // beyond the critical load factor of the pressure alone
  EXPECT_LT(r.end_load, 1.0);
  EXPECT_NEAR(r.end_load, kChainsExtrapolated, 4e-4 * kChainsExtrapolated);  // measured 2.1e-4
  ASSERT_GT(r.path.size(), 5u);
  EXPECT_EQ(r.path.front().load_factor, 0.0);
  EXPECT_NEAR(r.path.front().ovalisation, 0.0, 1e-12);  // rest: the vertices on the circle
  EXPECT_DOUBLE_EQ(r.path.back().load_factor, r.end_load);
  // The last path point is the touching equilibrium the result reports.
  ASSERT_EQ(r.path.back().displacements.size(), 2u);
  ASSERT_EQ(r.displacements.size(), 2u);
  EXPECT_EQ(r.path.back().displacements[0].ux, r.displacements[0].ux);
  EXPECT_EQ(r.path.back().displacements[1].ux, r.displacements[1].ux);
  EXPECT_EQ(r.node_x.size(), 40u);
  EXPECT_GT(r.path.back().ovalisation, 1.5);  // opposite sides nearly meet
  for (std::size_t i = 1; i < r.path.size(); ++i) EXPECT_TRUE(std::isfinite(r.path[i].ovalisation));
}

// Refined (80 elements of degree 4), the FE touches where the chains' extrapolation does:
// measured -2e-6 relative, within the extrapolation's own uncertainty (its next term).
TEST(FemPath, TheRefinedBeamTouchesWhereTheChainsExtrapolate) {
  ring::FemOptions o = scene_fem();
  o.elements = 80;
  o.degree = 4;
  const ring::StaticResult r = fem::solve_static(ringtest::pin_270_roller_90(), o, ringtest::collapse_statics());
  std::printf("80 elements of degree 4: end load %.8f, relative to the chains' extrapolation %.3e\n", r.end_load,
              (r.end_load - kChainsExtrapolated) / kChainsExtrapolated);
  ASSERT_TRUE(starts_with(r.end, "contact")) << r.end;
  EXPECT_NEAR(r.end_load, kChainsExtrapolated, 2e-5 * kChainsExtrapolated);
}

// A simple bifurcation (dead pressure at 1.5 lambda_1 of the FE's own linear buckling, the
// fem_bifurcation_test's case: 16 cells of degree 4) is passed by branch switching along
// the critical direction: the branch point within 1e-4 of 1 / 1.5 (the pre-buckling
// compression, fem_bifurcation_test: 3e-5 for dead pressure; measured -2.0e-5), then on to
// the touch (as the multibody chain's, n = 80: after the branch the load falls and the ring
// touches near the pin and roller, at 0.0423 here, 0.0368 for the chain).
TEST(FemPath, ThePathSwitchesOntoTheBranchAtASimpleBifurcation) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  ring::FemOptions o;
  o.elements = 16;
  o.degree = 4;
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, Kind::dead};
  b.count = 1;
  ring::StaticOptions st;
  st.loads.pressure = {1.5 * fem::compute_buckling(spec, o, b).factors[0], Kind::dead};
  st.path = true;
  st.record = {0.0, 180.0};
  const ring::StaticResult r = fem::solve_static(spec, o, st);
  for (double p : r.branch_points) std::printf("branch point %.8f (1/1.5 + %.3e)\n", p, p - 1.0 / 1.5);
  std::printf("end: %s at %.8f, %zu path points\n", r.end.c_str(), r.end_load, r.path.size());
  ASSERT_EQ(r.branch_points.size(), 1u) << r.end;
  EXPECT_NEAR(r.branch_points[0], 1.0 / 1.5, 1e-4);
  EXPECT_TRUE(starts_with(r.end, "contact")) << r.end;
  // From the other side of the pitchfork (static.branch = "negative"; the ring and the load
  // are symmetric about the y axis): the same path mirrored, the same touch.
  // The touch is bisected to 1e-6 of the arc step on either side, each side with its own
  // rounding over some 200 arc steps (measured: 7e-8 of the load, 6e-9 of |u|; the chains'
  // 40 steps leave 6e-9 and 3e-10).
  ringtest::expect_the_other_side_mirrors(
      r, st, [&](const ring::StaticOptions& s) { return fem::solve_static(spec, o, s); }, 5e-7, 5e-8);
}

// Without static.path the same loads are a NumericalError (the path does not reach the
// full load), as before.
TEST(FemPath, WithoutPathTheCollapseIsAnError) {
  ring::StaticOptions st = ringtest::collapse_statics();
  st.path = false;
  EXPECT_THROW(fem::solve_static(ringtest::pin_270_roller_90(), scene_fem(), st), ring::NumericalError);
}

// The reference refinement and the inextensible extrapolation combine several paths: refused
// with static.path, the message naming the key.
TEST(FemPath, ReferenceAndInextensibleAreRefusedWithPath) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  for (int which : {0, 1}) {
    ring::FemOptions o = scene_fem();
    (which == 0 ? o.reference : o.extensible) = which == 0;
    const std::string key = which == 0 ? "fem.reference" : "fem.extensible";
    try {
      fem::solve_static(spec, o, ringtest::collapse_statics());  // check_static first
      ADD_FAILURE() << key << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("static.path"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
