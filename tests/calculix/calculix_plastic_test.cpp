// The fibre law (ring.plastic = { stress = sigma_y }) in the CalculiX column's statics: ccx's
// von Mises plasticity (*PLASTIC) on the bricks of the expanded beam, against the pinched
// ring with the fibre law at small displacement (tests/support/fibre_ring.hpp).
//
// The expansion is not the fibre model. ccx integrates the section at its bricks' points,
// one brick through the depth (positions over the half-depth c, weights over c):
//   B31  -> C3D8I, 2 x 2 x 2 Gauss: +-1/sqrt(3) (1, 1);
//   B32R -> C3D20RB (ccx's gauss3d13, 2 x 5 x 5 = 50 points): 0, +-1/sqrt(3), +-sqrt(6/7)
//           (28/45, 27/55, 98/495);
//   B32  -> C3D20, 3 x 3 x 3 Gauss: 0, +-sqrt(3/5) (8/9, 5/9).
// Elastic bending integrates exactly (the stress is linear in the depth), but under perfect
// plasticity each law is piecewise linear, elastic until the outer points yield and flat once
// all off-axis points have, at sum w |y| sigma_y b c = (Mp = sigma_y b c^2 times)
//   B31: 2/sqrt(3) = 1.155,   B32R: 0.933,   B32: (10/9) sqrt(3/5) = 0.861,
// where the fibre law rises gradually from My = 2/3 Mp to Mp. FibrePinchedRing with these
// laws (GaussLaw below) is the oracle of a column that followed its own section law; what is
// left over is the 3-D stress state (the plastic flow constrained in one brick, shear in the
// von Mises criterion) and the beam discretization, measured below and bounded. B32 locks
// (elastic closing 1.9 % short at 80 elements) and is not held here.
//
// The ring: R = 10 m, E = 210 GPa, rectangle 0.1 x 0.12 m (as given), pinned at 0 deg, a
// roller at 180 deg, pinched at 90 and 270 deg; sigma_y so that Mp R / EI = 1e-4, so that
// the geometric nonlinearity of ccx's NLGEOM deviates from the small-displacement oracle by
// O(delta / R) ~ 1e-4..1e-3 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "calculix/ccx.hpp"
#include "calculix/statics.hpp"
#include "ring/errors.hpp"
#include "support/fibre_ring.hpp"
#include "support/plastic_ring.hpp"
#include "support/paper.hpp"

namespace {

#define REQUIRE_CCX()                                                                                  \
  if (calculix::find_ccx().empty()) GTEST_SKIP() << "ccx is not on the PATH (Debian package calculix-ccx; " \
                                                    "scripts/install-deps.sh installs it)"

constexpr double kMpR_EI = 1e-4;  ///< Mp R / EI of the test ring

using Element = ring::CalculixOptions::Element;

ring::RingSpec plastic_ring(double hardening = 0.0, ring::Plastic::Rule rule = ring::Plastic::Rule::kinematic) {
  ring::RingSpec s = ringtest::free_ring();
  s.section.shape = ring::Section::Shape::rectangle;
  s.section.width = 0.1;
  s.section.height = 0.12;
  s.supports.pin = 0.0;
  s.supports.roller = 180.0;
  const double Z = s.section.width * s.section.height * s.section.height / 4.0;
  ring::Plastic p;
  p.law = ring::Plastic::Law::fibre;
  p.stress = kMpR_EI * s.EI() / s.radius / Z;
  p.hardening = hardening;
  p.rule = rule;
  s.plastic = p;
  return s;
}

/// The Gauss points through the depth of ccx's brick of `e`: positions over c, weights over c.
struct Points {
  std::vector<double> y, w;
};
Points depth_points(Element e) {
  if (e == Element::b32) return {{-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  if (e == Element::b32r)
    return {{-std::sqrt(6.0 / 7.0), -1.0 / std::sqrt(3.0), 0.0, 1.0 / std::sqrt(3.0), std::sqrt(6.0 / 7.0)},
            {98.0 / 495.0, 27.0 / 55.0, 28.0 / 45.0, 27.0 / 55.0, 98.0 / 495.0}};
  return {{-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}, {1.0, 1.0}};
}

/// The expansion's section law under monotonic bending: the bilinear uniaxial law at the
/// Gauss points through the depth (the width is uniform: its points add up to b).
struct GaussLaw {
  GaussLaw(const ring::RingSpec& spec, Element e) : pts(depth_points(e)) {
    b = spec.section.width;
    c = spec.section.height / 2;
    E = spec.E;
    sy = spec.plastic->stress;
    h = spec.plastic->hardening;
  }
  double operator()(double kappa) const {
    double m = 0.0;
    for (std::size_t i = 0; i < pts.y.size(); ++i) {
      const double y = pts.y[i] * c, eps = kappa * y, ey = sy / E;
      const double s = std::abs(eps) <= ey ? E * eps : std::copysign(sy + h * E * (std::abs(eps) - ey), eps);
      m += pts.w[i] * b * c * s * y;
    }
    return m;
  }
  /// The moments where a pair of points yields (the law's kinks), N m.
  std::vector<double> kinks() const {
    std::vector<double> k;
    for (double y : pts.y)
      if (y > 0) k.push_back((*this)(sy / E / (y * c)));
    return k;
  }
  Points pts;
  double b, c, E, sy, h;
};

double pinch(const ring::RingSpec& spec, Element e, int elements, double P, int steps = 20) {
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -P}}, {270.0, {0.0, P}}};
  st.record = {90.0, 270.0};
  st.steps = steps;
  ring::CalculixOptions o;
  o.element = e;
  o.elements = elements;
  o.section = ring::CalculixOptions::Section::as_given;
  const ring::StaticResult r = calculix::solve_static(spec, o, st);
  return r.displacements[1].uy - r.displacements[0].uy;
}

