#include "compare/table.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <variant>

#include <Eigen/QR>
#include <nlohmann/json.hpp>

#include "compare/grid.hpp"
#include "compare/output.hpp"
#include "compare/spin.hpp"
#include "compare/registry.hpp"
#include "ring/sampling.hpp"

extern "C" const char ringvib_table1_csv[];  // generated from compare/data/table1.csv

namespace cmp {
namespace {

bool has_shapes(const ring::ModalResult& r) { return r.shapes.size() >= r.omega.size() && !r.omega.empty(); }

/// A spinning ring's modes are travelling waves: the real parts the results keep turn with
/// an arbitrary phase, so they pair by their waves instead of by MAC: the base's i-th mode of
/// wave (k, direction) with the other's i-th of the same wave (or none). -1: unpaired.
std::vector<int> pair_by_waves(const ring::ModalResult& base, const ring::ModalResult& other) {
  std::vector<int> out(base.omega.size(), -1);
  std::map<std::pair<int, int>, std::vector<int>> theirs;
  for (std::size_t j = 0; j < other.waves.size(); ++j)
    theirs[{other.waves[j].number, other.waves[j].direction}].push_back(static_cast<int>(j));
  std::map<std::pair<int, int>, std::size_t> seen;
  for (std::size_t i = 0; i < base.waves.size(); ++i) {
    const std::pair<int, int> key{base.waves[i].number, base.waves[i].direction};
    const std::size_t o = seen[key]++;
    const auto it = theirs.find(key);
    if (it != theirs.end() && o < it->second.size()) out[i] = it->second[o];
  }
  return out;
}

Column pair_column(const ring::ModalResult& base, const ring::ModalResult& other, int rows) {
  Column c;
  c.solver = other.solver;
  const bool spinning = !base.waves.empty() && base.waves.size() == base.omega.size() && !other.waves.empty() &&
                        other.waves.size() == other.omega.size();
  if (spinning) {
    const std::vector<int> p = pair_by_waves(base, other);
    for (int i = 0; i < rows; ++i) {
      const int j = i < static_cast<int>(p.size()) ? p[i] : -1;
      c.omega.push_back(j >= 0 ? other.omega[j] : NAN);
      c.mode.push_back(j + 1);
      c.mac.push_back(NAN);
      c.subspace.push_back(false);
    }
    return c;
  }
  const bool by_mac = has_shapes(base) && has_shapes(other);
  const Pairing p = by_mac ? pair_modes(base, other) : Pairing{};
  for (int i = 0; i < rows; ++i) {
    const int j = by_mac ? p.mode[i] : i;
    const bool paired = j >= 0 && j < static_cast<int>(other.omega.size());
    c.omega.push_back(paired ? other.omega[j] : NAN);
    c.mode.push_back(paired ? j + 1 : 0);
    c.mac.push_back(paired && by_mac ? p.mac[i] : NAN);
    c.subspace.push_back(paired && by_mac && p.subspace[i]);
  }
  return c;
}

/// The shapes of `modes` as columns (radial then tangential at every station).
Eigen::MatrixXd shape_matrix(const ring::ModalResult& r, const std::vector<int>& modes) {
  Eigen::MatrixXd A(2 * ring::kStations, modes.size());
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const ring::ModeShape& s = r.shapes[modes[k]];
    for (int i = 0; i < ring::kStations; ++i) {
      A(i, k) = s.radial[i];
      A(ring::kStations + i, k) = s.tangential[i];
    }
  }
  return A;
}

/// Consecutive modes within kDegenerate of each other's frequency.
std::vector<std::vector<int>> clusters(const ring::ModalResult& r) {
  std::vector<std::vector<int>> out;
  for (int j = 0; j < static_cast<int>(r.omega.size()); ++j) {
    if (j > 0 && std::abs(r.omega[j] - r.omega[j - 1]) <= kDegenerate * std::abs(r.omega[j]))
      out.back().push_back(j);
    else
      out.push_back({j});
  }
  return out;
}

std::string label(const std::string& solver) {
  const SolverEntry* e = find_solver(solver);
  return e ? e->label : solver;
}

bool weak(double mac) { return weak_mac(mac); }

/// True when the columns (and the reference) are models of more than one beam theory
/// (fem.theory, multibody.theory or lumped.variant against ring.theory): then each
/// header names its column's theory, since the columns differ by model, not only by
/// discretization.
bool mixed_theories(const Table& t) {
  std::set<std::string> seen;
  for (const auto& c : t.columns)
    if (!c.theory.empty()) seen.insert(c.theory);
  if (t.reference && !t.reference->theory.empty()) seen.insert(t.reference->theory);
  return seen.size() > 1;
}

/// A column's header: the solver's label, with its theory when the table mixes theories.
std::string header(const Table& t, const Column& c) {
  return label(c.solver) + (mixed_theories(t) && !c.theory.empty() ? " (" + c.theory + ")" : "");
}

/// True when row i of the column has a mode (Column::mode).
bool paired(const Column& c, int i) { return c.mode[i] > 0; }

/// A difference or error, or "unlike" where a pairing below kWeakMac made it meaningless,
/// or empty where a column has no mode in that row (nothing was compared).
std::string pct_cell(double v, bool compared) { return !compared ? "" : std::isnan(v) ? "unlike" : pct2(v); }

/// Rows of cells; the first row is the header.
std::vector<std::vector<std::string>> cells(const Table& t, bool with_flags) {
  std::vector<std::vector<std::string>> out;
  std::vector<std::string> head = {"mode"};
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    head.push_back(header(t, t.columns[c]));
    if (c > 0) head.push_back("diff %");
    if (t.reference) head.push_back("error %");
  }
  if (t.reference) head.push_back(header(t, *t.reference));
  if (!t.paper.empty())
    for (const auto& c : t.columns) {
      head.push_back("paper " + label(c.solver));
      head.push_back("vs paper %");
    }
  out.push_back(head);
  for (int i = 0; i < t.rows; ++i) {
    std::vector<std::string> r = {std::to_string(i + 1)};
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      const Column& col = t.columns[c];
      std::string v;
      if (paired(col, i)) {
        v = sig4(col.omega[i]);
        if (with_flags && col.mode[i] != i + 1) v += "*";
        if (with_flags && c > 0 && col.subspace[i]) v += "=";
        if (with_flags && weak(col.mac[i])) v += "?";
      }
      r.push_back(v);
      if (c > 0) r.push_back(pct_cell(col.diff_pct[i], paired(col, i) && paired(t.columns.front(), i)));
      if (t.reference) r.push_back(pct_cell(col.error_pct[i], paired(col, i) && paired(*t.reference, i)));
    }
    if (t.reference)
      r.push_back(paired(*t.reference, i) ? sig4(t.reference->omega[i]) +
                                                (with_flags && t.reference->subspace[i] ? "=" : "") +
                                                (with_flags && weak(t.reference->mac[i]) ? "?" : "")
                                          : "");
    if (!t.paper.empty())
      for (const auto& col : t.columns) {
        const auto p = i < static_cast<int>(t.paper.size()) ? paper_value(t.paper[i], col.solver) : std::nullopt;
        r.push_back(p ? sig4(*p) : "");
        r.push_back(p && paired(col, i) ? pct2((col.omega[i] - *p) / *p * 100.0) : "");
      }
    out.push_back(r);
  }
  return out;
}

