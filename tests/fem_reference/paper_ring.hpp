// The paper's ring (Yin & Wang, Table 1; /work/shared/paper/NOTES.md): R = 10 m,
// solid circle d = 0.12 m, E = 2.1e11 Pa, rho = 7.8e3 kg/m^3 (the printed 9.8e3 is a
// misprint).
#pragma once

#include <optional>

#include "ring/spec.hpp"

namespace femtest {

inline ring::RingSpec paper_ring(std::optional<double> pin = 180.0) {
  ring::RingSpec spec;
  spec.radius = 10.0;
  spec.E = 2.1e11;
  spec.rho = 7.8e3;
  spec.section.shape = ring::Section::Shape::circle;
  spec.section.diameter = 0.12;
  spec.supports.pin = pin;
  return spec;
}

}  // namespace femtest
