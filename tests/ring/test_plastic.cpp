// The bilinear point law of ring.plastic (ring/plastic.hpp) against its closed forms: the
// monotonic curve (yield at Y, then the tangent h k), the reversal (kinematic: reversed
// yield at M - 2Y; isotropic: at -M), the potential whose derivative is the force (central
// differences), and the loop area of strain cycles between +-e_a, 4 Y (1 - h) (e_a - e_y)
// for kinematic hardening (a parallelogram: the band's height 2Y times the plastic strain
// range 2 (1 - h)(e_a - e_y)).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "ring/plastic.hpp"
#include "ring/section_law.hpp"
#include "ring/spec.hpp"
#include "support/fibre_ring.hpp"
#include "support/plastic_ring.hpp"

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

// The fibre law (ring/section_law.hpp) against the elastic–perfectly plastic moment–curvature
// closed forms of the two shapes (e.g. Lubliner, "Plasticity Theory", 2008, sec. 4.4): with
// the elastic core's half-depth c = y_max kappa_y / kappa,
//  - rectangle b x h: M = My (3/2)(1 - (c / (h/2))^2 / 3), My = sigma_y b h^2 / 6;
//  - solid circle of radius r: M = 2 sigma_y [((c/4)(2c^2 - r^2) sqrt(r^2 - c^2) + (r^4/4) asin(c/r)) / c
//    + (2/3)(r^2 - c^2)^(3/2)], from My = sigma_y pi r^3 / 4 (c = r) to sigma_y d^3 / 6 (c = 0).
ring::RingSpec fibre_ring(ring::Section::Shape shape, double hardening = 0.0) {
  ring::RingSpec s;
  s.E = 2.0e11;
  s.section.shape = shape;
  s.section.diameter = 0.1;
  s.section.width = 0.05;
  s.section.height = 0.1;
  s.plastic = ring::Plastic{ring::Plastic::Law::fibre, 0.0, 2.5e8, hardening, Plastic::Rule::kinematic};
  return s;
}

double closed_form_moment(const ring::RingSpec& s, double kappa) {
  const double sy = s.plastic->stress;
  if (s.section.shape == ring::Section::Shape::rectangle) {
    const double b = s.section.width, h = s.section.height, My = sy * b * h * h / 6.0;
    const double ky = sy / (s.E * h / 2.0), c = std::min(1.0, ky / kappa);  // c over h/2
    return My * 1.5 * (1.0 - c * c / 3.0);
  }
  const double r = s.section.diameter / 2.0, ky = sy / (s.E * r), c = r * std::min(1.0, ky / kappa);
  return 2.0 * sy *
         (((c / 4.0) * (2.0 * c * c - r * r) * std::sqrt(r * r - c * c) + std::pow(r, 4) / 4.0 * std::asin(c / r)) / c +
          2.0 / 3.0 * std::pow(r * r - c * c, 1.5));
}

TEST(SectionLaw, FibresAreElasticEIToRoundOffThenFollowTheShapesMomentCurvatureLaw) {
  for (const auto shape : {ring::Section::Shape::rectangle, ring::Section::Shape::circle}) {
    const ring::RingSpec s = fibre_ring(shape);
    const ring::SectionLaw law(s);
    ASSERT_EQ(law.states(), ring::SectionLaw::kFibres);
    std::vector<PlasticState> st(law.states());
    const double ymax = shape == ring::Section::Shape::rectangle ? s.section.height / 2 : s.section.diameter / 2;
    const double ky = s.plastic->stress / (s.E * ymax);
    EXPECT_NEAR(law.at(st.data(), 0.5 * ky).force, s.EI() * 0.5 * ky, 1e-12 * s.EI() * ky);
    EXPECT_NEAR(law.at(st.data(), 0.5 * ky).tangent, s.EI(), 1e-12 * s.EI());
    // Past first yield: the fibres' quadrature against the closed form. The stress has kinks
    // at the elastic core's edges +-c, which fixed Gauss points pass with an error that
    // wanders with where c falls between them but whose worst case over the curvatures falls
    // as 1/fibres^2: measured worst relative errors over kappa / kappa_y in [1.1, 20]
    // (see the printout) fall at least 8-fold over two doublings, and at kFibres are below 1e-3.
    std::vector<double> worst;
    for (int n : {16, 32, 64, 128}) {
      const ring::SectionLaw fine(s, n);
      std::vector<PlasticState> fs(fine.states());
      double w = 0.0;
      for (int i = 0; i <= 100; ++i) {
        const double f = 1.1 + (20.0 - 1.1) * i / 100.0, exact = closed_form_moment(s, f * ky);
        w = std::max(w, std::abs(fine.at(fs.data(), f * ky).force - exact) / exact);
      }
      std::printf("%s: %d fibres, worst relative error %.3g\n", shape == ring::Section::Shape::circle ? "circle" : "rectangle", n, w);
      if (n == ring::SectionLaw::kFibres) EXPECT_LT(w, 1e-3);
      worst.push_back(w);
    }
    EXPECT_LT(worst[3], worst[1] / 8.0);
    EXPECT_LT(worst[2], worst[0] / 8.0);
    // The shape factors: 1.5 (rectangle) and 16 / (3 pi) (circle) of My.
    const double My = s.plastic->stress * s.I() / ymax;
    const double factor = shape == ring::Section::Shape::rectangle ? 1.5 : 16.0 / (3.0 * M_PI);
    EXPECT_NEAR(law.plastic_moment(), factor * My, 2e-4 * factor * My);
  }
}

