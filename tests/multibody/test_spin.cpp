// The spinning ring's modes on the rigid-segment chain (multibody/spin.hpp), in the frame that
// turns with it. Oracles:
// - tests/support/spinning_ring.hpp: the inextensible ring's wave pairs in closed form (with and
//   without the spin's tension, on a Winkler foundation) and Bryan's factor (k^2 - 1)/(k^2 + 1);
//   the chain is inextensible and converges to that ring at order 2 in 1/n (multibody/README.md),
//   measured here with tests/support/convergence.hpp;
// - the chain's own modes at rest (the dense path, another eigensolver: modes.hpp) for a tiny
//   speed;
// - the translations' mass and Coriolis products against the Jacobians of the segments'
//   centroids and the point masses' hinges by central differences of Chain::midpoints and
//   Chain::hinge_positions, and the mass against Chain's own mass matrix (paper's eq. 12).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "multibody/attachments.hpp"
#include "multibody/backend.hpp"
#include "multibody/chain.hpp"
#include "multibody/checks.hpp"
#include "multibody/modes.hpp"
#include "multibody/spin.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/spinning_ring.hpp"
#include "tests/multibody/common.hpp"

namespace {

using Tension = ring::Rotation::Tension;

/// The paper's free ring (R = 10 m, steel, d = 0.12 m) on a foundation kr = kt = 1500 N/m^2:
/// the k = 2 wave's foundation stiffness R (4 kr + kt) / R = 7500 N/m^2 matches its bending
/// EI k^2 (k^2 - 1)^2 / R^4 = 7697 N/m^2, and the foundation holds the rigid motions. Lowest
/// frequency at rest: sqrt(kt / rho A) = 4.12 rad/s (the k = 0 and k = 1 waves).
ring::RingSpec spinning_ring(double speed, Tension tension) {
  ring::RingSpec s = ringtest::free_ring();
  s.foundation.radial = 1500.0;
  s.foundation.tangential = 1500.0;
  s.rotation.speed = speed;
  s.rotation.tension = tension;
  return s;
}

/// 0.3 of the lowest frequency at rest. rho speed^2 R^2 / E = 5e-6, irrelevant to the
/// inextensible chain (no hoop strain), and the Coriolis split 4 k speed / (k^2 + 1) is 1.2 ..
/// 2 rad/s: far above round-off.
double test_speed() { return 0.3 * std::sqrt(1500.0 / ringtest::free_ring().rhoA()); }


/// The mode of wave number k travelling in `direction` (+1 with the spin), or -1.
int find_wave(const ring::ModalResult& r, int k, int direction) {
  for (std::size_t i = 0; i < r.waves.size(); ++i)
    if (r.waves[i].number == k && r.waves[i].direction == direction) return static_cast<int>(i);
  return -1;
}

constexpr int kCount = 10;  // up to the k = 3 pair (k = 4 starts near 23 rad/s)

struct PairCase {
  Tension tension;
  int k;
  const char* name;
};

class SpinningChain : public ::testing::TestWithParam<PairCase> {};

TEST_P(SpinningChain, WavePairConvergesAtOrderTwoToTheInextensibleRing) {
  const PairCase c = GetParam();
  const ring::RingSpec spec = spinning_ring(test_speed(), c.tension);
  const spintest::WavePair exact = spintest::inextensible(spintest::from_spec(spec), c.k);
  // The asymptotic range: k = 3's backward wave is pre-asymptotic below n = 80 (two error
  // sources of opposite sign; measured orders 2.44, 2.13, 2.03 over n = 40 .. 320 without the
  // tension, 0.4, 1.82, 1.96, 1.99 over n = 20 .. 320 with it), k = 2 from n = 20.
  const std::vector<int> ns = c.k == 2 ? std::vector<int>{40, 80, 160} : std::vector<int>{80, 160, 320};
  std::vector<double> forward, backward, bryan;
  for (int n : ns) {
    const ring::ModalResult r = multibody::compute_modes(spec, mbtest::dense_chain(n), kCount);
    ASSERT_EQ(r.frame, "rotating");
    ASSERT_EQ(r.waves.size(), r.omega.size());
    const int f = find_wave(r, c.k, +1), b = find_wave(r, c.k, -1);
    ASSERT_GE(f, 0) << "no forward wave k = " << c.k << " at n = " << n;
    ASSERT_GE(b, 0) << "no backward wave k = " << c.k << " at n = " << n;
    // Forward travels with the spin and is the lower in the turning frame (the sign of G).
    EXPECT_LT(r.omega[f], r.omega[b]) << "n = " << n;
    forward.push_back(ringtest::rel(r.omega[f], exact.forward));
    backward.push_back(ringtest::rel(r.omega[b], exact.backward));
    const double factor = 1.0 - (r.omega[b] - r.omega[f]) / (2.0 * c.k * spec.rotation.speed);
    bryan.push_back(std::abs(factor - spintest::bryan_inextensible(c.k)));
    // The gyroscopic residual of a dense Hermitian solve of order 2N (N = n): round-off times
    // the pencil's conditioning, measured 6e-15 .. 3e-12 for n = 20 .. 320.
    ASSERT_TRUE(r.max_residual.has_value());
    EXPECT_LT(*r.max_residual, 1e-10) << "n = " << n;
    RecordProperty(std::string(c.name) + "_n" + std::to_string(n),
                   "forward " + mbtest::sci(forward.back()) + " backward " + mbtest::sci(backward.back()) + " bryan " +
                       mbtest::sci(bryan.back()));
  }
  // The chain's order 2 (multibody/README.md: the modes at rest and on a foundation), +- 0.1
  // in the asymptotic range above. Ceilings at the finest n: measured at most 8.1e-5 (k = 2,
  // n = 160) and 2.7e-5 (k = 3, n = 320); 2e-4 fails a wrong term (an O(1) error).
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, forward), 2.0, 0.1, 2e-4)) << c.name << " forward";
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, backward), 2.0, 0.1, 2e-4)) << c.name << " backward";
  // Bryan's factor: the split 4 k speed / (k^2 + 1) is the mass's alone (spinning_ring.hpp), so
  // it converges with the mass (the segments' rotary inertia, the centroids), at order 2;
  // measured 9.2e-5 (k = 2, n = 160), 4.1e-5 (k = 3, n = 320).
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, bryan), 2.0, 0.1, 2e-4)) << c.name << " bryan";
}

