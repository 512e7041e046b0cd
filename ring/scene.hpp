// A scene: one TOML file that says what to compute (DESIGN.md, "Scene files").
// Parsed and validated once; the driver computes exactly what it lists.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ring/spec.hpp"

namespace ring {

/// Which modes to compute, with which solvers.
struct ModesRequest {
  int count = 23;                     ///< elastic modes (rigid ones are counted apart)
  std::vector<std::string> solvers;   ///< subset of {"multibody", "lumped", "fem"}
};

/// The three-way table: the base column, then each other solver and its difference.
struct TableRequest {
  bool present = false;               ///< the scene has a [table] section
  std::string base = "multibody";
  std::vector<std::string> against;   ///< other solvers, in column order
  bool reference = false;             ///< add the converged FE reference and errors
};

/// An accuracy gate for CI: max |value| in percent over modes [first, last].
struct Gate {
  std::string solver;                 ///< the column gated
  double max_pct = 0.0;               ///< largest allowed |error| or |difference|, %
  std::string against = "reference";  ///< "reference", "paper", or another solver's name
  int first_mode = 1, last_mode = 0;  ///< 1-based, inclusive; last 0 = all requested
};

/// Forced nonlinear response (the paper's section 5).
struct ResponseOptions {
  PointLoad load;                      ///< at, force, history, period
  double dt = 0.01;                    ///< s
  double t_end = 5.0;                  ///< s
  enum class Integrator { newmark, generalized_alpha };
  Integrator integrator = Integrator::newmark;
  double rho_inf = 0.8;                ///< generalized-alpha spectral radius, [0, 1]
  std::vector<double> record;          ///< degrees, points written
  double rayleigh_mass = 0.0;          ///< C = a M + b K: a, 1/s
  double rayleigh_stiffness = 0.0;     ///< b, s
  double hinge_damping = 0.0;          ///< N m s/rad at every hinge
};

/// Nonlinear statics under a point load, by load stepping.
struct StaticOptions {
  PointLoad load;
  int steps = 20;
  std::vector<double> record;
};

/// Everything a scene file can say, validated.
struct Scene {
  std::string file;    ///< the path it was read from ("" for scenes built in code)
  std::string title;
  RingSpec ring;
  MultibodyOptions multibody;
  FemOptions fem;
  LumpedOptions lumped;
  ModesRequest modes;
  TableRequest table;
  std::vector<Gate> gates;
  std::optional<ResponseOptions> response;
  std::optional<StaticOptions> statics;
  std::vector<std::string> warnings;   ///< e.g. the thin-ring assumption stretched
  std::string resolved_toml;           ///< the scene after --set overrides, as TOML

  /// True when the solver ("multibody", "lumped", "fem") is a column: in modes.solvers
  /// or in the table.
  bool column(const std::string& solver) const;
  /// True when the converged FE reference is asked for (table.reference or a gate).
  bool needs_reference() const;
  /// True when some requested output needs this solver's modes (a column, or the FE
  /// reference). Nothing else is built: a scene that doesn't need FE never loads it.
  bool needs(const std::string& solver) const;
};

/// Reads and validates a scene. `overrides` are "section.key=value" with the value in
/// TOML syntax (a bare word is taken as a string). Throws InputError naming the file
/// and the key (exit code 2) on a missing file, malformed TOML (with line and column),
/// an unknown key (with the nearest known key), a wrong type or a value out of range.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

/// Same, from TOML text; `name` is used in messages in place of a file name.
Scene parse_scene(const std::string& toml_text, const std::string& name,
                  const std::vector<std::string>& overrides = {});

/// The number of elastic modes the solver's model has under the scene's options
/// (n - 3 for the chains; what the frame and FE unknowns leave after supports and rigid modes).
long long max_elastic_modes(const Scene& scene, const std::string& solver);

/// The known solver names, in the canonical order.
const std::vector<std::string>& solver_names();

}  // namespace ring
