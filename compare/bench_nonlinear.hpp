// `ringvib bench` on a scene with [response] or [static]: the paper's cost claim
// ("particularly for nonlinear analysis, the multibody discrete method is simpler than
// the finite element method and takes little machine time", about 1/3 of the FE time)
// measured: every listed solver over a range of discretizations, its run time against
// the error of the loaded point's peak |u| (response) or |u| (statics) against the
// converged reference, in this process, in one run; with [buckling] the same for the
// first critical load factor, and with static.path = true for the load at which the path
// touches (its reference the reference solver's path at 2 and 4 times its scene size).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "compare/bench.hpp"
#include "ring/scene.hpp"

namespace cmp {

struct NonlinearBench {
  /// "response", "static", "buckling" (the first critical load factor) or "contact" (static.path:
  /// the load factor at which the path touches)
  std::string analysis;
  double loaded_point = 0.0;    ///< degrees
  double reference_value = 0.0; ///< the reference's peak |u| (response) or |u| (statics), m
  double reference_seconds = 0.0;
  std::string reference_note;   ///< contact: which runs make the reference and their change
  BenchStudy study;             ///< one curve per solver; max_error = mean_error = |error| %
};

/// Runs the sweep for each nonlinear analysis of the scene: for every solver of
/// response.solvers / static.solvers, sizes 20, 40, ..., 320 pieces that have a node at
/// every support, load and record point (the scene's other options unchanged), each
/// repeated until 0.3 s or 5 repeats (at least 1), the median time kept; a solver's sizes
/// stop once its error is at most the reference's accuracy or 1e-3 %. Needs the converged
/// reference (the reference solver's nonlinear analyses; for static.path its path at 2 and
/// 4 times its size); throws ring::InputError naming the key when it is not available.
/// Checks before anything runs that bench can measure the scene's nonlinear analyses:
/// the reference solver offers them and the loaded point is recorded (response.record,
/// static.record). Throws ring::InputError naming the key.
void check_bench_nonlinear(const ring::Scene& scene);
std::vector<NonlinearBench> bench_nonlinear(const ring::Scene& scene, std::ostream* progress);

/// The table, the time to 1 % and 0.1 %, and the multibody/FE time ratios at equal n = 40
/// and at equal error, with the verdict on the paper's claim.
std::string bench_nonlinear_text(const NonlinearBench& b);
/// bench_<analysis>.csv, bench_<analysis>.txt and the Pareto figure bench_<analysis>.png.
void write_bench_nonlinear(const std::string& dir, const NonlinearBench& b);

}  // namespace cmp
