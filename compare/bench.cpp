#include "compare/bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <ostream>
#include <sstream>

#include "compare/converge.hpp"
#include "compare/files.hpp"
#include "compare/output.hpp"
#include "compare/plot.hpp"
#include "compare/progress.hpp"
#include "compare/registry.hpp"
#include "compare/table.hpp"

namespace cmp {
namespace {

struct Timed {
  ring::ModalResult result;
  double median = 0.0;
  int repeats = 0;
};

/// Solves repeatedly; the median of the solvers' own wall times (process-internal).
Timed timed_solve(const ring::Scene& s, const SolverEntry& solver, int modes) {
  Timed t;
  std::vector<double> times;
  double total = 0.0;
  while (times.size() < 3 || (total < 0.3 && times.size() < 9)) {
    t.result = solver.modes(s, modes);
    times.push_back(t.result.seconds);
    total += t.result.seconds;
  }
  std::sort(times.begin(), times.end());
  t.median = times[times.size() / 2];
  t.repeats = static_cast<int>(times.size());
  return t;
}

}  // namespace

std::string fmt_seconds(double s) {
  if (s < 1e-3) return fmt::format("{:.1f} us", s * 1e6);
  if (s < 1.0) return fmt::format("{:.2f} ms", s * 1e3);
  return fmt::format("{:.2f} s", s);
}

std::vector<std::string> curve_names(const BenchStudy& b) {
  std::vector<std::string> curves;
  for (const auto& p : b.points)
    if (std::find(curves.begin(), curves.end(), p.curve) == curves.end()) curves.push_back(p.curve);
  return curves;
}

std::string time_to_error_lines(const BenchStudy& b, double second_pct) {
  std::ostringstream s;
  for (const auto& c : curve_names(b)) {
    const auto t1 = time_to_error(b, c, 1.0), t2 = time_to_error(b, c, second_pct);
    s << fmt::format("  {:<24} 1 %: {:<12} {:g} %: {}\n", c, t1 ? fmt_seconds(*t1) : "not reached", second_pct,
                     t2 ? fmt_seconds(*t2) : "not reached");
  }
  return s.str();
}

void plot_pareto(const std::string& dir, const std::string& name, const std::string& title, const std::string& ylabel,
                 const BenchStudy& b) {
  std::vector<Series> plot;
  for (const auto& c : curve_names(b)) {
    Series x{c, {}, {}};
    for (const auto& p : b.points)
      if (p.curve == c) {
        x.x.push_back(p.seconds);
        x.y.push_back(p.max_error);
      }
    plot.push_back(x);
  }
  plot_series(dir, name, title, "solver time, median (s)", ylabel, plot, true, true);
}

BenchStudy bench(const ring::Scene& scene, const References& references, std::ostream* progress) {
  BenchStudy b;
  b.modes = scene.modes.count;
  b.method_curve = solver(scene_schema().default_solver).curve(scene);
  ring::Scene p3 = scene;
  p3.fem.degree = 3;
  b.fe_curve = solver(scene.reference_solver).curve(p3);
  for (const auto* r : {&references.extensible, &references.inextensible})
    if (*r) b.reference_seconds = std::max(b.reference_seconds, (*r)->seconds);
  // The runs are listed first, so that the progress line can count them.
  std::vector<std::pair<const SolverEntry*, std::vector<std::pair<std::string, ring::Scene>>>> runs;
  long total = 0;
  for (const SolverEntry& entry : registry()) {
    if (!scene.column(entry.name)) continue;
    runs.emplace_back(&entry, entry.bench_sweep(scene, b.modes));
    total += static_cast<long>(runs.back().second.size());
  }
  ProgressLine line("bench", "runs", progress);
  long done = 0;
  for (const auto& [entry_ptr, sweep] : runs) {
    const SolverEntry& entry = *entry_ptr;
    const ring::ModalResult& reference = references.of(scene, entry.name);
    std::optional<Timed> coarser;
    std::string previous_curve;
    for (const auto& [curve, s] : sweep) {
      const int size = entry.size(s);
      line.note("bench " + curve + " at " + std::to_string(size));
      Timed t = timed_solve(s, entry, b.modes);
      line.update(++done, total);
      const auto [mx, mean] = errors_against(t.result, reference, b.modes);
      b.points.push_back({curve, size, t.result.unknowns, t.median, t.repeats, mx, mean});
      if (curve != previous_curve) coarser.reset();
      previous_curve = curve;
      const int n = size;
      if (entry.richardson && coarser) {
        // Richardson with order 2 from n/2 and n: the cost of both solves.
        ring::ModalResult x = t.result;
        const auto pf = pair_by_mac(reference, t.result), pc = pair_by_mac(reference, coarser->result);
        for (int i = 0; i < b.modes; ++i)
          x.omega[pf[i]] = (4.0 * t.result.omega[pf[i]] - coarser->result.omega[pc[i]]) / 3.0;
        const auto [mx, mean] = errors_against(x, reference, b.modes);
        b.points.push_back({curve + " + Richardson", n, t.result.unknowns, t.median + coarser->median, t.repeats,
                            mx, mean});
      }
      coarser = std::move(t);
    }
  }
  return b;
}

std::optional<double> time_to_error(const BenchStudy& b, const std::string& curve, double error_pct) {
  std::vector<const BenchPoint*> pts;
  for (const auto& p : b.points)
    if (p.curve == curve) pts.push_back(&p);
  std::sort(pts.begin(), pts.end(), [](auto* a, auto* c) { return a->seconds < c->seconds; });
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (pts[i]->max_error > error_pct) continue;
    if (i == 0) return pts[0]->seconds;
    // Interpolate log(time) against log(error) between the last point above and this one.
    const auto *a = pts[i - 1], *c = pts[i];
    const double f = (std::log(error_pct) - std::log(a->max_error)) / (std::log(c->max_error) - std::log(a->max_error));
    return std::exp(std::log(a->seconds) + f * (std::log(c->seconds) - std::log(a->seconds)));
  }
  return std::nullopt;
}

