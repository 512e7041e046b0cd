// `ringvib sweep`: one scene run over many variations of its keys, for method research.
// Each case is the scene with `--set` overrides; every case is validated before any
// runs; the cases run on all cores (threads), or across machines under MPI (dynamic
// distribution from rank 0); the rows come out in case order whatever the schedule, so a
// serial run, a threaded run and an MPI run write the same table apart from timings.
//
// Usage:
//   ringvib sweep scenes/sweep-thickness.toml --vary multibody.n=[20,40,80]
//       --vary 'ring.section=[{diameter=0.01}, {diameter=0.1}]' --out out/sweep
#pragma once

#include <functional>
#include <map>
#include <limits>
#include <string>
#include <vector>

#include "compare/commands.hpp"

namespace cmp {

struct SweepArgs {
  std::vector<std::string> vary;  ///< "key=[v1, v2, ...]" (values in TOML syntax)
  bool zip = false;               ///< lists in lockstep instead of their product
  std::string out;                ///< folder for sweep.csv, sweep.json, sweep.md, sweep.png
  bool resume = false;            ///< skip the cases already in out/sweep.csv with status ok
  int jobs = 0;                   ///< threads (0: all cores; under MPI: per rank, default 1)
  int ranks = 0;                  ///< > 0: start mpirun -np ranks itself (mpi::launch)
};

/// One row of the sweep's table. `values` are the varied keys' values as TOML text
/// (sweep_cases).
struct SweepRow {
  int index = 0;                       ///< case number, 0-based, in product (or zip) order
  std::vector<std::string> values;
  std::string solver;                  ///< "multibody", ..., or "" for a case that failed before
  std::string analysis;                ///< "modes", "response", "static"
  std::string quantity;                ///< "mode 3", "peak_u at 0 deg", "u at 90 deg"
  double value = 0.0;                  ///< omega (rad/s) or displacement (m)
  double error_pct = 0.0;              ///< against the reference; NaN without one
  long long unknowns = 0;
  double seconds = 0.0;
  std::string status = "ok";           ///< "ok", "input-error", "numerical-failure"
  std::string message;
};

/// The cases of the --vary lists: each case the values of `keys` in order. A --vary is
/// KEY=[v1, v2, ...] with the list in TOML (it may span lines); each value comes back as
/// one line of TOML text that reads back to the same value (ring::toml_array_items: the
/// form the table shows and the case's override uses). Throws ring::InputError for a
/// malformed --vary, a key given twice or inside another (ring.section and
/// ring.section.diameter), lists of different lengths with zip, or more than INT_MAX or
/// `max_cases` cases (counted before the list is built: the cost guard's bound on a
/// sweep's cases, check_sweep_cost says the rest).
std::vector<std::vector<std::string>> sweep_cases(const std::vector<std::string>& vary, bool zip,
                                                  std::vector<std::string>& keys,
                                                  double max_cases = std::numeric_limits<int>::max());

/// The cases already complete in `file` (a sweep.csv of the same keys; `--resume`), by
/// their values: a case of `cases` is kept only if every row it would have is there
/// (`expected_rows(i)` for case i) and ok. A missing file keeps nothing; a last line cut
/// short (a crash, a full disk) drops its case; any other malformed line or value is a
/// ring::InputError naming the file and the line, and so is a file that is not a regular
/// file or is over ring::kMaxResumeBytes (ring::read_input_file: checked before it is
/// opened).
std::map<std::vector<std::string>, std::vector<SweepRow>> done_cases(
    const std::string& file, const std::vector<std::string>& keys, const std::vector<std::vector<std::string>>& cases,
    const std::function<double(std::size_t)>& expected_rows);

/// Runs one case: the scene `text` (read once by the sweep) with a.set and the case's
/// overrides, every analysis it lists, as rows. A case that fails is one row with its
/// status and message; it never throws.
std::vector<SweepRow> run_case(const std::string& text, const CommonArgs& a, int index,
                               const std::vector<std::string>& overrides, const std::vector<std::string>& values);

/// The table as CSV (header: case, the varied keys, solver, analysis, quantity, value,
/// error_pct, unknowns, seconds, status, message) and as JSON ({"keys", "rows": [...]}).
std::string sweep_csv(const std::vector<std::string>& keys, const std::vector<SweepRow>& rows);
std::string sweep_json(const std::vector<std::string>& keys, const std::vector<SweepRow>& rows);

/// A sweep's table: the varied keys and every case's rows, in case order.
struct SweepTable {
  std::vector<std::string> keys;
  std::vector<SweepRow> rows;
};
/// The cases of `vary` (as --vary) on the scene `text` with a.set, checked before any runs
/// (the cases, the cost guard, every case's scene) and run on `jobs` threads (0: all cores),
/// as `ringvib sweep` runs them without MPI or --resume; `on_case(finished, total, failed)`
/// after each case, one call at a time. Throws ring::InputError before anything runs, and
/// ring::NumericalError when every case failed. The Python module's sweep.
SweepTable run_sweep(const std::string& text, const CommonArgs& a, const std::vector<std::string>& vary, bool zip,
                     int jobs, const std::function<void(int, int, int)>& on_case);

/// The subcommand. Exit 0 when the sweep completes (failed cases are rows); 2 for bad
/// input, found before any case runs (every case is checked); 3 when every case failed,
/// and then nothing is published.
int cmd_sweep(const CommonArgs& a, const SweepArgs& s, int argc, char** argv);

}  // namespace cmp
