// Stress: 1e5 unknowns, 23 modes, through ARPACK + UMFPACK, without running out of memory.
#include <gtest/gtest.h>

#include "fem_reference/modes.hpp"
#include "tests/support/close.hpp"
#include "tests/fem_reference/paper_ring.hpp"

namespace {

TEST(FemStress, HundredThousandUnknownsTwentyThreeModes) {
  const auto spec = femtest::paper_ring(180.0);
  ring::FemOptions o;
  o.elements = 12500;  // degree 4: 4 + 5 unknowns per cell -> 112 500 - 3 constrained
  o.degree = 4;
  const auto r = fem::compute_modes(spec, o, 23);
  EXPECT_GE(r.unknowns, 100000);
  ASSERT_EQ(r.omega.size(), 23u);
  // Oracle: the converged reference; the fine mesh is far inside the asymptotic range
  // (h^6 ~ 1e-21), so what remains is round-off of the refined solve.
  ring::FemOptions ref;
  ref.reference = true;
  const auto f = fem::compute_modes(spec, ref, 23);
  for (int i = 0; i < 23; ++i) EXPECT_TRUE(ringtest::IsClose(r.omega[i], f.omega[i], 1e-8)) << "mode " << i + 1;
}

}  // namespace
