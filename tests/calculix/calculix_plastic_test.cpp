// The fibre law (ring.plastic = { stress = sigma_y }) in the CalculiX column's statics: ccx's
// von Mises plasticity (*PLASTIC) on the bricks of the expanded beam, against the pinched
// ring with the fibre law at small displacement (tests/support/fibre_ring.hpp).
//
// The expansion is not the fibre model. ccx integrates the section at its bricks' Gauss
// points, one brick through the depth: B32R (C3D20R) and B31 (C3D8I) 2 points at +-c/sqrt(3),
// B32 (C3D20) 3 points at 0 and +-c sqrt(3/5) (weights 5/9 each for the outer ones, 8/9 for
// the centre). Elastic bending integrates exactly (the stress is linear in the depth), but
// under perfect plasticity the section law becomes bilinear: elastic until the outer Gauss
// points yield, then flat at
//   B32R, B31:  M* = 2 (b c) sigma_y c / sqrt(3)         = (2 / sqrt(3)) Mp = 1.1547 Mp,
//   B32:        M* = 2 (5/9) (b c) sigma_y c sqrt(3/5)   = (10/9) sqrt(3/5) Mp = 0.8607 Mp
// (rectangle b x 2c, Mp = sigma_y b c^2; the fibre law rises from My = 2/3 Mp to Mp
// gradually). So the pinched ring collapses at 1.155 P_c (B32R, B31) or 0.861 P_c (B32),
// not P_c = 4 Mp / R. The oracle here is therefore the pinched ring with the expansion's
// own Gauss-point section law (FibrePinchedRing with that law); the remaining difference,
// shear in the yield criterion (von Mises sqrt(sigma^2 + 3 tau^2)), the 3-D stress state and
// the beam discretization, is measured and bounded. The difference between the Gauss-point
// law and the true fibre law is the expansion's integration error, measured here and printed
// (calculix/README.md, "Plasticity").
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

TEST(CalculixPlastic, PrintOracles) {
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

TEST(CalculixPlastic, MeasureCollapse) {
  REQUIRE_CCX();
  const ring::RingSpec spec = plastic_ring();
  const ringtest::FibrePinchedRing fibre(spec);
  for (const Measure m : {Measure{Element::b32r, 80}, Measure{Element::b32r, 160}, Measure{Element::b31, 160},
                          Measure{Element::b32, 80}}) {
    try {
      const double d = pinch(spec, m.element, m.elements, 1.3 * fibre.collapse(), 130);
      std::printf("%s %d: carried 1.3 Pc, closing %.4e\n", ring::to_string(m.element).c_str(), m.elements, d);
    } catch (const std::exception& ex) {
      std::printf("%s %d: %s\n", ring::to_string(m.element).c_str(), m.elements, ex.what());
    }
    std::fflush(stdout);
  }
}

TEST(CalculixPlastic, MeasureExpansionAgainstFibreModel) {
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

}  // namespace
