// The convergence helper of every order test (tests/support/convergence.hpp) against
// synthetic errors of known order: e = C h^p exactly, e = C h^2 (1 + a perturbation), and a
// three-point fit whose slope and standard error are worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/convergence.hpp"

namespace {

bool contains(const ::testing::AssertionResult& r, const std::string& what) {
  return std::string(r.message()).find(what) != std::string::npos;
}

// An exact power law: the fit returns p to round-off and a zero interval, in h and in n.
TEST(ConvergenceHelper, ExactPowerLawGivesItsOrder) {
  const std::vector<int> ns{10, 20, 40, 80};
  std::vector<double> h, e;
  for (int n : ns) {
    h.push_back(1.0 / n);
    e.push_back(3.0 * std::pow(1.0 / n, 4.0));
  }
  const ringtest::Order by_h = ringtest::fit_order(ringtest::in_h(h, e));
  const ringtest::Order by_n = ringtest::fit_order(ringtest::in_n(ns, e));
  EXPECT_NEAR(by_h.order, 4.0, 1e-12);
  EXPECT_NEAR(by_n.order, 4.0, 1e-12);
  EXPECT_LT(by_h.standard_error, 1e-12);
  EXPECT_EQ(by_n.points, 4u);
  EXPECT_EQ(by_n.finest_h, 80.0);  // the largest n
  EXPECT_EQ(by_n.finest_error, e.back());
  EXPECT_EQ(by_h.finest_error, e.back());  // the smallest h
}

// e = C h^2 (1 + 0.05 sin(7 i)): the fit stays near 2 with a non-zero interval; a check
// against 2 +- 0.1 passes, one against 3 +- 0.1 fails and says why.
TEST(ConvergenceHelper, PerturbedSecondOrder) {
  std::vector<double> h, e;
  for (int i = 0; i < 5; ++i) {
    h.push_back(0.1 / std::pow(2.0, i));
    e.push_back(0.7 * h.back() * h.back() * (1.0 + 0.05 * std::sin(7.0 * i)));
  }
  const auto s = ringtest::in_h(h, e);
  const ringtest::Order o = ringtest::fit_order(s);
  EXPECT_NEAR(o.order, 2.0, 0.05);
  EXPECT_GT(o.standard_error, 1e-4);
  EXPECT_LT(o.standard_error, 0.05);
  EXPECT_TRUE(ringtest::OrderNear(s, 2.0, 0.1));
  EXPECT_TRUE(ringtest::OrderNear(s, 2.0, 0.1, 1e-4));  // finest e = 0.7 (0.1/16)^2 (1 + 0.014) = 2.8e-5

  const auto wrong = ringtest::OrderNear(s, 3.0, 0.1);
  EXPECT_FALSE(wrong);
  EXPECT_TRUE(contains(wrong, "fitted order")) << wrong.message();
  EXPECT_TRUE(contains(wrong, "expected 3 +- 0.1 [FAILED]")) << wrong.message();
  EXPECT_TRUE(contains(wrong, "finest error")) << wrong.message();

  const auto high = ringtest::OrderNear(s, 2.0, 0.1, 1e-5);
  EXPECT_FALSE(high);
  EXPECT_TRUE(contains(high, "ceiling 1e-05 [FAILED]")) << high.message();
}

// log-log points (0, 0), (1, 1), (2, 3): slope 3/2, intercept -1/6, residuals 1/6, -1/3,
// 1/6, so SSR = 1/6, Sxx = 2 and the standard error sqrt(SSR / (3 - 2) / Sxx) = sqrt(1/12).
TEST(ConvergenceHelper, StandardErrorOfTheSlopeByHand) {
  const ringtest::Order o =
      ringtest::fit_order(ringtest::in_h({1.0, std::exp(1.0), std::exp(2.0)}, {1.0, std::exp(1.0), std::exp(3.0)}));
  EXPECT_NEAR(o.order, 1.5, 1e-14);
  EXPECT_NEAR(o.standard_error, std::sqrt(1.0 / 12.0), 1e-14);
  EXPECT_EQ(o.finest_h, 1.0);
}

// Two points: the two-point order log(e0 / e1) / log(h0 / h1), interval zero.
TEST(ConvergenceHelper, TwoPointsGiveTheTwoPointOrder) {
  const ringtest::Order o = ringtest::fit_order(ringtest::in_n(std::vector<int>{40, 80}, {1.04e-2, 2.72e-3}));
  EXPECT_NEAR(o.order, std::log(1.04e-2 / 2.72e-3) / std::log(2.0), 1e-14);
  EXPECT_EQ(o.standard_error, 0.0);
  const auto r = ringtest::OrderNear(ringtest::in_n(std::vector<int>{40, 80}, {1.04e-2, 2.72e-3}), 3.0, 0.2);
  EXPECT_TRUE(contains(r, "two-point order")) << r.message();
  // The same two points picked from a longer series.
  const auto three = ringtest::in_n(std::vector<int>{20, 40, 80}, {3.0e-2, 1.04e-2, 2.72e-3});
  EXPECT_EQ(ringtest::fit_order(ringtest::subset(three, {1, 2})).order, o.order);
  EXPECT_THROW(ringtest::subset(three, {1}), std::invalid_argument);
}

// An error that is zero, negative or NaN cannot have an order: the check fails.
TEST(ConvergenceHelper, ErrorsWithoutALogarithmFail) {
  EXPECT_FALSE(ringtest::OrderNear(ringtest::in_h({1.0, 0.5, 0.25}, {1.0, 0.25, 0.0}), 2.0, 10.0));
  EXPECT_FALSE(ringtest::OrderNear(ringtest::in_h({1.0, 0.5, 0.25}, {1.0, -0.25, 0.0625}), 2.0, 10.0));
  EXPECT_FALSE(ringtest::OrderNear(ringtest::in_h({1.0, 0.5}, {1.0, std::nan("")}), 2.0, 10.0));
  EXPECT_THROW(ringtest::in_h({1.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(ringtest::in_n(std::vector<int>{1, 2}, {1.0}), std::invalid_argument);
}

}  // namespace
