// A scene: one TOML file that says what to compute (docs/scenes.md).
// Parsed and validated once; the driver computes exactly what it lists.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ring/analysis.hpp"
#include "ring/input_file.hpp"
#include "ring/options_schema.hpp"
#include "ring/spec.hpp"

namespace ring {

/// Which modes to compute, with which solvers.
struct ModesRequest {
  int count = 23;                     ///< elastic modes (rigid ones are counted apart)
  std::vector<std::string> solvers;   ///< subset of the known solvers (SceneSchema)
  /// "static": the modes about the nonlinear static equilibrium of [static] at its full
  /// load (its tangent stiffness, the prestress's geometric and the loads' own stiffness
  /// included), the frequencies under load; false: about the unloaded ring.
  bool preload_static = false;
  /// modes.frame: a spinning ring's frequencies in the fixed frame (true) or in the frame
  /// that turns with it (false, the default); ring/results.hpp, ModalResult::frame.
  bool fixed_frame = false;
};

/// A column of another code's results ([[table.import]]): frequencies from a CSV file
/// (`mode,omega` in rad/s or `mode,hz`), optionally its mode shapes at the common
/// stations (the layout of shapes_<solver>.csv), so that its modes pair by MAC.
struct ImportedColumn {
  std::string label;   ///< column name, gate key (gates.<label>); not a solver's name
  std::string file;    ///< path as resolved against the scene's folder
  std::string shapes;  ///< "" or the shapes file, resolved the same way
};

/// The three-way table: the base column, then each other solver and its difference.
struct TableRequest {
  bool present = false;               ///< the scene has a [table] section
  std::string base;                   ///< default: SceneSchema::default_solver
  std::vector<std::string> against;   ///< other solvers, in column order
  bool reference = false;             ///< add the converged FE reference and errors
  std::vector<ImportedColumn> imports;  ///< other codes' columns, after the solvers'
};

/// An accuracy gate for CI: max |value| in percent over modes [first, last].
struct Gate {
  std::string solver;                 ///< the column gated
  double max_pct = 0.0;               ///< largest allowed |error| or |difference|, %
  std::string against = "reference";  ///< "reference", "paper", or another solver's name
  int first_mode = 1, last_mode = 0;  ///< 1-based, inclusive; last 0 = all requested
  /// What is gated: "modes" (frequencies), "response" (peak |u| at the recorded points)
  /// or "static" (|u| at the recorded points).
  std::string analysis = "modes";
};

/// Which solvers run a nonlinear analysis ([response] or [static]), and whether the
/// converged FE reference is added.
struct NonlinearRequest {
  std::vector<std::string> solvers;   ///< default: SceneSchema::default_solver alone
  bool reference = false;
};

struct Scene;

/// What the scene reader must know of one solver to check a scene. The driver's solver
/// registry supplies these; the vocabulary itself names no solver.
struct SolverSchema {
  std::string name;                   ///< also the name of its option section
  std::string size_key;               ///< the discretization key named in messages ("multibody.n")
  /// Pieces around the ring under the scene's options: nodes at anchor + 360 k / size.
  std::function<int(const Scene&)> size;
  /// How many elastic modes its model has under the scene's options.
  std::function<long long(const Scene&)> elastic_modes;
  bool statics = false;               ///< offers nonlinear statics
  bool response = false;              ///< offers the forced nonlinear response
  bool buckling = false;              ///< offers linear buckling
  /// Integer options of its section whose valid range replaces the one `options` declares,
  /// by key: the reader refuses a value outside [first, second], naming the key. The
  /// registry's solvers declare their ranges in `options` and leave this empty.
  std::map<std::string, std::pair<long long, long long>> integer_ranges;
  /// Its section's keys (ring/options_schema.hpp, from the solver's folder). The reader
  /// checks the section against them (unknown keys with the nearest known one, types,
  /// ranges, choices; a theory key's "timoshenko" against the ring's shear coefficient) and
  /// keeps every value, given or defaulted, in Scene::options[name].
  OptionSchema options;
  /// Fills the solver's option struct of the scene from those values (the registry's: the
  /// solver's read_options); called before the cross-checks, which ask `size` and
  /// `elastic_modes`. Empty: the values stay in Scene::options alone.
  std::function<void(Scene&, const OptionValues&)> store;
};

/// All the solvers a scene may name.
struct SceneSchema {
  std::vector<SolverSchema> solvers;
  std::string default_solver;         ///< table base and nonlinear default (the paper's method)
  std::string reference_solver;       ///< the solver whose converged run is the reference
  const SolverSchema* find(const std::string& name) const;
  std::vector<std::string> names() const;
};

/// Everything a scene file can say, validated.
struct Scene {
  std::string file;    ///< the path it was read from ("" for scenes built in code)
  std::string title;
  RingSpec ring;
  MultibodyOptions multibody;
  FemOptions fem;
  LumpedOptions lumped;
  CalculixOptions calculix;
  /// Each solver section as the reader read it against the solver's schema, by solver
  /// name: every key, given or defaulted (SolverSchema::options). The option structs above
  /// are filled from these by SolverSchema::store; a solver without a struct here reads them.
  std::map<std::string, OptionValues> options;
  ModesRequest modes;
  TableRequest table;
  std::vector<Gate> gates;
  std::optional<ResponseOptions> response;
  NonlinearRequest response_request;   ///< response.solvers, response.reference
  std::optional<StaticOptions> statics;
  NonlinearRequest static_request;     ///< static.solvers, static.reference
  std::optional<BucklingOptions> buckling;
  NonlinearRequest buckling_request;   ///< buckling.solvers, buckling.reference
  std::vector<std::string> warnings;   ///< e.g. the thin-ring assumption stretched
  std::string resolved_toml;           ///< the scene after --set overrides, as TOML

