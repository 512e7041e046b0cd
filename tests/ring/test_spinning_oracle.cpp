// The spinning-ring oracles of tests/support/spinning_ring.hpp against facts from outside them:
// the extensible ring at rest (Hoppe, Love, Soedel: ring::closed_form::free_ring_extensible),
// the inextensible spinning ring's closed form (the EA -> infinity limit, deviation ~ I/(A R^2)),
// the spinning chain loop that keeps its shape in space, the free body's translation at rest in
// space, Bryan's factor (k^2 - 1)/(k^2 + 1) and the sense of the pattern's turn (it lags the
// ring: the forward wave is the lower one in the turning frame), and the breathing mode from
// the conservation of angular momentum.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <vector>

#include "ring/closed_form.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/spinning_ring.hpp"

namespace {

using ringtest::IsClose;
using spintest::ExtensibleRing;

/// The paper's steel ring (R = 10 m, d = 0.12 m: I/(A R^2) = 9e-6) as the oracle's input,
/// with a foundation and a spin.
ExtensibleRing paper_ring(double speed, bool tension, double kr = 0.0, double kt = 0.0) {
  const auto s = ringtest::free_ring();
  ExtensibleRing e;
  e.ring.radius = s.radius;
  e.ring.EI = s.EI();
  e.ring.rhoA = s.rhoA();
  e.ring.kr = kr;
  e.ring.kt = kt;
  e.ring.speed = speed;
  e.ring.tension = tension;
  e.EA = s.EA();
  return e;
}

/// The paper ring's lowest elastic frequency at rest (k = 2, ~4.18 rad/s).
double omega2_at_rest() { return ring::closed_form::free_ring_inextensional(ringtest::free_ring(), 2); }

/// sigma_min / sigma_max of K_k - omega^2 M + i omega G, assembled from the header's matrices
/// (not from its quartic): zero at a root.
double pencil_residual(const ExtensibleRing& e, int k, double omega) {
  const auto& r = e.ring;
  const double R = r.radius, W = std::abs(r.speed), m = r.rhoA, kk = double(k) * k;
  const double N0 = r.tension ? m * W * W * R * R : 0.0;
  const double a = (e.EA + N0) / (R * R), b = r.EI / std::pow(R, 4), n = N0 / (R * R), c = m * W * W;
  const std::complex<double> I(0.0, 1.0);
  Eigen::Matrix2cd K, G;
  K << a + b * kk * kk + n * kk + r.kr - c, I * double(k) * (a + b * kk + n), -I * double(k) * (a + b * kk + n),
      (a + b) * kk + n + r.kt - c;
  G << 0.0, -2.0 * m * W, 2.0 * m * W, 0.0;
  const Eigen::Matrix2cd P = K - omega * omega * m * Eigen::Matrix2cd::Identity() + I * omega * G;
  const auto sv = P.jacobiSvd().singularValues();
  return sv(1) / sv(0);
}

// Oracle: at rest the oracle is the extensible ring of Hoppe (1871) and Love (sec. 294) as
// Soedel's 2 x 2 (ring::closed_form::free_ring_extensible, same kinematics, a separate code
// path: its own determinant), with and without a foundation, for both tension settings (no
// prestress at rest). Tolerance 1e-12: the same quantities in a different arrangement, a few
// ulps times the lower root's conditioning (measured <= 3e-16).
TEST(SpinningOracle, AtRestIsTheExtensibleRing) {
  for (const double kr : {0.0, 2.0e5})
    for (const bool tension : {true, false})
      for (int k = 0; k <= 8; ++k) {
        auto spec = ringtest::free_ring();
        spec.foundation.radial = kr;
        spec.foundation.tangential = 0.5 * kr;
        const auto ref = ring::closed_form::free_ring_extensible(spec, k);
        const auto w = spintest::extensible(paper_ring(0.0, tension, kr, 0.5 * kr), k);
        ASSERT_EQ(w.roots.size(), 4u) << "k = " << k;
        EXPECT_TRUE(IsClose(w.flexural.forward, ref[0], 1e-12, 1e-12)) << "k = " << k << ", kr = " << kr;
        EXPECT_TRUE(IsClose(w.flexural.backward, ref[0], 1e-12, 1e-12)) << "k = " << k << ", kr = " << kr;
        EXPECT_TRUE(IsClose(w.extensional.forward, ref[1], 1e-12)) << "k = " << k << ", kr = " << kr;
        EXPECT_TRUE(IsClose(w.extensional.backward, ref[1], 1e-12)) << "k = " << k << ", kr = " << kr;
      }
}

// Oracle: the roots solve the header's matrix pencil (K_k - omega^2 M + i omega G), assembled
// here from the matrices rather than from the quartic: checks the quartic's expansion and the
// companion solve with Newton. sigma_min/sigma_max at round-off (measured <= 3.3e-16); 1e-9
// leaves room for the flexural roots, sqrt(I/(A R^2)) below the pencil's scale.
TEST(SpinningOracle, RootsSolveTheMatrixPencil) {
  const double W = 0.3 * omega2_at_rest();
  for (const bool tension : {true, false})
    for (int k = 1; k <= 8; ++k) {
      const auto e = paper_ring(W, tension, 1.0e5, 3.0e4);
      const auto w = spintest::extensible(e, k);
      ASSERT_EQ(w.roots.size(), 4u) << "k = " << k;
      for (double x : w.roots) EXPECT_LT(pencil_residual(e, k, x), 1e-9) << "k = " << k << ", omega = " << x;
    }
}

// Oracle: the inextensible spinning ring's closed form (spintest::inextensible: Bryan 1890,
// Huang & Soedel 1987) is the EA -> infinity limit. At fixed EI, rho A, R the flexural pair's
// deviation must fall like e = I/(A R^2) = EI/(EA R^2) (order 1 in e: the first correction of
// the extensible ring is O(e), as at rest, ring::closed_form's test). Spin 0.3 of the lowest
// frequency at rest, both tensions, with and without a foundation. Order 1 within 0.05
// (measured: 1.000 to 4 digits); the deviation at e = 1e-8 below 1e-6 (measured 5e-9 to 6.5e-8).
TEST(SpinningOracle, StiffMembraneTendsToTheInextensibleRing) {
  const double W = 0.3 * omega2_at_rest();
  for (const bool tension : {true, false})
    for (const double kr : {0.0, 1.0e5})
      for (int k = 2; k <= 5; ++k) {
        std::vector<double> es, dev_f, dev_b;
        for (const double e : {1e-5, 1e-6, 1e-7, 1e-8}) {
          auto ring = paper_ring(W, tension, kr, 0.3 * kr);
          ring.EA = ring.ring.EI / (e * ring.ring.radius * ring.ring.radius);
          const auto w = spintest::extensible(ring, k);
          const auto ref = spintest::inextensible(ring.ring, k);
          es.push_back(e);
          dev_f.push_back(ringtest::rel(w.flexural.forward, ref.forward));
          dev_b.push_back(ringtest::rel(w.flexural.backward, ref.backward));
        }
        const std::string what =
            "k = " + std::to_string(k) + ", tension = " + (tension ? "spin" : "none") + ", kr = " + std::to_string(kr);
        EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(es, dev_f), 1.0, 0.05, 1e-6)) << "forward, " << what;
        EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(es, dev_b), 1.0, 0.05, 1e-6)) << "backward, " << what;
        if (k == 2 && kr == 0.0)
          std::printf("inextensible limit k = 2 (%s): deviation forward %.3e %.3e %.3e %.3e\n",
                      tension ? "spin" : "none", dev_f[0], dev_f[1], dev_f[2], dev_f[3]);
      }
}

