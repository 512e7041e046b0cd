// Rings shared by the lumped-mass suites.
#pragma once

#include "ring/spec.hpp"
#include "support/paper.hpp"

namespace lumptest {

using ringtest::paper_ring;  // free
inline ring::RingSpec pinned_ring(double pin = 180.0) { return ringtest::paper_ring(pin); }
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