struct Measure {
  Element element;
  int elements;
};

TEST(CalculixPlastic, DISABLED_PrintOracles) {
  const ring::RingSpec spec = plastic_ring();
  const ringtest::FibrePinchedRing fibre(spec);
  for (Element e : {Element::b32r, Element::b31, Element::b32}) {
    const GaussLaw law(spec, e);
    std::vector<double> kinks;
    const ringtest::FibrePinchedRing gauss(spec, law, law.kinks());
    for (double f : {0.45, 0.6, 0.75, 0.8, 0.85, 0.9})
      std::printf("%s P/Pc %.2f fibre %.6e points %.6e (%+.4e)\n", ring::to_string(e).c_str(), f, fibre.closing(f * fibre.collapse()),
                  gauss.closing(f * fibre.collapse()), gauss.closing(f * fibre.collapse()) / fibre.closing(f * fibre.collapse()) - 1);
  }
}

TEST(CalculixPlastic, DISABLED_MeasureExpansionAgainstFibreModel) {
  REQUIRE_CCX();
  const ring::RingSpec spec = plastic_ring();
  const ringtest::FibrePinchedRing fibre(spec);
  const double Pc = fibre.collapse();
  for (const Measure m : {Measure{Element::b32r, 40}, Measure{Element::b32r, 80}, Measure{Element::b32r, 160},
                          Measure{Element::b31, 80}, Measure{Element::b31, 160}, Measure{Element::b32, 80}}) {
    const GaussLaw law(spec, m.element);
    const ringtest::FibrePinchedRing gauss(spec, law, law.kinks());
    for (double f : {0.45, 0.6, 0.75, 0.8, 0.9}) {
      if (m.element == Element::b32 && f > 0.8) continue;
      const double P = f * Pc;
      double d = 0.0;
      try {
        d = pinch(spec, m.element, m.elements, P);
      } catch (const std::exception& ex) {
        std::printf("%s %d P/Pc %.2f failed: %s\n", ring::to_string(m.element).c_str(), m.elements, f, ex.what());
        continue;
      }
      const double df = fibre.closing(P), dg = gauss.closing(P);
      std::printf("%s %4d P/Pc %.2f closing %.6e fibre %.6e (%+.4e) gauss %.6e (%+.4e); gauss/fibre-1 %+.4e\n",
                  ring::to_string(m.element).c_str(), m.elements, f, d, df, d / df - 1, dg, d / dg - 1, dg / df - 1);
      std::fflush(stdout);
    }
  }
}

