// The hinge's bending law (multibody/bending.hpp) against its own definition: the moment is
// the derivative of the potential and the tangent the derivative of the moment (central
// differences, exact up to round-off on a piecewise quadratic away from the band's edges),
// from the virgin state and from a committed plastic one; elastic, the law is K e with
// K = EI / l; the plastic laws are ring::HingeLaw on the spec's ring::SectionLaw
// (bending.hpp), and commit() adds the law's plastic work.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "multibody/bending.hpp"
#include "multibody/chain.hpp"
#include "ring/errors.hpp"
#include "ring/plastic.hpp"
#include "ring/section_law.hpp"
#include "tests/support/close.hpp"
#include "support/refusal.hpp"
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
      // The hinge law of bending.hpp: the section's (EI, Mp) law at kappa = e / l.
      const ring::SectionLaw section(spec);
      const ring::PlasticState virgin{};
      const double D = ring::HingeLaw(section, chain.l()).dissipated(&virgin, 3.0 * ey);
      // ... which is the bilinear law (K, Mp) on the rotation up to round-off.
      EXPECT_TRUE(ringtest::IsClose(D, ring::BilinearLaw(b.K(), Mp, hardening, rule).dissipated(virgin, 3.0 * ey),
                                    1e-14, 0.0));
      EXPECT_EQ(b.dissipated_by(strains), D);
      b.commit(strains);
      EXPECT_GT(b.state(2).plastic, 0.0);  // the resultant law's state: the plastic curvature, 1/m
      EXPECT_EQ(b.state(1).plastic, 0.0);
      EXPECT_EQ(b.dissipated(), D);
      EXPECT_EQ(b.largest_plastic_curvature(), std::abs(b.state(2).plastic));
      EXPECT_EQ(b.largest_plastic_rotation(), std::abs(b.state(2).plastic) * chain.l());
      for (double e : {2.5 * ey, 0.0, -2.0 * ey, 5.0 * ey}) expect_derivatives(b, 2, e, 1e-3 * ey);
      // The potential is zero at the committed plastic rotation l kappa_p (bending.hpp).
      EXPECT_EQ(b.potential(2, b.state(2).plastic * chain.l()), 0.0);
    }
}

// ---- the fibre law (ring.plastic.stress) on the paper's solid circle ----

ring::RingSpec fibre_ring(double sigma_y) {
  ring::RingSpec spec = ringtest::pin_roller_ring();
  ring::Plastic p;
  p.law = ring::Plastic::Law::fibre;
  p.stress = sigma_y;
  spec.plastic = p;
  return spec;
}

// The hinge holds SectionLaw::kFibres states; its moment is the section's at e / l (bending.hpp):
// elastic below first yield (K e, to the fibres' round-off), the moment the derivative of the
// potential and the tangent that of the moment (virgin and committed states), the law's
// energy identity (potential = stored + dissipated over a step), and the plastic curvature
// zero until a fibre yields.
TEST(HingeBending, FibreLawIsTheSectionsLawAtTheSegmentsCurvature) {
  const ring::RingSpec spec0 = ringtest::pin_roller_ring();
  // sigma_y such that My = sigma_y I / (d/2) = 1e-4 EI / R (the plastic statics' scale).
  const double My = 1e-4 * spec0.EI() / spec0.radius, sigma_y = My * 0.5 * spec0.section.diameter / spec0.section.inertia();
  const ring::RingSpec spec = fibre_ring(sigma_y);
  const Chain chain(spec, mbtest::dense_chain(16));
  HingeBending b(spec, chain);
  ASSERT_TRUE(b.plastic());
  EXPECT_EQ(b.states(), ring::SectionLaw::kFibres);
  const double ey = My / b.K();  // the first-yield rotation
  // Below first yield: K e (sum y^2 a = I to round-off: ring/section_law.hpp), nothing yields.
  for (double e : {0.5 * ey, -0.9 * ey}) {
    EXPECT_TRUE(ringtest::IsClose(b.moment(1, e), b.K() * e, 1e-13, 0.0)) << "at e = " << e;
    EXPECT_FALSE(b.at(1, e).yielding);
  }
  for (double e : {0.5 * ey, -0.7 * ey, 1.3 * ey, -4.0 * ey}) expect_derivatives(b, 2, e, 1e-4 * ey);
  Eigen::VectorXd strains = Eigen::VectorXd::Zero(chain.n());
  strains[2] = 3.0 * ey;
  const ring::SectionLaw section(spec);
  std::vector<ring::PlasticState> virgin(ring::SectionLaw::kFibres);
  const double D = ring::HingeLaw(section, chain.l()).dissipated(virgin.data(), 3.0 * ey);
  EXPECT_GT(D, 0.0);
  EXPECT_EQ(b.dissipated_by(strains), D);
  EXPECT_EQ(b.largest_plastic_curvature(), 0.0);
  b.commit(strains);
  EXPECT_EQ(b.dissipated(), D);
  EXPECT_EQ(b.largest_plastic_curvature(),
            std::abs(ring::HingeLaw(section, chain.l()).plastic_curvature(&b.state(2), 3.0 * ey)));
  EXPECT_GT(b.largest_plastic_curvature(), 0.0);
  for (double e : {2.5 * ey, 0.0, -2.0 * ey, 5.0 * ey}) expect_derivatives(b, 2, e, 1e-4 * ey);
  // The law's energy identity for one monotone step from the virgin state: the incremental
  // potential is the elastic energy stored (the fibres' l sigma^2 a / 2E) plus the plastic work
  // (ring/plastic.hpp), to round-off; while elastic, the potential is all stored.
  HingeBending c(spec, chain);
  const double V = c.potential(1, 4.0 * ey);
  Eigen::VectorXd one = Eigen::VectorXd::Zero(chain.n());
  one[1] = 4.0 * ey;
  c.commit(one);
  EXPECT_GT(c.dissipated(), 0.0);
  EXPECT_TRUE(ringtest::IsClose(c.stored(1, 4.0 * ey) + c.dissipated(), V, 1e-12, 0.0));
  EXPECT_TRUE(ringtest::IsClose(c.stored(3, 0.5 * ey), c.potential(3, 0.5 * ey), 1e-13, 0.0));
}

// A section given by {area, inertia} has no shape: the fibre law is refused by key, by the
// hinges' law and by the statics' and response's checks (a library caller's spec).
TEST(HingeBending, FibreLawOnASectionWithoutShapeIsRefusedByKey) {
  ring::RingSpec spec = fibre_ring(2.5e8);
  const double A = spec.section.area(), I = spec.section.inertia();
  spec.section.shape = ring::Section::Shape::general;
  spec.section.area_ = A;
  spec.section.inertia_ = I;
  const Chain chain(spec, mbtest::dense_chain(16));
  EXPECT_EQ(ringtest::refused_key([&] { HingeBending b(spec, chain); }), "ring.plastic.stress");
  EXPECT_EQ(ringtest::refused_key([&] { multibody::check_section_law(spec); }), "ring.plastic.stress");
}

}  // namespace
