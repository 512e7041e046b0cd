// The paper's ring, one definition for every suite and benchmark program (Yin & Wang,
// Table 1; README "The paper"):
// R = 10 m, solid circle d = 0.12 m, E = 2.1e11 Pa, rho = 7.8e3 kg/m^3 (the printed
// 9.8e3 is a misprint).
#pragma once

#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "ring/spec.hpp"

namespace ringtest {

/// The paper's ring, free (no pin) unless `pin` is given (the paper pins it at 180 deg).
inline ring::RingSpec paper_ring(std::optional<double> pin = std::nullopt) {
  ring::RingSpec s;
  s.radius = 10.0;
  s.E = 2.1e11;
  s.rho = 7.8e3;
  s.section.shape = ring::Section::Shape::circle;
  s.section.diameter = 0.12;
  s.supports.pin = pin;
  return s;
}

#ifdef RINGVIB_SOURCE_DIR  // defined for the test programs
/// The text of a file of the source tree (scenes, data), e.g. "scenes/paper1990.toml".
inline std::string source_text(const std::string& relative) {
  std::ifstream f(std::string(RINGVIB_SOURCE_DIR) + "/" + relative);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}
#endif

}  // namespace ringtest