// Below first yield (0.45 Pc = 0.86 P_y) the column is elastic: the default B32R at 80
// elements against the oracle's elastic closing (pi/4 - 2/pi) P R^3 / EI. Measured: +1.4e-4
// (80 elements), +1.9e-4 (160; -5.7e-4 at 40): the converged bricks' shear and thick-curved-beam
// terms, of order (h/R)^2 = 1.4e-4, as in the elastic statics. Bound: 5e-4.
TEST(CalculixPlastic, ElasticBelowFirstYield) {
  REQUIRE_CCX();
  const ring::RingSpec spec = plastic_ring();
  const ringtest::FibrePinchedRing fibre(spec);
  const double P = 0.45 * fibre.collapse();
  ASSERT_LT(P, fibre.first_yield());
  const double d = pinch(spec, Element::b32r, 80, P);
  std::printf("[ calculix ] B32R 80 at 0.45 Pc: closing %.6e, oracle %.6e (%+.3e)\n", d, fibre.closing(P),
              d / fibre.closing(P) - 1);
  EXPECT_NEAR(d / fibre.closing(P), 1.0, 5e-4);
}

// B31 expands into C3D8I bricks, 2 x 2 x 2 Gauss points: through the depth the section is
// two points at +-c/sqrt(3) (weight c each), whose moment is elastic to sqrt(3) My =
// (2/sqrt(3)) Mp and flat there (h = 0): a resultant law, elastic–perfectly plastic with
// Mp' = 1.155 Mp, instead of the fibre law's rise from 2/3 Mp to Mp. Its pinched ring is the
// classical one (tests/support/plastic_ring.hpp): elastic to P_y' = pi Mp' / R = 0.907 P_c,
// then hinges at the loads, collapse at 1.155 P_c. Held here: at 0.75 P_c, elastic for B31 and
// plastic for the fibre law, measured -1.05e-3 at 160 elements against the Mp' ring, B31's
// elastic discretization error (1.07e-3 at 0.45 P_c, 5.3e-3 at 80: order 2); bound 2e-3.
// Against the fibre law the difference is the two-point law's: -6.2 % (the fibre ring has
// yielded, B31's has not). Not held: past its first hinges B31 is stiffer than the Mp' ring
// (measured -17.5 % at 1.0 P_c, and ccx stops before 1.05 P_c in 40 increments), while with
// hardening it follows the two-point law past yield (the next test): calculix/README.md.
TEST(CalculixPlastic, B31IsAResultantLawAtTwoOverRootThreeMp) {
  REQUIRE_CCX();
  const ring::RingSpec spec = plastic_ring();
  const ringtest::FibrePinchedRing fibre(spec);
  const ringtest::PinchedPlasticRing hinge{spec.radius, spec.EI(), 2.0 / std::sqrt(3.0) * fibre.plastic_moment()};
  const double P = 0.75 * fibre.collapse();
  ASSERT_LT(P, hinge.first_yield());
  const double d = pinch(spec, Element::b31, 160, P), dh = hinge.closing(P), df = fibre.closing(P);
  std::printf("[ calculix ] B31 160 at 0.75 Pc: closing %.6e, Mp' ring %.6e (%+.3e), fibre %.6e (%+.3e)\n", d, dh,
              d / dh - 1, df, d / df - 1);
  EXPECT_NEAR(d / dh, 1.0, 2e-3);
  EXPECT_LE(std::abs(d / df - 1.0), std::abs(dh / df - 1.0) + 2e-3);
}

// B32R (the default) expands into C3D20RB bricks with 2 x 5 x 5 points: through the depth
// 0, +-c/sqrt(3), +-c sqrt(6/7) (weights 28/45, 27/55, 98/495 of c; ccx's gauss3d13), elastic
// to 1.08 My, fully plastic at 0.933 Mp. In one brick through the depth the plastic flow is
// constrained (the section cannot contract where it yields: a quadratic displacement across
// it), so the yielded points carry transverse stresses of the hoop stress's sign and a hoop
// stress above sigma_y (measured at 0.75 Pc next to the load: 1.096 sigma_y at the outer
// points). Measured at 80 elements against the fibre oracle: -7.7e-5 (0.6 Pc), -3.13e-2
// (0.75), +4.15e-2 (0.9), while the five-point law alone gives +4e-4, +2.6e-2, +22.8e-2: the
// constraint stiffens what the law softens. (160 elements: -3.2e-4, -2.9e-2, +10.7e-2: near its
// collapse the column still moves with the elements.) Bounds: 1e-3 at 0.6 Pc (just past first
// yield, P_y = 0.52 Pc), 5e-2 at 0.75 and 0.9 Pc.
TEST(CalculixPlastic, B32RAgainstTheFibreLaw) {
  REQUIRE_CCX();
  const ring::RingSpec spec = plastic_ring();
  const ringtest::FibrePinchedRing fibre(spec);
  for (const auto& [f, bound] : {std::pair{0.6, 1e-3}, std::pair{0.75, 5e-2}, std::pair{0.9, 5e-2}}) {
    const double P = f * fibre.collapse();
    const double d = pinch(spec, Element::b32r, 80, P), df = fibre.closing(P);
    std::printf("[ calculix ] B32R 80 at %.2f Pc: closing %.6e, fibre %.6e (%+.3e)\n", f, d, df, d / df - 1);
    EXPECT_NEAR(d / df, 1.0, bound) << f << " Pc";
  }
}

