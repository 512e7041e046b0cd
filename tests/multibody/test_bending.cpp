// The hinge's bending law (multibody/bending.hpp) against its own definition: the moment is
// the derivative of the potential and the tangent the derivative of the moment (central
// differences, exact up to round-off on a piecewise quadratic away from the band's edges),
// from the virgin state and from a committed plastic one; elastic, the law is K e with
// K = EI / l; commit() adds the law's plastic work.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "multibody/bending.hpp"
#include "multibody/chain.hpp"
#include "ring/plastic.hpp"
#include "tests/support/close.hpp"
#include "tests/multibody/common.hpp"

namespace {

using multibody::Chain;
using multibody::HingeBending;

ring::RingSpec plastic_ring(double Mp, double hardening, ring::Plastic::Rule rule) {
  ring::RingSpec spec = ringtest::pin_roller_ring();
  ring::Plastic p;
  p.moment = Mp;
  p.hardening = hardening;
  p.rule = rule;
  spec.plastic = p;
  return spec;
}

/// |moment - dV/de| and |tangent - dM/de| at e, by central differences of step h, over the
/// scale of the moment (N m) and of the stiffness (N m / rad).
void expect_derivatives(const HingeBending& b, int k, double e, double h) {
  const double K = b.K();
  const double dV = (b.potential(k, e + h) - b.potential(k, e - h)) / (2.0 * h);
  const double dM = (b.moment(k, e + h) - b.moment(k, e - h)) / (2.0 * h);
  // Round-off of the difference: eps |V| / h, |V| <= K e^2; 1e-7 relative holds it with room.
  EXPECT_TRUE(ringtest::IsClose(b.moment(k, e), dV, 1e-7, 1e-7 * K * std::abs(e))) << "at e = " << e;
  EXPECT_TRUE(ringtest::IsClose(b.tangent(k, e), dM, 1e-7, 1e-7 * K)) << "at e = " << e;
}

TEST(HingeBending, ElasticIsTheRestStiffnessTimesTheRotation) {
  const ring::RingSpec spec = ringtest::pin_roller_ring();
  const Chain chain(spec, mbtest::dense_chain(16));
  const HingeBending b(spec, chain);
  EXPECT_FALSE(b.plastic());
  EXPECT_EQ(b.K(), spec.EI() / chain.l());  // the definition, bending.hpp
  EXPECT_EQ(chain.K(), b.K());
  for (double e : {-1e-2, -1e-5, 0.0, 3e-4, 0.2}) {
    EXPECT_EQ(b.moment(3, e), b.K() * e);
    EXPECT_EQ(b.tangent(3, e), b.K());
    expect_derivatives(b, 3, e, 1e-3 * std::max(std::abs(e), 1e-6));
  }
}

TEST(HingeBending, MomentIsTheDerivativeOfThePotential) {
  for (const ring::Plastic::Rule rule : {ring::Plastic::Rule::kinematic, ring::Plastic::Rule::isotropic})
    for (double hardening : {0.0, 0.1}) {
      const ring::RingSpec spec0 = ringtest::pin_roller_ring();
      const double Mp = 1e-4 * spec0.EI() / spec0.radius;
      const ring::RingSpec spec = plastic_ring(Mp, hardening, rule);
      const Chain chain(spec, mbtest::dense_chain(16));
      HingeBending b(spec, chain);
      ASSERT_TRUE(b.plastic());
      const double ey = Mp / b.K();  // the yield rotation from the virgin state
      // Virgin state: inside the band, past it on either side (away from its edges by > h).
      for (double e : {0.5 * ey, -0.7 * ey, 1.5 * ey, -3.0 * ey}) expect_derivatives(b, 2, e, 1e-3 * ey);
      // Commit hinge 2 past yield (3 ey); the others stay at rest: a plastic state to return from.
      Eigen::VectorXd strains = Eigen::VectorXd::Zero(chain.n());
      strains[2] = 3.0 * ey;
      const double D = ring::BilinearLaw(b.K(), Mp, hardening, rule).dissipated(ring::PlasticState{}, 3.0 * ey);
      b.commit(strains);
      EXPECT_GT(b.state(2).plastic, 0.0);
      EXPECT_EQ(b.state(1).plastic, 0.0);
      EXPECT_EQ(b.dissipated(), D);
      EXPECT_EQ(b.largest_plastic_rotation(), std::abs(b.state(2).plastic));
      for (double e : {2.5 * ey, 0.0, -2.0 * ey, 5.0 * ey}) expect_derivatives(b, 2, e, 1e-3 * ey);
      // The potential is zero at the committed plastic rotation (bending.hpp).
      EXPECT_EQ(b.potential(2, b.state(2).plastic), 0.0);
    }
}

}  // namespace
