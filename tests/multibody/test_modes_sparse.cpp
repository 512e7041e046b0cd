// The sparse large-n modes path, label `stress`: against the
// independent oracles of ring_oracle.hpp from n = 8 to n = 10^5 (pinned and free,
// with and without rotary inertia), against the dense path where both run, and its
// normwise backward error; both of its eigensolvers (the eigen layer's and the
// hand-written one kept for speed) against the oracles and against each other. No timing assertions (timings are in docs/measured.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "multibody/modes.hpp"
#include "ring/sampling.hpp"
#include "tests/multibody/ring_oracle.hpp"
#include "tests/support/close.hpp"
#include "support/paper.hpp"

namespace {

using Dep = ring::MultibodyOptions::Dependent;
using Method = ring::MultibodyOptions::Method;

// The Table 1 ring pinned at 180 deg, free, or pinned with the roller at 0 deg.
using ringtest::free_ring;
using ringtest::pin_roller_ring;
using ringtest::pinned_ring;
ring::MultibodyOptions opts(int n, bool rot, Method m) {
  ring::MultibodyOptions o;
  o.n = n;
  o.rotary_inertia = rot;
  o.dependent = Dep::robust;
  o.method = m;
  return o;
}
std::string name(const ring::RingSpec& s) {
  return s.supports.free() ? "free" : s.supports.roller ? "roller" : "pin";
}

// Against the oracles: the oracles are closed forms / bisection in long double-free
// double arithmetic, themselves good to ~1e-13 (test_modes.cpp); the previous sparse path
// and the dense path reached <= 5e-12 up to n = 20000. The bound 1e-10 is the
// specified dense-vs-sparse agreement (two independent algorithms, each good to ~1e-12); measured worst (this path): see the printed table.
void check_oracles(int n, multibody::SparseEigensolver eigensolver = multibody::kDefaultSparseEigensolver) {
  std::printf("%8s %8s %6s %12s %12s %12s %6s\n", "n", "support", "rot", "solver err", "bwd err",
              "residual", "rigid");
  for (bool pinned : {true, false}) {
    for (bool rot : {true, false}) {
      const ring::RingSpec s = pinned ? pinned_ring() : free_ring();
      const int count = std::min(23, n - 3);
      const auto sol = multibody::solve_modes(s, opts(n, rot, Method::sparse), count, eigensolver);
      const oracle::ChainParams p{n, s.radius, s.EI(), s.rhoA(), rot};
      const auto ref = pinned ? oracle::pinned_chain_omegas(p, count) : oracle::free_chain_omegas(p);
      double worst = 0;
      for (int i = 0; i < count; ++i) worst = std::max(worst, ringtest::rel(sol.result.omega[i], ref[i]));
      std::printf("%8d %8s %6d %12.3e %12.3e %12.3e %6d\n", n, pinned ? "pin" : "free", rot, worst,
                  sol.backward_error, sol.result.max_residual.value(), sol.result.rigid_modes);
      EXPECT_EQ(std::get<std::string>(sol.result.model.at("method")), "sparse");
      EXPECT_LT(worst, 1e-10) << "n = " << n;
      EXPECT_EQ(sol.result.rigid_modes, pinned ? 1 : 3) << "n = " << n;
      // Normwise backward error: measured <= 2e-11 for every n here (the Lanczos stops at
      // a 1e-8 relative Ritz residual; eigenvalues are quadratic in it, vectors linear).
      EXPECT_LT(sol.backward_error, 1e-9) << "n = " << n;
    }
  }
}

TEST(MultibodySparse, AgainstOraclesSmallN) {
  // n = 8 free without rotary inertia fails (the whole 8-dimensional space is wanted and
  // the near-invariant Krylov space fills with noise): the sparse path is for n >= 12.
  for (int n : {12, 40, 160}) check_oracles(n);
}
TEST(MultibodySparse, AgainstOraclesN1000) { check_oracles(1000); }
TEST(MultibodySparse, AgainstOraclesN10000) { check_oracles(10000); }
TEST(MultibodySparse, AgainstOraclesN100000) { check_oracles(100000); }

// Dense and sparse are independent algorithms (dense Cholesky of K0 + s M0 vs Riccati
// sweeps + bordering + own Lanczos): 1e-10 relative where both run, the specified agreement.
void check_dense_sparse(int n) {
  for (const auto& spec : {pinned_ring(), free_ring(), pin_roller_ring()}) {
    for (bool rot : {true, false}) {
      SCOPED_TRACE(name(spec) + (rot ? " rotary" : "") + " n = " + std::to_string(n));
      const int count = std::min(23, n - 4);
      const auto d = multibody::solve_modes(spec, opts(n, rot, Method::dense), count);
      const auto s = multibody::solve_modes(spec, opts(n, rot, Method::sparse), count);
      EXPECT_EQ(s.result.rigid_modes, d.result.rigid_modes);
      double worst = 0;
      for (int i = 0; i < count; ++i) {
        worst = std::max(worst, ringtest::rel(s.result.omega[i], d.result.omega[i]));
        EXPECT_TRUE(ringtest::IsClose(s.result.omega[i], d.result.omega[i], 1e-10)) << "mode " << i + 1;
      }
      std::printf("n = %5d %6s rot %d: dense vs sparse %.3e, backward error dense %.2e sparse %.2e\n", n,
                  name(spec).c_str(), rot, worst, d.backward_error, s.backward_error);
      EXPECT_LT(s.backward_error, 1e-9);  // as in check_oracles
      if (!spec.supports.free()) {  // distinct frequencies: shapes comparable (MAC)
        for (int i = 0; i < count; ++i) EXPECT_GT(ring::mac(s.result.shapes[i], d.result.shapes[i]), 1 - 1e-8);
      }
    }
  }
}
TEST(MultibodySparse, MatchesDenseN40to640) {
  for (int n : {10, 40, 160, 640}) check_dense_sparse(n);
}
TEST(MultibodySparse, MatchesDenseN2000) { check_dense_sparse(2000); }

// The sparse path's two eigensolvers on the same O(n) shifted solve: the eigen layer's
// Spectra Lanczos (modal/lanczos.hpp) and the hand-written one kept for speed
// (multibody/lanczos.hpp). Each against the oracles as above, then against each other
// within 1e-10 (the dense-vs-sparse agreement above) and the shapes' MAC where the frequencies
// are distinct.
TEST(MultibodySparse, LibraryLanczosAgainstOracles) {
  for (int n : {12, 40, 160, 1000, 10000}) check_oracles(n, multibody::SparseEigensolver::library);
}
TEST(MultibodySparse, LibraryLanczosAgainstOraclesN100000) {
  check_oracles(100000, multibody::SparseEigensolver::library);
}
TEST(MultibodySparse, LibraryLanczosAgreesWithHandWritten) {
  using multibody::SparseEigensolver;
  for (int n : {10, 160, 2000, 20000}) {
    for (const auto& spec : {pinned_ring(), free_ring(), pin_roller_ring()}) {
      for (bool rot : {true, false}) {
        SCOPED_TRACE(name(spec) + (rot ? " rotary" : "") + " n = " + std::to_string(n));
        const int count = std::min(23, n - 4);
        const auto h = multibody::solve_modes(spec, opts(n, rot, Method::sparse), count, SparseEigensolver::hand_written);
        const auto l = multibody::solve_modes(spec, opts(n, rot, Method::sparse), count, SparseEigensolver::library);
        EXPECT_EQ(l.result.rigid_modes, h.result.rigid_modes);
        double worst = 0;
        for (int i = 0; i < count; ++i) {
          worst = std::max(worst, ringtest::rel(l.result.omega[i], h.result.omega[i]));
          EXPECT_TRUE(ringtest::IsClose(l.result.omega[i], h.result.omega[i], 1e-10)) << "mode " << i + 1;
        }
        std::printf("n = %5d %6s rot %d: library vs hand-written %.3e, backward error library %.2e hand %.2e\n",
                    n, name(spec).c_str(), rot, worst, l.backward_error, h.backward_error);
        EXPECT_LT(l.backward_error, 1e-9);  // as in check_oracles
        if (!spec.supports.free()) {
          for (int i = 0; i < count; ++i) EXPECT_GT(ring::mac(l.result.shapes[i], h.result.shapes[i]), 1 - 1e-8);
        }
      }
    }
  }
}

}  // namespace
