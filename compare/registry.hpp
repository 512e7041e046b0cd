// The solver registry: the one place that names the solvers. Tables, convergence,
// benchmarks, gates, the scene's solver checks, the scene reference (`ringvib keys`) and the
// command line loop over it. Adding a solver is its folder (its analyses and its option
// schema, e.g. multibody/options.hpp) and one entry in registry.cpp; a program or a test
// may add one at start-up with add_solver (tests/compare/test_toy_solver.cpp).
//
// Usage:
//   const ring::Scene s = cmp::load_scene("scenes/paper1990.toml", {});
//   for (const cmp::SolverEntry& e : cmp::registry())
//     if (s.column(e.name)) ring::ModalResult r = e.modes(s, s.modes.count);
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ring/paper_table.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// One solver as the driver sees it. An analysis the solver does not offer is an empty
/// function.
struct SolverEntry {
  std::string name;       ///< scene and command-line name; also its option section
  std::string label;      ///< column header in tables ("lumped mass", "FE")
  std::string size_key;   ///< the discretization key ("multibody.n", "fem.elements")
  std::string size_name;  ///< what the size counts, in tables ("n", "elements")
  /// Its option section's keys, from the solver's folder (ring/options_schema.hpp): the
  /// scene reader checks the section against them and `ringvib keys` prints them.
  ring::OptionSchema options;
  /// Fills the solver's options of the scene from what the reader read of its section
  /// (ring::SolverSchema::store); empty for a solver that reads Scene::options itself.
  std::function<void(ring::Scene&, const ring::OptionValues&)> store;

  /// Pieces around the ring (nodes at anchor + 360 k / size), and the scene with it changed.
  std::function<int(const ring::Scene&)> size;
  std::function<void(ring::Scene&, int)> set_size;
  /// The beam theory of its model under the scene's options (multibody.theory, fem.theory,
  /// lumped.variant): ring.theory is the ring's physics, this the model the solver is.
  /// Empty: the solver models ring.theory. Every other function of the entry receives
  /// model_scene(scene, entry), the scene with ring.theory replaced by it.
  std::function<ring::Theory(const ring::Scene&)> theory;
  /// The key that sets `theory` ("fem.theory", "lumped.variant"), for messages.
  std::string theory_key;
  /// Elastic modes the model has under the scene's options.
  std::function<long long(const ring::Scene&)> elastic_modes;
  /// True when the model converges to the inextensible ring (rigid links), false for
  /// the extensible one (frames, FE with EA).
  std::function<bool(const ring::Scene&)> inextensible;
  /// The curve name in convergence and benchmark output ("lumped (chain)", "fem (p = 3)").
  std::function<std::string(const ring::Scene&)> curve;
  /// The refinements `ringvib bench` times, as scenes (curve name, scene).
  std::function<std::vector<std::pair<std::string, ring::Scene>>(const ring::Scene&, int modes)> bench_sweep;
  int converge_steps = 5;      ///< refinements size x 1, 2, 4, ... in `ringvib converge`
  bool richardson = false;     ///< add a Richardson column (order 2) in convergence and bench
  /// Estimated peak memory (bytes) of `count` modes (count 0: the nonlinear solves) under
  /// the scene's options, for the cost guard (guard.hpp); calibrated in docs/commands.md ("Cost guard").
  std::function<double(const ring::Scene&, int count)> memory;
  /// Estimated peak memory (bytes) of its linear buckling (dense pencils), for the cost guard.
  std::function<double(const ring::Scene&)> buckling_memory;
  /// Memory of the code the solver loads on first use (a plug-in and its libraries), for
  /// the cost guard; 0 for a solver linked into ringvib.
  double code_bytes = 0.0;
  /// Its column of the paper's Table 1 (corrected values), if it has one.
  std::function<std::optional<double>(const ring::PaperRow&)> paper;

  /// What the solver refuses before it computes, per analysis, under the scene's options
  /// (check_scene calls them for the analyses the scene runs with the solver, and with
  /// reference_scene for the reference). Throw std::invalid_argument. O(1). Empty: none.
  std::function<void(const ring::Scene&)> check_modes, check_static, check_response, check_buckling;

  /// Analyses. Each throws ring::InputError (exit 2) for a request that cannot work and
  /// ring::NumericalError (exit 3; ring::IntegrationFailure for a response) on failure.
  std::function<ring::ModalResult(const ring::Scene&, int count)> modes;
  std::function<ring::StaticResult(const ring::Scene&)> statics;
  std::function<ring::TimeHistory(const ring::Scene&)> response;
  /// Linear buckling under the scene's [buckling] (ring::BucklingOptions).
  std::function<ring::BucklingResult(const ring::Scene&)> buckling;
  /// Why the solver has no `buckling`, for the refusal (empty: not said).
  std::string no_buckling_because;
  /// Writes the `count` lowest mode shapes as VTU files into `dir` (ParaView), if offered.
  std::function<void(const ring::Scene&, int count, const std::string& dir)> write_vtu;
};