INSTANTIATE_TEST_SUITE_P(Waves, SpinningChain,
                         ::testing::Values(PairCase{Tension::spin, 2, "spin_k2"}, PairCase{Tension::spin, 3, "spin_k3"},
                                           PairCase{Tension::none, 2, "none_k2"}, PairCase{Tension::none, 3, "none_k3"}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SpinningChain, PointMassesAtEveryHingeSpinAsTheRingOfTwiceTheMass) {
  // A point mass rho A l at each of the n hinges doubles the chain's mass: it converges to the
  // inextensible ring of mass 2 rho A per length (its tension, softening and Coriolis terms all
  // scale with the mass: spinning_ring.hpp), through the point masses' centrifugal force,
  // Coriolis products and mass. Measured orders 2.00 .. 2.01 over n = 40, 80, 160 (k = 2 and 3,
  // both waves, both tensions); +- 0.1. Ceilings: measured at most 5.2e-4 at n = 160 (k = 3).
  const std::vector<int> ns{40, 80, 160};
  for (Tension t : {Tension::spin, Tension::none}) {
    const ring::RingSpec bare = spinning_ring(test_speed(), t);
    spintest::Ring twice = spintest::from_spec(bare);
    twice.rhoA *= 2.0;
    for (int k = 2; k <= 3; ++k) {
      const spintest::WavePair exact = spintest::inextensible(twice, k);
      std::vector<double> forward, backward;
      for (int n : ns) {
        ring::RingSpec spec = bare;
        for (int h = 0; h < n; ++h) spec.masses.push_back({360.0 * h / n, bare.rhoA() * spec.length() / n, 0.0});
        const ring::ModalResult r = multibody::compute_modes(spec, mbtest::dense_chain(n), kCount);
        const int f = find_wave(r, k, +1), b = find_wave(r, k, -1);
        ASSERT_GE(f, 0);
        ASSERT_GE(b, 0);
        forward.push_back(ringtest::rel(r.omega[f], exact.forward));
        backward.push_back(ringtest::rel(r.omega[b], exact.backward));
      }
      const std::string what = (t == Tension::spin ? "spin k = " : "none k = ") + std::to_string(k);
      EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, forward), 2.0, 0.1, 1e-3)) << what << " forward";
      EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, backward), 2.0, 0.1, 1e-3)) << what << " backward";
    }
  }
}

