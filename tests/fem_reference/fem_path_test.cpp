// static.path for the FE beam: the equilibrium path through the bifurcation (branch
// switching along the tangent's least stable direction on the free unknowns) to the
// ring's touch, which ends the path as a result (paths/continuation.hpp;
// fem_reference/static_path.cpp, BeamEquilibrium), as the chains' do
// (tests/lumped_mass/path_test.cpp, tests/multibody/test_buckling.cpp).
//
// Oracle: the chains' touch load of scenes/ring-collapse.toml (centrelines of non-
// neighbouring parts one section depth apart): multibody n = 320 0.868029, the chains
// converging at order 2 to about 0.8682 (extrapolated). The FE beam is extensible (the
// chains are not): its touch load may differ by O(1e-4) relative (measured below).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "fem_reference/nonlinear.hpp"
#include "ring/errors.hpp"
#include "support/paper.hpp"

namespace {

using Kind = ring::Pressure::Kind;

/// scenes/ring-collapse.toml's statics: the follower pressure 12825 N/m and a squeeze of
/// 100 N along the diameter 0-180.
ring::StaticOptions collapse() {
  ring::StaticOptions st;
  st.loads.pressure = {12825.0, Kind::follower};
  st.loads.points = {{0.0, {-100.0, 0.0}}, {180.0, {100.0, 0.0}}};
  st.record = {0.0, 180.0};
  st.path = true;
  return st;
}

ring::FemOptions scene_fem() {
  ring::FemOptions o;
  o.elements = 40;
  o.degree = 3;
  return o;
}

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

constexpr double kChainsExtrapolated = 0.8682;  // order-2 extrapolation of the chains' touch
constexpr double kMultibody320 = 0.868029;

TEST(FemPath, TheCollapseEndsInContactNearTheChainsTouch) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::StaticResult r = fem::solve_static(spec, scene_fem(), collapse());
  std::printf("end: %s\nend load %.8f, branch points %zu, path points %zu, steps %d, Newton %d, %.2f s\n"
              "relative to multibody n = 320 (%.6f): %.3e; to the chains' extrapolation (%.4f): %.3e\n",
              r.end.c_str(), r.end_load, r.branch_points.size(), r.path.size(), r.steps, r.newton_iterations,
              r.seconds, kMultibody320, (r.end_load - kMultibody320) / kMultibody320, kChainsExtrapolated,
              (r.end_load - kChainsExtrapolated) / kChainsExtrapolated);
  for (double b : r.branch_points) std::printf("branch point %.8f\n", b);
  ASSERT_TRUE(starts_with(r.end, "contact: the centreline")) << r.end;
  EXPECT_GT(r.end_load, 0.5);  // beyond the critical load factor of the pressure alone
  EXPECT_LT(r.end_load, 1.0);
  EXPECT_NEAR(r.end_load, kChainsExtrapolated, 1e-3 * kChainsExtrapolated);
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

// Without static.path the same loads are a NumericalError (the path does not reach the
// full load), as before.
TEST(FemPath, WithoutPathTheCollapseIsAnError) {
  ring::StaticOptions st = collapse();
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
      fem::solve_static(spec, o, collapse());  // check_static first
      ADD_FAILURE() << key << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("static.path"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
