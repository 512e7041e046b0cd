#include "compare/sweep.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

#include <nlohmann/json.hpp>

#include "compare/files.hpp"
#include "compare/guard.hpp"
#include "compare/nonlinear.hpp"
#include "compare/output.hpp"
#include "compare/plot.hpp"
#include "compare/spin.hpp"
#include "compare/progress.hpp"
#include "compare/registry.hpp"
#include "compare/runner.hpp"
#include "compare/sweep_mpi.hpp"
#include "compare/table.hpp"
#include "ring/errors.hpp"
#include "ring/input_file.hpp"

namespace cmp {
namespace {

/// A --vary key as the override will use it: dotted parts without the spaces around
/// them ("ring. section" is ring.section), none empty.
std::string vary_key(const std::string& text) {
  auto trim = [](const std::string& x) {
    const auto p = x.find_first_not_of(" \t"), q = x.find_last_not_of(" \t");
    return p == std::string::npos ? std::string() : x.substr(p, q - p + 1);
  };
  std::string key;
  std::size_t start = 0;
  for (;;) {
    const auto dot = text.find('.', start);
    const std::string part = trim(text.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (part.empty())
      throw ring::InputError("", "--vary " + text.substr(0, 80),
                             "expected KEY=[v1, v2, ...] with KEY a scene key such as multibody.n");
    key += (key.empty() ? "" : ".") + part;
    if (dot == std::string::npos) return key;
    start = dot + 1;
  }
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

std::vector<std::string> csv_split(const std::string& line) {
  std::vector<std::string> f;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      f.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  f.push_back(cur);
  return f;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

nlohmann::json row_json(const SweepRow& r) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"case", r.index},     {"values", r.values},   {"solver", r.solver},   {"analysis", r.analysis},
          {"quantity", r.quantity}, {"value", num(r.value)}, {"error_pct", num(r.error_pct)},
          {"unknowns", r.unknowns}, {"seconds", r.seconds}, {"status", r.status}, {"message", r.message}};
}

SweepRow row_from_json(const nlohmann::json& j) {
  SweepRow r;
  r.index = j["case"];
  r.values = j["values"].get<std::vector<std::string>>();
  r.solver = j["solver"];
  r.analysis = j["analysis"];
  r.quantity = j["quantity"];
  r.value = j["value"].is_null() ? NAN : j["value"].get<double>();
  r.error_pct = j["error_pct"].is_null() ? NAN : j["error_pct"].get<double>();
  r.unknowns = j["unknowns"];
  r.seconds = j["seconds"];
  r.status = j["status"];
  r.message = j["message"];
  return r;
}

/// The case's scene: the sweep's text with --set, then the case's overrides; checked
/// like a scene of `run` (every solver's checks, the cost guard).
ring::Scene case_scene(const std::string& text, const CommonArgs& a, const std::vector<std::string>& overrides) {
  std::vector<std::string> set = a.set;
  set.insert(set.end(), overrides.begin(), overrides.end());
  ring::Scene s = parse_scene(text, a.scene, set);
  check_runnable(s, a.max_memory_gib, a.force);
  return s;
}

/// Rows a case adds to the table: a row per mode and column, and per recorded point and
/// solver of each nonlinear analysis.
double rows_of(const ring::Scene& s) {
  double rows = 0.0;
  if (modal(s)) rows += double(s.modes.count) * double(table_solvers(s).size());
  if (s.response) rows += double(s.response->record.size()) * double(s.response_request.solvers.size());
  if (s.statics) rows += double(s.statics->record.size()) * double(s.static_request.solvers.size());
  return std::max(rows, 1.0);
}

/// Checks every case (exit 2 naming the case) and the sweep's own memory: the table
/// (a row is ~ 300 bytes in memory plus its CSV and JSON text, ~ 200 bytes per varied
/// value) and the cases running at once (`jobs` of the largest per-case estimate).
/// Each case's scene is parsed and checked once here; returns the rows each case adds
/// to the table (rows_of), which --resume needs.
std::vector<double> check_sweep_cost(const std::string& text, const CommonArgs& a,
                                     const std::vector<std::vector<std::string>>& overrides,
                                     const std::vector<std::string>& keys, int jobs) {
  const double budget = a.max_memory_gib * double(1ull << 30);
  auto describe = [&](std::size_t i) {
    std::string which;
    for (const auto& x : overrides[i]) which += (which.empty() ? "" : ", ") + x;
    return "--vary case " + std::to_string(i) + " (" + which + ")";
  };
  const double per_row = 800.0 + 200.0 * double(keys.size());
  auto refuse_table = [&](double table) {
    if (!a.force && table > budget)
      throw ring::InputError("", "--vary",
                             std::to_string(overrides.size()) + " cases: the sweep's table would need about " +
                                 sig4(table / double(1ull << 30)) + " GiB, more than the budget of " +
                                 sig4(a.max_memory_gib) + " GiB (fewer values, --max-memory GiB, or --force)");
  };
  std::vector<double> rows(overrides.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    try {
      const ring::Scene s = case_scene(text, a, overrides[i]);
      rows[i] = rows_of(s);
      largest = std::max(largest, estimate_memory(s).bytes);
    } catch (const ring::InputError& e) {
      throw ring::InputError("", describe(i), e.what());
    }
    // The first case's table times the count first, so that 10^6 cases of a scene whose
    // table cannot fit are refused before 10^6 parses.
    if (i == 0) refuse_table(double(overrides.size()) * rows[0] * per_row);
  }
  double table = 0.0;
  for (double r : rows) table += r * per_row;
  refuse_table(table);
  const double at_once = std::min<double>(jobs, double(overrides.size())) * largest;
  if (!a.force && table + at_once > budget)
    throw ring::InputError("", "-j",
                           std::to_string(jobs) + " cases at once need about " +
                               sig4((table + at_once) / double(1ull << 30)) + " GiB with the table, more than the "
                               "budget of " + sig4(a.max_memory_gib) + " GiB (fewer jobs with -j N, --max-memory "
                               "GiB, or --force)");
  return rows;
}

/// Runs run(k) for k = 0 .. count - 1 on `jobs` threads, each taking the next k as it
/// finishes one (the cases of a sweep differ in cost by orders of magnitude).
void on_threads(std::size_t count, int jobs, const std::function<void(std::size_t)>& run) {
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> pool;
  for (int w = 0; w < std::min<int>(jobs, static_cast<int>(count)); ++w)
    pool.emplace_back([&] {
      for (std::size_t k; (k = next++) < count;) run(k);
    });
  for (auto& t : pool) t.join();
}

}  // namespace

std::map<std::vector<std::string>, std::vector<SweepRow>> done_cases(
    const std::string& file, const std::vector<std::string>& keys, const std::vector<std::vector<std::string>>& cases,
    const std::function<double(std::size_t)>& expected_rows) {
  std::map<std::vector<std::string>, std::vector<SweepRow>> done;
  struct stat st;
  if (stat(file.c_str(), &st) != 0 && errno == ENOENT) return done;  // nothing to resume: every case runs
  const std::string text = ring::read_input_file(file, ring::kMaxResumeBytes, "the --resume table (sweep.csv)");
  const bool cut = !text.empty() && text.back() != '\n';
  std::vector<std::string> lines;
  for (std::size_t start = 0; start < text.size();) {
    const auto end = text.find('\n', start);
    lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    start = end == std::string::npos ? text.size() : end + 1;
  }
  if (lines.empty()) return done;
  const auto head = csv_split(lines[0]);
  const std::size_t k = keys.size();
  if (head.size() != k + 10 || !std::equal(keys.begin(), keys.end(), head.begin() + 1))
    throw ring::InputError(file, "--resume", "was written by a sweep over other keys (its header: " +
                                                 lines[0].substr(0, 200) + ")");
  auto bad = [&](std::size_t line, const std::string& what) {
    return ring::InputError(file, "line " + std::to_string(line + 1), what + "; fix or remove the line, or run "
                                                                             "without --resume");
  };
  auto number_at = [&](const std::string& v, std::size_t line, const std::string& column) {
    if (v.empty()) return double(NAN);
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (end == v.c_str() || *end != '\0' || !std::isfinite(x))
      throw bad(line, "the " + column + " '" + v.substr(0, 40) + "' is not a finite number");
    return x;
  };
  std::set<std::vector<std::string>> failed;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const auto x = csv_split(lines[i]);
    if (x.size() != head.size()) {
      if (cut && i + 1 == lines.size()) break;  // the last row, cut short: its case runs again
      throw bad(i, "expected " + std::to_string(head.size()) + " fields, found " + std::to_string(x.size()));
    }
    SweepRow r;
    r.values.assign(x.begin() + 1, x.begin() + 1 + k);
    r.solver = x[k + 1];
    r.analysis = x[k + 2];
    r.quantity = x[k + 3];
    r.value = number_at(x[k + 4], i, "value");
    r.error_pct = number_at(x[k + 5], i, "error_pct");
    const double unknowns = number_at(x[k + 6], i, "unknowns");
    if (std::isfinite(unknowns) && !(std::abs(unknowns) < 9.2e18))  // the cast below needs it
      throw bad(i, "the unknowns '" + x[k + 6].substr(0, 40) + "' is out of range");
    r.unknowns = std::isfinite(unknowns) ? static_cast<long long>(unknowns) : 0;
    const double seconds = number_at(x[k + 7], i, "seconds");
    r.seconds = std::isfinite(seconds) ? seconds : 0.0;
    r.status = x[k + 8];
    r.message = x[k + 9];
    if (r.status != "ok" && r.status != "input-error" && r.status != "numerical-failure")
      throw bad(i, "the status '" + r.status.substr(0, 40) + "' is not ok, input-error or numerical-failure");
    if (r.status != "ok" || !std::isfinite(r.value)) failed.insert(r.values);
    done[r.values].push_back(r);
  }
  for (const auto& v : failed) done.erase(v);
  // Keep only the cases of this sweep that are complete.
  std::map<std::vector<std::string>, std::vector<SweepRow>> kept;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto it = done.find(cases[i]);
    if (it != done.end() && double(it->second.size()) == expected_rows(i)) kept[cases[i]] = it->second;
  }
  return kept;
}

