// The paper's ring (Yin & Wang, Table 1; README, "The paper"): R = 10 m,
// solid circle d = 0.12 m, E = 2.1e11 Pa, rho = 7.8e3 kg/m^3 (the printed 9.8e3 is a
// misprint).
#pragma once

#include <optional>

#include "ring/spec.hpp"
#include "support/paper.hpp"

namespace femtest {

/// Pinned at 180 degrees unless told otherwise (std::nullopt: free).
inline ring::RingSpec paper_ring(std::optional<double> pin = 180.0) { return ringtest::paper_ring(pin); }

}  // namespace femtest