TEST(SpinningChain, TheTimoshenkoChainSpinsAsTheEulerChainAsTheSectionThins) {
  // The Timoshenko chain's sections (shear and the sections' rotary inertia) change a wave's
  // frequency by O((d / R)^2) (k^2 (d/R)^2 times a constant) at the same n; its spin goes
  // through the border of the shear angles (statics.cpp, loaded_pencil). A pinned ring on a
  // foundation scaled with EI (the same modes in units of EI / rho A R^4), spinning at 0.3 of
  // sqrt(kt / rho A): the relative difference of the ten lowest modes falls like (d/R)^2,
  // measured 1.37e-5 .. 6.2e-4 at d = 0.12 m and a factor 4.00 lower at 0.06; order 2 +- 0.1.
  const std::vector<double> depths{0.12, 0.06};
  std::vector<std::vector<double>> differences(kCount);
  for (double d : depths) {
    ring::RingSpec spec = ringtest::pinned_ring(180.0);
    spec.section.diameter = d;
    spec.foundation.radial = spec.foundation.tangential = 1500.0 * std::pow(d / 0.12, 4);
    spec.rotation.speed = 0.3 * std::sqrt(spec.foundation.tangential / spec.rhoA());
    const ring::ModalResult euler = multibody::compute_modes(spec, mbtest::dense_chain(80), kCount);
    spec.theory = ring::Theory::timoshenko;
    const ring::ModalResult timoshenko = multibody::compute_modes(spec, mbtest::dense_chain(80), kCount);
    for (int i = 0; i < kCount; ++i) {
      EXPECT_EQ(timoshenko.waves[i].number, euler.waves[i].number) << i;
      EXPECT_EQ(timoshenko.waves[i].direction, euler.waves[i].direction) << i;
      differences[i].push_back(ringtest::rel(timoshenko.omega[i], euler.omega[i]));
    }
  }
  for (int i = 0; i < kCount; ++i)
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(depths, differences[i]), 2.0, 0.1, 1e-3)) << "mode " << i;
}

TEST(SpinningChain, EveryModeIsATravellingWaveAndPairsAreForwardThenBackward) {
  const ring::RingSpec spec = spinning_ring(test_speed(), Tension::spin);
  const ring::ModalResult r = multibody::compute_modes(spec, mbtest::dense_chain(40), kCount);
  EXPECT_EQ(r.rigid_modes, 0);
  EXPECT_EQ(r.residual_norm, ring::kResidual2Norm);
  ASSERT_EQ(r.shapes.size(), r.omega.size());
  for (std::size_t i = 1; i < r.omega.size(); ++i) EXPECT_LE(r.omega[i - 1], r.omega[i]);
  // k = 1 .. 4 come as one forward and one backward wave each, the forward one lower, as the
  // closed form's pairs.
  for (int k = 1; k <= 4; ++k) {
    const int f = find_wave(r, k, +1), b = find_wave(r, k, -1);
    ASSERT_GE(f, 0) << k;
    ASSERT_GE(b, 0) << k;
    EXPECT_LT(f, b) << k;
  }
  // The k = 0 wave (the ring turning on its tangential foundation; the closed form's k = 0,
  // g = 0) is standing. Its radial shape is the polygon's own ripple (the continuum's is 0), so
  // only the direction is asserted; its frequency within the chain's n = 40 error (2e-3
  // measured, order 2; 5e-3 allowed).
  const double w0 = spintest::inextensible(spintest::from_spec(spec), 0).forward;
  int nearest = 0;
  for (std::size_t i = 1; i < r.omega.size(); ++i)
    if (std::abs(r.omega[i] - w0) < std::abs(r.omega[nearest] - w0)) nearest = static_cast<int>(i);
  EXPECT_EQ(r.waves[nearest].direction, 0);
  EXPECT_TRUE(ringtest::IsClose(r.omega[nearest], w0, 5e-3));
}

TEST(SpinningChain, BryansFactorDoesNotDependOnTheTension) {
  // The closed form's split 2 g / m holds for every stiffness (spinning_ring.hpp): the two
  // tensions change K only, so the chain's splits agree to the eigensolves' round-off
  // (measured: every digit printed); 1e-9 of the split.
  const ring::ModalResult a = multibody::compute_modes(spinning_ring(test_speed(), Tension::spin), mbtest::dense_chain(40), kCount);
  const ring::ModalResult b = multibody::compute_modes(spinning_ring(test_speed(), Tension::none), mbtest::dense_chain(40), kCount);
  for (int k = 2; k <= 3; ++k) {
    const double split_a = a.omega[find_wave(a, k, -1)] - a.omega[find_wave(a, k, +1)];
    const double split_b = b.omega[find_wave(b, k, -1)] - b.omega[find_wave(b, k, +1)];
    EXPECT_TRUE(ringtest::IsClose(split_b, split_a, 1e-9)) << k;
  }
}

