// The two sides of a symmetric pitchfork (static.branch "positive" and "negative") on a
// ring symmetric about its y axis (the pin at 270 deg, the roller at 90, loads symmetric):
// one path, mirrored, for the tests of every solver.
#pragma once

#include <algorithm>
#include <cmath>

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

}  // namespace ringtest
