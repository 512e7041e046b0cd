// The pairs of an imperfect ring: a perfect ring's modes of wave number k >= 1 come in
// degenerate pairs (cos k theta, sin k theta); a point mass, a spring, a support or a
// foundation's variation splits each pair and fixes its orientation. For every pair a
// result's shapes show, split_pairs reports the two frequencies, the split and the
// orientation, the angle of the lower mode's radial antinode (Fox 1990; issue 49).
//
// A mode's wave number is the harmonic of its radial shape (at the kStations common
// stations) that carries the most of its energy; two modes pair when they share it and
// each has at least kPairShare of its radial energy in it (a pinned ring's modes, which are
// no rotations of one another, rarely do). Each mode pairs once, lowest modes first.
// The orientation: the lower mode's radial shape ~ A cos(k (theta - phi)), phi from the
// phase of its k-th harmonic, in [0, 180/k) degrees (a mode's sign is arbitrary, so its
// antinodes repeat every 180/k). A pair splits when its relative split exceeds kSplit.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "ring/results.hpp"

namespace cmp {

struct SplitPair {
  int wave = 0;                  ///< k, the shared wave number
  int lower = 0, upper = 0;      ///< 1-based mode numbers in the result's own order
  double omega_lower = 0.0, omega_upper = 0.0;  ///< rad/s
  double orientation = 0.0;      ///< degrees, in [0, 180/k): the lower mode's radial antinode
  double split() const { return omega_upper - omega_lower; }
  /// The split over the pair's mean frequency.
  double relative() const { return 2.0 * split() / (omega_upper + omega_lower); }
};

/// A mode's share of radial energy in its wave number, for it to pair.
constexpr double kPairShare = 0.5;
/// Relative splits at or below this are a degenerate pair (eigen-solvers' round-off ~1e-12).
constexpr double kSplit = 1e-9;

/// The split pairs of r (empty without shapes, and for an arch), by ascending lower mode.
std::vector<SplitPair> split_pairs(const ring::ModalResult& r);

/// As JSON: [{"wave", "modes": [lower, upper], "omega": [lower, upper], "split",
/// "relative_split", "orientation_deg"}].
nlohmann::json split_pairs_json(const std::vector<SplitPair>& pairs);

/// One solver's split pairs.
struct SolverSplits {
  std::string solver;
  std::vector<SplitPair> pairs;
};

/// A text section of the split pairs (one line per solver and pair), or "" when none has any.
std::string split_pairs_text(const std::vector<SolverSplits>& splits, bool markdown);

}  // namespace cmp
