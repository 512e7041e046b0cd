// Running the ccx program on a deck in a private temporary folder.
//
// - ccx is looked up on the PATH; missing: ring::InputError naming the solver and the
//   Debian package (exit 2).
// - The job runs in a fresh folder under $TMPDIR (or /tmp), `ringvib-ccx-XXXXXX`, with
//   ccx's threads set by OMP_NUM_THREADS, CCX_NPROC_EQUATION_SOLVER, CCX_NPROC_STIFFNESS
//   and CCX_NPROC_RESULTS; its standard output and error go to a file in that folder.
// - A run that exits non-zero, dies of a signal, prints "*ERROR" or outlasts the timeout
//   (then it is killed) is ring::NumericalError (exit 3) with the last lines of its output.
// - The folder is removed on every exit from run(); a signal to ringvib is the caller's to
//   handle: Hooks tell it the folder and the child as they come and go (ringvib's signal
//   handler, compare/files.cpp, kills the child and removes the folder).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace calculix {

/// What the caller's signal handling must know while ccx runs.
struct Hooks {
  std::function<void(const std::string& folder)> folder_made, folder_removed;
  std::function<void(int pid)> child;  ///< the running ccx; 0 when it ended
  /// Called about every 10 ms while ccx runs, on the calling thread. An exception it throws
  /// (an interruption: the Python module's Ctrl-C) kills ccx, removes the job folder and
  /// leaves run() as that exception.
  std::function<void()> poll;
};

struct RunOptions {
  double timeout = 600.0;  ///< s
  int threads = 1;
};

/// The most of ccx's output that run() holds, bytes (RunOutput::log).
constexpr std::size_t kLogKeep = std::size_t(128) << 10;

/// What a successful run leaves: the files ringvib reads, and ccx's output.
struct RunOutput {
  std::string dat;          ///< job.dat
  std::string sta;          ///< job.sta (the increments of a nonlinear step)
  /// ccx's standard output and error: whole up to kLogKeep bytes, else its first and last
  /// kLogKeep / 2 bytes (where ccx prints the equation count, and its last lines) joined by
  /// a line that says how much was left out.
  std::string log;
  double seconds = 0.0;     ///< wall time of the ccx process
  double cpu_seconds = 0.0; ///< its user + system time
};

/// The full path of ccx on the PATH, or "" if there is none.
std::string find_ccx();

/// Throws ring::InputError (exit 2) naming `solver` and the package when ccx is missing.
void require_ccx(const std::string& solver = "calculix");

/// The temporary folder jobs run in: $TMPDIR if set and not empty, else /tmp.
std::string temp_root();

/// What every run needs of its environment, checked before anything is computed: ccx on
/// the PATH (require_ccx) and temp_root() an existing folder that this process can write
/// and enter. Throws ring::InputError (exit 2) naming TMPDIR (or /tmp) and why.
void require_environment(const std::string& solver = "calculix");

/// Runs ccx on `deck` (job name "ring") and returns its output. Throws as above.
RunOutput run(const std::string& deck, const RunOptions& options, const Hooks& hooks = {});

/// The last `lines` lines of `text`.
std::string tail(const std::string& text, int lines);

}  // namespace calculix
