// The FE modes with the terms beyond the paper's ring (fem_reference/modes.hpp, "Terms"):
// a Winkler foundation, point masses with rotary inertia, elastic supports, further pins
// and a clamp. Oracles from outside the FE code: the closed forms of ring/closed_form.hpp,
// the receptance oracles of tests/support/ring_receptance.hpp (a finite point mass, a
// clamp), first-order perturbation of the Rayleigh quotient derived below, the stiff-spring limit
// (a pin, a clamp) with the rate 1/k that the stiffness ratio predicts, the hand count of
// rigid modes, and a fitted convergence order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem_reference/checks.hpp"
#include "fem_reference/modes.hpp"
#include "ring/closed_form.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/ring_receptance.hpp"

namespace {

using ring::FemOptions;
using ringtest::IsClose;

constexpr double kPi = 3.14159265358979323846;

/// Degree 8 on 40 elements: the free ring's k = 2..13 within ~2e-12 of the closed form
/// (fem_validation_test), so the discretization error is far below every tolerance here.
FemOptions fine(bool extensible) {
  FemOptions o;
  o.degree = 8;
  o.extensible = extensible;
  return o;
}

double ring_mass(const ring::RingSpec& s) { return 2.0 * kPi * s.radius * s.rhoA(); }

// (1) The free inextensible ring on a radial + tangential foundation: omega_k from
// closed_form::ring_on_foundation_inextensional for k = 0 (the rotation, held by k_t; a
// single mode), k = 1 (the translations, held by (k_r + k_t)/2) and the bending pairs
// k = 2..8. No rigid mode. Moduli of the order of EI/R^4 (214 N/m^2 here) so that the
// foundation and the bending both matter.
TEST(FemFoundation, InextensibleRingMatchesClosedFormK0To8) {
  auto spec = ringtest::free_ring();
  spec.foundation.radial = 1000.0;
  spec.foundation.tangential = 300.0;
  std::vector<double> exact{ring::closed_form::ring_on_foundation_inextensional(spec, 0)};
  for (int k = 1; k <= 8; ++k)
    for (int member = 0; member < 2; ++member)
      exact.push_back(ring::closed_form::ring_on_foundation_inextensional(spec, k));
  std::sort(exact.begin(), exact.end());
  const auto r = fem::compute_modes(spec, fine(false), static_cast<int>(exact.size()));
  EXPECT_EQ(r.rigid_modes, 0);
  ASSERT_EQ(r.omega.size(), exact.size());
  // 1e-8: as Hoppe's limit in fem_validation_test (the 1/beta extrapolation leaves
  // ~1e-10, the discretization ~1e-12; measured 1.6e-13 .. 5.5e-11, the largest at k = 8).
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_TRUE(IsClose(r.omega[i], exact[i], 1e-8)) << "mode " << i + 1;
}

// The same ring converges to the closed form at the fitted order 2(p - 1) = 4 of degree 3
// (modes.hpp): the largest error of the 17 modes k = 0..8 at 32, 64, 128 elements (16 is
// pre-asymptotic for k = 8: two elements per wave); 0.3 as in fem_convergence_test (a
// three-point fit's pre-asymptotic spread).
TEST(FemFoundation, ConvergesToTheClosedFormAtOrderTwoPMinusTwo) {
  auto spec = ringtest::free_ring();
  spec.foundation.radial = 1000.0;
  spec.foundation.tangential = 300.0;
  std::vector<double> exact{ring::closed_form::ring_on_foundation_inextensional(spec, 0)};
  for (int k = 1; k <= 8; ++k)
    for (int member = 0; member < 2; ++member)
      exact.push_back(ring::closed_form::ring_on_foundation_inextensional(spec, k));
  std::sort(exact.begin(), exact.end());
  const std::vector<int> meshes{32, 64, 128};
  std::vector<double> errors;
  for (int elements : meshes) {
    FemOptions o;
    o.degree = 3;
    o.elements = elements;
    o.extensible = false;
    const auto r = fem::compute_modes(spec, o, static_cast<int>(exact.size()));
    double e = 0.0;
    for (std::size_t i = 0; i < exact.size(); ++i) e = std::max(e, ringtest::rel(r.omega[i], exact[i]));
    errors.push_back(e);
  }
  // The order from the coarsest and the finest mesh (two points).
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{meshes.front(), meshes.back()}, {errors.front(), errors.back()}),
                                  4.0, 0.3));
}

