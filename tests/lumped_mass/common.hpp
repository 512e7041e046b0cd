// Options shared by the lumped-mass suites (the rings: support/paper.hpp).
#pragma once

#include "ring/spec.hpp"
#include "support/paper.hpp"

namespace lumptest {

inline ring::LumpedOptions options(int n, ring::LumpedOptions::Variant v) {
  ring::LumpedOptions o;
  o.n = n;
  o.variant = v;
  return o;
}
constexpr ring::LumpedOptions::Variant kChain = ring::LumpedOptions::Variant::chain;
constexpr ring::LumpedOptions::Variant kFrame = ring::LumpedOptions::Variant::frame;
constexpr ring::LumpedOptions::Variant kConsistent = ring::LumpedOptions::Variant::frame_consistent;

}  // namespace lumptest
