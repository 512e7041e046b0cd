// The forced response and the statics of a scene, and their text/CSV/JSON forms.
// Both run the multibody chain (the paper's section 5).
#pragma once

#include <string>

#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// Integrates the scene's [response] with its first solver. Throws
/// ring::IntegrationFailure when the integration stops early.
ring::TimeHistory respond(const ring::Scene& scene);
/// Solves the scene's [static].
ring::StaticResult solve_static(const ring::Scene& scene);

/// CSV with header t, ux_<deg>, uy_<deg> per recorded point, kinetic, strain, work,
/// energy_error, constraint_residual, newton_iterations (README, "The command").
std::string history_csv(const ring::TimeHistory& h);
/// {"displacements": [{"angle", "ux", "uy"}...], "steps", "newton_iterations", "solver",
/// "unknowns", "seconds"}.
std::string static_json(const ring::StaticResult& r);
std::string static_text(const ring::StaticResult& r);

/// Figures of a response: time histories of the recorded points, and the deformed
/// ring at the snapshot instants (the paper's Figure 5).
void plot_response(const std::string& dir, const ring::TimeHistory& h, double radius);

}  // namespace cmp
