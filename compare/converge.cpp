#include "compare/converge.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <sstream>

#include "compare/files.hpp"
#include "compare/output.hpp"
#include "compare/plot.hpp"
#include "compare/progress.hpp"
#include "compare/registry.hpp"
#include "compare/table.hpp"

namespace cmp {

std::pair<double, double> errors_against(const ring::ModalResult& r, const ring::ModalResult& ref, int modes) {
  const std::vector<int> pair = pair_by_mac(ref, r);
  double mx = 0.0, sum = 0.0;
  for (int i = 0; i < modes; ++i) {
    const double e = pair[i] < 0 ? INFINITY : std::abs(r.omega[pair[i]] - ref.omega[i]) / ref.omega[i] * 100.0;
    mx = std::max(mx, e);
    sum += e;
  }
  return {mx, sum / modes};
}

bool inextensible_limit(const ring::Scene& scene, const std::string& name) {
  return solver(name).inextensible(scene);
}

const ring::ModalResult& References::of(const ring::Scene& scene, const std::string& solver) const {
  const auto& r = inextensible_limit(scene, solver) ? inextensible : extensible;
  if (!r) throw std::logic_error("References::of: the reference for " + solver + " was not computed");
  return *r;
}

References compute_references(const ring::Scene& scene, std::ostream* progress) {
  References refs;
  for (const auto& name : solver_names()) {
    if (!scene.column(name)) continue;
    const bool inext = inextensible_limit(scene, name);
    auto& slot = inext ? refs.inextensible : refs.extensible;
    if (slot) continue;
    if (progress) *progress << "ringvib: computing the converged " << (inext ? "inextensible" : "extensible")
                            << " FE reference\n";
    ring::Scene s = scene;
    s.fem.extensible = !inext;
    slot = reference_modes(s, scene.modes.count);
  }
  return refs;
}

double fitted_order(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (y[i] > 0 && std::isfinite(y[i])) {
      lx.push_back(std::log(x[i]));
      ly.push_back(std::log(y[i]));
    }
  const std::size_t n = lx.size();
  if (n < 2) return NAN;
  const double mx = std::accumulate(lx.begin(), lx.end(), 0.0) / n, my = std::accumulate(ly.begin(), ly.end(), 0.0) / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (lx[i] - mx) * (ly[i] - my);
    sxx += (lx[i] - mx) * (lx[i] - mx);
  }
  return -sxy / sxx;
}

ConvergenceStudy converge(const ring::Scene& scene, const References& references, std::ostream* progress) {
  ConvergenceStudy c;
  c.modes = scene.modes.count;
  for (const auto* r : {&references.extensible, &references.inextensible})
    if (*r) c.reference_estimate = std::max(c.reference_estimate, (*r)->error_estimate);
  const double floor_pct = 100.0 * 100.0 * std::max(scene.fem.tolerance, c.reference_estimate);
  long total = 0, done = 0;
  for (const SolverEntry& entry : registry())
    if (scene.column(entry.name)) total += entry.converge_steps;
  ProgressLine line("converge", "sizes", progress);
  for (const SolverEntry& entry : registry()) {
    if (!scene.column(entry.name)) continue;
    const std::string& name = entry.name;
    const ring::ModalResult& reference = references.of(scene, name);
    ConvergenceSeries s;
    s.name = entry.curve(scene);
    s.parameter = entry.size_name;
    std::vector<ring::ModalResult> results;
    for (int k = 0; k < entry.converge_steps; ++k) {
      const int base = entry.size(scene);
      const double size = base << k;
      ring::Scene r = scene;
      entry.set_size(r, base << k);
      line.note(name + " at " + s.parameter + " = " + std::to_string(base << k));
      results.push_back(entry.modes(r, c.modes));
      line.update(++done, total);
      const auto [mx, mean] = errors_against(results.back(), reference, c.modes);
      s.size.push_back(size);
      s.max_error.push_back(mx);
      s.mean_error.push_back(mean);
      s.seconds.push_back(results.back().seconds);
    }
    std::vector<double> fx, fy;
    for (std::size_t i = 0; i < s.size.size(); ++i)
      if (s.max_error[i] > floor_pct) { fx.push_back(s.size[i]); fy.push_back(s.max_error[i]); }
    s.order = fitted_order(fx, fy);
    c.series.push_back(s);
    if (entry.richardson) {
      // Richardson with the observed order 2: w = (4 w_2n - w_n) / 3, paired by MAC.
      ConvergenceSeries rich{s.name + " (Richardson)", s.parameter, {}, {}, {}, {}, 0.0};
      for (std::size_t k = 1; k < results.size(); ++k) {
        ring::ModalResult x = results[k];
        const std::vector<int> pf = pair_by_mac(reference, results[k]), pc = pair_by_mac(reference, results[k - 1]);
        for (int i = 0; i < c.modes; ++i) x.omega[pf[i]] = (4.0 * results[k].omega[pf[i]] - results[k - 1].omega[pc[i]]) / 3.0;
        const auto [mx, mean] = errors_against(x, reference, c.modes);
        rich.size.push_back(s.size[k]);
        rich.max_error.push_back(mx);
        rich.mean_error.push_back(mean);
        rich.seconds.push_back(results[k].seconds + results[k - 1].seconds);
      }
      std::vector<double> rx, ry;
      for (std::size_t i = 0; i < rich.size.size(); ++i)
        if (rich.max_error[i] > floor_pct) { rx.push_back(rich.size[i]); ry.push_back(rich.max_error[i]); }
      rich.order = fitted_order(rx, ry);
      c.series.push_back(rich);
    }
  }
  return c;
}

std::string convergence_text(const ConvergenceStudy& c) {
  std::ostringstream s;
  s << "Max and mean |error| (%) over the " << c.modes
    << " lowest modes, each model against the converged FE reference of its own continuum\n"
    << "(inextensible for the rigid-link chains, extensible for frames and FE; estimated reference error "
    << c.reference_estimate << " relative)\n\n";
  for (const auto& x : c.series) {
    s << x.name << ": observed order " << (std::isfinite(x.order) ? pct2(x.order) : std::string("n/a")) << "\n";
    s << fmt::format("  {:>10}  {:>12}  {:>12}  {:>10}\n", x.parameter, "max |err| %", "mean |err| %", "seconds");
    for (std::size_t i = 0; i < x.size.size(); ++i)
      s << fmt::format("  {:10.0f}  {:12.3e}  {:12.3e}  {:10.3e}\n", x.size[i], x.max_error[i], x.mean_error[i],
                       x.seconds[i]);
    s << "\n";
  }
  return s.str();
}

void write_convergence(const std::string& dir, const ConvergenceStudy& c) {
  std::ostringstream csv;
  csv.precision(12);
  csv << "series,parameter,size,max_error_pct,mean_error_pct,seconds,fitted_order\n";
  std::vector<Series> plot;
  for (const auto& x : c.series) {
    for (std::size_t i = 0; i < x.size.size(); ++i)
      csv << '"' << x.name << "\"," << x.parameter << "," << x.size[i] << "," << x.max_error[i] << ","
          << x.mean_error[i] << "," << x.seconds[i] << "," << x.order << "\n";
    plot.push_back({x.name + " (order " + (std::isfinite(x.order) ? pct2(x.order) : std::string("n/a")) + ")", x.size,
                    x.max_error});
  }
  write_file(dir + "/convergence.csv", csv.str());
  plot_series(dir, "convergence",
              "Convergence to the FE reference, " + std::to_string(c.modes) + " lowest modes",
              "refinement (segments n, or FE elements)", "max |error| over the modes (%)", plot, true, true);
}

}  // namespace cmp