TEST(SpinningChain, TurningTheOtherWayGivesTheSameWavesWithTheSpin) {
  // Mirror symmetry: the frequencies do not depend on the spin's sign and the forward wave
  // (direction +1: with the spin, whichever way it turns) stays the lower one.
  const ring::RingSpec ccw = spinning_ring(test_speed(), Tension::spin), cw = spinning_ring(-test_speed(), Tension::spin);
  const ring::ModalResult a = multibody::compute_modes(ccw, mbtest::dense_chain(40), kCount);
  const ring::ModalResult b = multibody::compute_modes(cw, mbtest::dense_chain(40), kCount);
  for (int k = 2; k <= 3; ++k)
    for (int d : {+1, -1}) {
      const int i = find_wave(a, k, d), j = find_wave(b, k, d);
      ASSERT_GE(i, 0);
      ASSERT_GE(j, 0);
      // Round-off of two dense solves (the mirror's matrices differ in rounding): 1e-10.
      EXPECT_TRUE(ringtest::IsClose(b.omega[j], a.omega[i], 1e-10)) << k << " " << d;
    }
}

TEST(SpinningChain, ATinySpeedGivesTheModesAtRest) {
  // speed 1e-8 rad/s: the pairs split by 4 k speed / (k^2 + 1) <= 2e-8 rad/s (and the tension
  // and softening are O(speed^2)): 4e-9 relative at omega >= 4 rad/s; the rest the round-off of
  // two eigensolvers on the chain's pencil (~1e-12). Bound: 1e-8.
  ring::RingSpec rest = spinning_ring(0.0, Tension::spin);
  const ring::ModalResult at_rest = multibody::compute_modes(rest, mbtest::dense_chain(40), kCount);
  EXPECT_TRUE(at_rest.waves.empty());
  EXPECT_EQ(at_rest.frame, "");
  for (Tension t : {Tension::spin, Tension::none}) {
    const ring::ModalResult slow = multibody::compute_modes(spinning_ring(1e-8, t), mbtest::dense_chain(40), kCount);
    ASSERT_EQ(slow.omega.size(), at_rest.omega.size());
    for (std::size_t i = 0; i < slow.omega.size(); ++i)
      EXPECT_TRUE(ringtest::IsClose(slow.omega[i], at_rest.omega[i], 1e-8)) << "mode " << i;
  }
}

TEST(SpinningChain, TranslationProductsAreTheCentroidsJacobians) {
  // A free chain (x_0, y_0 unknowns) with two point masses, at a deformed q: the products
  // against J^T J and J^T S J from central differences of the centroids and the hinges
  // (truncation O(h^2) ~ 1e-12 relative at h = 1e-6, round-off eps / h ~ 1e-10).
  ring::RingSpec spec = spinning_ring(1.0, Tension::spin);
  spec.masses.push_back({90.0, 40.0, 0.0});
  spec.masses.push_back({0.0, 25.0, 0.0});
  const int n = 12;
  const multibody::Chain chain(spec, mbtest::dense_chain(n));
  const multibody::detail::Attachments terms(chain, spec);
  Eigen::VectorXd q = chain.q0();
  for (int j = 0; j < n; ++j) q[j] += 0.05 * std::sin(3.0 * j + 1.0);
  q[n] = 0.01;
  q[n + 1] = -0.02;
  const multibody::detail::TranslationProducts tp = multibody::detail::translation_products(chain, &terms, q);
  const int dofs = chain.dofs();
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(dofs, dofs), cor = mass;
  Eigen::Matrix2d S;
  S << 0.0, -1.0, 1.0, 0.0;
  const double h = 1e-6;
  auto jacobian = [&](auto position) {
    Eigen::MatrixXd J(2, dofs);
    for (int i = 0; i < dofs; ++i) {
      Eigen::VectorXd a = q, b = q;
      a[i] += h;
      b[i] -= h;
      J.col(i) = (position(a) - position(b)) / (2.0 * h);
    }
    return J;
  };
  for (int s = 0; s < n; ++s) {
    const Eigen::MatrixXd J = jacobian([&](const Eigen::VectorXd& x) { return Eigen::Vector2d(chain.midpoints(x).col(s)); });
    mass += chain.m() * J.transpose() * J;
    cor += chain.m() * J.transpose() * S * J;
  }
  for (const ring::PointMass& pm : spec.masses) {
    const int k = chain.hinge_at(pm.angle);
    const Eigen::MatrixXd J = jacobian([&](const Eigen::VectorXd& x) { return Eigen::Vector2d(chain.hinge_positions(x).col(k)); });
    mass += pm.mass * J.transpose() * J;
    cor += pm.mass * J.transpose() * S * J;
  }
  EXPECT_LT((tp.mass - mass).norm(), 1e-8 * mass.norm());
  EXPECT_LT((tp.coriolis - cor).norm(), 1e-8 * mass.norm());
  EXPECT_LT((tp.coriolis + tp.coriolis.transpose()).norm(), 1e-14 * mass.norm());
  // The chain's own mass (eq. 12 with the point masses) less the segments' rotary inertias:
  // the same sums in another code, to round-off.
  Eigen::MatrixXd chain_mass = chain.mass_matrix(q);
  terms.add_mass(q, chain_mass);
  chain_mass.diagonal().head(n).array() -= chain.Jr();
  EXPECT_LT((tp.mass - chain_mass).norm(), 1e-13 * chain_mass.norm());
}

