// Natural frequencies of the rigid-segment chain, at the accuracy the chain was specified with. Oracles:
// the paper's Table 1 (compare/data/table1.csv, mb_corrected), the closed form of the
// free inextensional ring (ring/closed_form), the independent Fourier and receptance
// formulations of ring_oracle.hpp (no multibody/ code), Cauchy interlacing, and the
// residuals of the eigenproblem itself.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "multibody/modes.hpp"
#include "ring/closed_form.hpp"
#include "ring/errors.hpp"
#include "ring/paper_table.hpp"
#include "ring/sampling.hpp"
#include "tests/multibody/ring_oracle.hpp"
#include "tests/support/close.hpp"
#include "tests/support/convergence.hpp"
#include "support/paper.hpp"

namespace {

using Dep = ring::MultibodyOptions::Dependent;

// The paper's ring (Table 1, support/paper.hpp) pinned at 180 deg, free, or pinned with
// the roller at 0 deg (diametrically opposite, as in the paper's section 5).
using ringtest::free_ring;
using ringtest::pin_roller_ring;
using ringtest::pinned_ring;
using Method = ring::MultibodyOptions::Method;
ring::MultibodyOptions opts(int n, bool rot = true, Dep d = Dep::robust, Method m = Method::automatic) {
  ring::MultibodyOptions o;
  o.n = n;
  o.rotary_inertia = rot;
  o.dependent = d;
  o.method = m;
  return o;
}
oracle::ChainParams params(const ring::RingSpec& s, int n, bool rot) {
  return {n, s.radius, s.EI(), s.rhoA(), rot};
}

TEST(MultibodyModes, PaperTableOneN40) {
  const auto rows = ring::read_paper_table(RINGVIB_SOURCE_DIR "/compare/data/table1.csv");
  ASSERT_EQ(rows.size(), 23u);
  const auto r = multibody::compute_modes(pinned_ring(), opts(40), 23);
  EXPECT_EQ(r.rigid_modes, 1);  // rotation about the pin (docs/paper.md)
  ASSERT_EQ(r.omega.size(), 23u);
  ASSERT_EQ(r.shapes.size(), 23u);
  for (int i = 0; i < 23; ++i) {
    const double ref = rows[i].mb_corrected.value();
    // Modes 1-9 within 0.8 %, all 23 within 2.5 % of the paper's multibody column: the
    // chain's specified agreement with the paper (docs/paper.md, item 3 measured 0.8 % and 2.1 %).
    const double tol = i < 9 ? 0.008 : 0.025;
    EXPECT_TRUE(ringtest::IsClose(r.omega[i], ref, tol)) << "mode " << i + 1;
    if (i > 0) {
      EXPECT_LE(r.omega[i - 1], r.omega[i]);
    }
  }
  EXPECT_EQ(r.solver, "multibody");
  EXPECT_EQ(std::get<long long>(r.model.at("n")), 40);
  EXPECT_EQ(std::get<std::string>(r.model.at("dependent")), "robust");
  EXPECT_EQ(std::get<bool>(r.model.at("rotary_inertia")), true);
  EXPECT_EQ(r.unknowns, 38);
  EXPECT_GT(r.seconds, 0.0);
}

TEST(MultibodyModes, PaperAndRobustDependentCoordinatesAgreeAtN40) {
  for (const auto& spec : {pinned_ring(), free_ring(), pin_roller_ring()}) {
    for (bool rot : {true, false}) {
      const int count = 23;
      SCOPED_TRACE(std::string(spec.supports.free() ? "free" : spec.supports.roller ? "roller" : "pin") + (rot ? " rotary" : ""));
      const auto a = multibody::compute_modes(spec, opts(40, rot, Dep::robust), count);
      const auto b = multibody::compute_modes(spec, opts(40, rot, Dep::paper), count);
      EXPECT_EQ(a.rigid_modes, b.rigid_modes);
      for (int i = 0; i < count; ++i)  // 1e-10 relative at n = 40: both dependent-coordinate choices solve one pencil, so they agree to the eigensolver's accuracy
        EXPECT_TRUE(ringtest::IsClose(b.omega[i], a.omega[i], 1e-10)) << "mode " << i + 1;
      // Same shapes (up to sign; double modes of the free ring may mix, so skip them).
      if (!spec.supports.free()) {
        for (int i = 0; i < count; ++i) EXPECT_GT(ring::mac(a.shapes[i], b.shapes[i]), 1 - 1e-8);
      }
    }
  }
}

TEST(MultibodyModes, FreeRingConvergesToClosedFormWithOrderTwo) {
  const ring::RingSpec s = free_ring();
  const std::vector<int> ns{40, 80, 160, 320};
  for (bool rot : {true, false}) {
    std::vector<std::vector<double>> err(6);  // wave numbers k = 2..7
    for (int n : ns) {
      const auto r = multibody::compute_modes(s, opts(n, rot), 12);
      EXPECT_EQ(r.rigid_modes, 3);  // two translations and a rotation
      for (int k = 2; k <= 7; ++k) {
        const double a = r.omega[2 * (k - 2)], b = r.omega[2 * (k - 2) + 1];
        // double pair (cos and sin k theta): equal to rounding
        EXPECT_TRUE(ringtest::IsClose(a, b, 1e-12)) << "n " << n << " k " << k;
        err[k - 2].push_back(ringtest::rel(a, ring::closed_form::free_ring_inextensional(s, k)));
      }
    }
    for (int k = 2; k <= 7; ++k) {
      const auto samples = ringtest::in_n(ns, err[k - 2]);  // fitted over n = 40..320, the order in 1/n
      const double order = ringtest::fit_order(samples).order;
      std::cout << "free ring k=" << k << (rot ? " (rotary inertia)" : " (no rotary inertia)")
                << ": errors " << err[k - 2][0] << " .. " << err[k - 2][3] << ", fitted order "
                << order << "\n";
      // 2 +- 0.1: the band within which the (k/n)^4 term at n = 40 leaves the fit while the
      // pair is asymptotic. Asserted for the first four double pairs (k <= 5); from k = 6
      // the n = 40 point is pre-asymptotic (k delta ~ 1, the (k/n)^4 term visible: fitted
      // 2.11 and 2.18 for k = 6, 7 with rotary inertia), printed above for the record.
      if (k <= 5) {
        EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.1)) << "k = " << k;
      }
      EXPECT_LT(err[k - 2][3], 1e-3);  // ceiling at n = 320: (k/n)^2-sized
    }
  }
}

