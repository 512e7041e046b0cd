// The paper's ring, one definition for every suite and benchmark program, each helper
// named by the supports it sets (Yin & Wang, Table 1; docs/paper.md): R = 10 m,
// solid circle d = 0.12 m, E = 2.1e11 Pa, rho = 7.8e3 kg/m^3 (the printed 9.8e3 is a
// misprint).
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace ringtest {

/// The paper's ring with no support: free, three rigid modes.
inline ring::RingSpec free_ring() {
  ring::RingSpec s;
  s.radius = 10.0;
  s.E = 2.1e11;
  s.rho = 7.8e3;
  s.section.shape = ring::Section::Shape::circle;
  s.section.diameter = 0.12;
  return s;
}

/// The paper's ring pinned at `pin` degrees (the paper pins it at A, 180 deg): one rigid
/// mode, the rotation about the pin.
inline ring::RingSpec pinned_ring(double pin = 180.0) {
  ring::RingSpec s = free_ring();
  s.supports.pin = pin;
  return s;
}

/// The paper's ring as its section 5 holds it: pinned at A (180 deg), a roller at C
/// (0 deg) moving along AC. No rigid mode.
inline ring::RingSpec pin_roller_ring() {
  ring::RingSpec s = pinned_ring(180.0);
  s.supports.roller = 0.0;
  return s;
}

/// The paper's ring on a pin at 270 deg and a roller at 90 deg (scenes/ring-buckling.toml,
/// ring-collapse.toml): statically determinate, the supports of the buckling closed forms
/// (ring::closed_form::pinned_ring_critical_pressure).
inline ring::RingSpec pin_270_roller_90() {
  ring::RingSpec s = pinned_ring(270.0);
  s.supports.roller = 90.0;
  return s;
}

/// scenes/ring-collapse.toml's statics: the follower pressure 12825 N/m (6 EI/R^3 to 2e-5,
/// the scene's rounded value), a squeeze of 100 N along the diameter 0-180 (the imperfection
/// that selects the buckled shape), the path to contact recorded at 0 and 180 deg.
inline ring::StaticOptions collapse_statics() {
  ring::StaticOptions st;
  st.loads.pressure = {12825.0, ring::Pressure::Kind::follower};
  st.loads.points = {{0.0, {-100.0, 0.0}}, {180.0, {100.0, 0.0}}};
  st.record = {0.0, 180.0};
  st.path = true;
  return st;
}

/// The ring of scenes/tyre-ring.toml: a steel-cord belt on a radial and tangential Winkler
/// foundation, no support (the foundation holds every rigid motion).
inline ring::RingSpec tyre_ring() {
  ring::RingSpec s;
  s.radius = 0.3;                                                    // m
  s.E = 2.0e10;                                                      // Pa, the steel-cord belt
  s.rho = 1600.0;                                                    // kg/m^3
  s.section = {ring::Section::Shape::rectangle, 0.0, 0.15, 0.008};  // width, height (m)
  s.foundation = {1.0e6, 3.0e5};                                     // N/m^2, radial and tangential
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

/// The paper's ring as scene text: the [ring] table of scenes/paper1990.toml, comments and
/// trailing blanks dropped ("[ring]\nradius = 10.0\nE = 2.1e11\nrho = 7.8e3\nsection =
/// { shape = \"circle\", diameter = 0.12 }\n"), for the scenes a test writes around it.
/// Empty if the file has no [ring] table (every caller's scene is then refused loudly).
inline std::string paper_ring_toml() {
  std::istringstream in(source_text("scenes/paper1990.toml"));
  std::string line, out;
  bool inside = false;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');  // no '#' in the table's strings
    if (hash != std::string::npos) line.erase(hash);
    line.erase(line.find_last_not_of(" \t") + 1);
    if (line.empty()) continue;
    if (line[0] == '[') {
      if (inside) break;
      inside = line == "[ring]";
    }
    if (inside) out += line + "\n";
  }
  return out;
}
#endif

}  // namespace ringtest
