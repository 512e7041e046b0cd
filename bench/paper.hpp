// The paper's ring for every benchmark program (Yin & Wang, Table 1; the tests' copy is
// tests/support/paper.hpp): R = 10 m, solid circle d = 0.12 m, E = 2.1e11 Pa,
// rho = 7.8e3 kg/m^3, pinned at 180 deg; with `roller`, a roller at 0 deg (the forced
// scenes').
#pragma once

#include "ring/spec.hpp"

namespace ringbench {

inline ring::RingSpec paper_ring(bool roller = false) {
  ring::RingSpec s;
  s.radius = 10.0;
  s.E = 2.1e11;
  s.rho = 7.8e3;
  s.section.shape = ring::Section::Shape::circle;
  s.section.diameter = 0.12;
  s.supports.pin = 180.0;
  if (roller) s.supports.roller = 0.0;
  return s;
}

}  // namespace ringbench