bool any_reordered(const Table& t) {
  for (const auto& c : t.columns)
    for (int i = 0; i < t.rows; ++i)
      if (paired(c, i) && c.mode[i] != i + 1) return true;
  return false;
}

bool any_subspace(const Table& t) {
  for (std::size_t c = 1; c < t.columns.size(); ++c)
    for (int i = 0; i < t.rows; ++i)
      if (t.columns[c].subspace[i]) return true;
  return t.reference && std::find(t.reference->subspace.begin(), t.reference->subspace.end(), true) !=
                            t.reference->subspace.end();
}

std::string footnotes(const Table& t) {
  std::ostringstream s;
  s << t.unit << ". diff % = (" << label(t.columns[0].solver) << " - other) / other * 100 (the paper's definition)";
  if (t.reference) s << "; error % = (value - reference) / reference * 100, reference = converged FE";
  s << ".\n";
  // A spinning ring's columns pair by their waves (pair_by_waves), not by MAC.
  bool spinning = false;
  for (const auto& sp : t.spins) spinning |= !sp.second.empty();
  if (any_reordered(t))
    s << (spinning ? "* paired by wave (number and direction) with a mode of another number in that solver's own order.\n"
                   : "* paired by MAC with a mode of another number in that solver's own order.\n");
  if (any_subspace(t))
    s << "= one of a double value (equal to " << kDegenerate << " relative), compared as a subspace: its MAC is\n"
      << "  cos^2 of the base mode's angle to the pair's plane (each solver may return any basis of it).\n";
  if (!t.paper.empty()) s << "paper = Yin & Wang Table 1 (corrected values, docs/paper.md); vs paper % = (computed - paper) / paper * 100.\n";
  double worst = 1.0;
  auto count = [&](const Column& c) {
    for (double m : c.mac)
      if (std::isfinite(m)) worst = std::min(worst, m);
  };
  for (const auto& c : t.columns) count(c);
  if (t.reference) count(*t.reference);
  if (spinning) return s.str();
  s << "Lowest MAC of any paired mode: " << sig4(worst) << ".\n";
  if (worst < kWeakMac)
    s << "? paired with MAC < " << kWeakMac << ": the shapes differ, so no difference or error is given (\"unlike\"): "
      << "refine the coarser model, or compare fewer modes.\n";
  return s.str();
}

}  // namespace