// Oracle: a spinning chain loop (no bending, no foundation) under its own hoop tension
// rho A Omega^2 R^2 keeps any shape fixed in space: its transverse waves run at Omega R relative to
// the chain (sqrt(N0/rho A)), so the backward one stands still (Aitken's chain loop, 1878; the
// lariat). The backward flexural wave's fixed-frame frequency is 0 for every k and any EA.
// Tolerance 1e-10 k Omega: the root from the companion and Newton (measured <= 1.8e-16).
TEST(SpinningOracle, ChainLoopBackwardWaveStandsStillInSpace) {
  const double W = 2.0;
  for (const double EA : {1e6, 1e9, 1e11})
    for (int k = 1; k <= 8; ++k) {
      auto ring = paper_ring(W, true);
      ring.ring.EI = 0.0;
      ring.EA = EA;
      const auto w = spintest::extensible(ring, k);
      EXPECT_NEAR(w.flexural.backward_fixed, 0.0, 1e-10 * k * W) << "k = " << k << ", EA = " << EA;
      EXPECT_LT(w.flexural.forward, w.flexural.backward) << "k = " << k << ", EA = " << EA;
    }
}

// Oracle: the free ring's k = 1 holds the rigid translation, at rest in the fixed frame (a free
// body's translation does not turn with the turning frame): the backward flexural k = 1 wave is
// Omega in the turning frame, 0 in the fixed one, whatever the tension, EA, EI. 1e-10 Omega: a
// double root, found as the root of P' (measured exact to the last bit).
TEST(SpinningOracle, FreeRingTranslationRestsInSpace) {
  for (const bool tension : {true, false})
    for (const double W : {0.5, 2.0, 10.0}) {
      const auto w = spintest::extensible(paper_ring(W, tension), 1);
      EXPECT_NEAR(w.flexural.backward, W, 1e-10 * W) << "speed = " << W;
      // Its companion root is the same translation (a double root: static and uniformly moving),
      // filed as the forward wave at -Omega (spintest::inextensible's forward there).
      EXPECT_NEAR(w.flexural.forward, -W, 1e-10 * W) << "speed = " << W;
      EXPECT_NEAR(w.flexural.forward_fixed, 0.0, 1e-10 * W) << "speed = " << W;
      EXPECT_NEAR(w.flexural.backward_fixed, 0.0, 1e-10 * W) << "speed = " << W;
    }
}