  std::string reference_solver;        ///< copied from the schema it was read with

  /// True when the solver is a column: in modes.solvers or in the table.
  bool column(const std::string& solver) const;
  /// True when `label` is an imported column of the table ([[table.import]]).
  bool imported(const std::string& label) const;
  /// True when the converged modal reference is asked for (table.reference or a gate).
  bool needs_reference() const;
  /// True when some requested output needs this solver's modes (a column, or the
  /// reference). Nothing else is built: a scene that doesn't need FE never loads it.
  bool needs(const std::string& solver) const;
  /// True when a nonlinear analysis of the scene runs this solver (or its reference).
  bool runs_nonlinear(const std::string& solver) const;
  /// True when [buckling] runs this solver (or its reference).
  bool runs_buckling(const std::string& solver) const;
};

/// The deepest nesting of tables and arrays (dotted-key parts, [table] header parts, open
/// arrays and inline tables) at any point of a scene; its largest size is kMaxSceneBytes
/// (ring/input_file.hpp).
constexpr std::size_t kMaxNesting = 1000;

/// Refuses TOML text nested deeper than kMaxNesting at some point (InputError naming `name`
/// and the line), before a parser recurses into it. Dots and brackets in strings, comments
/// and numbers do not count. O(size of text).
void check_nesting(const std::string& text, const std::string& name);

/// Reads and validates a scene against the known solvers. `overrides` are
/// "section.key=value" with the value in TOML syntax (a bare word is taken as a string).
/// Throws InputError naming the file and the key (exit code 2) on a missing file,
/// malformed TOML (with line and column), an unknown key (with the nearest known key), a
/// wrong type or a value out of range, a solver that is not in the schema or does not
/// offer the analysis, more modes than a model has, or a point that is not a node of a
/// model that uses it.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, const SceneSchema& schema);

/// The text of the scene file at `path` (at most kMaxSceneBytes; a FIFO or /dev/stdin is
/// read once: read_input_file's InputKind::stream), for a caller that parses it several
/// times (a sweep's cases). Throws InputError naming the path.
std::string read_scene_text(const std::string& path);

/// The elements of a TOML array given as text (a `--vary` list: "[v1, v2, ...]", which may
/// span lines and hold comments), each as one line of TOML text that an override
/// "key=<item>" reads back to exactly the same value: integers in decimal, floats in the
/// shortest form that reads back to the same double (0.1, 1e-300; 1e4 becomes 10000.0),
/// strings as basic strings with escapes ("a\"b"), booleans, arrays and inline tables
/// inline (`{ diameter = 0.01 }`, keys in order). Every item is read back and compared.
/// Throws InputError naming `where` for text that is not one non-empty TOML array, or
/// nests deeper than kMaxNesting.
std::vector<std::string> toml_array_items(const std::string& text, const std::string& where);

/// `s` as a TOML basic string ("..." with escapes; one line, whatever it holds).
std::string toml_quoted(std::string_view s);

/// Same as load_scene, from TOML text; `name` is used in messages in place of a file name.
Scene parse_scene(const std::string& toml_text, const std::string& name, const std::vector<std::string>& overrides,
                  const SceneSchema& schema);

}  // namespace ring
