// Table 1 of Yin & Wang (1989/90) as data: the published frequencies that the
// --paper columns show and the tests use as an oracle. The solvers never read it.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ring {

/// One row of compare/data/table1.csv (rad/s; empty cells are std::nullopt).
/// *_corrected replace printed values that contradict the paper's own error
/// percentages (docs/paper.md).
struct PaperRow {
  int mode = 0;
  std::optional<double> mb_printed, lm_printed, lm_error_pct_printed, fe_printed,
      fe_error_pct_printed, mb_corrected, lm_corrected, fe_corrected;
};

/// Parses the CSV text (lines starting with '#' are comments). Throws InputError on
/// a malformed line, naming `name` and the line number.
std::vector<PaperRow> parse_paper_table(const std::string& csv_text, const std::string& name);
/// Reads and parses the file at `path`.
std::vector<PaperRow> read_paper_table(const std::string& path);

}  // namespace ring
