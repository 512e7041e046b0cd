// ringvib: runs what a scene file asks for (README). main() parses, dispatches,
// catches and maps failures to the documented exit codes.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "compare/commands.hpp"
#include "compare/fem_module.hpp"
#include "compare/files.hpp"
#include "compare/registry.hpp"
#include "compare/sweep.hpp"
#include "compare/trim.hpp"
#include "ring/errors.hpp"

namespace {

void add_common(CLI::App* c, cmp::CommonArgs& a) {
  c->add_option("scene", a.scene, "scene file (TOML)")->required();
  c->add_option("--set", a.set, "override a scene key: section.key=value (value in TOML syntax)");
  c->add_flag("-q,--quiet", a.quiet, "no progress messages on stderr");
  c->add_option("--max-memory", a.max_memory_gib, "cost guard: refuse scenes estimated to need more (GiB, default 8)")
      ->check(CLI::Validator(
          [](const std::string& v) {
            // CLI11's PositiveNumber lets "nan" and "inf" through, which switch the guard off.
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            return end != v.c_str() && *end == '\0' && std::isfinite(x) && x > 0
                       ? std::string()
                       : "expected a finite number of GiB > 0, got '" + v + "'";
          },
          "GiB > 0"));
  c->add_flag("--force", a.force, "skip the cost guard");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ringvib: in-plane vibration of thin rings; three solvers cross-validated (Yin & Wang 1989/90)"};
  // The version and the FE plug-in this program would load (found relative to it, never by a
  // build path: compare/fem_module.cpp), so that an install can be checked without a solve.
  app.set_version_flag("--version", [] {
    const std::string plugin = cmp::fem_module::plugin_path();
    std::string where;
    for (const std::string& p : cmp::fem_module::plugin_candidates()) where += (where.empty() ? "" : ", ") + p;
    return std::string("ringvib ") + RINGVIB_VERSION + "\nFE plug-in: " +
           (plugin.empty() ? "not found (looked for " + where + ")" : plugin);
  });
  app.require_subcommand(1);
  cmp::CommonArgs a;
  std::string out, junit, format = "text", solver, vtu, csv;
  bool paper = false, json = false;
  std::optional<int> count;

  auto* run = app.add_subcommand("run", "every analysis the scene lists; --out DIR writes report.md, data and figures");
  add_common(run, a);
  run->add_option("--out", out, "folder for the report, CSV/JSON and figures");
  run->add_option("--junit", junit, "write the gates as JUnit XML to this file");
  run->add_flag("--paper", paper, "add the published Table 1 values and each column's deviation");

  auto* table = app.add_subcommand("table", "the three-way frequency table with differences (and errors)");
  add_common(table, a);
  table->add_flag("--paper", paper, "add the published Table 1 values and each column's deviation");
  table->add_option("--format", format, "text | md | csv | json")->check(CLI::IsMember({"text", "md", "csv", "json"}));

  auto* modes = app.add_subcommand("modes", "natural frequencies of one solver");
  add_common(modes, a);
  std::string names;
  for (const auto& n : cmp::solver_names()) names += (names.empty() ? "" : " | ") + n;
  modes->add_option("--solver", solver, names)
      ->required()
      ->check(CLI::IsMember(cmp::solver_names()));
  modes->add_option("--count", count, "number of elastic modes (default: modes.count)")->check(CLI::Range(1, 100000));
  modes->add_flag("--json", json, "print JSON");
  modes->add_option("--vtu", vtu, "FE only: write the mode shapes as VTU files into this folder");

  auto* respond = app.add_subcommand("respond", "the forced nonlinear response of [response]");
  add_common(respond, a);
  respond->add_option("--csv", csv, "write the time history to this CSV file (- or default: stdout)");
  respond->add_option("--solver", solver, "only this solver (default: response.solvers)")
      ->check(CLI::IsMember(cmp::solver_names()));
  respond->add_option("--format", format, "the comparison table of several solvers: text | md | csv | json")
      ->check(CLI::IsMember({"text", "md", "csv", "json"}));

  auto* statics = app.add_subcommand("static", "nonlinear static equilibrium of [static]");
  add_common(statics, a);
  statics->add_flag("--json", json, "print JSON");
  statics->add_option("--solver", solver, "only this solver (default: static.solvers)")
      ->check(CLI::IsMember(cmp::solver_names()));
  statics->add_option("--format", format, "the comparison table of several solvers: text | md | csv | json")
      ->check(CLI::IsMember({"text", "md", "csv", "json"}));

  auto* buckling = app.add_subcommand("buckling", "linear buckling of [buckling]: critical load factors and modes");
  add_common(buckling, a);
  buckling->add_flag("--json", json, "print JSON");
  buckling->add_option("--solver", solver, "only this solver (default: buckling.solvers)")
      ->check(CLI::IsMember(cmp::solver_names()));
  buckling->add_option("--format", format, "the table of several solvers: text | md | csv | json")
      ->check(CLI::IsMember({"text", "md", "csv", "json"}));

  auto* converge = app.add_subcommand("converge", "error against refinement and observed orders, per solver");
  add_common(converge, a);
  converge->add_option("--out", out, "folder for the CSV and the log-log figure");

  auto* bench = app.add_subcommand("bench", "run time against error for every solver (Pareto front)");
  add_common(bench, a);
  bench->add_option("--out", out, "folder for bench.csv, bench.txt and the log-log figure");

  auto* sweep = app.add_subcommand("sweep", "the scene over many --vary values, on all cores or under mpirun");
  add_common(sweep, a);
  cmp::SweepArgs sw;
  sweep->add_option("--vary", sw.vary, "KEY=[v1, v2, ...] (values in TOML syntax); several: all combinations")
      ->required();
  sweep->add_flag("--zip", sw.zip, "the --vary lists in lockstep instead of all combinations");
  sweep->add_option("--out", sw.out, "folder for sweep.csv, sweep.json, sweep.md and sweep.png (default: CSV on stdout)");
  sweep->add_flag("--resume", sw.resume, "skip the cases already in --out DIR/sweep.csv with status ok");
  sweep->add_option("-j,--jobs", sw.jobs, "threads (default: all cores)")->check(CLI::Range(1, 1024));
  sweep->add_option("--ranks", sw.ranks,
                    "run on N MPI ranks, starting mpirun -np N itself: an interrupt then exits 128 + signal")
      ->check(CLI::Range(2, 1 << 20));

  auto* trim = app.add_subcommand("trim", "point masses at given angles that cancel the split of a pair of modes");
  add_common(trim, a);
  cmp::TrimArgs tr;
  trim->add_option("--mode", tr.mode, "a mode of the pair to trim (1-based, the untrimmed scene's order)")->required();
  trim->add_option("--at", tr.at, "one or two angles (degrees, nodes of the model): where masses go")
      ->required()
      ->delimiter(',');
  trim->add_option("--solver", tr.solver, "the model that measures the split (default: the scene's first modal solver)");
  trim->add_option("--tolerance", tr.tolerance, "relative split to reach (default 1e-6)");
  trim->add_flag("--json", tr.json, "print {mode, wave, solver, masses: [{at, mass}], split_before, split_after, ...}");
  trim->add_option("--out", tr.out, "write the trimmed scene (the scene with the trim masses) to this file");

  auto* export_deck = app.add_subcommand("export-deck", "write an external solver's input deck without running it");
  add_common(export_deck, a);
  export_deck->add_option("--solver", solver, "calculix")->required()->check(CLI::IsMember({"calculix"}));
  export_deck->add_option("--out", out, "folder for the deck (ring.inp)")->required();

  auto* keys = app.add_subcommand("keys", "the scene reference of the solver sections, from their option schemas (Markdown)");

  // An unknown subcommand is named, with the known ones (CLI11 alone says only that a
  // subcommand is required).
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string list;
    for (const auto* sub : app.get_subcommands({})) {
      known |= sub->get_name() == argv[1];
      list += (list.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "ringvib: error: unknown subcommand '" << argv[1] << "'; expected one of " << list
                << " (ringvib --help)\n";
      return 2;
    }
  }
  cmp::install_signal_cleanup();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // --help/--version exit 0; usage errors exit 2
  }

  return cmp::run_command(a.scene, [&]() -> int {
    if (*run) return cmp::cmd_run(a, out, junit, paper);
    if (*table) return cmp::cmd_table(a, paper, format);
    if (*modes) return cmp::cmd_modes(a, solver, count, json, vtu);
    if (*respond) return cmp::cmd_respond(a, csv, solver, format);
    if (*statics) return cmp::cmd_static(a, json, solver, format);
    if (*buckling) return cmp::cmd_buckling(a, json, solver, format);
    if (*converge) return cmp::cmd_converge(a, out);
    if (*bench) return cmp::cmd_bench(a, out);
    if (*sweep) return cmp::cmd_sweep(a, sw, argc, argv);
    if (*trim) return cmp::cmd_trim(a, tr);
    if (*export_deck) return cmp::cmd_export_deck(a, solver, out);
    if (*keys) return cmp::cmd_keys();
    return 2;
  }, std::cerr);
}