/// Every solver, in the canonical order (the paper's method first).
const std::vector<SolverEntry>& registry();
/// Adds a solver after the built-in ones, its analyses wrapped as theirs are (model theory,
/// finite results, solver name and wall time), so that scenes, commands and the scene
/// reference know it. Throws std::invalid_argument for a name the registry has already or an
/// option schema of another section (a name that is a scene section, "modes", is refused by
/// the reader as a std::logic_error). Not thread-safe: call it before any scene is read or any command
/// runs; it invalidates references into registry() and scene_schema().
void add_solver(SolverEntry entry);
/// Removes a solver that add_solver added (built-in solvers stay); same caveats.
void remove_solver(const std::string& name);
/// The entry of `name`; throws ring::InputError naming the known solvers.
const SolverEntry& solver(const std::string& name);
/// The entry of `name`, or null ("reference" and other column names are not solvers).
const SolverEntry* find_solver(const std::string& name);
/// The names, in registry order.
std::vector<std::string> solver_names();
/// What the scene reader needs of the registry.
const ring::SceneSchema& scene_schema();
/// The scene reference of the solver sections, in Markdown: each solver's option schema as
/// a table (ring::markdown), in registry order. `ringvib keys` prints it; docs/scenes.md
/// holds it between the markers kKeysBegin and kKeysEnd (a test keeps them equal).
std::string keys_markdown();
inline constexpr const char* kKeysBegin = "<!-- begin: generated by `ringvib keys` -->";
inline constexpr const char* kKeysEnd = "<!-- end: generated by `ringvib keys` -->";

/// Reads and validates a scene against the registry (ring::load_scene).
ring::Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});
ring::Scene parse_scene(const std::string& toml_text, const std::string& name,
                        const std::vector<std::string>& overrides = {});

/// The model's scales (ring::scale_violation: values whose products overflow, named by
/// their key), then every solver's checks (SolverEntry::check_*) for the analyses the scene
/// runs with it, and the reference solver's for the references it asks for: the scene is
/// refused (ring::InputError naming the key, solver or analysis, exit 2) before any solver
/// runs.
void check_scene(const ring::Scene& scene);
/// One solver's modal checks (SolverEntry::check_modes) on the scene, as check_scene runs
/// them for its columns: for `modes --solver NAME` on a solver the scene does not list.
void check_modes_of(const ring::Scene& scene, const SolverEntry& e);

/// The scene the converged references run: the reference solver's reference option on,
/// and its model theory that of the ring (fem.theory dropped: the reference is the physics).
ring::Scene reference_scene(const ring::Scene& scene);
/// The scene a solver computes: `scene` with ring.theory replaced by the solver's model
/// theory (SolverEntry::theory; unchanged for a solver without one). The registry's
/// entries apply it themselves; O(size of the scene), a copy.
ring::Scene model_scene(const ring::Scene& scene, const SolverEntry& e);

/// No NaN or infinity is a result: each throws ring::NumericalError (exit 3) naming the
/// solver and the first value of the result that is not finite (its quantity, mode or
/// recorded point, and step or station). Every analysis of the registry's entries passes
/// through them, so a solver's overflow is reported, never printed. Checked: frequencies,
/// max_residual (where reported), shapes; load factors; displacements, node positions and
/// path points; the time history's times and displacements and its snapshots (its energy
/// columns are the energy guard's, ring/energy_guard.hpp, and NaN in ccx's, which computes
/// none). O(size of the result).
void require_finite(const ring::ModalResult& r);
void require_finite(const ring::BucklingResult& r);
void require_finite(const ring::StaticResult& r);
void require_finite(const ring::TimeHistory& r);

/// The `count` lowest elastic modes of a solver with the scene's options.
ring::ModalResult solve_modes(const ring::Scene& scene, const std::string& name, int count);
/// The converged modal reference: the reference solver with its reference option on.
ring::ModalResult reference_modes(const ring::Scene& scene, int count);
/// The converged nonlinear references of the reference solver.
ring::StaticResult reference_static(const ring::Scene& scene);
ring::TimeHistory reference_response(const ring::Scene& scene);
ring::BucklingResult reference_buckling(const ring::Scene& scene);

}  // namespace cmp
