// Sampling of polygonal models at the common stations, and the MAC.
#include <gtest/gtest.h>

#include <cmath>

#include "ring/sampling.hpp"
#include "support/close.hpp"

namespace {

// Oracle: a rigid translation (ux, uy) = (1, 0) has radial cos(a), tangential -sin(a).
TEST(Sampling, RigidTranslation) {
  const int n = 40;
  const ring::ModeShape s = ring::sample_polygon(180.0, std::vector<double>(n, 1.0), std::vector<double>(n, 0.0));
  for (int i = 0; i < ring::kStations; i += 7) {
    const double a = ring::station_angle(i) * M_PI / 180.0;
    EXPECT_NEAR(s.radial[i], std::cos(a), 1e-14);
    EXPECT_NEAR(s.tangential[i], -std::sin(a), 1e-14);
  }
}

// Oracle: the MAC is 1 for proportional shapes and 0 for the orthogonal cos/sin pair.
TEST(Sampling, MacOfKnownPairs) {
  ring::ModeShape c, sn;
  for (int i = 0; i < ring::kStations; ++i) {
    const double a = ring::station_angle(i) * M_PI / 180.0;
    c.radial.push_back(std::cos(2 * a));
    c.tangential.push_back(-0.5 * std::sin(2 * a));
    sn.radial.push_back(std::sin(2 * a));
    sn.tangential.push_back(0.5 * std::cos(2 * a));
  }
  ring::ModeShape c3 = c;
  for (double& x : c3.radial) x *= -3.0;
  for (double& x : c3.tangential) x *= -3.0;
  EXPECT_NEAR(ring::mac(c, c3), 1.0, 1e-14);
  EXPECT_NEAR(ring::mac(c, sn), 0.0, 1e-14);
}

}  // namespace