Pairing pair_modes(const ring::ModalResult& base, const ring::ModalResult& other) {
  const int nb = static_cast<int>(base.omega.size());
  const std::vector<std::vector<int>> groups = clusters(other);
  const Eigen::MatrixXd B = shape_matrix(base, [&] {
    std::vector<int> all(nb);
    for (int i = 0; i < nb; ++i) all[i] = i;
    return all;
  }());
  const Eigen::VectorXd norms = B.colwise().squaredNorm();
  struct Pair { double mac; int i, g; };
  std::vector<Pair> pairs;
  for (int g = 0; g < static_cast<int>(groups.size()); ++g) {
    // cos^2 of each base mode's angle to the cluster's span: |Q^T b|^2 / |b|^2 with Q an
    // orthonormal basis of the members' shapes (thin QR).
    const Eigen::MatrixXd A = shape_matrix(other, groups[g]);
    const Eigen::MatrixXd Q = A.householderQr().householderQ() * Eigen::MatrixXd::Identity(A.rows(), A.cols());
    const Eigen::VectorXd projected = (Q.transpose() * B).colwise().squaredNorm();
    for (int i = 0; i < nb; ++i) pairs.push_back({norms[i] > 0 ? projected[i] / norms[i] : 0.0, i, g});
  }
  // Strongest first; ties broken by closeness in mode number, so that equal MACs keep
  // the order.
  std::stable_sort(pairs.begin(), pairs.end(), [&](const Pair& a, const Pair& b) {
    if (std::abs(a.mac - b.mac) > 1e-6) return a.mac > b.mac;
    return std::abs(a.i - groups[a.g].front()) < std::abs(b.i - groups[b.g].front());
  });
  std::vector<int> group_of(nb, -1);
  std::vector<double> mac(nb, 0.0);
  std::vector<std::size_t> taken(groups.size(), 0);
  for (const auto& p : pairs) {
    if (group_of[p.i] >= 0 || taken[p.g] == groups[p.g].size()) continue;
    group_of[p.i] = p.g;
    mac[p.i] = p.mac;
    ++taken[p.g];
  }
  // Each cluster hands its members to its base modes in order.
  Pairing out{std::vector<int>(nb, -1), std::vector<double>(nb, NAN), std::vector<bool>(nb, false)};
  std::vector<std::size_t> next(groups.size(), 0);
  for (int i = 0; i < nb; ++i) {
    const int g = group_of[i];
    if (g < 0) continue;
    out.mode[i] = groups[g][next[g]++];
    out.mac[i] = mac[i];
    out.subspace[i] = groups[g].size() > 1;
  }
  return out;
}

std::vector<int> pair_by_mac(const ring::ModalResult& base, const ring::ModalResult& other) {
  return pair_modes(base, other).mode;
}

Table build_table(const std::string& title, const std::vector<ring::ModalResult>& results,
                  const ring::ModalResult* reference, int rows) {
  Table t;
  t.title = title;
  t.rows = rows;
  const ring::ModalResult& base = results.front();
  auto theory = [](const ring::ModalResult& r) {
    const auto it = r.model.find("theory");
    const std::string* name = it == r.model.end() ? nullptr : std::get_if<std::string>(&it->second);
    return name ? *name : std::string();
  };
  for (const auto& r : results) {
    t.columns.push_back(pair_column(base, r, rows));
    t.columns.back().theory = theory(r);
    t.splits.push_back({r.solver, split_pairs(r)});
    t.spins.emplace_back(r.solver, r.spin_pairs);
  }
  if (reference) t.splits.push_back({"reference", split_pairs(*reference)});
  if (reference) t.spins.emplace_back("reference", reference->spin_pairs);
  if (reference) {
    t.reference = pair_column(base, *reference, rows);
    t.reference->theory = theory(*reference);
  }
  // A pairing below kWeakMac compares unlike modes: no difference or error (NaN).
  const auto& b = t.columns.front().omega;
  for (std::size_t c = 1; c < t.columns.size(); ++c)
    for (int i = 0; i < rows; ++i) {
      const Column& col = t.columns[c];
      t.columns[c].diff_pct.push_back(weak(col.mac[i]) ? NAN : (b[i] - col.omega[i]) / col.omega[i] * 100.0);
    }
  if (reference)
    for (auto& c : t.columns)
      for (int i = 0; i < rows; ++i) {
        const double ref = t.reference->omega[i];
        c.error_pct.push_back(weak(c.mac[i]) || weak(t.reference->mac[i]) ? NAN : (c.omega[i] - ref) / ref * 100.0);
      }
  return t;
}