// The extensible ring on the same foundation against the 2x2 closed form with diag(k_r, k_t)
// (closed_form::free_ring_extensible, its flexural branch; k = 0 is the rotation held by
// k_t, the breathing branches lie far above): k = 0..8, 1e-8 as the free ring's extensible
// test in fem_validation_test (the reference's accuracy, p = 8 on 40 elements; measured
// 1.3e-15 .. 1.2e-12).
TEST(FemFoundation, ExtensibleRingMatchesTwoByTwoClosedFormK0To8) {
  auto spec = ringtest::free_ring();
  spec.foundation.radial = 1000.0;
  spec.foundation.tangential = 300.0;
  std::vector<double> exact{ring::closed_form::free_ring_extensible(spec, 0)[0]};
  for (int k = 1; k <= 8; ++k)
    for (int member = 0; member < 2; ++member) exact.push_back(ring::closed_form::free_ring_extensible(spec, k)[0]);
  std::sort(exact.begin(), exact.end());
  const auto r = fem::compute_modes(spec, fine(true), static_cast<int>(exact.size()));
  EXPECT_EQ(r.rigid_modes, 0);
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_TRUE(IsClose(r.omega[i], exact[i], 1e-8)) << "mode " << i + 1;
}

// A foundation of zero stiffness is no foundation: today's free ring, three rigid modes,
// Hoppe's frequencies (the same 1e-8 as above).
TEST(FemFoundation, ZeroModuliGiveTheFreeRing) {
  auto spec = ringtest::free_ring();
  spec.foundation.radial = 0.0;
  spec.foundation.tangential = 0.0;
  const auto r = fem::compute_modes(spec, fine(false), 4);
  EXPECT_EQ(r.rigid_modes, 3);
  for (int k = 2; k <= 3; ++k)
    EXPECT_TRUE(IsClose(r.omega[2 * (k - 2)], ring::closed_form::free_ring_inextensional(spec, k), 1e-8));
}

/// Quantities of one FE run at a perturbation strength s, and their first-order
/// predictions (linear in s).
struct FirstOrder {
  std::vector<double> fe, predicted;
};

/// A first-order prediction, checked as such: what it leaves, fe - predicted, is the
/// second-order part, so from strength s (`full`) to s/2 (`half`) it falls by 4 (within
/// 10 %: the O(s^3) part, relative ~ the shift itself, < 1e-2 here). Where it is below
/// 1e-8 at s (a member the term does not touch, by symmetry: exactly 0; the FE's
/// noise is ~1e-10) the prediction is simply met to 1e-8. The leftover is at most 5 %
/// of the prediction (first order dominates).
void expect_first_order(const FirstOrder& full, const FirstOrder& half, const std::string& what) {
  ASSERT_EQ(full.fe.size(), full.predicted.size());
  for (std::size_t i = 0; i < full.fe.size(); ++i) {
    const double left = full.fe[i] - full.predicted[i], left_half = half.fe[i] - half.predicted[i];
    if (std::abs(left) < 1e-8) {
      EXPECT_LT(std::abs(left_half), 1e-8) << what << ", quantity " << i;
      continue;
    }
    EXPECT_LT(std::abs(left), 0.05 * std::abs(full.predicted[i])) << what << ", quantity " << i;
    EXPECT_TRUE(IsClose(left / left_half, 4.0, 0.1))
        << what << ", quantity " << i << ": leftover " << left << " at s, " << left_half << " at s/2";
  }
}

/// omega^2 / omega_base^2 - 1 of modes first..first+count-1 against the base's first `count`.
std::vector<double> relative_shift(const ring::ModalResult& with, const ring::ModalResult& base, int first,
                                   int count) {
  std::vector<double> d;
  for (int i = 0; i < count; ++i) d.push_back(std::pow(with.omega[first + i] / base.omega[i], 2) - 1.0);
  return d;
}