namespace {

bool plot_sweep(const std::string& dir, const std::vector<std::string>& keys, const std::vector<SweepRow>& rows) {
  // Against the first varied key (when its values are numbers): per solver and per
  // combination of the other keys, the max |error| over the case's rows (or, without a
  // reference, the first row's value).
  std::map<std::string, Series> curves;
  std::map<std::pair<int, std::string>, std::pair<double, double>> per_case;  // (case, solver) -> (x, y)
  bool any_error = false;
  for (const auto& r : rows) any_error |= r.status == "ok" && std::isfinite(r.error_pct);
  std::string first;  // what "the first value" is, for the axis: "mode 1, omega (rad/s)"
  for (const auto& r : rows) {
    if (r.status != "ok" || r.values.empty()) continue;
    if (first.empty()) first = r.quantity + (r.analysis == "modes" ? ", omega (rad/s)" : " (m)");
    char* end = nullptr;
    const double x = std::strtod(r.values[0].c_str(), &end);
    if (end == r.values[0].c_str() || *end) return false;  // not a number: no figure
    const double y = any_error ? std::abs(r.error_pct) : r.value;
    auto key = std::make_pair(r.index, r.solver);
    auto it = per_case.find(key);
    if (it == per_case.end()) per_case[key] = {x, y};
    else if (any_error) it->second.second = std::max(it->second.second, y);
    std::string label = r.solver;
    for (std::size_t i = 1; i < keys.size(); ++i) label += ", " + keys[i] + " = " + r.values[i];
    curves[label].name = label;
  }
  for (const auto& [key, xy] : per_case) {
    const auto& which = key;  // a lambda may not capture a structured binding before C++20 (clang)
    const auto& r = *std::find_if(rows.begin(), rows.end(), [&](const SweepRow& x) {
      return x.index == which.first && x.solver == which.second;
    });
    std::string label = r.solver;
    for (std::size_t i = 1; i < keys.size(); ++i) label += ", " + keys[i] + " = " + r.values[i];
    curves[label].x.push_back(xy.first);
    curves[label].y.push_back(xy.second);
  }
  std::vector<Series> plot;
  bool positive = true;
  std::vector<double> xs;
  for (auto& [label, s] : curves) {
    plot.push_back(s);
    for (double x : s.x) positive &= x > 0;
    xs.insert(xs.end(), s.x.begin(), s.x.end());
  }
  if (plot.empty()) return false;
  // A log axis for values spaced by ratios (n = 20, 40, 80), a linear one for values spaced
  // by differences (a load raised in equal steps): whichever spacing varies less.
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  if (positive && xs.size() >= 3) {
    auto spread = [&](auto step) {
      double lo = HUGE_VAL, hi = 0.0;
      for (std::size_t i = 1; i < xs.size(); ++i) lo = std::min(lo, step(i)), hi = std::max(hi, step(i));
      return hi / lo;
    };
    positive = spread([&](std::size_t i) { return std::log(xs[i] / xs[i - 1]); }) <
               spread([&](std::size_t i) { return xs[i] - xs[i - 1]; });
  }
  plot_series(dir, "sweep",
              any_error ? "Largest |error| against the reference, per case" : "First value of each case",
              keys[0], any_error ? "max |error| (%)" : first, plot, positive, any_error);
  return true;
}

/// The Campbell diagram of a sweep whose first key is rotation.speed: every wave branch
/// ("wave k forward|backward" rows) per solver against the speed, and the critical speeds
/// where a branch in the fixed frame changes sign (linear between the cases). Returns the
/// markdown lines of the critical speeds, or nullopt when the sweep has no such rows.
/// Drawn so that the key stays short: forward solid, backward dashed; one colour per wave number
/// (its key "k = K" once), or, when further keys vary (rotation.tension), one colour per value
/// of them (its key once); the solvers' branches of one wave overlie each other.
std::optional<std::string> plot_campbell(const std::string& dir, const std::vector<std::string>& keys,
                                         const std::vector<SweepRow>& rows) {
  if (keys.empty() || keys[0] != "rotation.speed") return std::nullopt;
  struct Branch {
    std::string extras;  // the further keys' values, ", key = value" each
    int wave;
    std::string solver;
    bool backward;
    bool operator<(const Branch& o) const {
      return std::tie(extras, wave, solver, backward) < std::tie(o.extras, o.wave, o.solver, o.backward);
    }
  };
  std::map<Branch, Series> branches;
  std::vector<std::string> combos;  // the distinct extras, in order of appearance
  for (const auto& r : rows) {
    if (r.status != "ok" || r.quantity.rfind("wave ", 0) != 0) continue;
    std::string extras;
    for (std::size_t i = 1; i < keys.size(); ++i) extras += ", " + keys[i] + " = " + r.values[i];
    if (std::find(combos.begin(), combos.end(), extras) == combos.end()) combos.push_back(extras);
    const Branch b{extras, std::atoi(r.quantity.c_str() + 5), r.solver, r.quantity.find("backward") != std::string::npos};
    Series& s = branches[b];
    s.name = r.solver + ", " + r.quantity + extras;  // the critical speeds' label; the key's is set below
    s.x.push_back(std::strtod(r.values[0].c_str(), nullptr));
    s.y.push_back(r.value);
    s.dash = b.backward ? 2 : 1;
  }
  if (branches.empty()) return std::nullopt;
  std::vector<Series> plot;
  std::ostringstream critical;
  std::set<std::string> keyed;
  for (auto& [branch, s] : branches) {
    std::vector<std::size_t> order(s.x.size());
    std::iota(order.begin(), order.end(), 0);
    const std::vector<double>& xs = s.x;  // a lambda may not capture a structured binding before C++20 (clang)
    std::sort(order.begin(), order.end(), [&xs](std::size_t a, std::size_t b) { return xs[a] < xs[b]; });
    Series sorted = s;
    for (std::size_t i = 0; i < order.size(); ++i) sorted.x[i] = s.x[order[i]], sorted.y[i] = s.y[order[i]];
    for (std::size_t i = 1; i < sorted.x.size(); ++i)
      if ((sorted.y[i - 1] < 0.0) != (sorted.y[i] < 0.0)) {
        const double x = sorted.x[i - 1] + (sorted.x[i] - sorted.x[i - 1]) * sorted.y[i - 1] / (sorted.y[i - 1] - sorted.y[i]);
        critical << "- " << s.name << ": " << sig4(x) << " rad/s\n";
      }
    const bool by_combo = combos.size() > 1;
    const std::string key = by_combo ? branch.extras.substr(2) : "k = " + std::to_string(branch.wave);
    sorted.color = by_combo ? static_cast<int>(std::find(combos.begin(), combos.end(), branch.extras) - combos.begin())
                            : branch.wave;
    sorted.name = keyed.insert(key).second ? key : "";
    plot.push_back(sorted);
  }
  plot_series(dir, "campbell", "Campbell diagram: the waves' frequencies against the spin (solid forward, dashed backward)",
              "rotation.speed (rad/s)", "omega (rad/s)", plot);
  const std::string found = critical.str();
  return "\n## Campbell diagram\n\n![campbell](campbell.png)\n\nCritical speeds (a branch of the fixed frame "
         "through zero: the wave stands still in space): " +
         (found.empty() ? std::string("none between the speeds swept (a backward wave's branch changes sign there only in "
                                             "the fixed frame, modes.frame = \"fixed\").\n")
                        : "\n\n" + found);
}

}  // namespace

