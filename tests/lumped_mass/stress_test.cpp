// Large n on the sparse path: the low modes must keep converging at the fitted order 2
// (convergence_test.cpp) all the way up, i.e. rounding must stay below the discretization
// error. The solvers never touch the assembled K (eigen.hpp): with it, rounding would
// cost eps (R/l)^4 ~ 1e-3 relative at n = 1e4, and the lowest modes would be noise.
// Oracle: the closed-form free ring (ring/closed_form.hpp) and the O(h^2) law: the error
// at n = 10000 must be err(320) (320/10000)^2 to within 3 % (the O(h^4) remainder at
// n = 320 is < 1 % of the error, judging by the ratios 4.00 +- 0.02 between successive
// errors in convergence_test; rounding is bounded by eps (R/l)^2 = 6e-10 relative at
// n = 10000, well below the 6.6e-9 smallest error here; measured agreement 0.5 %).
#include <gtest/gtest.h>

#include <cstdio>

#include "lumped_mass/modes.hpp"
#include "ring/closed_form.hpp"
#include "common.hpp"
#include "tests/support/close.hpp"

namespace {

using ring::LumpedOptions;

class LumpedStress : public ::testing::TestWithParam<LumpedOptions::Variant> {};

TEST_P(LumpedStress, FreeRingStaysOnTheSecondOrderLawAtTenThousand) {
  const LumpedOptions::Variant v = GetParam();
  const ring::RingSpec spec = ringtest::free_ring();
  const ring::ModalResult coarse = lumped::compute_modes(spec, lumptest::options(320, v), 4);
  const ring::ModalResult fine = lumped::compute_modes(spec, lumptest::options(10000, v), 4, lumped::Method::sparse);
  EXPECT_EQ(fine.rigid_modes, 3);
  for (int k : {2, 3}) {
    const double exact = v == lumptest::kChain ? ring::closed_form::free_ring_inextensional(spec, k)
                                               : ring::closed_form::free_ring_extensible(spec, k)[0];
    for (int copy = 0; copy < 2; ++copy) {
      const int i = 2 * (k - 2) + copy;
      const double e_coarse = (coarse.omega[i] - exact) / exact, e_fine = (fine.omega[i] - exact) / exact;
      const double predicted = e_coarse * (320.0 / 10000.0) * (320.0 / 10000.0);
      std::printf("[lumped %s stress] k = %d copy %d: error n=320 %.4e, n=10000 %.4e, O(h^2) prediction %.4e "
                  "(%.2f s, %lld unknowns)\n",
                  ring::to_string(v).c_str(), k, copy, e_coarse, e_fine, predicted, fine.seconds, fine.unknowns);
      EXPECT_TRUE(ringtest::IsClose(e_fine, predicted, 0.03)) << "k = " << k;
    }
  }
  // Not asserted: the contract's residual ||Kx - w^2 Mx|| / (||Kx|| + w^2 ||Mx||) of a
  // double-precision vector has a floor ~eps ||K|| / w^2 (the frames' axial EA/l), which
  // grows with n regardless of the solver; printed for the report.
  std::printf("[lumped %s stress] n = 10000 max_residual (contract metric) %.2e\n", ring::to_string(v).c_str(),
              fine.max_residual.value());
}

INSTANTIATE_TEST_SUITE_P(Variants, LumpedStress,
                         ::testing::Values(lumptest::kChain, lumptest::kFrame, lumptest::kConsistent),
                         [](const ::testing::TestParamInfo<LumpedOptions::Variant>& i) {
                           return std::string(i.param == lumptest::kChain   ? "chain"
                                              : i.param == lumptest::kFrame ? "frame"
                                                                            : "frame_consistent");
                         });

}  // namespace