constexpr int kPairs = 5;  ///< pairs k = 2..6 in the perturbation tests

// (2) A point mass m0 at 0 deg splits pair k: the member radial at the mass drops by
// -m0 k^2 / (pi R rho A (k^2 + 1)) (the lower one), the tangential by -m0 / (...)
// (closed_form::point_mass_shift, first order). m0 = 1e-3 of the ring's mass: shifts up to
// 2e-3, what the first order leaves is O(m0^2) (expect_first_order).
TEST(FemPointMass, SplitsPairsAsThePerturbationOfTheRayleighQuotient) {
  const auto base = fem::compute_modes(ringtest::free_ring(), fine(false), 2 * kPairs);
  auto run = [&](double m) {
    auto spec = ringtest::free_ring();
    spec.masses.push_back({0.0, m, 0.0});
    FirstOrder out{relative_shift(fem::compute_modes(spec, fine(false), 2 * kPairs), base, 0, 2 * kPairs), {}};
    EXPECT_EQ(fem::compute_modes(spec, fine(false), 1).rigid_modes, 3);
    for (int k = 2; k < 2 + kPairs; ++k) {
      const auto [tangential, radial] = ring::closed_form::point_mass_shift(spec, m, k);
      out.predicted.push_back(radial);      // the lower member
      out.predicted.push_back(tangential);  // the upper member
    }
    return out;
  };
  const double m0 = 1e-3 * ring_mass(ringtest::free_ring());
  expect_first_order(run(m0), run(m0 / 2), "point mass");
}

// The rotary inertia J of a point mass at 0 deg acts on the rotation phi = (u - w')/R
// there. Of pair k (inextensional: u = V cos k theta, w = k V sin k theta, and the
// member turned by a quarter wave) only the member tangential at the mass turns:
// phi(0) = V (1 - k^2)/R, so first order gives d(omega^2)/omega^2 =
// -J (k^2 - 1)^2 / (R^2 pi R rho A (k^2 + 1)) for it (now the lower member) and 0 for the
// radial member, whose phi is odd about the mass (kinetic energy of the mode
// rho A R pi (k^2 + 1) V^2 / 2; derived here). J = 2e-5 of the ring's mass times R^2:
// shifts up to 1.3e-3 at k = 6.
TEST(FemPointMass, RotaryInertiaTurnsOnlyTheTangentialMember) {
  const auto base = fem::compute_modes(ringtest::free_ring(), fine(false), 2 * kPairs);
  auto run = [&](double J) {
    auto spec = ringtest::free_ring();
    spec.masses.push_back({0.0, 0.0, J});
    const double R = spec.radius;
    FirstOrder out{relative_shift(fem::compute_modes(spec, fine(false), 2 * kPairs), base, 0, 2 * kPairs), {}};
    for (int k = 2; k < 2 + kPairs; ++k) {
      const double k2 = k * k;
      out.predicted.push_back(-J * (k2 - 1) * (k2 - 1) / (R * R * kPi * R * spec.rhoA() * (k2 + 1)));
      out.predicted.push_back(0.0);
    }
    return out;
  };
  const auto spec = ringtest::free_ring();
  const double J = 2e-5 * ring_mass(spec) * spec.radius * spec.radius;
  expect_first_order(run(J), run(J / 2), "rotary inertia");
}

