// The two sides of a symmetric pitchfork (static.branch "positive" and "negative") on a
// ring symmetric about its y axis (the pin at 270 deg, the roller at 90, loads symmetric):
// one path, mirrored, for the tests of every solver.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ring/analysis.hpp"
#include "ring/results.hpp"

namespace ringtest {

/// The largest difference between a's displacements at the recorded angles theta and b's
/// at 180 - theta mirrored about the y axis (ux -> -ux), over the largest |u| of a: 0 when
/// b is a's mirror image. Angles of a without a mirror among b's count as 1 (no match).
inline double mirror_mismatch(const ring::StaticResult& a, const ring::StaticResult& b) {
  double scale = 0.0, worst = 0.0;
  for (const auto& p : a.displacements) scale = std::max(scale, std::hypot(p.ux, p.uy));
  for (const auto& p : a.displacements) {
    const auto q = std::find_if(b.displacements.begin(), b.displacements.end(), [&](const ring::PointDisplacement& d) {
      return std::abs(std::remainder(d.angle - (180.0 - p.angle), 360.0)) < 1e-9;
    });
    if (q == b.displacements.end()) return 1.0;
    worst = std::max(worst, std::hypot(p.ux + q->ux, p.uy - q->uy));
  }
  return scale > 0.0 ? worst / scale : worst;
}

/// The path `r` (static.branch "positive", one branch point) seen from the other side:
/// `solve(st)` with static.branch "negative" has the same branch point (both sides leave
/// from one bracket), the touch at the same load within `load_tol` (relative) and is r's
/// mirror image within `shape_tol` (mirror_mismatch), while r is not symmetric itself.
template <class Solve>
void expect_the_other_side_mirrors(const ring::StaticResult& r, ring::StaticOptions st, Solve solve, double load_tol,
                                   double shape_tol) {
  st.branch_side = -1;
  const ring::StaticResult m = solve(st);
  ASSERT_EQ(m.branch_points.size(), 1u) << m.end;
  ASSERT_EQ(r.branch_points.size(), 1u) << r.end;
  std::printf("either side: branch %.3e, touch %.3e, mirror %.3e\n", m.branch_points[0] - r.branch_points[0],
              m.end_load / r.end_load - 1.0, mirror_mismatch(r, m));
  EXPECT_NEAR(m.branch_points[0], r.branch_points[0], 1e-12);
  EXPECT_NEAR(m.end_load / r.end_load, 1.0, load_tol);
  EXPECT_LT(mirror_mismatch(r, m), shape_tol);
  EXPECT_GT(mirror_mismatch(r, r), 0.1);  // the path is not symmetric itself
}

}  // namespace ringtest
