// One definition of "close" for all suites: |a - b| <= atol + rtol * |b|.
// Every call site states where its atol and rtol come from.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace ringtest {

inline ::testing::AssertionResult IsClose(double a, double b, double rtol, double atol = 0.0) {
  const double d = std::abs(a - b);
  if (std::isfinite(a) && d <= atol + rtol * std::abs(b)) return ::testing::AssertionSuccess();
  std::ostringstream s;
  s.precision(16);
  s << a << " vs " << b << ": |diff| = " << d << ", rel = " << d / std::abs(b)
    << " > atol " << atol << " + rtol " << rtol;
  return ::testing::AssertionFailure() << s.str();
}

/// Relative difference |a - b| / |b|.
inline double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace ringtest
