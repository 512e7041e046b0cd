// Internal to fem_reference/: does a closed planar curve, given as a polygon through
// points spaced along it, come closer to itself than a distance? The statics of the
// geometrically exact beam (static_path.cpp) use it on the deformed centreline, with the
// section depth as the distance: two parts of the ring that are not neighbours along it
// and whose centrelines are closer than the depth have touched. No deal.II.
#pragma once

#include <array>
#include <vector>

namespace fem::detail {

using Point2 = std::array<double, 2>;

/// The closest approach of two edges of the closed polygon `loop` (edge k joins
/// loop[k] and loop[k+1], the last edge closes the loop) whose indices differ by at
/// least `min_gap` both ways round the loop, among the pairs closer than `reach`;
/// distance 0 when the edges cross. `first`, `second` = -1 when no pair is closer than
/// `reach` (then distance = reach). Expected O(edges) (a uniform grid of buckets).
/// `open` (an arch): `loop` is an open polyline, no edge closes it, and edges are
/// counted apart along it only.
struct Approach {
  double distance = 0.0;
  int first = -1, second = -1;
};
Approach closest_approach(const std::vector<Point2>& loop, int min_gap, double reach, bool open = false);

/// Distance between the segments [a, b] and [c, d]: 0 when they cross. O(1).
double segment_gap(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

}  // namespace fem::detail