// A spring on the ring makes the elastic deck's material orthotropic (the section rigid across
// its width, deck.cpp); ccx 2.20 stops on a beam section of an orthotropic material with
// *PLASTIC, so the plastic deck keeps the isotropic one and runs: with a spring of 1e-9 N/m
// (no force to speak of: 1e-9 N/m x 5e-4 m) the closing at 0.75 Pc is the springless one's
// to ccx's printed digits (measured: equal; an elastic run of this ring with either material
// gives the same closing to 8 digits, so nothing is lost for point loads on this section).
TEST(CalculixPlastic, ASpringKeepsTheIsotropicMaterialAndRuns) {
  REQUIRE_CCX();
  ring::RingSpec spec = plastic_ring();
  const ringtest::FibrePinchedRing fibre(spec);
  const double P = 0.75 * fibre.collapse();
  const double bare = pinch(spec, Element::b32r, 80, P);
  spec.supports.springs = {{45.0, 1e-9, 1e-9, 0.0}};
  const double sprung = pinch(spec, Element::b32r, 80, P);
  EXPECT_NEAR(sprung / bare, 1.0, 1e-6);  // ccx prints 7 digits
}

// Hardening: the *PLASTIC table's slope H = h E / (1 - h) gives the uniaxial tangent h E past
// yield. B31 with h = 0.1, both rules (monotonic loading: the same curve), at 0.9 and 1.2 P_c
// (beyond the perfectly plastic collapse, carried by the hardening) against the pinched ring
// with B31's two-point law with the same hardening, at 80 and 160 elements. Measured (both
// rules alike): 0.9 P_c -5.3e-3, -1.05e-3; 1.2 P_c -2.19e-2, -4.5e-3: B31's discretization,
// order 2.3 (ratio 4.9; the plastic zones sampled by two points per element). Bounds at 160:
// 2e-3 (0.9 P_c) and 6e-3 (1.2 P_c); the error falls by more than 3 from 80 to 160.
TEST(CalculixPlastic, HardeningFollowsTheTwoPointLawWithEitherRule) {
  REQUIRE_CCX();
  for (ring::Plastic::Rule rule : {ring::Plastic::Rule::kinematic, ring::Plastic::Rule::isotropic}) {
    const ring::RingSpec spec = plastic_ring(0.1, rule);
    const ringtest::FibrePinchedRing fibre(spec);
    const GaussLaw law(spec, Element::b31);
    const ringtest::FibrePinchedRing points(spec, law, law.kinks());
    for (const auto& [f, bound] : {std::pair{0.9, 2e-3}, std::pair{1.2, 6e-3}}) {
      const double P = f * fibre.collapse();
      const double d = pinch(spec, Element::b31, 160, P), dp = points.closing(P);
      const double d80 = pinch(spec, Element::b31, 80, P);
      EXPECT_GT(std::abs(d80 / dp - 1), 3.0 * std::abs(d / dp - 1)) << f << " Pc";
      std::printf("[ calculix ] B31, h = 0.1, %s, at %.2f Pc: two-point law %.6e, closing 80 %+.3e, 160 %+.3e; fibre %.6e\n",
                  rule == ring::Plastic::Rule::kinematic ? "kinematic" : "isotropic", f, dp, d80 / dp - 1, d / dp - 1,
                  fibre.closing(P));
      EXPECT_NEAR(d / dp, 1.0, bound) << f << " Pc";
    }
  }
}

}  // namespace