// Oracle: Bryan (1890): the vibration pattern of a spinning thin ring turns in space, with the
// spin, at (k^2 - 1)/(k^2 + 1) of it, i.e. lags the ring. The pattern of the flexural pair turns
// at (forward_fixed - backward_fixed)/(2 k) in space, so the factor is 1 - (w_b - w_f)/(2 k
// Omega), and its lag means the forward wave is the LOWER one in the turning frame. Thin limit:
// the deviation from Bryan's factor falls like e = I/(A R^2) (order 1 within 0.05; measured
// 1.0000), as C e with C measured 17 at k = 2 falling to 4 at k = 6: below 20 e at the paper ring
// (e = 9e-6; the ceiling at e = 1e-7: 2e-6). Tension spin, spin 0.3 of the
// lowest frequency at rest, with a foundation (Bryan's factor of the inextensible ring holds for
// any foundation).
TEST(SpinningOracle, BryansFactorAndTheForwardWaveIsLower) {
  const double W = 0.3 * omega2_at_rest();
  for (int k = 2; k <= 6; ++k) {
    std::vector<double> es, dev;
    for (const double e : {1e-4, 1e-5, 1e-6, 1e-7}) {
      auto ring = paper_ring(W, true, 1.0e5, 3.0e4);
      ring.EA = ring.ring.EI / (e * ring.ring.radius * ring.ring.radius);
      const auto w = spintest::extensible(ring, k);
      EXPECT_LT(w.flexural.forward, w.flexural.backward) << "k = " << k;
      // The roots sum to 0 (no cubic term in the header's quartic): the extensional pair is
      // split the other way by as much. 1e-12 of the extensional frequency: round-off of four
      // roots of that size (measured <= 1.5e-16).
      EXPECT_NEAR(w.flexural.backward - w.flexural.forward, w.extensional.forward - w.extensional.backward,
                  1e-12 * w.extensional.backward)
          << "k = " << k;
      const double bryan = (w.flexural.forward_fixed - w.flexural.backward_fixed) / (2.0 * k * W);
      es.push_back(e);
      dev.push_back(std::abs(bryan - spintest::bryan_inextensible(k)));
    }
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(es, dev), 1.0, 0.05, 2e-6)) << "k = " << k;
    const auto w = spintest::extensible(paper_ring(W, true, 1.0e5, 3.0e4), k);
    const double bryan = (w.flexural.forward_fixed - w.flexural.backward_fixed) / (2.0 * k * W);
    EXPECT_NEAR(bryan, spintest::bryan_inextensible(k), 20.0 * 9e-6) << "k = " << k;
    std::printf("Bryan k = %d: paper ring %.8f vs %.8f; deviation at e = 1e-4..1e-7: %.2e %.2e %.2e %.2e\n", k, bryan,
                spintest::bryan_inextensible(k), dev[0], dev[1], dev[2], dev[3]);
  }
}