TEST(MultibodyModes, ResidualsAndMassOrthonormality) {
  // robust at n = 40 and 160; paper at n = 40 only: its residuals grow with cond(J_2)
  // (2e-10 .. 8e-10 at n = 160, recorded by the stress test MultibodyStress).
  for (const auto& spec : {pinned_ring(), free_ring(), pin_roller_ring()}) {
    for (Dep d : {Dep::robust, Dep::paper}) {
      for (int n : {40, 160}) {
        if (d == Dep::paper && n > 40) continue;
        SCOPED_TRACE("n = " + std::to_string(n) + (d == Dep::paper ? " paper" : " robust") + (spec.supports.free() ? " free" : spec.supports.roller ? " roller" : " pin"));
        const auto sol = multibody::solve_modes(spec, opts(n, n == 40, d), 23);
        // relative eigen-residual and M0-orthonormality below 1e-10: the eigensolver's specified accuracy
        EXPECT_LT(sol.result.max_residual.value(), 1e-10);
        const Eigen::MatrixXd G = sol.x.transpose() * sol.model.M0 * sol.x;
        EXPECT_LT((G - Eigen::MatrixXd::Identity(23, 23)).cwiseAbs().maxCoeff(), 1e-10);
        // the residual recomputed here, independently of the solver's own bookkeeping
        for (int k = 0; k < 23; ++k) {
          const double w2 = sol.result.omega[k] * sol.result.omega[k];
          const Eigen::VectorXd Kx = sol.model.K0 * sol.x.col(k), Mx = sol.model.M0 * sol.x.col(k);
          EXPECT_LT((Kx - w2 * Mx).norm() / (Kx.norm() + w2 * Mx.norm()), 1e-10);
        }
        // the chain-coordinate shapes satisfy the linearized constraints J dq = 0
        const multibody::Chain c(spec, opts(n));
        const Eigen::MatrixXd Jdq = c.constraint_jacobian(c.q0()) * sol.dq;
        EXPECT_LT(Jdq.cwiseAbs().maxCoeff(), 1e-10 * c.l() * sol.dq.cwiseAbs().maxCoeff());
        // hinge displacements = hinge Jacobians (Chain, finite-difference tested) times dq
        for (int k = 0; k < 3; ++k) {
          const Eigen::Matrix2Xd hinges = c.rest_displacements(sol.dq.col(k));
          for (int h : {1, n / 3, n - 1}) {
            const Eigen::Vector2d u = c.hinge_jacobian(c.q0(), h) * sol.dq.col(k);
            EXPECT_NEAR(hinges(0, h), u.x(), 1e-12 * hinges.row(0).cwiseAbs().maxCoeff());
            EXPECT_NEAR(hinges(1, h), u.y(), 1e-12 * hinges.row(1).cwiseAbs().maxCoeff());
          }
        }
      }
    }
  }
}