// Elastic supports at first order, the same derivation for the strain energy: a spring
// kx at 0 deg (along the radial direction there) raises the radial member of pair k by
// d(omega^2) = kx k^2 / (pi R rho A (k^2 + 1)) and holds the x translation, an elastic
// mode at omega^2 = kx / (ring mass); a rotational spring kr there raises the tangential
// member by kr (k^2 - 1)^2 / (R^2 pi R rho A (k^2 + 1)) and holds the rotation about the
// centre (phi = u/R), omega^2 = kr / (R^2 ring mass). Each leaves two rigid modes; the
// held motion is the lowest elastic mode. Shifts up to ~2e-3.
TEST(FemSprings, SmallSpringsShiftTheirMemberToFirstOrder) {
  const auto base = fem::compute_modes(ringtest::free_ring(), fine(false), 2 * kPairs);
  auto run = [&](double kx, double kr) {
    auto spec = ringtest::free_ring();
    spec.supports.springs.push_back({0.0, kx, 0.0, kr});
    const double R = spec.radius, rhoA = spec.rhoA();
    const auto r = fem::compute_modes(spec, fine(false), 2 * kPairs + 1);
    EXPECT_EQ(r.rigid_modes, 2);
    FirstOrder out{{r.omega[0] * r.omega[0]}, {kx / ring_mass(spec) + kr / (R * R * ring_mass(spec))}};
    const auto shift = relative_shift(r, base, 1, 2 * kPairs);
    out.fe.insert(out.fe.end(), shift.begin(), shift.end());
    for (int k = 2; k < 2 + kPairs; ++k) {
      const double k2 = k * k, w2 = std::pow(base.omega[2 * (k - 2)], 2);
      const double radial = kx * k2 / (kPi * R * rhoA * (k2 + 1)) / w2;
      const double tangential = kr * (k2 - 1) * (k2 - 1) / (R * R * kPi * R * rhoA * (k2 + 1)) / w2;
      out.predicted.push_back(std::min(radial, tangential));  // one of them is 0
      out.predicted.push_back(std::max(radial, tangential));
    }
    return out;
  };
  const double kx = 100.0, kr = 0.002 * ringtest::free_ring().EI() / ringtest::free_ring().radius;
  expect_first_order(run(kx, 0.0), run(kx / 2, 0.0), "spring kx");
  expect_first_order(run(0.0, kr), run(0.0, kr / 2), "spring kr");
}


// A finite point mass (a tenth of the ring's mass, no rotary inertia) at 0 deg on the free
// inextensible ring, and the inextensible ring clamped at 0 deg, against the receptance
// oracles of the continuous ring (tests/support/ring_receptance.hpp: Fourier modes, roots
// of the point receptance; converged to 1e-11 in its series length). Eight modes each;
// 1e-8 as Hoppe's limit above (the FE's 1/beta extrapolation ~1e-10, discretization at
// p = 8 ~1e-11; the clamp's jump in moment sits on a vertex, so the order is kept).
// Measured: point mass 6e-13 .. 5.9e-10, clamp 8e-13 .. 1.8e-9 (mode 8).
TEST(FemReceptance, PointMassAndClampMatchTheContinuousRing) {
  const auto free = ringtest::free_ring();
  const receptance::Ring oracle{free.radius, free.EI(), free.rhoA()};
  const int n = 8;
  {
    auto spec = free;
    const double m0 = 0.1 * ring_mass(spec);
    spec.masses.push_back({0.0, m0, 0.0});
    const auto exact = receptance::point_mass_omegas(oracle, m0, n);
    const auto r = fem::compute_modes(spec, fine(false), n);
    EXPECT_EQ(r.rigid_modes, 3);
    for (int i = 0; i < n; ++i) EXPECT_TRUE(IsClose(r.omega[i], exact[i], 1e-8)) << "point mass, mode " << i + 1;
  }
  {
    auto spec = ringtest::pinned_ring(0.0);
    spec.supports.clamp = 0.0;
    const auto exact = receptance::clamped_omegas(oracle, n);
    const auto r = fem::compute_modes(spec, fine(false), n);
    EXPECT_EQ(r.rigid_modes, 0);
    for (int i = 0; i < n; ++i) EXPECT_TRUE(IsClose(r.omega[i], exact[i], 1e-8)) << "clamp, mode " << i + 1;
  }
}

/// Largest relative difference of the first n frequencies of a and b.
double largest_difference(const ring::ModalResult& a, const ring::ModalResult& b, int n) {
  double d = 0.0;
  for (int i = 0; i < n; ++i) d = std::max(d, ringtest::rel(a.omega[i], b.omega[i]));
  return d;
}

