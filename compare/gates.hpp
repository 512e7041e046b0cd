// CI accuracy gates: the largest |error| or |difference| a scene allows, per solver and
// mode range. `ringvib run` exits 1 when one fails.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "compare/nonlinear.hpp"
#include "compare/table.hpp"
#include "ring/scene.hpp"

namespace cmp {

struct GateResult {
  ring::Gate gate;
  bool pass = false;
  int worst_mode = 0;     ///< 1-based (modes)
  double worst_point = 0; ///< degrees (response, static)
  double worst_pct = 0;   ///< |value| at the worst mode, %
  double weak_mac = NAN;  ///< modes: the MAC below kWeakMac that made worst_mode incomparable
  std::string name() const;  ///< "multibody vs reference, modes 1-23, max 6%"
  std::string line() const;  ///< "PASS multibody vs reference ...: worst mode 23, 5.12 % <= 6 %"
};

/// Evaluates every modal gate of the scene on the table. A gate that cannot be evaluated
/// (a NaN, a missing paper value for every mode) fails.
std::vector<GateResult> evaluate_gates(const std::vector<ring::Gate>& gates, const Table& table);

/// Evaluates the gates of one nonlinear analysis (gate.analysis == table.analysis) on its
/// comparison table: |error| (or |difference| against another solver) of the peak |u|
/// (response) or |u| (statics) over the recorded points where it is defined. A gate with
/// no defined value fails.
std::vector<GateResult> evaluate_nonlinear_gates(const std::vector<ring::Gate>& gates, const NonlinearTable& table);

/// JUnit XML with one test case per gate.
std::string junit_xml(const std::string& suite, const std::vector<GateResult>& results);

}  // namespace cmp
