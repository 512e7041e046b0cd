#include "ring/sampling.hpp"

#include <cmath>
#include <cstddef>

#include "ring/spec.hpp"

namespace ring {
namespace {

/// cos and sin of every station angle, computed once (a constant table).
struct StationDirections {
  double c[kStations], s[kStations];
  StationDirections() {
    for (int i = 0; i < kStations; ++i) {
      c[i] = std::cos(station_angle(i) * M_PI / 180.0);
      s[i] = std::sin(station_angle(i) * M_PI / 180.0);
    }
  }
};
const StationDirections& directions() {
  static const StationDirections d;
  return d;
}

}  // namespace

ModeShape sample_polygon(double anchor_deg, const std::vector<double>& ux,
                         const std::vector<double>& uy) {
  const int n = static_cast<int>(ux.size());
  const StationDirections& dir = directions();
  const double anchor = wrap_degrees(anchor_deg);
  ModeShape s;
  s.radial.resize(kStations);
  s.tangential.resize(kStations);
  for (int i = 0; i < kStations; ++i) {
    double rel = station_angle(i) - anchor;  // wrap_degrees without fmod
    if (rel < 0.0) rel += 360.0;
    const double steps = rel * n / 360.0;
    int k = static_cast<int>(std::floor(steps));
    double f = steps - k;
    if (k >= n) { k = n - 1; f = 1.0; }  // steps rounded up to n
    const int k1 = (k + 1) % n;
    const double x = (1.0 - f) * ux[k] + f * ux[k1];
    const double y = (1.0 - f) * uy[k] + f * uy[k1];
    const double c = dir.c[i], sn = dir.s[i];
    s.radial[i] = c * x + sn * y;
    s.tangential[i] = -sn * x + c * y;
  }
  normalize(s);
  return s;
}

ModeShape sample_arc(const Arc& arc, const std::vector<double>& ux, const std::vector<double>& uy) {
  const int n = static_cast<int>(ux.size()) - 1;
  const StationDirections& dir = directions();
  ModeShape s;
  s.radial.assign(kStations, 0.0);
  s.tangential.assign(kStations, 0.0);
  for (int i = 0; i < kStations; ++i) {
    const double rel = arc.offset(station_angle(i));
    if (rel > arc.span() + 1e-9) continue;
    const double steps = std::min(rel * n / arc.span(), static_cast<double>(n));
    const int k = std::min(static_cast<int>(std::floor(steps)), n - 1);
    const double f = steps - k;
    const double x = (1.0 - f) * ux[k] + f * ux[k + 1];
    const double y = (1.0 - f) * uy[k] + f * uy[k + 1];
    const double c = dir.c[i], sn = dir.s[i];
    s.radial[i] = c * x + sn * y;
    s.tangential[i] = -sn * x + c * y;
  }
  normalize(s);
  return s;
}

void normalize(ModeShape& shape) {
  double big = 0.0;
  for (const auto* v : {&shape.radial, &shape.tangential})
    for (double x : *v)
      if (std::abs(x) > std::abs(big)) big = x;
  if (big == 0.0) return;
  for (auto* v : {&shape.radial, &shape.tangential})
    for (double& x : *v) x /= big;
}

double mac(const ModeShape& a, const ModeShape& b) {
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (std::size_t i = 0; i < a.radial.size(); ++i) {
    ab += a.radial[i] * b.radial[i] + a.tangential[i] * b.tangential[i];
    aa += a.radial[i] * a.radial[i] + a.tangential[i] * a.tangential[i];
    bb += b.radial[i] * b.radial[i] + b.tangential[i] * b.tangential[i];
  }
  return (aa > 0.0 && bb > 0.0) ? ab * ab / (aa * bb) : 0.0;
}

}  // namespace ring