std::vector<std::vector<std::string>> sweep_cases(const std::vector<std::string>& vary, bool zip,
                                                  std::vector<std::string>& keys, double max_cases) {
  if (vary.empty()) throw ring::InputError("", "--vary", "expected at least one --vary KEY=[v1, v2, ...]");
  std::vector<std::vector<std::string>> lists;
  keys.clear();
  for (const auto& v : vary) {
    const auto eq = v.find('=');
    if (eq == std::string::npos)
      throw ring::InputError("", "--vary " + v.substr(0, 80), "expected KEY=[v1, v2, ...]");
    const std::string key = vary_key(v.substr(0, eq));
    // One list per key, and no key inside another: a case would set the value twice,
    // and the table's columns would not say which one ran.
    for (const auto& k : keys) {
      if (k == key)
        throw ring::InputError("", "--vary " + key, "given twice; put all its values in one list");
      const bool inside = key.rfind(k + ".", 0) == 0, outside = k.rfind(key + ".", 0) == 0;
      if (inside || outside)
        throw ring::InputError("", "--vary " + key,
                               "overlaps --vary " + k + " (" + (inside ? key + " is part of " + k : k + " is part of " + key) +
                                   "), so a case would set it twice; vary one of them (a list of inline tables can vary several keys of a table together)");
    }
    keys.push_back(key);
    lists.push_back(ring::toml_array_items(v.substr(eq + 1), "--vary " + key));
  }
  std::vector<std::vector<std::string>> cases;
  if (zip) {
    for (const auto& l : lists)
      if (l.size() != lists[0].size())
        throw ring::InputError("", "--zip", "the --vary lists must have equal lengths (" + keys[0] + ": " +
                                                std::to_string(lists[0].size()) + " values)");
    for (std::size_t i = 0; i < lists[0].size(); ++i) {
      std::vector<std::string> c;
      for (std::size_t k = 0; k < keys.size(); ++k) c.push_back(lists[k][i]);
      cases.push_back(c);
    }
    return cases;
  }
  // Counted before the product is built: case numbers are ints (SweepRow::index).
  double count = 1.0;
  for (const auto& l : lists) count *= double(l.size());
  if (count > double(std::numeric_limits<int>::max()))
    throw ring::InputError("", "--vary", sig4(count) + " cases (the product of the lists); a sweep numbers at most " +
                                             std::to_string(std::numeric_limits<int>::max()) + " (fewer values, or --zip)");
  if (count > max_cases)
    throw ring::InputError("", "--vary", sig4(count) + " cases (the product of the lists): their list and table alone "
                                             "would exceed the memory budget (fewer values, --zip, --max-memory "
                                             "GiB, or --force)");
  cases.push_back({});
  for (const auto& l : lists) {  // the first key varies slowest
    std::vector<std::vector<std::string>> next;
    for (const auto& c : cases)
      for (const auto& v : l) {
        auto d = c;
        d.push_back(v);
        next.push_back(d);
      }
    cases = std::move(next);
  }
  return cases;
}

