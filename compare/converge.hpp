// Convergence studies: each solver's error against the converged FE reference over a
// refinement sequence, the fitted order, and for the multibody chain a Richardson-
// extrapolated column (two refinements, assuming the observed second order).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// The converged continua the discretizations tend to. The rigid-link chains (multibody,
/// lumped chain) are inextensible; frame elements and FE (unless fem.extensible = false)
/// are extensible. The two differ at order (r_g/R)^2, but for a pinned ring with a far
/// larger constant than for a free one (0.07 % at mode 23 of the paper's ring, against
/// 0.002 % for the free ring's k = 13): more than a refined chain's discretization error,
/// so each discretization is measured against its own limit.
struct References {
  std::optional<ring::ModalResult> extensible, inextensible;
  /// The reference `solver` converges to under the scene's options.
  const ring::ModalResult& of(const ring::Scene& scene, const std::string& solver) const;
};

/// True when `solver` under the scene's options converges to the inextensible ring.
bool inextensible_limit(const ring::Scene& scene, const std::string& solver);

/// Computes the FE references the scene's columns need (each at most once).
References compute_references(const ring::Scene& scene, std::ostream* progress);

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
  double reference_estimate = 0.0;  ///< the references' largest remaining relative error
  std::vector<ConvergenceSeries> series;
};

/// Refines every solver the scene runs, each measured against its own limit, over its
/// registry entry's refinements (size x 1, 2, 4, ...: the chains 5, FE 4 at the scene's
/// degree), with a Richardson column where the entry asks for one. Modes are paired with the reference
/// by MAC. Points closer to the reference than 100x its tolerance are left out of the fit.
ConvergenceStudy converge(const ring::Scene& scene, const References& references, std::ostream* progress);

/// Max and mean |error| in % of `r` against `reference` over the first `modes` modes,
/// paired by MAC. O(modes^2 kStations).
std::pair<double, double> errors_against(const ring::ModalResult& r, const ring::ModalResult& reference, int modes);

/// Least-squares slope of log(y) against log(x), negated (the observed order).
double fitted_order(const std::vector<double>& x, const std::vector<double>& y);

std::string convergence_text(const ConvergenceStudy& c);
void write_convergence(const std::string& dir, const ConvergenceStudy& c);

}  // namespace cmp
