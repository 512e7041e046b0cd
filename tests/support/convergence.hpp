// One convergence-order check for all suites (the shape of scikit-fem's
// tests/test_convergence.py): fit the order p of e ~ C h^p by least squares
// on log e against log h, compare it with the expected order, and bound the error at the
// finest h.
//
//   const auto s = ringtest::in_n(ns, errors);            // h = 2 pi R / n
//   EXPECT_TRUE(ringtest::OrderNear(s, 2.0, 0.1, 1e-4)) << "mode " << k;
//
// The fit's interval is the standard error of the slope, sqrt(SSR / (m - 2) / Sxx) over m
// points; with two points the line passes through both and the interval is zero (the
// fitted order is the two-point order log(e0 / e1) / log(h0 / h1)). The interval is
// reported, not asserted: the tolerance of each call states its own source.
//
// "h" is whatever the error is a power of: the mesh size, the time step, depth / R, a
// stiffness factor (then p may be negative: a difference that falls like 1 / kappa has
// p = -1 in h = kappa).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ringtest {

/// Pairs (h_i, e_i), e ~ C h^p. `log_h` is log h (for n elements, -log n: h ~ 1 / n).
struct Samples {
  std::vector<double> h, e;  // as given: h, or n when `per_n`
  std::vector<double> log_h;
  bool per_n = false;
};

/// Samples against a size h (mesh size, time step, a ratio): the order is the slope in h.
inline Samples in_h(const std::vector<double>& h, const std::vector<double>& e) {
  if (h.size() != e.size() || h.size() < 2)
    throw std::invalid_argument("ringtest::in_h: need as many h as errors, at least 2 (got " +
                                std::to_string(h.size()) + " and " + std::to_string(e.size()) + ")");
  Samples s;
  s.h = h;
  s.e = e;
  for (double x : h) s.log_h.push_back(std::log(x));
  return s;
}

/// Samples against a count n of elements (segments, cells) with h ~ 1 / n: the order is
/// minus the slope in n.
template <class N>
Samples in_n(const std::vector<N>& n, const std::vector<double>& e) {
  if (n.size() != e.size() || n.size() < 2)
    throw std::invalid_argument("ringtest::in_n: need as many n as errors, at least 2 (got " +
                                std::to_string(n.size()) + " and " + std::to_string(e.size()) + ")");
  Samples s;
  s.e = e;
  s.per_n = true;
  for (const N& x : n) {
    s.h.push_back(static_cast<double>(x));
    s.log_h.push_back(-std::log(static_cast<double>(x)));
  }
  return s;
}

/// The samples at the given indices, in that order: a two-point order of one refinement
/// (`subset(s, {1, 2})`) or a fit over part of the samples.
inline Samples subset(const Samples& s, const std::vector<std::size_t>& indices) {
  if (indices.size() < 2) throw std::invalid_argument("ringtest::subset: need at least 2 indices");
  Samples out;
  out.per_n = s.per_n;
  for (std::size_t i : indices) {
    out.h.push_back(s.h.at(i));
    out.e.push_back(s.e.at(i));
    out.log_h.push_back(s.log_h.at(i));
  }
  return out;
}

/// A fitted order: the least-squares slope of log e against log h, its standard error
/// (0 with two points), and the error at the finest h (the smallest h, the largest n).
struct Order {
  double order = std::numeric_limits<double>::quiet_NaN();
  double standard_error = std::numeric_limits<double>::quiet_NaN();
  std::size_t points = 0;
  double finest_h = std::numeric_limits<double>::quiet_NaN();  // as given: h, or n
  double finest_error = std::numeric_limits<double>::quiet_NaN();
};

/// Least-squares fit of log e = a + p log h, O(m) in the m samples. A non-positive or
/// non-finite error makes the order NaN (which OrderNear reports as a failure).
inline Order fit_order(const Samples& s) {
  Order o;
  const std::size_t m = s.e.size();
  o.points = m;
  std::size_t finest = 0;
  for (std::size_t i = 1; i < m; ++i)
    if (s.log_h[i] < s.log_h[finest]) finest = i;
  o.finest_h = s.h[finest];
  o.finest_error = s.e[finest];
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  std::vector<double> log_e(m);
  for (std::size_t i = 0; i < m; ++i) {
    log_e[i] = std::log(s.e[i]);  // NaN for e < 0, -inf for e = 0: the order is NaN
    const double x = s.log_h[i], y = log_e[i];
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (m == 2) {  // the line through both points, without the sums' cancellation
    o.order = (log_e[1] - log_e[0]) / (s.log_h[1] - s.log_h[0]);
    o.standard_error = std::isfinite(o.order) ? 0.0 : o.order;
    return o;
  }
  const double k = static_cast<double>(m);
  o.order = (k * sxy - sx * sy) / (k * sxx - sx * sx);
  const double intercept = (sy - o.order * sx) / k, mean_x = sx / k;
  double ssr = 0.0, Sxx = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    const double r = log_e[i] - intercept - o.order * s.log_h[i];
    ssr += r * r;
    Sxx += (s.log_h[i] - mean_x) * (s.log_h[i] - mean_x);
  }
  o.standard_error = std::sqrt(ssr / (k - 2.0) / Sxx);
  return o;
}

/// Success when the fitted order lies within `tolerance` of `expected` (|p - expected| <=
/// tolerance, as EXPECT_NEAR) and the error at the finest h is below `finest_ceiling`
/// (strictly, as EXPECT_LT; infinity: no ceiling). The failure names the fitted order with
/// its interval, the expected order and tolerance, the finest error and its ceiling, and
/// every sample.
inline ::testing::AssertionResult OrderNear(const Samples& s, double expected, double tolerance,
                                            double finest_ceiling = std::numeric_limits<double>::infinity()) {
  const Order o = fit_order(s);
  const bool order_ok = std::abs(o.order - expected) <= tolerance;  // false for NaN
  const bool ceiling_ok = o.finest_error < finest_ceiling;           // false for NaN
  if (order_ok && ceiling_ok) return ::testing::AssertionSuccess();
  std::ostringstream m;
  m.precision(6);
  m << "fitted order " << o.order << " +- " << o.standard_error << " (standard error, " << o.points
    << (o.points == 2 ? " points: the two-point order" : " points") << "), expected " << expected << " +- " << tolerance
    << (order_ok ? "" : " [FAILED]") << "; finest error " << o.finest_error << " at " << (s.per_n ? "n = " : "h = ")
    << o.finest_h;
  if (std::isfinite(finest_ceiling)) m << ", ceiling " << finest_ceiling << (ceiling_ok ? "" : " [FAILED]");
  m << "; samples (" << (s.per_n ? "n" : "h") << ", error):";
  for (std::size_t i = 0; i < s.e.size(); ++i) m << " (" << s.h[i] << ", " << s.e[i] << ")";
  return ::testing::AssertionFailure() << m.str();
}

}  // namespace ringtest
