#include "compare/imports.hpp"

#include <cmath>
#include <sstream>

#include "ring/errors.hpp"
#include "ring/input_file.hpp"
#include "ring/sampling.hpp"

namespace cmp {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

/// One CSV file read line by line, its failures named by file, line and column. The file
/// is checked and read whole first, within `cap` (ring::read_input_file): a FIFO or device
/// named in a scene is refused unopened, a file over the cap unread.
class CsvFile {
 public:
  CsvFile(std::string path, std::size_t cap, const std::string& what)
      : path_(std::move(path)), in_(ring::read_input_file(path_, cap, what)) {}
  /// The next line that is neither blank nor a comment, split at commas; false at the end.
  bool next(std::vector<std::string>& cells) {
    for (std::string line; std::getline(in_, line);) {
      ++line_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const auto first = line.find_first_not_of(" \t");
      if (first == std::string::npos || line[first] == '#') continue;
      cells.clear();
      std::stringstream s(line);
      for (std::string c; std::getline(s, c, ',');) {
        const auto a = c.find_first_not_of(" \t"), b = c.find_last_not_of(" \t");
        cells.push_back(a == std::string::npos ? "" : c.substr(a, b - a + 1));
      }
      if (!line.empty() && line.back() == ',') cells.push_back("");
      return true;
    }
    return false;
  }
  [[noreturn]] void fail(std::size_t column, const std::string& what) const {
    throw ring::InputError(path_, "line " + std::to_string(line_) + (column ? ", column " + std::to_string(column) : ""),
                           what);
  }
  double number(const std::vector<std::string>& cells, std::size_t column, const std::string& what) const {
    const std::string& c = cells[column - 1];
    try {
      std::size_t used = 0;
      const double x = std::stod(c, &used);
      if (used == c.size() && std::isfinite(x)) return x;
    } catch (...) {
    }
    fail(column, "expected " + what + ", got '" + c.substr(0, 40) + "'");
  }
  int line() const { return line_; }

 private:
  std::string path_;
  std::istringstream in_;
  int line_ = 0;
};

std::vector<ring::ModeShape> read_shapes(const std::string& path, std::size_t modes) {
  CsvFile f(path, ring::kMaxShapesBytes, "the imported shapes file");
  std::vector<std::string> cells;
  if (!f.next(cells)) f.fail(0, "empty: expected the header angle_deg,radial_1,tangential_1,...");
  if (cells.size() != 1 + 2 * modes)
    f.fail(0, "expected angle_deg and a radial and a tangential column for each of the " + std::to_string(modes) +
                  " modes of the frequency file (" + std::to_string(1 + 2 * modes) + " columns), got " +
                  std::to_string(cells.size()));
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string want =
        c == 0 ? "angle_deg" : (c % 2 ? "radial_" : "tangential_") + std::to_string((c + 1) / 2);
    if (cells[c] != want) f.fail(c + 1, "expected the header '" + want + "', got '" + cells[c].substr(0, 40) + "'");
  }
  std::vector<ring::ModeShape> shapes(modes);
  for (auto& s : shapes) {
    s.radial.resize(ring::kStations);
    s.tangential.resize(ring::kStations);
  }
  for (int st = 0; st < ring::kStations; ++st) {
    if (!f.next(cells))
      f.fail(0, "ends after " + std::to_string(st) + " stations; expected " + std::to_string(ring::kStations) +
                    " (every degree from 0)");
    if (cells.size() != 1 + 2 * modes)
      f.fail(0, "expected " + std::to_string(1 + 2 * modes) + " values, got " + std::to_string(cells.size()));
    const double angle = f.number(cells, 1, "the station's angle in degrees");
    if (std::abs(angle - ring::station_angle(st)) > 1e-9)
      f.fail(1, "expected the station at " + std::to_string(static_cast<int>(ring::station_angle(st))) + " degrees");
    for (std::size_t k = 0; k < modes; ++k) {
      shapes[k].radial[st] = f.number(cells, 2 + 2 * k, "a radial displacement");
      shapes[k].tangential[st] = f.number(cells, 3 + 2 * k, "a tangential displacement");
    }
  }
  if (f.next(cells)) f.fail(0, "more lines than the " + std::to_string(ring::kStations) + " stations");
  for (std::size_t k = 0; k < modes; ++k) {
    double norm = 0.0;
    for (int st = 0; st < ring::kStations; ++st)
      norm += shapes[k].radial[st] * shapes[k].radial[st] + shapes[k].tangential[st] * shapes[k].tangential[st];
    if (norm == 0.0) f.fail(0, "mode " + std::to_string(k + 1) + " has a zero shape");
    ring::normalize(shapes[k]);
  }
  return shapes;
}

}  // namespace

ring::ModalResult read_imported(const ring::ImportedColumn& column) {
  CsvFile f(column.file, ring::kMaxImportBytes, "the imported file");
  std::vector<std::string> cells;
  if (!f.next(cells)) f.fail(0, "empty: expected the header mode,omega (rad/s) or mode,hz");
  if (cells.size() != 2) f.fail(0, "expected the header mode,omega (rad/s) or mode,hz: two columns");
  if (cells[0] != "mode") f.fail(1, "expected the header 'mode', got '" + cells[0].substr(0, 40) + "'");
  if (cells[1] != "omega" && cells[1] != "hz")
    f.fail(2, "expected the header 'omega' (rad/s) or 'hz', got '" + cells[1].substr(0, 40) + "'");
  const std::string unit = cells[1];
  const double factor = unit == "hz" ? kTwoPi : 1.0;
  ring::ModalResult r;
  r.solver = column.label;
  r.model["file"] = column.file;
  r.model["unit"] = unit == "hz" ? std::string("hz") : std::string("rad/s");
  r.residual_norm = "imported";
  r.max_residual.reset();  // not known: JSON null, not a perfect 0
  while (f.next(cells)) {
    if (cells.size() != 2) f.fail(0, "expected two values (mode, " + unit + "), got " + std::to_string(cells.size()));
    const double mode = f.number(cells, 1, "the mode number");
    if (mode != static_cast<double>(r.omega.size() + 1))
      f.fail(1, "expected mode " + std::to_string(r.omega.size() + 1) + " (modes numbered 1, 2, 3, ... in order)");
    const double w = f.number(cells, 2, unit == "hz" ? "a frequency in Hz" : "a frequency in rad/s");
    if (w <= 0.0) f.fail(2, "expected a frequency > 0 (leave rigid modes out)");
    r.omega.push_back(w * factor);
  }
  if (r.omega.empty()) f.fail(0, "no modes after the header");
  for (std::size_t k = 1; k < r.omega.size(); ++k)
    if (r.omega[k] < r.omega[k - 1] * (1.0 - 1e-12))
      throw ring::InputError(column.file, "mode " + std::to_string(k + 1),
                             "frequencies must ascend (mode " + std::to_string(k + 1) + " is below mode " +
                                 std::to_string(k) + ")");
  if (!column.shapes.empty()) r.shapes = read_shapes(column.shapes, r.omega.size());
  r.model["modes"] = static_cast<long long>(r.omega.size());
  return r;
}

}  // namespace cmp
