#include "compare/gates.hpp"

#include <cmath>
#include <sstream>

#include "compare/output.hpp"

namespace cmp {
namespace {

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

const Column* find(const Table& t, const std::string& solver) {
  for (const auto& c : t.columns)
    if (c.solver == solver) return &c;
  return nullptr;
}

}  // namespace

std::string GateResult::name() const {
  std::ostringstream s;
  s << gate.solver << " vs " << gate.against << ", ";
  if (gate.analysis == "modes") s << "modes " << gate.first_mode << "-" << gate.last_mode;
  else s << (gate.analysis == "response" ? "response peak |u|" : "static |u|");
  s << ", max " << gate.max_pct << " %";
  return s.str();
}

std::string GateResult::line() const {
  std::ostringstream s;
  s << (pass ? "PASS " : "FAIL ") << name() << ": ";
  if (!std::isnan(weak_mac)) {
    s << "mode " << worst_mode << " is paired with MAC " << sig4(weak_mac) << " < " << kWeakMac
      << ": unlike shapes, no error to bound";
    return s.str();
  }
  s << "worst ";
  if (gate.analysis == "modes") s << "mode " << worst_mode;
  else s << "point " << sig4(worst_point) << " deg";
  s << ", " << pct2(worst_pct) << " % " << (pass ? "<=" : ">") << " " << gate.max_pct << " %";
  return s.str();
}

std::vector<GateResult> evaluate_nonlinear_gates(const std::vector<ring::Gate>& gates, const NonlinearTable& table) {
  std::vector<GateResult> out;
  const std::string quantity = table.analysis == "response" ? "peak_u" : "u";
  auto column = [&](const std::string& solver) {
    for (std::size_t c = 0; c < table.solvers.size(); ++c)
      if (table.solvers[c] == solver) return static_cast<int>(c);
    return -1;
  };
  for (const ring::Gate& g : gates) {
    if (g.analysis != table.analysis) continue;
    GateResult r;
    r.gate = g;
    const int c = column(g.solver), o = g.against == "reference" ? -1 : column(g.against);
    double scale = 0.0;  // the size of the compared-with values: below 1e-9 of it a point does not move
    for (const auto& row : table.rows)
      if (row.quantity == quantity && o >= 0) scale = std::max(scale, std::abs(row.value[o]));
    bool evaluated = false;
    for (const auto& row : table.rows) {
      if (row.quantity != quantity || c < 0) continue;
      double v = NAN;
      if (g.against == "reference") {
        if (row.reference) v = row.error_pct.at(c);
      } else if (o >= 0 && std::abs(row.value[o]) > 1e-9 * scale) {
        v = (row.value[c] - row.value[o]) / std::abs(row.value[o]) * 100.0;
      }
      if (!std::isfinite(row.value[c])) v = INFINITY;
      else if (std::isnan(v)) continue;  // not defined: the compared-with value is ~0
      evaluated = true;
      v = std::abs(v);
      if (!evaluated || v > r.worst_pct || std::isinf(v)) {
        r.worst_pct = v;
        r.worst_point = row.angle;
      }
    }
    r.pass = evaluated && std::isfinite(r.worst_pct) && r.worst_pct <= g.max_pct;
    out.push_back(r);
  }
  return out;
}

std::vector<GateResult> evaluate_gates(const std::vector<ring::Gate>& gates, const Table& table) {
  std::vector<GateResult> out;
  for (ring::Gate g : gates) {
    if (g.analysis != "modes") continue;
    if (g.last_mode == 0 || g.last_mode > table.rows) g.last_mode = table.rows;
    GateResult r;
    r.gate = g;
    r.pass = true;
    const Column* col = find(table, g.solver);
    const Column* other = g.against == "reference" ? (table.reference ? &*table.reference : nullptr)
                        : g.against == "paper" ? nullptr : find(table, g.against);
    bool evaluated = false;
    for (int i = g.first_mode - 1; col && i < g.last_mode; ++i) {
      double ref = NAN;
      if (g.against == "paper") {
        if (i < static_cast<int>(table.paper.size()))
          if (auto p = paper_value(table.paper[i], g.solver)) ref = *p;
        if (!std::isfinite(ref)) continue;  // not printed in the paper
      } else if (other) {
        ref = other->omega[i];
      }
      evaluated = true;
      const double mac = std::min(col->mac[i], g.against == "paper" || !other ? 1.0 : other->mac[i]);
      if (weak_mac(col->mac[i]) || weak_mac(mac)) {  // unlike modes: the gate cannot hold
        r.worst_pct = INFINITY;
        r.worst_mode = i + 1;
        r.weak_mac = weak_mac(col->mac[i]) ? col->mac[i] : mac;
        break;
      }
      const double v = std::abs((col->omega[i] - ref) / ref * 100.0);
      if (!std::isfinite(v)) {  // a NaN fails the gate, at this mode
        r.worst_pct = INFINITY;
        r.worst_mode = i + 1;
        break;
      }
      if (r.worst_mode == 0 || v > r.worst_pct) {
        r.worst_pct = v;
        r.worst_mode = i + 1;
      }
    }
    r.pass = evaluated && std::isfinite(r.worst_pct) && r.worst_pct <= g.max_pct;
    out.push_back(r);
  }
  return out;
}

std::string junit_xml(const std::string& suite, const std::vector<GateResult>& results) {
  int failures = 0;
  for (const auto& r : results) failures += !r.pass;
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s << "<testsuites tests=\"" << results.size() << "\" failures=\"" << failures << "\">\n";
  s << "  <testsuite name=\"" << xml_escape(suite) << "\" tests=\"" << results.size() << "\" failures=\"" << failures
    << "\">\n";
  for (const auto& r : results) {
    s << "    <testcase classname=\"ringvib.gates\" name=\"" << xml_escape(r.name()) << "\"";
    if (r.pass) {
      s << "/>\n";
    } else {
      s << ">\n      <failure message=\"" << xml_escape(r.line()) << "\"/>\n    </testcase>\n";
    }
  }
  s << "  </testsuite>\n</testsuites>\n";
  return s.str();
}

}  // namespace cmp
