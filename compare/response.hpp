// One solver's forced response and statics as text, CSV and JSON, and the figures of one
// response (the paper's Figures 4 and 5).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// CSV with header t, ux_<deg>, uy_<deg> per recorded point, kinetic, strain, (a plastic ring: dissipated,) work,
/// energy_error, constraint_residual, newton_iterations (docs/commands.md, "What each command does").
std::string history_csv(const ring::TimeHistory& h);
/// {"displacements": [{"angle", "ux", "uy"}...], "steps", "newton_iterations", "solver",
/// "unknowns", "seconds", "dissipated", "plastic_curvature"}; with a path also "end",
/// "end_load", "branch_points", "path_points" and "path": [{"load_factor", "displacements",
/// "ovalisation", "dissipated", "plastic_curvature"}].
std::string static_json(const ring::StaticResult& r);
std::string static_text(const ring::StaticResult& r);
/// static.path: one line per solver with a path: its equilibria, branch points and end.
std::string path_summary(const std::vector<ring::StaticResult>& results);
/// static.path: the path as CSV (load_factor, ovalisation, ux_A, uy_A for each recorded point,
/// dissipated, plastic_curvature).
std::string static_path_csv(const ring::StaticResult& r);
/// static.path: load factor against ovalisation (a ring) or against the displacements of the first
/// recorded point (an arch), every solver's path overlaid (static_path.png).
/// static.displacement (`drive` its value at load factor 1): the reaction's component along
/// the drive (N) against the driven point's displacement along it (m) instead.
void plot_static_paths(const std::string& dir, const std::vector<ring::StaticResult>& results, const ring::RingSpec& ring,
                       const std::optional<std::array<double, 2>>& drive = std::nullopt);
/// static.history: load factor against the displacement of the first recorded point (its
/// component with the larger range), every solver's path overlaid (static_history.png): the
/// loops of cyclic loading of a plastic ring.
void plot_static_history(const std::string& dir, const std::vector<ring::StaticResult>& results,
                         const std::optional<std::array<double, 2>>& drive = std::nullopt);
/// static_path_shapes.png: the deformed ring of `r`'s path at five equilibria, nearest to 0,
/// 1/4, ..., 1 of its largest ovalisation (rest to the touch), true to scale.
void plot_path_shapes(const std::string& dir, const ring::StaticResult& r, const ring::RingSpec& ring);

/// Figures of a response: time histories of the recorded points, and the deformed
/// ring at the snapshot instants (the paper's Figure 5).
void plot_response(const std::string& dir, const ring::TimeHistory& h, const ring::RingSpec& ring);

}  // namespace cmp