// (3) Stiff springs converge to the constraint they approximate: the spring's compliance
// 1/k adds to the constrained ring's, so omega^2(k) = omega^2_limit - C/k + O(1/k^2): the
// difference falls by 10 per decade of k. kx = ky = k at 0 deg on the free ring -> the ring
// pinned there; kr = k at the pin -> the clamp. Same mesh (anchored at 0 deg) both sides,
// so the discretization error cancels except the clamp's: the spring holds the mean
// rotation {phi}, the clamp both cells' (their jump ~ discretization error, < 1e-11 here).
// Stiffness ratios 1e3..1e6 of the ring's EI/R^3 (EI/R for kr), six modes: largest
// differences 2.7e-2 .. 2.6e-5 (pin; the sixth mode's, C ~ 26 EI/R^3) and 2.0e-3 .. 2.0e-6
// (clamp), measured. The fitted slope over the three decades is -1 within 0.02 (the
// O(1/k^2) part is below 3 % of the first decade's), and the difference at 1e6 is below
// 1e-4 (the measured ones with room: a ceiling, not a fit).
TEST(FemSprings, StiffSpringsConvergeToPinAndClampAtRateOneOverK) {
  struct Case {
    const char* what;
    ring::RingSpec limit;
    double scale;
    bool rotation;
  };
  auto pinned = ringtest::pinned_ring(0.0);
  auto clamped = pinned;
  clamped.supports.clamp = 0.0;
  const auto free = ringtest::free_ring();
  const std::vector<Case> cases{{"kx = ky -> pin", pinned, free.EI() / std::pow(free.radius, 3), false},
                                {"kr -> clamp", clamped, free.EI() / free.radius, true}};
  const int n = 6;
  for (const auto& c : cases) {
    const auto limit = fem::compute_modes(c.limit, fine(true), n);
    std::vector<double> ks, d;
    for (double ratio : {1e3, 1e4, 1e5, 1e6}) {
      const double k = ratio * c.scale;
      ring::RingSpec spec = c.rotation ? pinned : free;
      spec.supports.springs.push_back(c.rotation ? ring::Spring{0.0, 0.0, 0.0, k} : ring::Spring{0.0, k, k, 0.0});
      const auto r = fem::compute_modes(spec, fine(true), n);
      EXPECT_EQ(r.rigid_modes, c.limit.rigid_modes()) << c.what;
      ks.push_back(k);
      d.push_back(largest_difference(r, limit, n));
    }
    // The slope from the first and the last decade (two points): a power of the stiffness, -1.
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h({ks.front(), ks.back()}, {d.front(), d.back()}), -1.0, 0.02))
        << c.what;
    EXPECT_LT(d.back(), 1e-4) << c.what;
  }
}

// (4) Rigid modes: the FE model has exactly spec.rigid_modes() zero modes (checked in
// modes.cpp: the counted ones below 1e-2 of the lowest elastic one) and no more: its
// lowest elastic frequency is a held motion or a bending mode, far from zero. The counts
// are the hand count of the motions the terms leave free.
TEST(FemRigidModes, CountsFollowTheTerms) {
  struct Case {
    const char* what;
    ring::RingSpec spec;
    int rigid;
  };
  std::vector<Case> cases;
  auto add = [&](const char* what, int rigid, auto edit) {
    auto s = ringtest::free_ring();
    edit(s);
    cases.push_back({what, s, rigid});
  };
  add("free", 3, [](ring::RingSpec&) {});
  add("radial foundation: the rotation", 1, [](ring::RingSpec& s) { s.foundation.radial = 100.0; });
  add("tangential foundation: none", 0, [](ring::RingSpec& s) { s.foundation.tangential = 100.0; });
  add("spring kx: y and the rotation", 2, [](ring::RingSpec& s) { s.supports.springs.push_back({0.0, 100.0, 0.0, 0.0}); });
  add("spring kx, ky: the rotation about it", 1,
      [](ring::RingSpec& s) { s.supports.springs.push_back({90.0, 100.0, 100.0, 0.0}); });
  add("spring kr: both translations", 2, [](ring::RingSpec& s) { s.supports.springs.push_back({90.0, 0.0, 0.0, 100.0}); });
  add("point mass: as free", 3, [](ring::RingSpec& s) { s.masses.push_back({45.0, 10.0, 1.0}); });
  add("pin", 1, [](ring::RingSpec& s) { s.supports.pin = 0.0; });
  add("two pins", 0, [](ring::RingSpec& s) {
    s.supports.pin = 0.0;
    s.supports.pins = {90.0};
  });
  add("clamp", 0, [](ring::RingSpec& s) {
    s.supports.pin = 0.0;
    s.supports.clamp = 0.0;
  });
  for (const auto& c : cases) {
    ASSERT_EQ(c.spec.rigid_modes(), c.rigid) << c.what;
    const auto r = fem::compute_modes(c.spec, fine(true), 3);
    EXPECT_EQ(r.rigid_modes, c.rigid) << c.what;
    // The lowest held motion here: the rotation on kr = 100 N m/rad, 8.6e-3 of the scale.
    EXPECT_GT(r.omega[0], 1e-3 * c.spec.bending_frequency_scale()) << c.what;
  }
}