TEST(SectionLaw, TheFibreLawsPotentialIsTheIntegralOfItsMomentAndAHingeScalesIt) {
  const ring::RingSpec s = fibre_ring(ring::Section::Shape::circle, 0.05);
  const ring::SectionLaw law(s);
  std::vector<PlasticState> st(law.states());
  const double ky = s.plastic->stress / (s.E * s.section.diameter / 2);
  law.commit(st.data(), 4.0 * ky);  // a bent section, then probed around other curvatures
  const double l = 0.3;
  const ring::HingeLaw hinge(law, l);
  for (double k : {-6.0 * ky, -ky, 0.5 * ky, 2.0 * ky, 7.0 * ky}) {
    const double d = 1e-6 * ky;
    const double fd = (law.at(st.data(), k + d).potential - law.at(st.data(), k - d).potential) / (2 * d);
    EXPECT_NEAR(fd, law.at(st.data(), k).force, 1e-6 * law.plastic_moment()) << k / ky;
    // The hinge: the same moment at theta = kappa l, its potential over theta, its tangent / l.
    const double th = k * l, dt = d * l;
    EXPECT_DOUBLE_EQ(hinge.at(st.data(), th).force, law.at(st.data(), k).force);
    const double hfd = (hinge.at(st.data(), th + dt).potential - hinge.at(st.data(), th - dt).potential) / (2 * dt);
    EXPECT_NEAR(hfd, hinge.at(st.data(), th).force, 1e-6 * law.plastic_moment());
    EXPECT_NEAR(hinge.at(st.data(), th).tangent, law.at(st.data(), k).tangent / l, 1e-9 * s.EI() / l);
  }
}

}  // namespace

