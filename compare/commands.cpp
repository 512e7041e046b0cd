#include "compare/pairs.hpp"
#include "compare/spin.hpp"
#include "compare/commands.hpp"

#include <fmt/format.h>


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "calculix/modes.hpp"
#include "compare/bench.hpp"
#include "compare/buckling.hpp"
#include "compare/bench_nonlinear.hpp"
#include "compare/converge.hpp"
#include "compare/files.hpp"
#include "compare/gates.hpp"
#include "compare/guard.hpp"
#include "compare/nonlinear.hpp"
#include "compare/output.hpp"
#include "compare/plot.hpp"
#include "compare/progress.hpp"
#include "compare/report.hpp"
#include "compare/response.hpp"
#include "compare/runner.hpp"
#include "compare/registry.hpp"
#include "compare/table.hpp"
#include "ring/errors.hpp"
#include "ring/scene.hpp"

namespace cmp {

namespace {

/// Progress on stderr, only on a terminal and without --quiet (compare/progress.hpp).
class Progress {
 public:
  explicit Progress(bool quiet) : out_(progress_stream(quiet)) {}
  void say(const std::string& what) const {
    if (out_) *out_ << "ringvib: " << what << "\n";
  }
  /// Where the solvers' progress goes: stderr, or null when off.
  std::ostream* stream() const { return out_; }