TEST(MultibodyModes, PinPlusRollerHasNoRigidModeAndInterlaces) {
  for (bool rot : {true, false}) {
    const auto pin = multibody::compute_modes(pinned_ring(), opts(40, rot), 30);
    const auto rol = multibody::compute_modes(pin_roller_ring(), opts(40, rot), 29);
    EXPECT_EQ(rol.rigid_modes, 0);
    EXPECT_EQ(pin.rigid_modes, 1);
    // Cauchy interlacing for one added constraint (Rayleigh's theorem): with the pinned
    // spectrum p_0 = 0 (rigid) <= p_1 <= ..., the roller's q_i obey p_i <= q_i <= p_{i+1}.
    // Slack 1e-12 relative for rounding of equal values.
    std::vector<double> p{0.0};
    p.insert(p.end(), pin.omega.begin(), pin.omega.end());
    for (std::size_t i = 0; i < rol.omega.size(); ++i) {
      EXPECT_GE(rol.omega[i], p[i] * (1 - 1e-12)) << "mode " << i + 1;
      EXPECT_LE(rol.omega[i], p[i + 1] * (1 + 1e-12)) << "mode " << i + 1;
    }
    // The roller hinge (station 0 deg) does not move across the pin's diameter (y), and
    // the pin (station 180 deg) does not move at all; shapes are scaled to max 1.
    for (const auto& sh : rol.shapes) {
      EXPECT_LT(std::abs(sh.tangential[0]), 1e-10);
      EXPECT_LT(std::abs(sh.radial[180]) + std::abs(sh.tangential[180]), 1e-10);
    }
  }
}

TEST(MultibodyModes, FreeRingShapesHaveTheirWaveNumber) {
  // Oracle: a free ring's mode k has radial displacement in span{cos k a, sin k a}.
  const auto r = multibody::compute_modes(free_ring(), opts(40), 8);
  for (int i = 0; i < 8; ++i) {
    const int k = 2 + i / 2;
    double c = 0, s = 0, total = 0;
    for (int st = 0; st < ring::kStations; ++st) {
      const double a = ring::station_angle(st) * M_PI / 180, w = r.shapes[i].radial[st];
      c += w * std::cos(k * a);
      s += w * std::sin(k * a);
      total += w * w;
    }
    const double captured = 2.0 * (c * c + s * s) / ring::kStations / total;
    EXPECT_GT(captured, 0.99) << "mode " << i + 1;  // n = 40 polygon: ~1e-3 leaks to aliases
  }
}

// Large n: the chain's specified solver accuracy (1e-8 relative for every requested
// frequency, with and without rotary inertia) against formulations that share no code
// with multibody/ and have no ill-conditioning (ring_oracle.hpp).
void check_against_oracles(int n, bool rot, Method method = Method::automatic) {
  const auto pin = multibody::compute_modes(pinned_ring(), opts(n, rot, Dep::robust, method), 23);
  const auto ref = oracle::pinned_chain_omegas(params(pinned_ring(), n, rot), 23);
  EXPECT_EQ(pin.rigid_modes, 1);
  double worst = 0;
  for (int i = 0; i < 23; ++i) worst = std::max(worst, ringtest::rel(pin.omega[i], ref[i]));
  const auto fr = multibody::compute_modes(free_ring(), opts(n, rot, Dep::robust, method), 23);
  const auto fref = oracle::free_chain_omegas(params(free_ring(), n, rot));
  EXPECT_EQ(fr.rigid_modes, 3);
  for (int i = 0; i < 23; ++i) worst = std::max(worst, ringtest::rel(fr.omega[i], fref[i]));
  std::cout << "n = " << n << (rot ? " rotary" : " no rotary") << " method "
            << std::get<std::string>(pin.model.at("method"))
            << ": worst relative difference to the independent oracles " << worst << "\n";
  EXPECT_LT(worst, 1e-8);  // the specified solver accuracy
}

