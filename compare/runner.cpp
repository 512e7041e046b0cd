#include "compare/runner.hpp"

#include <algorithm>

#include "compare/guard.hpp"
#include "compare/imports.hpp"
#include "compare/registry.hpp"

namespace cmp {

void check_runnable(const ring::Scene& scene, double max_memory_gib, bool force) {
  check_scene(scene);
  // Imported columns are read now, so that a bad file is refused before anything runs.
  for (const auto& c : scene.table.imports) read_imported(c);
  check_cost(scene, Budget{max_memory_gib * double(1ull << 30), force});
}

std::vector<std::string> table_solvers(const ring::Scene& s) {
  std::vector<std::string> v;
  if (s.table.present) {
    v.push_back(s.table.base);
    for (const auto& o : s.table.against) v.push_back(o);
  }
  for (const auto& o : s.modes.solvers)
    if (std::find(v.begin(), v.end(), o) == v.end()) v.push_back(o);
  return v;
}

bool modal(const ring::Scene& s) { return !s.modes.solvers.empty() || s.table.present; }

ModalRun compute_modal(const ring::Scene& s, std::ostream* progress) {
  ModalRun r;
  for (const auto& name : table_solvers(s)) {
    if (progress) *progress << "ringvib: computing " << s.modes.count << " modes with " << name << "\n";
    r.columns.push_back(solve_modes(s, name, s.modes.count));
  }
  for (const auto& c : s.table.imports) r.columns.push_back(read_imported(c));
  if (s.needs_reference()) {
    if (progress) *progress << "ringvib: computing the converged FE reference\n";
    r.reference = reference_modes(s, s.modes.count);
  }
  return r;
}

Table make_table(const ring::Scene& s, const ModalRun& r, bool paper) {
  Table t = build_table(s.title, r.columns, r.reference ? &*r.reference : nullptr, s.modes.count);
  if (s.modes.preload_static) t.unit = "rad/s about the equilibrium of [static] at its full load (modes.preload)";
  bool gates_need_paper = false;
  for (const auto& g : s.gates) gates_need_paper |= g.against == "paper";
  if (paper || gates_need_paper) t.paper = paper_table();
  return t;
}

}  // namespace cmp
