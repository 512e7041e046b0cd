// Fitted convergence orders of the FE eigenvalues against the free-ring closed form.
//
// Expected order: 2(p - 1) in h for the relative frequency error. The symmetric C0
// interior-penalty form is consistent and coercive, so the energy-norm error of the
// eigenfunction is O(h^(p-1)) (w'' of a degree-p field) and, as for any consistent
// symmetric Galerkin method, the eigenvalue error is its square: O(h^(2(p-1))); the
// frequency omega = sqrt(lambda) has the same relative order. The tangential field of
// degree p+1 and the exact geometry add nothing slower.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fem_reference/modes.hpp"
#include "ring/closed_form.hpp"
#include "support/paper.hpp"

namespace {

class FemConvergence : public ::testing::TestWithParam<int> {};

TEST_P(FemConvergence, FittedOrderIsTwoPMinusTwo) {
  const int p = GetParam();
  const auto spec = ringtest::free_ring();
  // k = 4 (modes 5 and 6); 32, 64, 128 cells are in the asymptotic range for p = 2..4
  // and stay above the ~1e-12 round-off floor.
  const double exact = ring::closed_form::free_ring_extensible(spec, 4)[0];
  std::vector<double> log_h, log_e;
  for (int n : {32, 64, 128}) {
    ring::FemOptions o;
    o.elements = n;
    o.degree = p;
    const auto r = fem::compute_modes(spec, o, 6);
    log_h.push_back(std::log(2 * M_PI / n));
    log_e.push_back(std::log(std::abs(r.omega[4] - exact) / exact));
  }
  // least-squares slope of log(error) against log(h)
  const double mh = (log_h[0] + log_h[1] + log_h[2]) / 3, me = (log_e[0] + log_e[1] + log_e[2]) / 3;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < 3; ++i) {
    sxy += (log_h[i] - mh) * (log_e[i] - me);
    sxx += (log_h[i] - mh) * (log_h[i] - mh);
  }
  const double rate = sxy / sxx, expected = 2.0 * (p - 1);
  EXPECT_NEAR(rate, expected, 0.2) << "observed order " << rate << " for p = " << p;  // 0.2: the bound
  // ceiling on the finest error: the constant must not hide a wrong model
  EXPECT_LT(std::exp(log_e.back()), 1e-2);
}

INSTANTIATE_TEST_SUITE_P(Degrees, FemConvergence, ::testing::Values(2, 3, 4));

}  // namespace
