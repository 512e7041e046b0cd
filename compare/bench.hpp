// `ringvib bench`: run time against error for every solver over a range of
// discretizations, measured in this process on this machine in one run, so that the
// times are comparable as ratios (absolute times depend on the machine and its load).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/converge.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

struct BenchPoint {
  std::string curve;       ///< "multibody", "multibody + Richardson", "lumped (chain)", "fem (p = 3)"
  int size = 0;            ///< n or elements
  long long unknowns = 0;
  double seconds = 0.0;    ///< median solver time over the repeats
  int repeats = 0;
  double max_error = 0.0;  ///< max |error| over the requested modes, %
  double mean_error = 0.0; ///< mean |error|, %
};

struct BenchStudy {
  int modes = 0;
  double reference_seconds = 0.0;
  std::vector<BenchPoint> points;
  /// The curves of the paper's claim: its method, and FE at p = 3 (the ratios printed).
  std::string method_curve = "multibody", fe_curve = "fem (p = 3)";
};

/// Runs the sweep, each model against its own continuum (References): every solver the scene runs (multibody and lumped n = 40 x 2^k up to
/// 2560; FE elements 10..160 at p = 2, 3, 4), each point repeated until 0.3 s or 9
/// repeats (at least 3), the median time kept. `progress` may be null.
BenchStudy bench(const ring::Scene& scene, const References& references, std::ostream* progress);

/// Time a curve needs to reach `error_pct` max error (log-log interpolation between
/// the bracketing points), or nullopt if it never does.
std::optional<double> time_to_error(const BenchStudy& b, const std::string& curve, double error_pct);

std::string bench_text(const BenchStudy& b);

/// A duration for people: "12.3 us", "4.56 ms", "7.89 s".
std::string fmt_seconds(double s);
/// The curve names of the study, in order of first appearance.
std::vector<std::string> curve_names(const BenchStudy& b);
/// The "time to reach 1 % and <second> %" lines of every curve.
std::string time_to_error_lines(const BenchStudy& b, double second_pct);
/// The Pareto figure NAME.png: max error against median time, one curve each.
void plot_pareto(const std::string& dir, const std::string& name, const std::string& title, const std::string& ylabel,
                 const BenchStudy& b);
void write_bench(const std::string& dir, const BenchStudy& b);

}  // namespace cmp