TEST(SpinningChain, PastTheDivergenceSpeedTheStiffnessIsNotPositive) {
  // Without the tension, the closed form's k = 0 wave has K = pi R (kt - rho A speed^2): it
  // diverges at speed = sqrt(kt / rho A) (4.12 rad/s); the chain's k = 0 frequency at n = 40 is
  // within 2e-3 of it, so 5 % beyond is past the chain's divergence too: a numerical failure
  // (exit 3), not a frequency. With the tension the k = 0 wave keeps kt (K = pi R kt) and the
  // k = 1 wave diverges at sqrt((kr + kt) / (2 rho A)), the same speed here.
  const double divergence = std::sqrt(1500.0 / ringtest::free_ring().rhoA());
  EXPECT_THROW(multibody::compute_modes(spinning_ring(1.05 * divergence, Tension::none), mbtest::dense_chain(40), kCount),
               ring::NumericalError);
  EXPECT_NO_THROW(multibody::compute_modes(spinning_ring(0.95 * divergence, Tension::none), mbtest::dense_chain(40), kCount));
}

TEST(SpinningChain, AutoStaysDenseAndWhatCannotWorkIsRefusedByKey) {
  const ring::RingSpec spec = spinning_ring(test_speed(), Tension::spin);
  // "auto" would take the O(n) modes from n = 257 at rest; the spinning ring's are dense.
  EXPECT_EQ(multibody::backend(mbtest::chain_options(400, ring::MultibodyOptions::Method::automatic), spec, kCount),
            multibody::Backend::dense);
  auto refused = [&](const ring::RingSpec& s, const ring::MultibodyOptions& o, const std::string& key) {
    try {
      multibody::compute_modes(s, o, kCount);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).find(key) != std::string::npos ? ::testing::AssertionSuccess()
                                                                   : ::testing::AssertionFailure() << e.what();
    }
    return ::testing::AssertionFailure() << "not refused";
  };
  EXPECT_TRUE(refused(spec, mbtest::chain_options(40, ring::MultibodyOptions::Method::sparse), "multibody.method"));
  EXPECT_TRUE(refused(spec, mbtest::chain_options(40, ring::MultibodyOptions::Method::sparse), "rotation.speed"));
  EXPECT_TRUE(refused(spec, mbtest::dense_chain(3000), "multibody.n"));
  ring::MultibodyOptions paper = mbtest::dense_chain(40);
  paper.dependent = ring::MultibodyOptions::Dependent::paper;
  EXPECT_TRUE(refused(spec, paper, "multibody.dependent"));
  ring::RingSpec loose = spec;  // no foundation: three rigid motions
  loose.foundation = {};
  EXPECT_TRUE(refused(loose, mbtest::dense_chain(40), "rotation.speed"));
  ring::RingSpec shear = spec;  // free: the Timoshenko chain's statics need a pin (sections.hpp)
  shear.theory = ring::Theory::timoshenko;
  EXPECT_TRUE(refused(shear, mbtest::dense_chain(40), "supports.pin"));
  ring::RingSpec arch = ringtest::pinned_ring(0.0);
  arch.arc = ring::Arc{0.0, 180.0};
  arch.rotation.speed = 1.0;
  EXPECT_TRUE(refused(arch, mbtest::dense_chain(40), "ring.arc"));
  ring::RingSpec nan = spec;
  nan.rotation.speed = std::nan("");
  EXPECT_TRUE(refused(nan, mbtest::dense_chain(40), "rotation.speed"));
  // The analyses without a turning frame refuse the spin (the chain's loads would hold its
  // centrifugal force: loading.hpp).
  EXPECT_THROW(multibody::solve_modes(spec, mbtest::dense_chain(40), kCount), std::invalid_argument);
  ring::StaticOptions statics;
  EXPECT_THROW(multibody::check_static(spec, mbtest::dense_chain(40), statics), std::invalid_argument);
  ring::ResponseOptions response;
  EXPECT_THROW(multibody::check_response(spec, mbtest::dense_chain(40), response), std::invalid_argument);
}

}  // namespace
