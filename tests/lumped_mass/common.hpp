// Rings shared by the lumped-mass suites.
#pragma once

#include "ring/spec.hpp"

namespace lumptest {

/// The paper's ring (NOTES.md): R = 10 m, solid circle d = 0.12 m, E = 2.1e11 Pa,
/// rho = 7.8e3 kg/m^3 (the printed 9.8e3 is a misprint).
inline ring::RingSpec paper_ring() {
  ring::RingSpec s;
  s.radius = 10.0;
  s.E = 2.1e11;
  s.rho = 7.8e3;
  s.section.shape = ring::Section::Shape::circle;
  s.section.diameter = 0.12;
  return s;
}
inline ring::RingSpec pinned_ring(double pin = 180.0) {
  ring::RingSpec s = paper_ring();
  s.supports.pin = pin;
  return s;
}
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
