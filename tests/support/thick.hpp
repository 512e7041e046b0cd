// A thick steel ring for the Timoshenko tests of every solver (shared so that each solver's
// suite measures the same ring).
#pragma once

#include "ring/spec.hpp"

namespace ringtest {

/// A steel ring of radius 1 m, theory Timoshenko (nu = 0.3, Cowper's kappa), section of
/// radial depth `depth` m (rectangle: height = depth, width 0.02 m; circle: diameter = depth),
/// free.
inline ring::RingSpec thick_ring(ring::Section::Shape shape, double depth) {
  ring::RingSpec s;
  s.radius = 1.0;
  s.E = 2.1e11;
  s.rho = 7.8e3;
  s.nu = 0.3;
  s.theory = ring::Theory::timoshenko;
  s.section.shape = shape;
  if (shape == ring::Section::Shape::rectangle) {
    s.section.width = 0.02;
    s.section.height = depth;
  } else {
    s.section.diameter = depth;
  }
  return s;
}

/// The ring of scenes/thick-ring.toml: R = 0.1 m, steel, rectangle 0.01 m wide and 0.02 m
/// deep (depth/R = 0.2), theory Timoshenko (nu = 0.3, Cowper's kappa), free.
inline ring::RingSpec scene_thick_ring() {
  ring::RingSpec s = thick_ring(ring::Section::Shape::rectangle, 0.02);
  s.radius = 0.1;
  s.section.width = 0.01;
  return s;
}

}  // namespace ringtest
