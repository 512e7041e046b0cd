// Two independent implementations of the same model must agree (issue 5, STYLE.md
// "cross-check independent algorithms"): the lumped chain (Cartesian hinge positions,
// link-length constraints, springs as functions of positions; lumped_mass/) against the
// multibody chain without rotary inertia (segment angles, closure constraints;
// multibody/). Same n-gon, same masses m = rho A l at the midpoints, same springs EI/l.
#include <gtest/gtest.h>

#include <cstdio>

#include "lumped_mass/modes.hpp"
#include "multibody/modes.hpp"
#include "ring/sampling.hpp"
#include "common.hpp"
#include "tests/support/close.hpp"

namespace {

struct Case {
  int n;
  const char* supports;  // "pin", "free", "roller"
};

class LumpedVsMultibody : public ::testing::TestWithParam<Case> {};

TEST_P(LumpedVsMultibody, AllElasticModesAgree) {
  const Case c = GetParam();
  ring::RingSpec spec = lumptest::paper_ring();
  if (std::string(c.supports) != "free") spec.supports.pin = 180.0;
  if (std::string(c.supports) == "roller") spec.supports.roller = 0.0;
  ring::MultibodyOptions mo;
  mo.n = c.n;
  mo.rotary_inertia = false;
  const int count = c.n - 3;  // every elastic mode of the chain, for any supports
  const ring::ModalResult mb = multibody::compute_modes(spec, mo, count);
  const ring::ModalResult lm = lumped::compute_modes(spec, lumptest::options(c.n, lumptest::kChain), count);
  EXPECT_EQ(lm.rigid_modes, mb.rigid_modes);
  ASSERT_EQ(lm.omega.size(), mb.omega.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < lm.omega.size(); ++i) {
    worst = std::max(worst, ringtest::rel(lm.omega[i], mb.omega[i]));
    // 1e-9: the bound. Both are backward-stable solutions of the same pencil;
    // the lumped solver's rounding is ~eps (R/l)^2 relative (eigen.hpp), ~1e-13 here.
    EXPECT_TRUE(ringtest::IsClose(lm.omega[i], mb.omega[i], 1e-9)) << "mode " << i + 1;
  }
  double worst_mac = 1.0;
  if (std::string(c.supports) != "free") {
    // Supported rings have simple eigenvalues, so the shapes are defined up to sign;
    // the free ring's double eigenvalues have arbitrary bases and are not compared.
    for (int i = 0; i < 20; ++i) {
      const double m = ring::mac(lm.shapes[i], mb.shapes[i]);
      worst_mac = std::min(worst_mac, m);
      // 1e-8: MAC = cos^2 of the angle between shapes; the eigenvectors' rounding is
      // ~1e-10 relative (gap >= 1 % between neighbouring modes).
      EXPECT_GT(m, 1.0 - 1e-8) << "mode " << i + 1;
    }
  }
  std::printf("[lumped vs multibody] n = %d, %s: %zu modes, max rel. diff %.2e, min MAC %.12f\n", c.n,
              c.supports, lm.omega.size(), worst, worst_mac);
}

INSTANTIATE_TEST_SUITE_P(Chains, LumpedVsMultibody,
                         ::testing::Values(Case{40, "pin"}, Case{40, "free"}, Case{40, "roller"}, Case{160, "pin"},
                                           Case{160, "free"}, Case{160, "roller"}),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return std::string(i.param.supports) + "_n" + std::to_string(i.param.n);
                         });

}  // namespace
