// Closest approach of a closed polygon to itself (self_contact.hpp).
#include "fem_reference/self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace fem::detail {
namespace {

double norm(double x, double y) { return std::hypot(x, y); }

/// Distance from x to the segment [a, b].
double to_segment(const Point2& x, const Point2& a, const Point2& b) {
  const double ex = b[0] - a[0], ey = b[1] - a[1];
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0.0 ? ((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return norm(a[0] + t * ex - x[0], a[1] + t * ey - x[1]);
}

/// Twice the signed area of the triangle (a, b, c): > 0 when c is left of a -> b.
double turn(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

}  // namespace

double segment_gap(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  // Proper crossing: c and d on opposite sides of ab, and a and b on opposite sides of cd.
  const double s1 = turn(a, b, c), s2 = turn(a, b, d), s3 = turn(c, d, a), s4 = turn(c, d, b);
  if (s1 * s2 < 0.0 && s3 * s4 < 0.0) return 0.0;
  // Otherwise the closest pair of points has an end point of one segment in it.
  return std::min(std::min(to_segment(a, c, d), to_segment(b, c, d)), std::min(to_segment(c, a, b), to_segment(d, a, b)));
}

Approach closest_approach(const std::vector<Point2>& loop, int min_gap, double reach, bool open) {
  const int points = static_cast<int>(loop.size());
  const int n = open ? points - 1 : points;  // edges
  Approach best{reach, -1, -1};
  if (n < 3 || (open ? min_gap >= n : 2 * min_gap > n)) return best;
  auto end = [&](int k) -> const Point2& { return loop[open ? k + 1 : (k + 1) % n]; };
  double longest = 0.0;
  for (int k = 0; k < n; ++k) longest = std::max(longest, norm(end(k)[0] - loop[k][0], end(k)[1] - loop[k][1]));
  // Two edges closer than `reach` have midpoints closer than longest + reach, so with
  // buckets of that side they lie in the same or neighbouring buckets.
  const double side = longest + reach;
  auto bucket = [&](int k) {
    const double mx = 0.5 * (loop[k][0] + end(k)[0]), my = 0.5 * (loop[k][1] + end(k)[1]);
    return std::array<long long, 2>{static_cast<long long>(std::floor(mx / side)),
                                    static_cast<long long>(std::floor(my / side))};
  };
  auto key = [](long long bx, long long by) { return bx * 2654435761LL + by; };
  std::unordered_map<long long, std::vector<int>> buckets;
  std::vector<std::array<long long, 2>> where(n);
  for (int k = 0; k < n; ++k) {
    where[k] = bucket(k);
    buckets[key(where[k][0], where[k][1])].push_back(k);
  }
  for (int i = 0; i < n; ++i)
    for (long long bx = where[i][0] - 1; bx <= where[i][0] + 1; ++bx)
      for (long long by = where[i][1] - 1; by <= where[i][1] + 1; ++by) {
        const auto found = buckets.find(key(bx, by));
        if (found == buckets.end()) continue;
        for (int j : found->second) {
          // Each pair once (i < j), and only edges min_gap apart both ways round.
          if (j - i < min_gap || (!open && n - (j - i) < min_gap)) continue;
          const double d = segment_gap(loop[i], end(i), loop[j], end(j));
          if (d < best.distance) best = {d, i, j};
        }
      }
  return best;
}

}  // namespace fem::detail
