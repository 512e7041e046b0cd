// The cost guard: an estimate of the memory a scene needs, checked before anything is
// solved, so that a request no machine this runs on can finish (multibody.n = 1e8, a
// dense eigen-solve at n = 20000, 1e8 time steps) is an input error naming the key and
// the estimate instead of minutes of work and an out-of-memory crash.
//
// The estimates are per solver (SolverEntry::memory) and per analysis, calibrated on
// measured peaks (docs/commands.md, "Cost guard"): they aim at the right order of magnitude, not
// at the byte.
#pragma once

#include <string>

#include "ring/scene.hpp"

namespace cmp {

struct Budget {
  double max_bytes = 8.0 * (1ull << 30);  ///< --max-memory (GiB on the command line)
  bool force = false;                     ///< --force: go ahead whatever the estimate
};

/// The largest estimated memory of the scene's analyses, in bytes, and the key that
/// drives it ("multibody.n", "response.t_end", ...).
struct Estimate {
  double bytes = 0.0;
  std::string key;
  std::string what;  ///< "the multibody modes", "the response history", ...
};
Estimate estimate_memory(const ring::Scene& scene);

/// Throws ring::InputError (exit 2) naming the key and the estimate when it exceeds the
/// budget (unless budget.force).
void check_cost(const ring::Scene& scene, const Budget& budget);

}  // namespace cmp