// (5) The reference refinement converges with the terms: a clamped ring with a further
// pin, an elastic support, a point mass and a foundation. h-refinement at p = 3 converges
// at the fitted order 2(p - 1) = 4 (modes.hpp; the clamp's constraint and the point terms
// keep the form consistent), measured against the reference, which stops at its 1e-9
// change (error estimate <= that). Measured: the reference stops at p = 9 on the 8 cells
// (p-refinement, exponential), estimate 1e-12; p = 3 errors 6.6e-3, 4.2e-4, 2.6e-5 at
// 16, 32, 64 elements (fitted order 3.99).
TEST(FemReference, ConvergesWithAllTermsAtOrderTwoPMinusTwo) {
  auto spec = ringtest::pinned_ring(0.0);
  spec.supports.clamp = 0.0;
  spec.supports.pins = {135.0};
  spec.supports.springs.push_back({225.0, 500.0, 200.0, 1e4});
  spec.masses.push_back({90.0, 20.0, 50.0});
  spec.foundation.radial = 50.0;
  spec.foundation.tangential = 20.0;
  const int n = 6;
  FemOptions o;
  o.elements = 8;
  o.reference = true;
  const auto ref = fem::compute_modes(spec, o, n);
  EXPECT_LE(ref.error_estimate, 1e-9);
  EXPECT_EQ(ref.rigid_modes, 0);
  const std::vector<int> meshes{16, 32, 64};
  std::vector<double> errors;
  for (int elements : meshes) {
    FemOptions h;
    h.elements = elements;
    h.degree = 3;
    const auto r = fem::compute_modes(spec, h, n);
    errors.push_back(largest_difference(r, ref, n));
  }
  // The order from the coarsest and the finest mesh (two points). 0.3: the pre-asymptotic
  // spread of a three-point fit (the free ring's test, fem_convergence_test).
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{meshes.front(), meshes.back()}, {errors.front(), errors.back()}),
                                  4.0, 0.3));
}

// Point quantities off the FE vertices are refused naming their key; so are negative
// values and the terms on the polygon (its chords have no undeformed radial direction
// of the circle's).
TEST(FemTerms, RefusesWhatCanNeverWork) {
  auto expect_refused = [](const ring::RingSpec& s, const FemOptions& o, const std::string& key) {
    try {
      fem::check_modes(s, o);
      ADD_FAILURE() << "not refused: " << key;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  FemOptions o;  // 40 elements: vertices every 9 deg
  auto s = ringtest::free_ring();
  s.masses.push_back({10.0, 1.0, 0.0});
  expect_refused(s, o, "masses.at");
  s = ringtest::free_ring();
  s.supports.springs.push_back({9.0, -1.0, 0.0, 0.0});
  expect_refused(s, o, "supports.springs.kx");
  s = ringtest::pinned_ring(0.0);
  s.supports.pins = {100.0};
  expect_refused(s, o, "supports.pins");
  s = ringtest::pinned_ring(0.0);
  s.supports.clamp = 90.0;
  expect_refused(s, o, "supports.clamp");
  s = ringtest::free_ring();
  s.foundation.radial = 1.0;
  o.geometry = FemOptions::Geometry::polygon;
  expect_refused(s, o, "foundation");
}

}  // namespace
