// The nonlinear half of a scene: every solver's forced response and statics, run over
// the registry, and their comparison at the recorded points (a table like the modal one:
// the base solver's value, every other solver's difference (base - other) / other * 100,
// the paper's definition, and with a reference every solver's error against it).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// Every nonlinear result the scene asks for, in the order of response.solvers /
/// static.solvers, and the converged references if asked for.
struct NonlinearRun {
  std::vector<ring::TimeHistory> histories;
  std::optional<ring::TimeHistory> history_reference;
  std::vector<ring::StaticResult> statics;
  std::optional<ring::StaticResult> static_reference;
};

/// Runs the scene's [response] and [static] with every listed solver (or only `only`,
/// when not empty). An integration failure of any solver propagates
/// (ring::IntegrationFailure, with its solver's partial history).
NonlinearRun run_nonlinear(const ring::Scene& scene, const std::string& only = "", std::ostream* progress = nullptr);

/// One compared quantity at one recorded point.
struct NonlinearRow {
  static constexpr double kWholeRing = -1000.0;  ///< `angle` of a quantity of the whole ring
  double angle = 0.0;                ///< degrees, or kWholeRing ("ring" in the tables)
  bool whole_ring() const { return angle == kWholeRing; }
  std::string quantity;              ///< "peak_u", "t_peak" (response); "ux", "uy", "u" (statics)
  std::vector<double> value;         ///< per solver, table order
  std::vector<double> diff_pct;      ///< per solver; NaN for the base and where the other is ~0
  std::optional<double> reference;
  std::vector<double> error_pct;     ///< per solver, with a reference; NaN where it is ~0
};

struct NonlinearTable {
  std::string title;
  std::string analysis;              ///< "response" or "static"
  std::vector<std::string> solvers;  ///< base first
  std::vector<NonlinearRow> rows;
  bool has_reference() const { return !rows.empty() && rows.front().reference.has_value(); }
};

/// Response: per recorded point, the peak of |u| = sqrt(ux^2 + uy^2) over the history
/// and the time it occurs. Statics: ux, uy and |u| per recorded point, and for a plastic
/// ring the dissipated energy, for a path through a limit point its first limit load factor
/// (point "ring", quantities "dissipated" and "limit_load"). A relative
/// difference or error is left out (NaN) where the value it is taken against is below
/// 1e-9 of the largest value of that quantity (a pinned point, a symmetry plane).
NonlinearTable response_table(const std::string& title, const std::vector<ring::TimeHistory>& histories,
                              const ring::TimeHistory* reference);
NonlinearTable static_table(const std::string& title, const std::vector<ring::StaticResult>& results,
                            const ring::StaticResult* reference);

/// Text and Markdown with 4 significant digits; CSV and JSON at full precision. JSON:
/// {"title", "analysis", "base", "rows": [{"point", "quantity", "<solver>",
/// "<solver>_diff_pct", "reference", "<solver>_error_pct"}]} (null where not defined).
std::string format_text(const NonlinearTable& t);
std::string format_markdown(const NonlinearTable& t);
std::string format_csv(const NonlinearTable& t);
std::string format_json(const NonlinearTable& t);

/// Figures: the recorded displacements of every solver overlaid against time (the
/// paper's Figure 4) and the deformed ring of every solver at the snapshot instants
/// (Figure 5); the deformed ring of every solver under the static load.
void plot_histories(const std::string& dir, const std::vector<ring::TimeHistory>& histories, const ring::RingSpec& ring);
void plot_static_shapes(const std::string& dir, const std::vector<ring::StaticResult>& results, const ring::RingSpec& ring);

}  // namespace cmp
