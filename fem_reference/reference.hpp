// Internal to fem_reference/: the converged-reference policy of the geometrically exact
// beam's analyses (statics, response, buckling): raise the degree to fem::kMaxDegree, then
// split the cells, until two successive discretizations agree to the tolerance. One policy,
// written once (nonlinear.cpp, buckling.cpp and preload.cpp use it). The linear modes keep their own
// loop (modes.cpp), which also decides when to refine the raw eigenpairs.
#pragma once

#include <string>
#include <utility>

#include "fem_reference/ring_model.hpp"

namespace fem::detail {

/// Refines `setup` (degree, then cells) until `change(previous, next)` < tolerance;
/// returns the last discretization's result; `estimate` is that last change and
/// `refinements` the number of refinements taken. Throws ring::NumericalError after
/// kReferenceMaxSteps refinements. Cost: one `solve` per refinement.
template <class Solve, class Change>
auto refine_until(Setup& setup, double tolerance, Solve&& solve, Change&& change, double& estimate,
                  int& refinements, const std::string& what) {
  auto current = solve(setup);
  for (refinements = 1;; ++refinements) {
    if (refinements > kReferenceMaxSteps)
      throw ring::NumericalError("fem: " + what + " reference not converged after " +
                                 std::to_string(kReferenceMaxSteps) + " refinements");
    if (setup.degree < kMaxDegree)
      ++setup.degree;
    else
      setup.subdivisions *= 2;
    auto next = solve(setup);
    estimate = change(current, next);
    current = std::move(next);
    if (estimate < tolerance) return current;
  }
}

}  // namespace fem::detail
