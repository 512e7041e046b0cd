// Closed forms against values computed or printed elsewhere.
#include <gtest/gtest.h>

#include <cmath>

#include "ring/closed_form.hpp"
#include "support/close.hpp"
#include "support/paper.hpp"

namespace {

using ringtest::free_ring;

// Oracle: the formula evaluated by an independent implementation (Python 3.11, math
// module, written from Soedel eq. 6.6.14 without this code), to 1e-15.
TEST(ClosedForm, FreeRingInextensionalPaperRing) {
  const auto s = free_ring();
  EXPECT_TRUE(ringtest::IsClose(ring::closed_form::free_ring_inextensional(s, 2), 4.176859328030314, 1e-13));
  EXPECT_TRUE(ringtest::IsClose(ring::closed_form::free_ring_inextensional(s, 3), 11.813942219650084, 1e-13));
  EXPECT_TRUE(ringtest::IsClose(ring::closed_form::free_ring_inextensional(s, 13), 260.74246929512196, 1e-13));
  EXPECT_THROW(ring::closed_form::free_ring_inextensional(s, 1), std::invalid_argument);
}

// Oracle: the 2x2 characteristic polynomial solved in Python (same source); the lower root
// there loses ~5 digits to cancellation, hence 1e-9.
TEST(ClosedForm, FreeRingExtensibleBranches) {
  const auto s = free_ring();
  const auto w2 = ring::closed_form::free_ring_extensible(s, 2);
  EXPECT_TRUE(ringtest::IsClose(w2[0], 4.176811210819966, 1e-9));
  EXPECT_TRUE(ringtest::IsClose(w2[1], 1160.2520682767242, 1e-12));
  const auto w5 = ring::closed_form::free_ring_extensible(s, 5);
  EXPECT_TRUE(ringtest::IsClose(w5[0], 36.632869935188644, 1e-9));
  EXPECT_TRUE(ringtest::IsClose(w5[1], 2645.795349765418, 1e-12));
}

// Oracle: the breathing mode of a ring is c/R with c = sqrt(E/rho) (Love, sec. 294);
// k = 1 has a rigid translation.
TEST(ClosedForm, BreathingAndTranslation) {
  const auto s = free_ring();
  EXPECT_TRUE(ringtest::IsClose(ring::closed_form::free_ring_extensible(s, 0)[1], std::sqrt(s.E / s.rho) / s.radius, 1e-14));
  EXPECT_EQ(ring::closed_form::free_ring_extensible(s, 1)[0], 0.0);
}

// Oracle: making the ring axially rigid (A -> large at fixed I and rho A) must recover
// the inextensional formula; the flexural branch is lower by O(I/(A R^2)).
TEST(ClosedForm, ExtensibleTendsToInextensional) {
  ring::RingSpec s = free_ring();
  s.section.shape = ring::Section::Shape::general;
  s.section.area_ = 1e6;
  s.section.inertia_ = 1.0e-5;
  s.rho = 7.8e3 * 0.0113097 / 1e6;  // keep rho A near the paper's
  for (int k = 2; k <= 8; ++k) {
    const double inext = ring::closed_form::free_ring_inextensional(s, k);
    const double ext = ring::closed_form::free_ring_extensible(s, k)[0];
    EXPECT_LE(ext, inext);
    EXPECT_TRUE(ringtest::IsClose(ext, inext, 1e-10));  // I/(A R^2) = 1e-13
  }
}

// Oracle: Roark's Formulas for Stress and Strain, 7th ed., Table 9.2 case 1, prints the
// coefficients 0.1488 and 0.1366 of P R^3 / EI (4 digits: 5e-4 relative).
TEST(ClosedForm, DiametralLoadMatchesRoark) {
  const auto s = free_ring();
  const double c = 1000.0 * std::pow(s.radius, 3) / s.EI();
  const auto d = ring::closed_form::diametral_load(s, 1000.0);
  EXPECT_TRUE(ringtest::IsClose(d.along / c, 0.1488, 5e-4));
  EXPECT_TRUE(ringtest::IsClose(d.across / c, 0.1366, 5e-4));
}

// Oracle: section formulas, pi d^2/4 and pi d^4/64 (any handbook), b h^3/12.
TEST(ClosedForm, SectionProperties) {
  ring::Section c;
  c.diameter = 0.12;
  EXPECT_TRUE(ringtest::IsClose(c.area(), 0.011309733552923255, 1e-15));
  EXPECT_TRUE(ringtest::IsClose(c.inertia(), 1.0178760197630929e-05, 1e-15));
  ring::Section r;
  r.shape = ring::Section::Shape::rectangle;
  r.width = 0.2;
  r.height = 0.1;
  EXPECT_TRUE(ringtest::IsClose(r.inertia(), 0.2 * 0.001 / 12.0, 1e-15));
  EXPECT_TRUE(ringtest::IsClose(r.depth(), 0.1, 1e-15));
}

// A thick ring (R = 0.1 m, rectangle 10 x 30 mm: depth/R = 0.3; steel, nu = 0.3, Cowper's
// kappa = 10 (1 + nu) / (12 + 11 nu)). Oracle: the roots of det(K - omega^2 M) = 0, the cubic's
// coefficients found in exact rational arithmetic and its roots by bisection (Python 3.11,
// fractions module, written from the formulas of the header's sources without this code).
// The roots are exact to ~1e-15; 1e-10 leaves room for Eigen's 3x3 solver.
TEST(ClosedForm, TimoshenkoRingThreeBranches) {
  ring::RingSpec s;
  s.radius = 0.1;
  s.E = 2.1e11;
  s.rho = 7800.0;
  s.theory = ring::Theory::timoshenko;
  s.section.shape = ring::Section::Shape::rectangle;
  s.section.width = 0.01;
  s.section.height = 0.03;
  const std::array<std::array<double, 3>, 4> expected{{{0.0, 51887.45216627708, 343790.2283848359},
                                                       {11376.315950526368, 115746.25830856196, 363889.03521150677},
                                                       {80826.97464043487, 264430.172557793, 448373.8120479953},
                                                       {233742.66320199886, 521386.8470765358, 648729.2207808223}}};
  const std::array<int, 4> ks{0, 2, 5, 10};
  for (std::size_t i = 0; i < ks.size(); ++i) {
    const auto w = ring::closed_form::free_ring_timoshenko(s, ks[i]);
    for (int j = 0; j < 3; ++j) {
      if (expected[i][j] == 0.0) EXPECT_EQ(w[j], 0.0) << "k = " << ks[i];
      else EXPECT_TRUE(ringtest::IsClose(w[j], expected[i][j], 1e-10)) << "k = " << ks[i] << ", branch " << j;
    }
  }
  // k = 0: the breathing mode is w alone, sqrt(E/rho)/R exactly.
  EXPECT_TRUE(ringtest::IsClose(ring::closed_form::free_ring_timoshenko(s, 0)[1], std::sqrt(s.E / s.rho) / s.radius, 1e-13));
  EXPECT_EQ(ring::closed_form::free_ring_timoshenko(s, 1)[0], 0.0);  // the rigid translation
}

// The thin limit: with shear stiffness and rotary inertia of a thin ring (depth/R = 1e-3) the
// lower two branches approach the Euler-Bernoulli extensible ring's; shear and rotary inertia
// change omega by O((k depth/R)^2) relative (Kirkhope 1976), so 10 (k d/R)^2 bounds the difference.
TEST(ClosedForm, TimoshenkoRingThinLimitIsEulerBernoulli) {
  ring::RingSpec s;
  s.radius = 1.0;
  s.section.shape = ring::Section::Shape::rectangle;
  s.section.width = 0.001;
  s.section.height = 0.001;
  for (int k : {2, 3, 5, 10}) {
    const auto t = ring::closed_form::free_ring_timoshenko(s, k);
    const auto e = ring::closed_form::free_ring_extensible(s, k);
    const double bound = 10.0 * std::pow(k * s.section.height / s.radius, 2);
    EXPECT_TRUE(ringtest::IsClose(t[0], e[0], bound)) << "k = " << k;
    EXPECT_TRUE(ringtest::IsClose(t[1], e[1], bound)) << "k = " << k;
    EXPECT_LT(t[0], e[0]) << "shear and rotary inertia only lower a frequency (Rayleigh), k = " << k;
  }
  s.shear_coefficient = 0.0;
  s.section.shape = ring::Section::Shape::general;  // no shape, no Cowper: refused
  s.section.area_ = 1e-6;
  s.section.inertia_ = 1e-13;
  EXPECT_THROW(ring::closed_form::free_ring_timoshenko(s, 2), std::invalid_argument);
}

// The pressurized ring's series at p = 0 is the diametral closed form (two independent
// routes: Roark's formula and the Fourier sum of closed_form.cpp), to the sum's truncation.
// The critical pressures are the classical 3, 4 and 4.5 EI/R^3 (Timoshenko & Gere, sec. 7.4).
TEST(ClosedForm, PressurizedRingSeries) {
  const auto s = free_ring();
  const auto d0 = ring::closed_form::diametral_load(s, 100.0);
  const auto d = ring::closed_form::diametral_load_under_pressure(s, 100.0, {0.0, ring::Pressure::Kind::follower});
  EXPECT_TRUE(ringtest::IsClose(d.along, d0.along, 1e-12));
  EXPECT_TRUE(ringtest::IsClose(d.across, d0.across, 1e-10));
  const double unit = s.EI() / std::pow(s.radius, 3);
  EXPECT_DOUBLE_EQ(ring::closed_form::critical_pressure(s, ring::Pressure::Kind::follower) / unit, 3.0);
  EXPECT_DOUBLE_EQ(ring::closed_form::critical_pressure(s, ring::Pressure::Kind::dead) / unit, 4.0);
  EXPECT_DOUBLE_EQ(ring::closed_form::critical_pressure(s, ring::Pressure::Kind::central) / unit, 4.5);
  EXPECT_THROW(ring::closed_form::diametral_load_under_pressure(s, 1.0, {3.01 * unit, ring::Pressure::Kind::follower}),
               std::invalid_argument);
  // Roark's coefficients for the hanging (or standing) ring under its own weight.
  const auto h = ring::closed_form::hanging_ring_self_weight(s, 9.81);
  const double c = s.rhoA() * 9.81 * std::pow(s.radius, 4) / s.EI();
  EXPECT_NEAR(h.sag / c, 0.4674, 5e-5);
  EXPECT_NEAR(h.across / c, 0.4292, 5e-5);
}

}  // namespace