// The fibre ring's oracle (tests/support/fibre_ring.hpp) checked from outside itself: its
// moment against Lubliner's closed forms above, its elastic closing against Roark's, and its
// compatibility and unit-load integrals, given the resultant law with a little hardening,
// against the limit analysis of the resultant law (tests/support/plastic_ring.hpp).
TEST(FibrePinchedRingOracle, MatchesTheClosedFormsItIsBuiltFrom) {
  for (const auto shape : {ring::Section::Shape::rectangle, ring::Section::Shape::circle}) {
    ring::RingSpec s = fibre_ring(shape);
    s.radius = 1.0;
    const ringtest::FibrePinchedRing ring(s);
    const double ymax = shape == ring::Section::Shape::rectangle ? s.section.height / 2 : s.section.diameter / 2;
    const double ky = s.plastic->stress / (s.E * ymax);
    EXPECT_NEAR(ring.closed_form_moment(0.3 * ky), s.EI() * 0.3 * ky, 1e-12 * s.EI() * ky);
    for (double f : {1.5, 3.0, 20.0})  // (the closed forms above hold past first yield)
      EXPECT_NEAR(ring.closed_form_moment(f * ky), closed_form_moment(s, f * ky), 1e-12 * closed_form_moment(s, f * ky));
    EXPECT_NEAR(ring.EI(), s.EI(), 1e-12 * s.EI());
    const double P = 0.8 * ring.first_yield();
    const double roark = (M_PI / 4 - 2 / M_PI) * P / s.EI();
    EXPECT_NEAR(ring.closing(P), roark, 1e-10 * roark);
    EXPECT_NEAR(ring.moment_under_load(P), P / M_PI, 1e-10 * P);
    // Past first yield the closing grows faster than the elastic one and stays finite.
    EXPECT_GT(ring.closing(0.9 * ring.collapse()), (M_PI / 4 - 2 / M_PI) * 0.9 * ring.collapse() / s.EI());
  }
  // The resultant law (EI kappa to Mp, then the tangent hr EI) through the oracle's general
  // path tends to the four-hinge closed form as hr -> 0: the spread plastic zone at the load
  // has the width Delta / q (Delta = M0 - Mp ~ sqrt(hr)), so the difference falls as sqrt(hr).
  ring::RingSpec s = fibre_ring(ring::Section::Shape::rectangle);
  s.radius = 1.0;
  const double Mp = 1.0e5, EI = s.EI();
  const ringtest::PinchedPlasticRing hinge{1.0, EI, Mp};
  std::vector<double> gaps;
  for (double hr : {1e-6, 1e-8}) {
    const ringtest::FibrePinchedRing ring(
        s, [&](double k) { return std::copysign(std::abs(k) * EI <= Mp ? std::abs(k) * EI : Mp + hr * (std::abs(k) * EI - Mp), k); },
        {Mp});
    const double P = 0.5 * (hinge.first_yield() + hinge.collapse());
    gaps.push_back(std::abs(ring.closing(P) - hinge.closing(P)) / hinge.closing(P));
  }
  std::printf("resultant law through the fibre oracle: relative gap %.3g (hr 1e-6), %.3g (hr 1e-8)\n", gaps[0], gaps[1]);
  EXPECT_LT(gaps[1], 1e-3);
  EXPECT_LT(gaps[1], gaps[0] / 5.0);  // sqrt(100) = 10-fold expected
}

// The four-hinge mechanism's large-deflection load against the virtual work it is built from,
// in its own parameter phi: c(phi) = 2 R (1 - cos phi + sin phi), each of four hinges turning by
// 2 phi, so P dc/dphi = 8 Mp. The derivative is a central difference (h = 1e-5: error ~1e-10).
TEST(PinchedPlasticRingOracle, TheMechanismLoadDoesTheHingesWork) {
  const ringtest::PinchedPlasticRing ring{2.0, 3.0, 5.0};
  EXPECT_DOUBLE_EQ(ring.mechanism_load(0.0), ring.collapse());
  const auto closing = [&](double phi) { return 2.0 * ring.R * (1.0 - std::cos(phi) + std::sin(phi)); };
  for (double phi : {0.05, 0.3, 0.7}) {
    const double h = 1e-5, dc = (closing(phi + h) - closing(phi - h)) / (2.0 * h);
    EXPECT_NEAR(ring.mechanism_load(closing(phi)) * dc, 8.0 * ring.Mp, 1e-8 * ring.Mp) << "phi " << phi;
  }
  EXPECT_NEAR(ring.mechanism_load(2.0 * ring.R), ring.collapse() / std::sqrt(2.0), 1e-14 * ring.collapse());
}

// DeRuntz & Hodge's plates against the virtual work they are built from, in the arc angle alpha:
// c(alpha) = 2 R cos alpha, the flat length R (pi/2 - alpha) per quarter, dissipation 8 Mp |d alpha|.
TEST(PinchedPlasticRingOracle, ThePlatesLoadDoesTheTravellingAndStationaryHingesWork) {
  const ringtest::PinchedPlasticRing ring{2.0, 3.0, 5.0};
  EXPECT_DOUBLE_EQ(ring.plates_load(0.0), ring.collapse());
  const auto closing = [&](double alpha) { return 2.0 * ring.R * std::cos(alpha); };
  for (double alpha : {1.5, 1.1, 0.6}) {
    const double h = 1e-5, dc = (closing(alpha - h) - closing(alpha + h)) / (2.0 * h);  // c grows as alpha falls
    EXPECT_NEAR(ring.plates_load(closing(alpha)) * dc, 8.0 * ring.Mp, 1e-8 * ring.Mp) << "alpha " << alpha;
    EXPECT_NEAR(ring.plates_contact_length(closing(alpha)), 2.0 * ring.R * (M_PI / 2.0 - alpha), 1e-12);
  }
}
