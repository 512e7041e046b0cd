// The subcommands of `ringvib` (docs/commands.md). Each returns the process
// exit code: 0 success, 1 a gate failed; bad input throws ring::InputError (2) and a
// numerical failure ring::NumericalError (3), caught in main().
#pragma once

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "compare/bench.hpp"
#include "compare/bench_nonlinear.hpp"
#include "compare/converge.hpp"
#include "compare/nonlinear.hpp"
#include "compare/table.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

struct CommonArgs {
  std::string scene;
  std::vector<std::string> set;  ///< --set section.key=value
  bool quiet = false;            ///< no progress on stderr
  double max_memory_gib = 8.0;   ///< --max-memory: the cost guard's budget
  bool force = false;            ///< --force: skip the cost guard
};

// ---- What the commands compute, shared with the Python module (python/module.cpp) ----
// Each checks the scene as its command does (after the scene reader and the cost guard) and
// returns the result that the command prints and the module converts: one place for the
// rules, so the two cannot drift apart.

/// The scene a nonlinear command runs for `solver` (`--solver NAME`): that solver alone and
/// no reference, so that the checks and the cost guard see only it (a solver the command
/// does not run cannot refuse the scene). Empty `solver`: the scene as it is.
ring::Scene narrowed(ring::Scene s, ring::NonlinearRequest ring::Scene::*request, const std::string& solver);
/// The solver a single-solver result is for: `option`, or the only one the request lists
/// without a reference; nothing when it compares several.
std::optional<std::string> single_solver(const std::string& option, const ring::NonlinearRequest& q);
/// `ringvib modes`: the `count` (default modes.count) lowest elastic modes of `solver`, its
/// checks run even where the scene does not list it; `count_key` names the count in errors.
ring::ModalResult run_modes(const ring::Scene& s, const std::string& solver, std::optional<int> count,
                            const std::string& count_key);
/// `ringvib table`: the modal comparison table (InputError when the scene asks for no modes).
Table run_table(const ring::Scene& s, bool paper, std::ostream* progress);
/// `ringvib static|respond|buckling` with one solver (`solver` as single_solver names it):
/// its result, the scene's section required. `s` is already narrowed.
ring::StaticResult run_static(const ring::Scene& s, const std::string& solver, std::ostream* progress);
ring::TimeHistory run_response(const ring::Scene& s, const std::string& solver, std::ostream* progress);
ring::BucklingResult run_buckling_of(const ring::Scene& s, const std::string& solver, std::ostream* progress);
/// The comparison tables `ringvib static|respond` print for the solvers of a run, and the
/// buckling table `ringvib buckling` prints (the scene's section required).
NonlinearTable static_comparison(const ring::Scene& s, const NonlinearRun& r);
NonlinearTable response_comparison(const ring::Scene& s, const NonlinearRun& r);
Table buckling_comparison(const ring::Scene& s, std::ostream* progress);
/// The section a command needs: InputError "the scene has no [section] section" otherwise.
void require_section(const ring::Scene& s, const std::string& section);

int cmd_run(const CommonArgs& a, const std::string& out_dir, const std::string& junit, bool paper);
int cmd_table(const CommonArgs& a, bool paper, const std::string& format);
int cmd_modes(const CommonArgs& a, const std::string& solver, std::optional<int> count, bool json,
              const std::string& vtu_dir);
/// One solver (--solver NAME, or the only one listed): its history as CSV. Several: the
/// comparison table of their peaks in `format` (text | md | csv | json).
int cmd_respond(const CommonArgs& a, const std::string& csv, const std::string& solver, const std::string& format);
/// One solver: its equilibrium (text, or JSON with --json). Several: the comparison table.
int cmd_static(const CommonArgs& a, bool json, const std::string& solver, const std::string& format);
/// [buckling]: one solver, its critical load factors (text, or JSON with --json); several
/// (or a reference), the buckling table in `format`.
int cmd_buckling(const CommonArgs& a, bool json, const std::string& solver, const std::string& format);
int cmd_converge(const CommonArgs& a, const std::string& out_dir);
/// The study `ringvib converge` prints (and the Python module's converge returns): every
/// solver of the scene refined against its own converged limit. Throws ring::InputError
/// when the scene asks for no modes.
ConvergenceStudy run_converge(const ring::Scene& s, std::ostream* progress);
int cmd_bench(const CommonArgs& a, const std::string& out_dir);
/// The studies `ringvib bench` prints (and the Python module's bench returns): the modal
/// sweep when the scene asks for modes, one sweep per nonlinear analysis. Throws
/// ring::InputError when the scene asks for nothing bench can time.
struct BenchRun {
  std::optional<BenchStudy> modal;
  std::vector<NonlinearBench> nonlinear;
};
BenchRun run_bench(const ring::Scene& s, std::ostream* progress);
/// Writes the input deck of an external solver (calculix: DIR/ring.inp, the deck its
/// column runs for modes.count modes) without running it.
int cmd_export_deck(const CommonArgs& a, const std::string& solver, const std::string& out_dir);
/// Prints the scene reference of every solver's section in Markdown (keys_markdown: the
/// keys, units, defaults, valid values and meanings their option schemas declare), the text
/// docs/scenes.md holds between its markers.
int cmd_keys();

/// Runs one command as `ringvib` does: its exit code, or the documented code of what it
/// throws with the message on `err` ("ringvib: error: ..."): ring::InputError and a
/// solver's std::invalid_argument 2 (the latter prefixed with `scene`), ring::NumericalError
/// and any other failure 3. main() and in-process callers (tests) share it.
int run_command(const std::string& scene, const std::function<int()>& command, std::ostream& err);

}  // namespace cmp