std::vector<SweepRow> run_case(const std::string& text, const CommonArgs& a, int index,
                               const std::vector<std::string>& overrides, const std::vector<std::string>& values) {
  std::vector<SweepRow> rows;
  auto row = [&]() {
    SweepRow r;
    r.index = index;
    r.values = values;
    r.value = NAN;
    r.error_pct = NAN;
    return r;
  };
  try {
    const ring::Scene s = case_scene(text, a, overrides);
    if (modal(s)) {
      const ModalRun m = compute_modal(s, nullptr);
      const std::vector<ring::ModalResult>& columns = m.columns;
      const std::optional<ring::ModalResult>& reference = m.reference;
      const Table t = make_table(s, m, false);
      for (std::size_t c = 0; c < columns.size(); ++c)
        for (int i = 0; i < t.rows; ++i) {
          SweepRow r = row();
          r.solver = columns[c].solver;
          r.analysis = "modes";
          r.quantity = "mode " + std::to_string(i + 1);
          r.value = t.columns[c].omega[i];
          if (reference) r.error_pct = t.columns[c].error_pct[i];
          r.unknowns = columns[c].unknowns;
          r.seconds = columns[c].seconds;
          rows.push_back(r);
        }
      // A spinning ring: each wave pair's branches in the scene's frame (the fixed frame's
      // signed, so that a backward wave passes through zero at its critical speed), the rows
      // of the Campbell diagram.
      const bool fixed = s.modes.fixed_frame;
      for (const auto& col : columns)
        for (const auto& p : col.spin_pairs)
          for (const int dir : {1, -1}) {
            SweepRow r = row();
            r.solver = col.solver;
            r.analysis = "modes";
            r.quantity = "wave " + std::to_string(p.wave) + " " + direction_name(dir);
            r.value = dir > 0 ? (fixed ? p.forward_fixed : p.forward) : (fixed ? p.backward_fixed : p.backward);
            r.unknowns = col.unknowns;
            r.seconds = col.seconds;
            rows.push_back(r);
          }
    }
    if (s.response || s.statics) {
      const NonlinearRun nl = run_nonlinear(s);
      auto add = [&](const NonlinearTable& t, const std::string& quantity, auto& results) {
        for (const auto& tr : t.rows) {
          if (tr.quantity != quantity) continue;
          for (std::size_t c = 0; c < tr.value.size(); ++c) {
            SweepRow r = row();
            r.solver = t.solvers[c];
            r.analysis = t.analysis;
            r.quantity = quantity + " at " + sig4(tr.angle) + " deg";
            r.value = tr.value[c];
            if (tr.reference) r.error_pct = tr.error_pct[c];
            r.unknowns = results[c].unknowns;
            r.seconds = results[c].seconds;
            rows.push_back(r);
          }
        }
      };
      if (!nl.histories.empty())
        add(response_table(s.title, nl.histories, nl.history_reference ? &*nl.history_reference : nullptr), "peak_u",
            nl.histories);
      if (!nl.statics.empty())
        add(static_table(s.title, nl.statics, nl.static_reference ? &*nl.static_reference : nullptr), "u", nl.statics);
    }
  } catch (const ring::InputError& e) {
    rows.clear();
    SweepRow r = row();
    r.status = "input-error";
    r.message = e.what();
    rows.push_back(r);
  } catch (const std::exception& e) {
    rows.clear();
    SweepRow r = row();
    r.status = "numerical-failure";
    r.message = e.what();
    rows.push_back(r);
  }
  return rows;
}