 private:
  std::ostream* out_;
};

/// `only`: the request of a nonlinear command that --solver NAME narrows to that solver
/// (nullptr otherwise). The command then runs that solver alone and no reference
/// (run_nonlinear), so the checks and the cost guard see only it: a solver the command does
/// not run cannot refuse the scene (the multibody chain has no "midpoint" integrator).
ring::Scene load(const CommonArgs& a, ring::NonlinearRequest ring::Scene::*only = nullptr,
                 const std::string& solver = "") {
  ring::Scene s = load_scene(a.scene, a.set);
  if (only) s = narrowed(std::move(s), only, solver);
  check_runnable(s, a.max_memory_gib, a.force);
  for (const auto& w : s.warnings) std::cerr << "ringvib: warning: " << a.scene << ": " << w << "\n";
  return s;
}

std::string modes_text(const ring::ModalResult& m) {
  std::ostringstream s;
  s << m.solver << ":";
  for (const auto& [k, v] : m.model) s << " " << k << "=" << model_value(v);
  s << "\nrigid modes: " << m.rigid_modes << "\n";
  const bool waves = m.waves.size() == m.omega.size() && !m.waves.empty();
  if (!m.frame.empty()) s << "spinning: frequencies in the " << (m.frame == "fixed" ? "fixed" : "turning") << " frame\n";
  s << "\n  mode   omega rad/s        Hz" << (waves ? "  wave" : "") << "\n";
  for (std::size_t i = 0; i < m.omega.size(); ++i) {
    s << fmt::format("  {:4d}  {:>12}  {:>8}", i + 1, sig4(m.omega[i]), sig4(m.omega[i] / (2 * M_PI)));
    if (waves) s << fmt::format("  {} {}", m.waves[i].number, direction_name(m.waves[i].direction));
    s << "\n";
  }
  s << fmt::format("\n{} unknowns, solved in {:.3g} s, max relative eigen-residual {} ({})\n", m.unknowns,
                   m.seconds, residual_cell(m), m.residual_norm);
  s << split_pairs_text({{m.solver, split_pairs(m)}}, false);
  s << spin_pairs_text({{m.solver, m.spin_pairs}}, false);
  return s.str();
}

std::string format_nonlinear(const NonlinearTable& t, const std::string& format) {
  if (format == "md") return format_markdown(t);
  if (format == "csv") return format_csv(t);
  if (format == "json") return format_json(t);
  return format_text(t);
}

/// The names each command may write into its output folder (Outputs::folder checks that
/// none of them is taken by a folder, a symlink or a device before anything is computed).
const std::vector<std::string> kRunNames = {"report", "table", "modes_", "shapes_", "mode_shapes", "difference",
                                            "error", "response", "static", "buckling"};
const std::vector<std::string> kConvergeNames = {"convergence"};
const std::vector<std::string> kBenchNames = {"bench"};
const std::vector<std::string> kVtuNames = {"fem_modes"};
const std::vector<std::string> kDeckNames = {"ring"};

void require_modes(const ring::Scene& s, const std::string& command) {
  if (!modal(s))
    throw ring::InputError(s.file, "modes",
                           "`" + command + "` compares natural frequencies, and the scene asks for none (add a "
                           "[modes] or [table] section, or a solver section without [response]/[static])");
}

}  // namespace

ring::Scene narrowed(ring::Scene s, ring::NonlinearRequest ring::Scene::*request, const std::string& solver) {
  if (!solver.empty()) {
    (s.*request).solvers = {solver};
    (s.*request).reference = false;
  }
  return s;
}

std::optional<std::string> single_solver(const std::string& option, const ring::NonlinearRequest& q) {
  if (!option.empty()) return option;
  if (q.solvers.size() == 1 && !q.reference) return q.solvers.front();
  return std::nullopt;
}

void require_section(const ring::Scene& s, const std::string& section) {
  const bool has = section == "static" ? s.statics.has_value() : section == "response" ? s.response.has_value()
                                                                                       : s.buckling.has_value();
  if (!has) throw ring::InputError(s.file, section, "the scene has no [" + section + "] section");
}

ring::ModalResult run_modes(const ring::Scene& s, const std::string& solver, std::optional<int> count,
                            const std::string& count_key) {
  const SolverEntry& entry = cmp::solver(solver);
  const int k = count.value_or(s.modes.count);
  if (count && *count < 1) throw ring::InputError(s.file, count_key, "expected at least 1 mode");
  // The count is checked against the model like modes.count (gates do not apply here).
  if (count && k > entry.elastic_modes(s))
    throw ring::InputError(s.file, count_key, std::to_string(k) + " modes asked, but the " + solver +
                                                  " model has only " + std::to_string(entry.elastic_modes(s)) +
                                                  " elastic modes");
  check_modes_of(s, entry);  // a solver the scene does not list has not been checked by the reader
  return entry.modes(s, k);
}

Table run_table(const ring::Scene& s, bool paper, std::ostream* progress) {
  require_modes(s, "table");
  return make_table(s, compute_modal(s, progress), paper);
}

ring::StaticResult run_static(const ring::Scene& s, const std::string& solver, std::ostream* progress) {
  require_section(s, "static");
  return run_nonlinear(s, solver, progress).statics.front();
}

ring::TimeHistory run_response(const ring::Scene& s, const std::string& solver, std::ostream* progress) {
  require_section(s, "response");
  return run_nonlinear(s, solver, progress).histories.front();
}

ring::BucklingResult run_buckling_of(const ring::Scene& s, const std::string& solver, std::ostream* progress) {
  require_section(s, "buckling");
  return run_buckling(s, solver, progress).results.front();
}

NonlinearTable static_comparison(const ring::Scene& s, const NonlinearRun& r) {
  require_section(s, "static");
  return static_table(s.title, r.statics, r.static_reference ? &*r.static_reference : nullptr);
}

NonlinearTable response_comparison(const ring::Scene& s, const NonlinearRun& r) {
  require_section(s, "response");
  return response_table(s.title, r.histories, r.history_reference ? &*r.history_reference : nullptr);
}

Table buckling_comparison(const ring::Scene& s, std::ostream* progress) {
  require_section(s, "buckling");
  return buckling_table(s, run_buckling(s, "", progress));
}

int cmd_modes(const CommonArgs& a, const std::string& solver, std::optional<int> count, bool json,
              const std::string& vtu_dir) {
  const ring::Scene s = load(a);
  Outputs files;
  if (!vtu_dir.empty()) files.folder(vtu_dir, "--vtu", kVtuNames);
  const SolverEntry& entry = cmp::solver(solver);
  if (!vtu_dir.empty() && !entry.write_vtu)
    throw ring::InputError(a.scene, "--vtu", "VTU output is for the FE solver (--solver " + s.reference_solver + ")");
  files.open();
  const ring::ModalResult m = run_modes(s, solver, count, "--count");
  if (!vtu_dir.empty()) {
    entry.write_vtu(s, count.value_or(s.modes.count), files.stage());
    files.publish();
  }
  std::cout << (json ? modal_json(m, false) : modes_text(m));
  return 0;
}

int cmd_table(const CommonArgs& a, bool paper, const std::string& format) {
  const ring::Scene s = load(a);
  require_modes(s, "table");
  const Progress p(a.quiet);
  const Table t = run_table(s, paper, p.stream());
  if (format == "md") std::cout << format_markdown(t);
  else if (format == "csv") std::cout << format_csv(t);
  else if (format == "json") std::cout << format_json(t);
  else std::cout << format_text(t);
  return 0;
}

int cmd_run(const CommonArgs& a, const std::string& out_dir, const std::string& junit, bool paper) {
  const ring::Scene s = load(a);
  const Progress p(a.quiet);
  Outputs files;
  if (!out_dir.empty()) files.folder(out_dir, "--out", kRunNames);
  if (!junit.empty()) files.file(junit, "--junit", a.scene);
  files.open();
  RunReport rep;
  rep.scene = &s;
  int code = 0;

  if (modal(s)) {
    const ModalRun r = compute_modal(s, p.stream());
    rep.modal = r.columns;
    rep.reference = r.reference;
    rep.table = make_table(s, r, paper);
    std::cout << format_text(*rep.table) << "\n";
    rep.gates = evaluate_gates(s.gates, *rep.table);
    for (const auto& g : rep.gates) {
      std::cout << g.line() << "\n";
      if (!g.pass) code = 1;
    }
  }
  if (s.response || s.statics) {
    NonlinearRun nl = run_nonlinear(s, "", p.stream());
    // One solver prints what `respond`/`static` print; several (or a reference) the
    // comparison table. The report always has the table.
    if (!nl.histories.empty()) {
      rep.history = nl.histories.front();
      rep.response_table = response_table(s.title, nl.histories, nl.history_reference ? &*nl.history_reference : nullptr);
      if (nl.histories.size() > 1 || nl.history_reference)
        std::cout << format_text(*rep.response_table) << "\n";
      else
        std::cout << "response: " << rep.history->t.size() - 1 << " steps to t = " << rep.history->t.back() << " s\n";
    }
    if (!nl.statics.empty()) {
      rep.statics = nl.statics.front();
      rep.static_table = static_table(s.title, nl.statics, nl.static_reference ? &*nl.static_reference : nullptr);
      if (nl.statics.size() > 1 || nl.static_reference)
        std::cout << format_text(*rep.static_table) << path_summary(nl.statics) << "\n";
      else std::cout << static_text(*rep.statics);
    }
    rep.nonlinear = std::move(nl);
    for (const auto* t : {rep.response_table ? &*rep.response_table : nullptr,
                          rep.static_table ? &*rep.static_table : nullptr}) {
      if (!t) continue;
      for (const auto& g : evaluate_nonlinear_gates(s.gates, *t)) {
        std::cout << g.line() << "\n";
        if (!g.pass) code = 1;
        rep.gates.push_back(g);
      }
    }
  }
  if (s.buckling) {
    const BucklingRun b = run_buckling(s, "", p.stream());
    if (b.results.size() > 1 || b.reference) {
      rep.buckling_table = buckling_table(s, b);
      std::cout << format_text(*rep.buckling_table) << "\n";
    } else {
      std::cout << buckling_text(s, b.results.front()) << "\n";
    }
    rep.buckling = b;
  }
  if (!junit.empty()) files.stage_file(junit, junit_xml(s.title.empty() ? a.scene : s.title, rep.gates));
  if (!out_dir.empty()) {
    p.say("writing the report, data and figures to " + out_dir);
    write_report(files.stage(), rep);
  }
  files.publish();
  if (!out_dir.empty()) std::cout << "wrote " << out_dir << "/report.md\n";
  return code;
}

int cmd_respond(const CommonArgs& a, const std::string& csv, const std::string& solver, const std::string& format) {
  ring::Scene s = load(a, &ring::Scene::response_request, solver);
  require_section(s, "response");
  // --csv - is standard output, as without --csv.
  const bool to_file = !csv.empty() && csv != "-";
  Outputs files;
  if (to_file) files.file(csv, "--csv", a.scene);
  const Progress p(a.quiet);
  std::ostream* progress = p.stream();
  const auto one = single_solver(solver, s.response_request);
  if (!one) {
    if (to_file)
      throw ring::InputError(a.scene, "--csv", "the scene runs several solvers (response.solvers); pick one with "
                                               "--solver NAME, or write every history with run --out DIR");
    const NonlinearRun r = run_nonlinear(s, "", progress);
    std::cout << format_nonlinear(response_comparison(s, r), format);
    return 0;
  }
  files.open();
  const ring::TimeHistory h = run_response(s, *one, progress);
  if (!to_file) {
    std::cout << history_csv(h);
    return 0;
  }
  files.stage_file(csv, history_csv(h));
  files.publish();
  return 0;
}

int cmd_static(const CommonArgs& a, bool json, const std::string& solver, const std::string& format) {
  const ring::Scene s = load(a, &ring::Scene::static_request, solver);
  require_section(s, "static");
  const Progress p(a.quiet);
  std::ostream* progress = p.stream();
  const auto one = single_solver(solver, s.static_request);
  if (!one) {
    const NonlinearRun r = run_nonlinear(s, "", progress);
    const NonlinearTable t = static_comparison(s, r);
    std::cout << format_nonlinear(t, json ? "json" : format);
    if (!json && format == "text") std::cout << path_summary(r.statics);
    return 0;
  }
  const ring::StaticResult r = run_static(s, *one, progress);
  std::cout << (json ? static_json(r) : static_text(r));
  return 0;
}

int cmd_buckling(const CommonArgs& a, bool json, const std::string& solver, const std::string& format) {
  const ring::Scene s = load(a, &ring::Scene::buckling_request, solver);
  require_section(s, "buckling");
  const Progress p(a.quiet);
  const auto one = single_solver(solver, s.buckling_request);
  const BucklingRun r = run_buckling(s, one.value_or(""), p.stream());
  if (one) {
    std::cout << (json ? buckling_json(r.results.front()) : buckling_text(s, r.results.front()));
    return 0;
  }
  const Table t = buckling_table(s, r);
  const std::string f = json ? "json" : format;
  if (f == "md") std::cout << format_markdown(t);
  else if (f == "csv") std::cout << format_csv(t);
  else if (f == "json") std::cout << format_json(t);
  else std::cout << format_text(t);
  return 0;
}

ConvergenceStudy run_converge(const ring::Scene& s, std::ostream* progress) {
  require_modes(s, "converge");
  return converge(s, compute_references(s, progress), progress);
}

int cmd_converge(const CommonArgs& a, const std::string& out_dir) {
  const ring::Scene s = load(a);
  require_modes(s, "converge");
  const Progress p(a.quiet);
  Outputs files;
  if (!out_dir.empty()) files.folder(out_dir, "--out", kConvergeNames);
  files.open();
  const ConvergenceStudy c = run_converge(s, p.stream());
  std::cout << convergence_text(c);
  if (!out_dir.empty()) {
    write_convergence(files.stage(), c);
    files.publish();
    std::cout << "wrote " << out_dir << "/convergence.csv and convergence.png\n";
  }
  return 0;
}

namespace {
/// What bench can time, checked before anything runs (the nonlinear reference and the
/// recorded loaded point included).
void check_bench(const ring::Scene& s) {
  if (!modal(s) && !s.response && !s.statics && !s.buckling)
    throw ring::InputError(s.file, "modes",
                           "`bench` times modes, a [response], a [static] or a [buckling], and the scene has none");
  if (s.response || s.statics || s.buckling) check_bench_nonlinear(s);
}
}  // namespace

BenchRun run_bench(const ring::Scene& s, std::ostream* progress) {
  check_bench(s);
  // The modal sweep for the solvers whose modes the scene lists, the nonlinear sweeps for
  // its [response] and [static].
  BenchRun r;
  if (modal(s)) r.modal = bench(s, compute_references(s, progress), progress);
  r.nonlinear = bench_nonlinear(s, progress);
  return r;
}

int cmd_bench(const CommonArgs& a, const std::string& out_dir) {
  const ring::Scene s = load(a);
  check_bench(s);
  const Progress p(a.quiet);
  Outputs files;
  if (!out_dir.empty()) files.folder(out_dir, "--out", kBenchNames);
  files.open();
  const BenchRun run = run_bench(s, p.stream());
  const std::optional<BenchStudy>& modal_study = run.modal;
  const std::vector<NonlinearBench>& nonlinear = run.nonlinear;
  if (modal_study) std::cout << bench_text(*modal_study);
  for (const NonlinearBench& b : nonlinear) std::cout << (modal_study ? "\n" : "") << bench_nonlinear_text(b);
  if (!out_dir.empty()) {
    if (modal_study) write_bench(files.stage(), *modal_study);
    for (const NonlinearBench& b : nonlinear) write_bench_nonlinear(files.stage(), b);
    files.publish();
    std::cout << "wrote " << out_dir << "/bench*.csv, .txt and .png\n";
  }
  return 0;
}

int cmd_export_deck(const CommonArgs& a, const std::string& solver, const std::string& out_dir) {
  // The deck needs neither ccx nor the cost guard: only the reader's checks and the deck's own.
  const ring::Scene s = load_scene(a.scene, a.set);
  if (solver != "calculix")
    throw ring::InputError(a.scene, "--solver", "export-deck writes the deck of an external solver: calculix");
  Outputs files;
  files.folder(out_dir, "--out", kDeckNames);
  calculix::Deck deck;
  try {
    deck = calculix::modes_deck(s.ring, s.calculix, s.modes.count, s.title);
  } catch (const ring::InputError& e) {
    throw ring::InputError(a.scene, "", e.what());
  }
  files.open();
  write_file(files.stage() + "/ring.inp", deck.text);
  files.publish();
  std::cout << "wrote " << out_dir << "/ring.inp (run it with: cd " << out_dir << " && ccx ring)\n";
  return 0;
}

int cmd_keys() {
  std::cout << keys_markdown();
  return 0;
}

int run_command(const std::string& scene, const std::function<int()>& command, std::ostream& err) {
  try {
    return command();
  } catch (const ring::InputError& e) {
    err << "ringvib: error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {  // a solver's "can never work" check
    err << "ringvib: error: " << scene << ": " << e.what() << "\n";
    return 2;
  } catch (const ring::NumericalError& e) {
    err << "ringvib: numerical failure: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    err << "ringvib: failure: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace cmp
