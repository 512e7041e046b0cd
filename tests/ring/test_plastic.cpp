// The bilinear point law of ring.plastic (ring/plastic.hpp) against its closed forms: the
// monotonic curve (yield at Y, then the tangent h k), the reversal (kinematic: reversed
// yield at M - 2Y; isotropic: at -M), the potential whose derivative is the force (central
// differences), and the loop area of strain cycles between +-e_a, 4 Y (1 - h) (e_a - e_y)
// for kinematic hardening (a parallelogram: the band's height 2Y times the plastic strain
// range 2 (1 - h)(e_a - e_y)).
#include <gtest/gtest.h>

#include <cmath>

#include "ring/plastic.hpp"

namespace {

using ring::BilinearLaw;
using ring::Plastic;
using ring::PlasticState;

constexpr double k = 2.0e5, Y = 300.0, ey = Y / k;

/// Drives the law through the strains e (committing each) and returns the last state.
PlasticState drive(const BilinearLaw& law, PlasticState s, double from, double to, int steps,
                   double* work = nullptr, double* dissipated = nullptr) {
  for (int i = 1; i <= steps; ++i) {
    const double a = from + (to - from) * (i - 1) / steps, b = from + (to - from) * i / steps;
    // Trapezoidal work of the force over the increment: exact for a piecewise linear force
    // when the increment does not straddle the yield edge; the tests use fine increments.
    if (work) *work += 0.5 * (law.at(s, a).force + law.at(s, b).force) * (b - a);
    if (dissipated) *dissipated += law.dissipated(s, b);
    s = law.commit(s, b);
  }
  return s;
}

TEST(PlasticLaw, MonotonicCurveYieldsAtYThenHardensWithTangentHk) {
  const double h = 0.05;
  const BilinearLaw law(k, Y, h, Plastic::Rule::kinematic);
  const PlasticState rest;
  EXPECT_NEAR(law.at(rest, 0.5 * ey).force, 0.5 * Y, 1e-12 * Y);
  EXPECT_FALSE(law.at(rest, 0.5 * ey).yielding);
  EXPECT_NEAR(law.at(rest, 3.0 * ey).force, Y + h * k * 2.0 * ey, 1e-12 * Y);
  EXPECT_NEAR(law.at(rest, -3.0 * ey).force, -Y - h * k * 2.0 * ey, 1e-12 * Y);
  EXPECT_DOUBLE_EQ(law.at(rest, 3.0 * ey).tangent, h * k);
  // The return map from the committed state is path independent on a monotonic path.
  const PlasticState s = drive(law, rest, 0.0, 3.0 * ey, 17);
  EXPECT_NEAR(law.at(s, 3.0 * ey).force, Y + h * k * 2.0 * ey, 1e-11 * Y);
  EXPECT_NEAR(s.plastic, (1.0 - h) * 2.0 * ey, 1e-12 * ey);
}

TEST(PlasticLaw, KinematicReversesAtMMinus2YAndIsotropicAtMinusM) {
  const double h = 0.1;
  for (const auto rule : {Plastic::Rule::kinematic, Plastic::Rule::isotropic}) {
    const BilinearLaw law(k, Y, h, rule);
    const PlasticState s = drive(law, {}, 0.0, 4.0 * ey, 40);
    const double M = law.at(s, 4.0 * ey).force;  // Y + h k 3 ey
    const double reversed = rule == Plastic::Rule::kinematic ? M - 2.0 * Y : -M;
    // Unloading is elastic down to `reversed` and yields just past it.
    const double edge = 4.0 * ey - (M - reversed) / k;
    EXPECT_FALSE(law.at(s, edge + 1e-9 * ey).yielding);
    EXPECT_TRUE(law.at(s, edge - 1e-6 * ey).yielding);
    EXPECT_NEAR(law.at(s, edge).force, reversed, 1e-10 * Y);
  }
}

TEST(PlasticLaw, PotentialIsTheIntegralOfTheForce) {
  const BilinearLaw law(k, Y, 0.2, Plastic::Rule::isotropic);
  const PlasticState s = drive(law, {}, 0.0, 2.5 * ey, 10);
  for (double e : {-4.0 * ey, -0.3 * ey, 1.1 * ey, 2.0 * ey, 5.0 * ey}) {
    const double d = 1e-6 * ey;
    const double fd = (law.at(s, e + d).potential - law.at(s, e - d).potential) / (2.0 * d);
    // Central differences of a piecewise quadratic: exact up to round-off of potential / d.
    EXPECT_NEAR(fd, law.at(s, e).force, 1e-6 * Y) << e / ey;
  }
}

TEST(PlasticLaw, KinematicCycleLoopAreaIs4YTimesThePlasticStrainRange) {
  const double h = 0.05, ea = 5.0 * ey;
  const BilinearLaw law(k, Y, h, Plastic::Rule::kinematic);
  PlasticState s = drive(law, {}, 0.0, ea, 500);
  double work = 0.0, dissipated = 0.0;
  s = drive(law, s, ea, -ea, 2000, &work, &dissipated);
  s = drive(law, s, -ea, ea, 2000, &work, &dissipated);
  const double area = 4.0 * Y * (1.0 - h) * (ea - ey);
  // The trapezoidal work errs only on the two increments that straddle a yield edge:
  // at most (h k de^2) per edge, de = 2 ea / 2000.
  EXPECT_NEAR(work, area, 4.0 * k * std::pow(2.0 * ea / 2000, 2)) << work / area;
  // Over a closed cycle the dissipated work is the loop (the stored energy returns).
  EXPECT_NEAR(dissipated, area, 1e-9 * area);
}

TEST(PlasticLaw, EnergyIdentityWorkIsStoredPlusDissipated) {
  // Isotropic hardening stores no energy in the band's centre: along a monotonic path the
  // work equals the elastic energy plus the plastic work.
  const BilinearLaw law(k, Y, 0.0, Plastic::Rule::isotropic);
  double work = 0.0, dissipated = 0.0;
  const PlasticState s = drive(law, {}, 0.0, 6.0 * ey, 6000, &work, &dissipated);
  EXPECT_NEAR(work, law.stored(s, 6.0 * ey) + dissipated, 1e-6 * work);
  EXPECT_NEAR(dissipated, Y * 5.0 * ey, 1e-6 * work);  // perfectly plastic: Y times e_p
}

}  // namespace
