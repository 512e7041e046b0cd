// The paper's three-way table, regenerated: a base column, each other solver with its
// difference (base - other) / other * 100 (the paper's definition), and optionally the
// converged FE reference with every column's error (x - ref) / ref * 100.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/pairs.hpp"
#include "ring/paper_table.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// One solver's column, its modes paired with the base solver's rows.
struct Column {
  std::string solver;
  std::vector<double> omega;      ///< [row], rad/s (the paired mode of this solver)
  /// [row], 1-based mode number in this solver's own order; 0: no mode of this column pairs
  /// with the row (an imported column with fewer modes than modes.count). Then omega, mac,
  /// diff_pct and error_pct of the row hold NaN, and every format leaves them empty (text,
  /// Markdown and CSV: an empty cell; JSON: the key left out) instead of printing NaN.
  std::vector<int> mode;
  /// [row], MAC with the base mode (1 for the base; see pair_modes); NaN where the modes
  /// paired by order (a column without shapes): no MAC, an empty cell.
  std::vector<double> mac;
  std::vector<bool> subspace;     ///< [row], paired against a (near-)degenerate cluster
  std::vector<double> diff_pct;   ///< [row], (base - this) / this * 100 (empty for the base; NaN: unlike)
  std::vector<double> error_pct;  ///< [row], (this - reference) / reference * 100 (if a reference; NaN: unlike)
  /// The model's beam theory (ModalResult::model["theory"]: "euler-bernoulli", "timoshenko";
  /// "" when the result does not say, as an imported column).
  std::string theory;
};

struct Table {
  std::string title;
  std::string unit = "rad/s";               ///< what the values are, first words of the notes
  int rows = 0;
  std::vector<Column> columns;              ///< base first
  std::optional<Column> reference;          ///< paired with the base like any column
  std::vector<ring::PaperRow> paper;        ///< with --paper: Table 1 as published
  /// Each column's (and the reference's) pairs split by the scene's terms (compare/pairs.hpp),
  /// listed after the table where any has one.
  std::vector<SolverSplits> splits;
  /// A spinning ring's wave pairs per solver (and "reference"), compare/spin.hpp.
  std::vector<std::pair<std::string, std::vector<ring::SpinPair>>> spins;
};

/// Below this MAC a pairing compares unlike shapes: marked "?" in the table, with no
/// difference or error (the cell says "unlike"), and a gate over that mode fails.
constexpr double kWeakMac = 0.5;
inline bool weak_mac(double mac) { return mac < kWeakMac; }  // false for NaN (no shapes)

/// Modes whose frequencies agree to this relative tolerance are one (near-)degenerate
/// cluster: a free ring's (or a ring on a foundation's) double frequencies, equal to
/// round-off in every solver, whose two members are any basis of their plane.
constexpr double kDegenerate = 1e-6;

/// How `other`'s modes pair with `base`'s, per base mode: the index in `other` (-1: none
/// left), the MAC of the pairing, and whether it was made against a cluster of `other`.
struct Pairing {
  std::vector<int> mode;
  std::vector<double> mac;
  std::vector<bool> subspace;
};

/// Pairs the modes of `other` with those of `base` by the modal assurance criterion on the
/// common stations, (near-)degenerate clusters of `other` (kDegenerate) as subspaces: a
/// base mode's MAC with a cluster is cos^2 of its angle to the cluster's span (the
/// projection onto an orthonormal basis of the members' shapes; a single mode's is the
/// ordinary MAC), so a double frequency pairs at 1 whatever basis each solver picked for
/// it. Strongest pairs first (greedy); a cluster takes as many base modes as it has
/// members, handing them its members in order. O(k^2 kStations) for k modes.
Pairing pair_modes(const ring::ModalResult& base, const ring::ModalResult& other);

/// pair_modes' indices alone.
std::vector<int> pair_by_mac(const ring::ModalResult& base, const ring::ModalResult& other);

/// Builds the table from computed results (the base first in `results`).
Table build_table(const std::string& title, const std::vector<ring::ModalResult>& results,
                  const ring::ModalResult* reference, int rows);

/// Formats: aligned text, Markdown, CSV, JSON (the contract of docs/commands.md).
std::string format_text(const Table& t);
std::string format_markdown(const Table& t);
std::string format_csv(const Table& t);
std::string format_json(const Table& t);

/// The paper's published value for a solver column (multibody -> mb_corrected, ...).
std::optional<double> paper_value(const ring::PaperRow& row, const std::string& solver);

/// Table 1 as shipped in compare/data/table1.csv (embedded in the program).
std::vector<ring::PaperRow> paper_table();

}  // namespace cmp
