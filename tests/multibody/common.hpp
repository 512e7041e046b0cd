// Shared by the multibody suites: the paper's ring as section 5 holds it, and a number
// format for RecordProperty.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>

#include "ring/spec.hpp"
#include "support/paper.hpp"

namespace mbtest {

/// A number for RecordProperty, in scientific notation with 4 significant digits.
inline std::string sci(double x) {
  std::ostringstream s;
  s << std::setprecision(4) << std::scientific << x;
  return s.str();
}

/// The paper's ring pinned at A (180 deg) with the roller at C (0 deg), as in section 5.
inline ring::RingSpec paper_ring() {
  ring::RingSpec s = ringtest::paper_ring(180.0);
  s.supports.roller = 0.0;
  return s;
}

}  // namespace mbtest
