#include "ring/paper_table.hpp"

#include <fstream>
#include <sstream>

#include "ring/errors.hpp"

namespace ring {

std::vector<PaperRow> parse_paper_table(const std::string& csv_text, const std::string& name) {
  std::vector<PaperRow> rows;
  std::istringstream in(csv_text);
  std::string line;
  int lineno = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) { header_seen = true; continue; }  // column names
    std::vector<std::string> cells;
    std::stringstream ls(line);
    std::string c;
    while (std::getline(ls, c, ',')) cells.push_back(c);
    while (cells.size() < 9) cells.emplace_back();
    auto num = [&](int i) -> std::optional<double> {
      if (cells[i].empty()) return std::nullopt;
      try {
        return std::stod(cells[i]);
      } catch (const std::exception&) {
        throw InputError(name, "line " + std::to_string(lineno),
                         "expected a number in column " + std::to_string(i + 1) + ", got '" + cells[i] + "'");
      }
    };
    PaperRow r;
    r.mode = static_cast<int>(num(0).value_or(0));
    r.mb_printed = num(1); r.lm_printed = num(2); r.lm_error_pct_printed = num(3);
    r.fe_printed = num(4); r.fe_error_pct_printed = num(5);
    r.mb_corrected = num(6); r.lm_corrected = num(7); r.fe_corrected = num(8);
    rows.push_back(r);
  }
  return rows;
}

std::vector<PaperRow> read_paper_table(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw InputError(path, "", "cannot open the paper's table");
  std::stringstream s;
  s << f.rdbuf();
  return parse_paper_table(s.str(), path);
}

}  // namespace ring