TEST(MultibodyModes, AccurateAgainstIndependentFormulationN40) {
  check_against_oracles(40, true);
  check_against_oracles(40, false);
}
TEST(MultibodyModes, AccurateAgainstIndependentFormulationN640) {
  check_against_oracles(640, true);
  check_against_oracles(640, false);
}

TEST(MultibodyModes, SparsePathMatchesDenseAtN160) {
  for (const auto& spec : {pinned_ring(), free_ring(), pin_roller_ring()}) {
    for (bool rot : {true, false}) {
      SCOPED_TRACE(std::string(spec.supports.free() ? "free" : spec.supports.roller ? "roller" : "pin") + (rot ? " rotary" : ""));
      const auto d = multibody::compute_modes(spec, opts(160, rot, Dep::robust, Method::dense), 23);
      const auto sol = multibody::solve_modes(spec, opts(160, rot, Dep::robust, Method::sparse), 23);
      const auto& s = sol.result;
      EXPECT_EQ(std::get<std::string>(s.model.at("method")), "sparse");
      EXPECT_EQ(std::get<std::string>(d.model.at("method")), "dense");
      EXPECT_EQ(s.rigid_modes, d.rigid_modes);
      // independent algorithms (dense Cholesky vs Riccati sweeps + own Lanczos): 1e-10,
      // two orders above the 1e-12 both reach against the oracles at this n
      for (int i = 0; i < 23; ++i) EXPECT_TRUE(ringtest::IsClose(s.omega[i], d.omega[i], 1e-10)) << "mode " << i + 1;
      // Normwise backward error of the sparse path at n = 160: measured 1e-14 .. 1.1e-12
      // (its Lanczos stops at a 1e-8 relative Ritz residual); max_residual is floored by
      // the rounding of K0 x (up to 1e-9 here, modes.hpp) and not a test of the solver.
      EXPECT_LT(sol.backward_error, 1e-10);
      if (!spec.supports.free()) {
        for (int i = 0; i < 23; ++i) EXPECT_GT(ring::mac(s.shapes[i], d.shapes[i]), 1 - 1e-8);
      }
    }
  }
}

TEST(MultibodyModes, SparsePathAccurateAgainstIndependentFormulationN2000) {
  check_against_oracles(2000, true, Method::sparse);
  check_against_oracles(2000, false, Method::sparse);
}

TEST(MultibodyModes, OraclesConvergeToTheContinuum) {
  // Sanity of the test's own oracle: the Fourier chain tends to Love's free ring.
  const ring::RingSpec s = free_ring();
  for (int k = 2; k <= 6; ++k) {
    const auto w = oracle::free_chain_omegas(params(s, 20000, true));
    EXPECT_TRUE(ringtest::IsClose(w[2 * (k - 2)], ring::closed_form::free_ring_inextensional(s, k), 1e-6));
  }
}

TEST(MultibodyModes, RejectsWhatCanNeverWork) {
  EXPECT_THROW(multibody::compute_modes(pinned_ring(), opts(40), 0), std::invalid_argument);
  EXPECT_THROW(multibody::compute_modes(pinned_ring(), opts(40), 38), std::invalid_argument);  // 37 elastic
  EXPECT_NO_THROW(multibody::compute_modes(pinned_ring(), opts(40), 37));
  EXPECT_THROW(multibody::compute_modes(pinned_ring(), opts(3), 1), std::invalid_argument);
  // the paper's dependent angles exist on the dense path only
  EXPECT_THROW(multibody::compute_modes(pinned_ring(), opts(40, true, Dep::paper, Method::sparse), 5),
               std::invalid_argument);
  // smallest chain: the pinned square has 4 - 2 - 1 = 1 elastic mode
  const auto sq = multibody::compute_modes(pinned_ring(), opts(4), 1);
  EXPECT_EQ(sq.rigid_modes, 1);
  EXPECT_TRUE(ringtest::IsClose(sq.omega[0], oracle::pinned_chain_omegas(params(pinned_ring(), 4, true), 1)[0], 1e-12));
}

}  // namespace