std::string sweep_csv(const std::vector<std::string>& keys, const std::vector<SweepRow>& rows) {
  std::ostringstream s;
  s << "case";
  for (const auto& k : keys) s << "," << csv_field(k);
  s << ",solver,analysis,quantity,value,error_pct,unknowns,seconds,status,message\n";
  for (const auto& r : rows) {
    s << r.index;
    for (const auto& v : r.values) s << "," << csv_field(v);
    s << "," << r.solver << "," << r.analysis << "," << csv_field(r.quantity) << "," << number(r.value) << ","
      << number(r.error_pct) << "," << r.unknowns << "," << number(r.seconds) << "," << r.status << ","
      << csv_field(r.message) << "\n";
  }
  return s.str();
}

std::string sweep_json(const std::vector<std::string>& keys, const std::vector<SweepRow>& rows) {
  nlohmann::json j;
  j["keys"] = keys;
  j["rows"] = nlohmann::json::array();
  for (const auto& r : rows) j["rows"].push_back(row_json(r));
  return j.dump(2) + "\n";
}

SweepTable run_sweep(const std::string& text, const CommonArgs& a, const std::vector<std::string>& vary, bool zip,
                     int jobs, const std::function<void(int, int, int)>& on_case) {
  SweepTable out;
  const double max_cases = a.force ? std::numeric_limits<int>::max() : a.max_memory_gib * double(1ull << 30) / 1e3;
  const auto cases = sweep_cases(vary, zip, out.keys, max_cases);
  std::vector<std::vector<std::string>> overrides;
  for (const auto& c : cases) {
    std::vector<std::string> o;
    for (std::size_t k = 0; k < out.keys.size(); ++k) o.push_back(out.keys[k] + "=" + c[k]);
    overrides.push_back(std::move(o));
  }
  if (jobs <= 0) jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  check_sweep_cost(text, a, overrides, out.keys, jobs);
  std::vector<std::vector<SweepRow>> results(cases.size());
  std::atomic<int> finished{0}, failed{0};
  std::mutex report;
  on_threads(cases.size(), jobs, [&](std::size_t i) {
    results[i] = run_case(text, a, static_cast<int>(i), overrides[i], cases[i]);
    if (results[i].size() == 1 && results[i][0].status != "ok") ++failed;
    const int f = ++finished;
    if (on_case) {
      const std::lock_guard<std::mutex> one(report);
      on_case(f, static_cast<int>(cases.size()), failed.load());
    }
  });
  for (auto& r : results)
    for (auto& x : r) out.rows.push_back(std::move(x));
  if (!cases.empty() && failed.load() == static_cast<int>(cases.size()))
    throw ring::NumericalError("every case of the sweep failed (the first: " + out.rows.front().message + ")");
  return out;
}