std::string bench_text(const BenchStudy& b) {
  std::ostringstream s;
  s << "Run time against error, " << b.modes << " lowest modes, error against the converged FE reference\n"
    << "of each model's own continuum (inextensible for the rigid-link chains, extensible for frames and FE)\n"
    << "(solver time inside this process, median of repeats; compare times as ratios)\n\n";
  s << fmt::format("{:<24} {:>6} {:>9} {:>12} {:>8} {:>13} {:>13}\n", "curve", "size", "unknowns", "time", "repeats",
                   "max |err| %", "mean |err| %");
  for (const auto& p : b.points)
    s << fmt::format("{:<24} {:6d} {:9d} {:>12} {:8d} {:13.3e} {:13.3e}\n", p.curve, p.size, p.unknowns,
                     fmt_seconds(p.seconds), p.repeats, p.max_error, p.mean_error);
  s << "\nTime to reach a max error of 1 % and of 0.01 % on the " << b.modes << " modes:\n"
    << time_to_error_lines(b, 0.01);
  // The paper's claim: multibody at n = 40 takes about 1/3 of the FE time.
  const BenchPoint *mb40 = nullptr, *fe40 = nullptr;
  for (const auto& p : b.points) {
    if (p.curve == b.method_curve && p.size == 40) mb40 = &p;
    if (p.curve == b.fe_curve && p.size == 40) fe40 = &p;
  }
  if (mb40 && fe40)
    s << "\nMultibody / FE time at equal n = 40 (FE p = 3): " << sig4(mb40->seconds / fe40->seconds)
      << " (the paper claims about 1/3 against its SAP5 run); their max errors " << sig4(mb40->max_error) << " % and "
      << sig4(fe40->max_error) << " %.\n";
  for (double e : {1.0, 0.01}) {
    const auto m = time_to_error(b, b.method_curve, e), f = time_to_error(b, b.fe_curve, e);
    if (m && f)
      s << "Multibody / FE (p = 3) time at equal max error " << e << " %: " << sig4(*m / *f) << "\n";
    else if (f)
      s << "At equal max error " << e << " %: multibody does not reach it in the sweep; FE (p = 3) needs "
        << fmt_seconds(*f) << "\n";
  }
  return s.str();
}

void write_bench(const std::string& dir, const BenchStudy& b) {
  std::ostringstream csv;
  csv.precision(12);
  csv << "curve,size,unknowns,seconds_median,repeats,max_error_pct,mean_error_pct\n";
  for (const auto& p : b.points)
    csv << '"' << p.curve << "\"," << p.size << "," << p.unknowns << "," << p.seconds << "," << p.repeats << ","
        << p.max_error << "," << p.mean_error << "\n";
  write_file(dir + "/bench.csv", csv.str());
  plot_pareto(dir, "bench", "Run time against error, " + std::to_string(b.modes) + " lowest modes (lower left is better)",
              "max |error| against the reference (%)", b);
  write_file(dir + "/bench.txt", bench_text(b));
}

}  // namespace cmp