// Oracle: the breathing mode (k = 0) of a free spinning ring, in the fixed frame with polar
// coordinates: the angular momentum r^2 theta_t = R^2 Omega is kept, the radial equation
// rho A R (r_tt - r theta_t^2) = -N with N = (N0 + EA w/R)(1 + w/R) (the Green-Lagrange strain's
// force) and N0 = rho A Omega^2 R^2 give omega^2 = EA/(rho A R^2) + 4 Omega^2; the other k = 0
// root is the spin's change (0). A fast spin (Omega^2 = 0.1 EA/(rho A R^2)) so that the spin's
// share is far above round-off. 1e-13: a biquadratic's two roots (measured exact to the last bit).
TEST(SpinningOracle, BreathingModeKeepsAngularMomentum) {
  auto ring = paper_ring(0.0, true);
  const double m = ring.ring.rhoA, R = ring.ring.radius, b2 = ring.EA / (m * R * R);
  for (const double f : {0.0, 0.01, 0.1}) {
    ring.ring.speed = std::sqrt(f * b2);
    const auto w = spintest::extensible(ring, 0);
    const double W = ring.ring.speed;
    EXPECT_TRUE(IsClose(w.extensional.forward, std::sqrt(b2 + 4.0 * W * W), 1e-13)) << "f = " << f;
    EXPECT_TRUE(IsClose(w.extensional.backward, w.extensional.forward, 1e-15)) << "f = " << f;
    // sqrt of a round-off ~1e-16 b2 in omega^2: ~1e-8 sqrt(b2) (measured <= 9e-10 sqrt(b2))
    EXPECT_NEAR(w.flexural.forward, 0.0, 1e-7 * std::sqrt(b2)) << "f = " << f;
  }
}

// ---- The Timoshenko oracle (spintest::timoshenko) ----

/// A thick version of the paper's ring (d = 1 m, d/R = 0.1: shear and rotary inertia matter)
/// as a RingSpec (for ring::closed_form) and as the oracle's input.
ring::RingSpec thick_spec(double kr = 0.0, double kt = 0.0) {
  auto s = ringtest::free_ring();
  s.section.diameter = 1.0;
  s.theory = ring::Theory::timoshenko;
  s.foundation.radial = kr;
  s.foundation.tangential = kt;
  return s;
}

spintest::TimoshenkoRing thick_ring(double speed, bool tension, double kr = 0.0, double kt = 0.0) {
  const auto s = thick_spec(kr, kt);
  spintest::TimoshenkoRing t;
  t.ring.radius = s.radius;
  t.ring.EI = s.EI();
  t.ring.rhoA = s.rhoA();
  t.ring.kr = kr;
  t.ring.kt = kt;
  t.ring.speed = speed;
  t.ring.tension = tension;
  t.EA = s.EA();
  t.kGA = s.kGA();
  t.rhoI = s.rhoI();
  return t;
}

// Oracle: at rest the Timoshenko oracle is the free Timoshenko ring of Seidel & Erdelyi (1964)
// and Kirkhope (1976), ring::closed_form::free_ring_timoshenko (its own basis, Cauchy-Binet and
// bisection), with and without a foundation; and with EA = infinity its inextensible form
// (free_ring_timoshenko_inextensional). 1e-10: two algorithms on the same pencil (measured
// <= 3e-15).
TEST(SpinningOracle, TimoshenkoAtRestIsTheClosedForm) {
  for (const double kr : {0.0, 3.0e7})
    for (int k = 0; k <= 6; ++k) {
      const auto ref = ring::closed_form::free_ring_timoshenko(thick_spec(kr, 0.4 * kr), k);
      const auto w = spintest::timoshenko(thick_ring(0.0, true, kr, 0.4 * kr), k);
      ASSERT_EQ(w.branches.size(), 3u) << "k = " << k;
      for (int j = 0; j < 3; ++j) {
        EXPECT_TRUE(IsClose(w.branches[j].forward, ref[j], 1e-10, 1e-10)) << "k = " << k << ", branch " << j;
        EXPECT_TRUE(IsClose(w.branches[j].backward, ref[j], 1e-10, 1e-10)) << "k = " << k << ", branch " << j;
      }
      if (k < 2) continue;
      auto stiff = thick_ring(0.0, true, kr, 0.4 * kr);
      stiff.EA = std::numeric_limits<double>::infinity();
      const auto ri = ring::closed_form::free_ring_timoshenko_inextensional(thick_spec(kr, 0.4 * kr), k);
      const auto wi = spintest::timoshenko(stiff, k);
      ASSERT_EQ(wi.branches.size(), 2u) << "k = " << k;
      for (int j = 0; j < 2; ++j)
        EXPECT_TRUE(IsClose(wi.branches[j].backward, ri[j], 1e-10)) << "inextensible, k = " << k << ", branch " << j;
    }
}

