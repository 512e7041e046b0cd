// ring::PlatePair, the contact law of [plates] that every solver uses: its gap, and the
// contact length measured on polygons whose gap is linear along each chord, so that the
// interpolated zero crossings and the lengths are exact.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ring/analysis.hpp"

namespace {

ring::RingSpec unit_ring() {
  ring::RingSpec spec;
  spec.radius = 1.0;
  return spec;
}

ring::PlatePair plates(double axis, double travel) {
  ring::StaticOptions::Plates p;
  p.axis = axis;
  p.travel = travel;
  p.stiffness = 3.0;
  return ring::PlatePair(unit_ring(), p);
}

struct Polygon {
  std::vector<double> x, y;
  void add(double px, double py) { x.push_back(px), y.push_back(py); }
};

/// A closed polygon with a roof at the top, y = top - slope |x| for |x| <= 0.2 (x in steps of
/// 0.04), its mirror image at the bottom, and one point at each side (y = 0, facing neither
/// plate). `lift` raises the gap of the top roof's middle point by that much.
Polygon roofs(double top, double slope, double lift = 0.0) {
  Polygon p;
  for (int i = 5; i >= -5; --i) {
    const double x = 0.04 * i;
    p.add(x, top - slope * std::abs(x) - (i == 0 ? lift : 0.0));
  }
  p.add(-0.85, 0.0);
  for (int i = -5; i <= 5; ++i) {
    const double x = 0.04 * i;
    p.add(x, -(top - slope * std::abs(x)));
  }
  p.add(0.85, 0.0);
  return p;
}

}  // namespace

TEST(PlatePair, TheGapIsTheDistanceToThePlateThatMovesInByHalfTheTravel) {
  const ring::PlatePair p = plates(90.0, 0.2);
  EXPECT_NEAR(p.gap(0, 0.0, 1.0, 0.0), 0.0, 1e-15);  // touching at rest
  EXPECT_NEAR(p.gap(1, 0.0, -1.0, 0.0), 0.0, 1e-15);
  EXPECT_NEAR(p.gap(0, 0.3, 1.0, 1.0), -0.1, 1e-15);  // the plate moved in by 0.1
  EXPECT_NEAR(p.gap(1, 0.0, -0.8, 1.0), 0.1, 1e-15);
  EXPECT_NEAR(p.gap(0, 0.0, 0.95, 0.5), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(p.pressure(-0.01), 0.03);  // k <-g>
  EXPECT_DOUBLE_EQ(p.pressure(0.01), 0.0);
  EXPECT_DOUBLE_EQ(p.energy(-0.01), 0.5 * 3.0 * 1e-4);
  EXPECT_TRUE(p.in_contact(0.0));
  EXPECT_TRUE(p.in_contact(1e-13));  // round-off at rest counts as touching
  EXPECT_FALSE(p.in_contact(1e-9));
  // A plate along another axis: its normal is (cos axis, sin axis).
  EXPECT_NEAR(plates(30.0, 0.2).gap(0, std::cos(M_PI / 6), std::sin(M_PI / 6), 0.0), 0.0, 1e-15);
}

TEST(PlatePair, ARingAtRestOrAwayFromThePlatesHasNoContactLength) {
  Polygon circle, smaller;
  for (int i = 0; i < 16; ++i) {
    circle.add(std::cos(i * M_PI / 8), std::sin(i * M_PI / 8));
    smaller.add(0.9 * std::cos(i * M_PI / 8), 0.9 * std::sin(i * M_PI / 8));
  }
  const ring::PlatePair p = plates(90.0, 0.1);
  for (double l : p.contact_lengths(circle.x, circle.y, 0.0)) EXPECT_DOUBLE_EQ(l, 0.0);
  for (double l : p.contact_lengths(smaller.x, smaller.y, 1.0)) EXPECT_DOUBLE_EQ(l, 0.0);
}

TEST(PlatePair, TheContactLengthEndsWhereTheGapCrossesZeroAlongAChord) {
  // The plates stand at |y| = 0.9 (R - travel / 2); the roofs reach 0.91 and fall by 0.1 per
  // unit x: the gap is -0.01 + 0.1 |x|, zero at |x| = 0.1, and each contact is the piece of
  // the roof between, 0.2 sqrt(1 + 0.1^2) long.
  const Polygon roof = roofs(0.91, 0.1);
  const auto lengths = plates(90.0, 0.2).contact_lengths(roof.x, roof.y, 1.0);
  EXPECT_NEAR(lengths[0], 0.2 * std::sqrt(1.01), 1e-14);
  EXPECT_NEAR(lengths[1], 0.2 * std::sqrt(1.01), 1e-14);
  // Seen from plates along the other axis the polygon touches nothing at this approach.
  for (double l : plates(0.0, 0.2).contact_lengths(roof.x, roof.y, 1.0)) EXPECT_DOUBLE_EQ(l, 0.0);
}

TEST(PlatePair, TheContactLengthIsTheExtentOfTheContactWhenTheMiddleLiftsOff) {
  // The top roof's middle point lifted by 0.012 (gap +0.002): the contact is at two pieces, and
  // its length is still from end to end, along the chords through the lifted point.
  const Polygon roof = roofs(0.91, 0.1, 0.012);
  const auto lengths = plates(90.0, 0.2).contact_lengths(roof.x, roof.y, 1.0);
  const double tent = std::hypot(0.04, 0.004), dip = std::hypot(0.04, 0.008);
  EXPECT_NEAR(lengths[0], 0.2 * std::sqrt(1.01) - 2.0 * tent + 2.0 * dip, 1e-14);
  EXPECT_NEAR(lengths[1], 0.2 * std::sqrt(1.01), 1e-14);
}
