// Files written atomically: content goes to a temporary name in the same folder and
// is renamed into place, so an interrupted run never leaves a half-written result.
#pragma once

#include <string>

#include "ring/results.hpp"

namespace cmp {

/// Writes `content` to `path` via `path.tmp-<pid>` and rename(2). Throws
/// std::runtime_error naming the path on failure.
void write_file(const std::string& path, const std::string& content);

/// Creates `dir` and its parents if needed. Throws ring::InputError if impossible.
void make_dirs(const std::string& dir);

/// A model description value as text (booleans as true/false).
std::string model_value(const ring::ModelValue& v);

/// Formats a frequency to 4 significant digits like the paper (2.463, 11.30, 101.5).
std::string sig4(double v);
/// Formats a percentage with two decimals (-0.93).
std::string pct2(double v);

}  // namespace cmp
