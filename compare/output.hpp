// Files written atomically: content goes to a temporary name in the same folder and
// is renamed into place, so an interrupted run never leaves a half-written result.
#pragma once

#include <string>

#include "ring/results.hpp"

namespace cmp {

/// Writes `content` to `path` via `path.tmp-<pid>` and rename(2). The temporary file is
/// removed if a signal ends the run meanwhile (install_signal_cleanup). Throws
/// std::runtime_error naming the path on failure.
void write_file(const std::string& path, const std::string& content);

/// Creates `dir` and its parents if needed. Throws ring::InputError if impossible.
void make_dirs(const std::string& dir);

/// Checks, before anything is computed, that a file can be written at `path` (option
/// `option`, e.g. "--csv"): not a folder, not the scene file itself, its folder exists
/// and is writable. Throws ring::InputError naming the option and the user's path.
void check_output_file(const std::string& path, const std::string& option, const std::string& scene);
/// Same for a folder that will be created if missing (--out, --vtu): not an existing
/// file, and its nearest existing ancestor is a writable folder.
void check_output_dir(const std::string& dir, const std::string& option);

/// On SIGINT, SIGTERM and SIGHUP: remove every temporary file still being written, stop
/// the running gnuplot, and die of the signal (exit status 128 + signal in a shell).
void install_signal_cleanup();
/// Temporary paths (files, or empty folders) to remove if a signal ends the run, and
/// the child process to stop; registered and released by the writers.
void register_temporary(const std::string& path);
void release_temporary(const std::string& path);
void register_child(int pid);
/// `dir` is the staging folder of this run: it and every file finished in it are
/// removed on a signal until publish_folder moves them into place.
void begin_staging(const std::string& dir);
/// Called by the writers when `path` is complete (see begin_staging).
void finished_file(const std::string& path);

/// Replaces the files of an earlier ringvib run in `dir` by the files in `staging` (a
/// sibling folder the new run wrote): the files listed in dir's manifest
/// (.ringvib-files) are removed, the new ones renamed in, the manifest rewritten, and
/// `staging` removed. Files in `dir` that ringvib did not write stay.
void publish_folder(const std::string& staging, const std::string& dir);

/// A model description value as text (booleans as true/false).
std::string model_value(const ring::ModelValue& v);

/// Formats a frequency to 4 significant digits like the paper (2.463, 11.30, 101.5).
std::string sig4(double v);
/// Formats a percentage with two decimals (-0.93).
std::string pct2(double v);

}  // namespace cmp
