// Convergence studies: each solver's error against the converged FE reference over a
// refinement sequence, the fitted order, and for the multibody chain a Richardson-
// extrapolated column (two refinements, assuming the observed second order).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

struct ConvergenceSeries {
  std::string name;               ///< "multibody", "multibody (Richardson)", "fem (p = 3)", ...
  std::string parameter;          ///< what is refined: "n" or "elements"
  std::vector<double> size;       ///< the refinement parameter
  std::vector<double> max_error;  ///< max |error| over the requested modes, %
  std::vector<double> mean_error; ///< mean |error|, %
  std::vector<double> seconds;    ///< solver time
  double order = 0.0;             ///< fitted -slope of log(max error) against log(size)
};

struct ConvergenceStudy {
  int modes = 0;
  double reference_estimate = 0.0;  ///< the reference's own remaining relative error
  std::vector<ConvergenceSeries> series;
};

/// Refines every solver the scene runs: multibody and lumped n x {1, 2, 4, 8, 16},
/// FE elements x {1, 2, 4, 8} at the scene's degree. Modes are paired with the reference
/// by MAC. Points closer to the reference than 100x its tolerance are left out of the fit.
ConvergenceStudy converge(const ring::Scene& scene, const ring::ModalResult& reference, std::ostream* progress);

/// Least-squares slope of log(y) against log(x), negated (the observed order).
double fitted_order(const std::vector<double>& x, const std::vector<double>& y);

std::string convergence_text(const ConvergenceStudy& c);
void write_convergence(const std::string& dir, const ConvergenceStudy& c);

}  // namespace cmp
