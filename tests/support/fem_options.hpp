// The FE beam's options with a mesh and a degree and the rest at their defaults: the fixture
// of the FE suites that vary only the mesh.
#pragma once

#include "ring/spec.hpp"

namespace ringtest {

inline ring::FemOptions fem_options(int elements, int degree = 3) {
  ring::FemOptions o;
  o.elements = elements;
  o.degree = degree;
  return o;
}

}  // namespace ringtest
