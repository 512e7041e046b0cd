// The arch's vocabulary (ring/spec.hpp Arc, node_angles, node_index; ring/sampling.hpp
// sample_arc): nodes at from + span k / n, k = 0..n, whatever turn of the circle a point is
// named in. Oracles: the arithmetic of equal pieces and the rigid translation's closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ring/sampling.hpp"
#include "ring/spec.hpp"

namespace {

ring::RingSpec deep_arch() {
  ring::RingSpec spec;
  spec.arc = ring::Arc{-17.5, 197.5};  // DaDeppo & Schmidt's 215 degrees, apex at 90
  return spec;
}

TEST(Arch, PutsNPlusOneNodesFromTheFromEndToTheToEnd) {
  const ring::RingSpec spec = deep_arch();
  const std::vector<double> a = ring::node_angles(spec, 10);
  ASSERT_EQ(a.size(), 11u);
  EXPECT_NEAR(a.front(), 342.5, 1e-12);  // -17.5 wrapped
  EXPECT_NEAR(a[5], 90.0, 1e-12);        // the apex: the middle node of an even n
  EXPECT_NEAR(a.back(), 197.5, 1e-12);
  EXPECT_EQ(ring::node_count(spec, 10), 11);
  EXPECT_DOUBLE_EQ(spec.anchor(), -17.5);
}

TEST(Arch, FindsItsNodesInAnyTurnAndNothingOutside) {
  const ring::RingSpec spec = deep_arch();
  EXPECT_EQ(ring::node_index(spec, -17.5, 10), 0);
  EXPECT_EQ(ring::node_index(spec, 342.5, 10), 0);
  EXPECT_EQ(ring::node_index(spec, 90.0, 10), 5);
  EXPECT_EQ(ring::node_index(spec, 197.5, 10), 10);
  EXPECT_EQ(ring::node_index(spec, 197.5 - 360.0, 10), 10);
  EXPECT_EQ(ring::node_index(spec, 100.0, 10), -1);  // between nodes
  EXPECT_EQ(ring::node_index(spec, 240.0, 10), -1);  // in the gap, 2 pieces past the end
  EXPECT_TRUE(spec.arc->contains(0.0));
  EXPECT_TRUE(spec.arc->contains(197.5));
  EXPECT_FALSE(spec.arc->contains(200.0));
  EXPECT_FALSE(spec.arc->contains(-18.0));
  // A closed ring keeps the ring's rule: node n is node 0.
  ring::RingSpec closed;
  closed.supports.pin = 180.0;
  EXPECT_EQ(ring::node_index(closed, 180.0 + 360.0, 8), 0);
  EXPECT_EQ(ring::node_index(closed, 135.0, 8), 7);
  EXPECT_EQ(ring::node_angles(closed, 8).size(), 8u);
}

// Oracle: a rigid translation (1, 0) has radial cos(a) and tangential -sin(a) on the arch and
// nothing in its gap.
TEST(Arch, SamplesTheArchAndLeavesTheGapEmpty) {
  const ring::RingSpec spec = deep_arch();
  const int n = 43;
  const ring::ModeShape s = ring::sample_arc(*spec.arc, std::vector<double>(n + 1, 1.0), std::vector<double>(n + 1, 0.0));
  for (int i = 0; i < ring::kStations; ++i) {
    const double deg = ring::station_angle(i), a = deg * M_PI / 180.0;
    if (spec.arc->contains(deg)) {
      EXPECT_NEAR(s.radial[i], std::cos(a), 1e-14) << deg;
      EXPECT_NEAR(s.tangential[i], -std::sin(a), 1e-14) << deg;
    } else {
      EXPECT_EQ(s.radial[i], 0.0) << deg;
      EXPECT_EQ(s.tangential[i], 0.0) << deg;
    }
  }
}

// Oracle: the centroid of an arc of opening 2h lies at R sin(h) / h on its bisector; an arch
// pinned at one end hangs (holds its rotation under gravity) when that centroid lies below the pin.
TEST(Arch, HangsFromAPinWhenItsCentroidLiesBelow) {
  ring::RingSpec spec;
  spec.arc = ring::Arc{180.0, 360.0};  // the lower half, centroid at (0, -2R/pi)
  ring::Loads g;
  g.gravity = {0.0, -9.81};
  spec.supports.pin = 180.0;            // at (-R, 0): the centroid is below it
  EXPECT_EQ(ring::static_rigid_modes(spec, g), 0);
  spec.arc = ring::Arc{0.0, 180.0};     // the upper half, centroid at (0, 2R/pi): above
  EXPECT_EQ(ring::static_rigid_modes(spec, g), 1);
}

}  // namespace