// Oracle: shear-rigid (kGA = infinity) without rotary inertia, the Timoshenko oracle is the
// Euler-Bernoulli one (spintest::extensible: the quartic, a separate derivation and solve), and
// with EA = infinity too the inextensible closed form (spintest::inextensible), spinning, both
// tensions, with a foundation. 1e-10 (measured <= 9.2e-15).
TEST(SpinningOracle, TimoshenkoShearRigidIsTheEulerBernoulliOracle) {
  const double W = 0.3 * omega2_at_rest();
  for (const bool tension : {true, false})
    for (int k = 0; k <= 8; ++k) {
      const auto e = paper_ring(W, tension, 1.0e5, 3.0e4);
      spintest::TimoshenkoRing t;
      t.ring = e.ring;
      t.EA = e.EA;
      const auto ref = spintest::extensible(e, k);
      const auto w = spintest::timoshenko(t, k);
      ASSERT_EQ(w.branches.size(), 2u) << "k = " << k;
      EXPECT_TRUE(IsClose(w.branches[0].forward, ref.flexural.forward, 1e-10, 1e-10)) << "k = " << k;
      EXPECT_TRUE(IsClose(w.branches[0].backward, ref.flexural.backward, 1e-10, 1e-10)) << "k = " << k;
      EXPECT_TRUE(IsClose(w.branches[1].forward, ref.extensional.forward, 1e-10)) << "k = " << k;
      EXPECT_TRUE(IsClose(w.branches[1].backward, ref.extensional.backward, 1e-10)) << "k = " << k;
      if (k < 2) continue;
      t.EA = std::numeric_limits<double>::infinity();
      const auto ri = spintest::inextensible(t.ring, k);
      const auto wi = spintest::timoshenko(t, k);
      ASSERT_EQ(wi.branches.size(), 1u) << "k = " << k;
      EXPECT_TRUE(IsClose(wi.branches[0].forward, ri.forward, 1e-10)) << "inextensible, k = " << k;
      EXPECT_TRUE(IsClose(wi.branches[0].backward, ri.backward, 1e-10)) << "inextensible, k = " << k;
    }
}

// Oracle: the thick spinning ring's k = 1 translation rests in space (as for the thin ring):
// backward = Omega, forward = -Omega; the pattern lags (forward below backward) for k >= 2.
// 1e-8 Omega: a double root found through a central-difference f' (measured <= 5.6e-12).
TEST(SpinningOracle, TimoshenkoTranslationRestsAndForwardIsLower) {
  for (const bool tension : {true, false}) {
    const double W = 0.3 * ring::closed_form::free_ring_timoshenko(thick_spec(), 2)[0];
    const auto t = thick_ring(W, tension);
    const auto w1 = spintest::timoshenko(t, 1);
    ASSERT_EQ(w1.branches.size(), 3u);
    EXPECT_NEAR(w1.branches[0].backward, W, 1e-8 * W);
    EXPECT_NEAR(w1.branches[0].forward, -W, 1e-8 * W);
    for (int k = 2; k <= 6; ++k) {
      const auto w = spintest::timoshenko(t, k);
      ASSERT_EQ(w.branches.size(), 3u) << "k = " << k;
      EXPECT_LT(w.branches[0].forward, w.branches[0].backward) << "k = " << k;
    }
  }
}

}  // namespace