int cmd_sweep(const CommonArgs& a, const SweepArgs& args, int argc, char** argv) {
  const auto t0 = std::chrono::steady_clock::now();
  const int ranks = mpi::launched_size();
  if (ranks > 1 && !mpi::built()) {
    // Every rank would run the whole sweep: only the first does, and says why.
    if (mpi::launched_rank() != 0) return 0;
    std::cerr << "ringvib: note: this ringvib was built without MPI; rank 0 runs the whole sweep alone\n";
  }
  const bool distributed = ranks > 1 && mpi::built();
  const bool root = !distributed || mpi::launched_rank() == 0;

  // Everything is checked before anything runs: the cases, the sweep's own memory, each
  // case's scene (every solver's checks and the cost guard), the outputs. The scene file
  // is read once; every case is that text with its overrides.
  std::vector<std::string> keys;
  // A case holds at least a row of the table (~ 1 KB with its values and its CSV and
  // JSON text, check_sweep_cost): more cases than the budget holds are refused before
  // the list is built.
  const double max_cases = a.force ? std::numeric_limits<int>::max() : a.max_memory_gib * double(1ull << 30) / 1e3;
  const auto cases = sweep_cases(args.vary, args.zip, keys, max_cases);
  const std::string text = ring::read_scene_text(a.scene);
  std::vector<std::vector<std::string>> overrides;
  for (const auto& c : cases) {
    std::vector<std::string> o;
    for (std::size_t k = 0; k < keys.size(); ++k) o.push_back(keys[k] + "=" + c[k]);
    overrides.push_back(std::move(o));
  }
  const int jobs = distributed ? 1 : args.jobs > 0 ? args.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::vector<double> rows_per_case = check_sweep_cost(text, a, overrides, keys, jobs);
  Outputs files;
  if (!args.out.empty()) files.folder(args.out, "--out", {"sweep"});
  if (args.resume && args.out.empty()) throw ring::InputError("", "--resume", "needs --out DIR (the sweep to resume)");
  if (args.ranks > 0) {
    // Checked, so launched: the ranks run this command without --ranks.
    if (ranks > 1) throw ring::InputError("", "--ranks", "starts mpirun, and this sweep already runs under one");
    if (!mpi::built())
      throw ring::InputError("", "--ranks", "this ringvib was built without MPI; run the sweep on this machine's cores "
                                            "without --ranks");
    return mpi::launch(args.ranks, argc, argv);
  }
  if (root) files.open();  // locks DIR before --resume reads it
  std::map<std::vector<std::string>, std::vector<SweepRow>> done;
  if (args.resume)
    done = done_cases(args.out + "/sweep.csv", keys, cases, [&](std::size_t i) { return rows_per_case[i]; });
  std::vector<int> todo;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (!done.count(cases[i])) todo.push_back(static_cast<int>(i));

  ProgressLine line("sweep", "cases done", root ? progress_stream(a.quiet) : nullptr);
  std::atomic<int> finished{0}, failed{0};
  auto run = [&](int i) {
    auto rows = run_case(text, a, i, overrides[i], cases[i]);
    if (rows.size() == 1 && rows[0].status != "ok") ++failed;
    const int f = ++finished;
    line.update(f, static_cast<long>(todo.size()), std::to_string(failed.load()) + " failed");
    return rows;
  };
  std::vector<std::vector<SweepRow>> results(cases.size());
  if (distributed) {
    std::vector<std::string> texts;
    const auto serialize = [&](int k) {
      nlohmann::json j = nlohmann::json::array();
      for (const auto& r : run(todo[k])) j.push_back(row_json(r));
      return j.dump();
    };
    if (!mpi::distribute(argc, argv, static_cast<int>(todo.size()), serialize, texts)) return 0;
    for (std::size_t k = 0; k < todo.size(); ++k)
      for (const auto& j : nlohmann::json::parse(texts[k])) results[todo[k]].push_back(row_from_json(j));
  } else {
    on_threads(todo.size(), jobs, [&](std::size_t k) { results[todo[k]] = run(todo[k]); });
  }
  line.finish();

  // Counted from the rows, so that under MPI every rank's failures count.
  std::vector<SweepRow> rows;
  int failed_cases = 0, failed_here = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const bool kept = done.count(cases[i]) > 0;
    const auto& r = kept ? done[cases[i]] : results[i];
    const bool bad = r.size() == 1 && r[0].status != "ok";
    failed_cases += bad;
    failed_here += bad && !kept;
    for (SweepRow x : r) {
      x.index = static_cast<int>(i);  // a kept case takes its number in this sweep
      rows.push_back(std::move(x));
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << "ringvib: sweep: " << cases.size() << " cases, " << todo.size() << " run, "
            << cases.size() - todo.size() << " resumed, " << failed_here << " failed, in " << sig4(wall) << " s on "
            << (distributed ? std::to_string(ranks) + " MPI ranks" : "1 process") << "\n";
  // A sweep in which every case failed is a failure: nothing is published.
  if (!cases.empty() && failed_cases == static_cast<int>(cases.size()))
    throw ring::NumericalError("every case of the sweep failed (the first: " + rows.front().message + ")");
  if (args.out.empty()) {
    std::cout << sweep_csv(keys, rows);
    return 0;
  }
  const std::string& dir = files.stage();
  write_file(dir + "/sweep.csv", sweep_csv(keys, rows));
  write_file(dir + "/sweep.json", sweep_json(keys, rows));
  std::ostringstream md;
  md << "# Sweep of " << a.scene << "\n\n" << cases.size() << " cases over";
  for (const auto& k : keys) md << " `" << k << "`";
  md << (args.zip ? " (in lockstep)" : " (all combinations)") << "; " << todo.size() << " run here, "
     << cases.size() - todo.size() << " kept from an earlier run; " << failed_cases << " failed.\n\n"
     << "Data: `sweep.csv`, `sweep.json` (one row per case x solver x mode or recorded point).\n";
  if (plot_sweep(dir, keys, rows)) md << "\n![sweep](sweep.png)\n";
  if (const auto campbell = plot_campbell(dir, keys, rows)) md << *campbell;
  write_file(dir + "/sweep.md", md.str());
  files.publish();
  return 0;
}

}  // namespace cmp