std::optional<double> paper_value(const ring::PaperRow& row, const std::string& solver) {
  const SolverEntry* e = find_solver(solver);
  if (!e || !e->paper) return std::nullopt;
  return e->paper(row);
}

std::vector<ring::PaperRow> paper_table() { return ring::parse_paper_table(ringvib_table1_csv, "compare/data/table1.csv"); }

std::string format_text(const Table& t) {
  std::ostringstream s;
  if (!t.title.empty()) s << t.title << "\n\n";
  s << text_grid(cells(t, true)) << "\n" << footnotes(t) << split_pairs_text(t.splits, false)
    << spin_pairs_text(t.spins, false);
  return s.str();
}

std::string format_markdown(const Table& t) {
  std::ostringstream s;
  s << markdown_grid(cells(t, true)) << "\n" << footnotes(t) << split_pairs_text(t.splits, true)
    << spin_pairs_text(t.spins, true);
  return s.str();
}

std::string format_csv(const Table& t) {
  std::ostringstream s;
  s.precision(17);
  s << "mode";
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    const auto& n = t.columns[c].solver;
    s << "," << n << "," << n << "_mode," << n << "_mac";
    if (c > 0) s << "," << n << "_diff_pct";
    if (t.reference) s << "," << n << "_error_pct";
  }
  if (t.reference) s << ",reference";
  if (!t.paper.empty())
    for (const auto& c : t.columns) s << ",paper_" << c.solver << "," << c.solver << "_vs_paper_pct";
  s << "\n";
  for (int i = 0; i < t.rows; ++i) {
    s << i + 1;
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      const Column& col = t.columns[c];
      // NaN: no datum (no mode in this row, no MAC without shapes, unlike modes): empty.
      auto cell = [&](double v) { s << ","; if (!std::isnan(v)) s << v; };
      cell(col.omega[i]);
      s << ",";
      if (paired(col, i)) s << col.mode[i];
      cell(col.mac[i]);
      if (c > 0) cell(col.diff_pct[i]);
      if (t.reference) cell(col.error_pct[i]);
    }
    if (t.reference) {
      s << ",";
      if (paired(*t.reference, i)) s << t.reference->omega[i];
    }
    if (!t.paper.empty())
      for (const auto& col : t.columns) {
        const auto p = i < static_cast<int>(t.paper.size()) ? paper_value(t.paper[i], col.solver) : std::nullopt;
        s << ",";
        if (p) s << *p;
        s << ",";
        if (p && paired(col, i)) s << (col.omega[i] - *p) / *p * 100.0;
      }
    s << "\n";
  }
  return s.str();
}

std::string format_json(const Table& t) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < t.rows; ++i) {
    nlohmann::json r;
    r["mode"] = i + 1;
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      const Column& col = t.columns[c];
      if (!paired(col, i)) continue;  // no mode in this row: its keys left out
      r[col.solver] = col.omega[i];
      r[col.solver + "_mode"] = col.mode[i];
      if (std::isfinite(col.mac[i])) r[col.solver + "_mac"] = col.mac[i];
      if (c > 0 && !std::isnan(col.diff_pct[i])) r[col.solver + "_diff_pct"] = col.diff_pct[i];
      if (t.reference && !std::isnan(col.error_pct[i])) r[col.solver + "_error_pct"] = col.error_pct[i];
      if (!t.paper.empty() && i < static_cast<int>(t.paper.size()))
        if (auto p = paper_value(t.paper[i], col.solver)) {
          r["paper_" + col.solver] = *p;
          r[col.solver + "_vs_paper_pct"] = (col.omega[i] - *p) / *p * 100.0;
        }
    }
    if (t.reference && paired(*t.reference, i)) r["reference"] = t.reference->omega[i];
    rows.push_back(r);
  }
  nlohmann::json j;
  j["title"] = t.title;
  j["base"] = t.columns.front().solver;
  j["rows"] = rows;
  for (const auto& sp : t.splits)
    if (!sp.pairs.empty()) j["pairs"][sp.solver] = split_pairs_json(sp.pairs);
  for (const auto& [solver, ps] : t.spins)
    if (!ps.empty()) j["wave_pairs"][solver] = spin_pairs_json(ps);
  return j.dump(2) + "\n";
}

}  // namespace cmp
