// The one Newton iteration (newton.hpp).
#include "paths/newton.hpp"

namespace paths {

NewtonResult newton(NewtonSystem& system, const Rule& rule) {
  NewtonResult out;
  bool refresh = false;     // factor again at the next iteration
  double previous = 0.0;    // the size of the previous applied correction (0: none yet)
  for (int it = 1; it <= rule.cap; ++it) {
    out.iterations = it;
    const bool fresh = !rule.reuse || refresh || !system.has_matrix();
    if (it == 1) out.reused = !fresh;
    if (!system.linearize(fresh)) return out;
    refresh = false;
    Correction c;
    if (!system.solve(c) || !std::isfinite(c.size) || !std::isfinite(c.move)) return out;
    if (!(c.move <= 1.0)) {  // left the basin: with a kept matrix, try a fresh one
      if (fresh) return out;
      refresh = true;
      continue;
    }
    if (rule.reuse && !fresh) {
      // A matrix kept from an earlier solve serves one iteration; one kept within the solve
      // while it shrinks the correction at least 8-fold.
      if (previous == 0.0 || c.size > 0.125 * previous) refresh = true;
    }
    if (c.size > rule.refresh_above) refresh = true;
    previous = c.size;
    system.apply();
    switch (system.settle(c.size <= rule.tolerance, c)) {
      case Verdict::converged:
        out.converged = true;
        return out;
      case Verdict::failed:
        return out;
      case Verdict::iterate:
        break;
    }
  }
  return out;
}

}  // namespace paths
