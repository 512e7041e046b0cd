// FE reference: time to the reference (23 pinned-ring modes to 1e-9) and time against
// error for p = 2..6 (error = largest relative error of the 23 frequencies against the
// reference). Run: build/bin/bench_fem_modes --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true  (medians are the numbers to quote).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fem_reference/modes.hpp"
#include "tests/support/paper.hpp"

namespace {

using ringtest::pinned_ring;

const std::vector<double>& reference() {
  static const std::vector<double> omega = [] {
    ring::FemOptions o;
    o.reference = true;
    o.tolerance = 1e-11;
    return fem::compute_modes(pinned_ring(), o, 23).omega;
  }();
  return omega;
}

void BM_Reference(benchmark::State& state) {
  const auto spec = pinned_ring();
  ring::FemOptions o;
  o.reference = true;
  ring::ModalResult r;
  for (auto _ : state) r = fem::compute_modes(spec, o, 23);
  state.counters["unknowns"] = static_cast<double>(r.unknowns);
  state.counters["degree"] = static_cast<double>(std::get<long long>(r.model.at("degree")));
  state.counters["error_estimate"] = r.error_estimate;
  state.counters["max_residual"] = r.max_residual.value();
  state.counters["solver_seconds"] = r.seconds;
}
BENCHMARK(BM_Reference)->Unit(benchmark::kMillisecond);

// args: degree p, elements
void BM_TimeVsError(benchmark::State& state) {
  const auto spec = pinned_ring();
  ring::FemOptions o;
  o.degree = static_cast<int>(state.range(0));
  o.elements = static_cast<int>(state.range(1));
  const auto& ref = reference();
  ring::ModalResult r;
  for (auto _ : state) r = fem::compute_modes(spec, o, 23);
  double err = 0;
  for (int i = 0; i < 23; ++i) err = std::max(err, std::abs(r.omega[i] - ref[i]) / ref[i]);
  state.counters["unknowns"] = static_cast<double>(r.unknowns);
  state.counters["max_rel_error"] = err;
  state.counters["solver_seconds"] = r.seconds;
}
BENCHMARK(BM_TimeVsError)
    ->ArgsProduct({{2, 3, 4, 5, 6}, {20, 40, 80, 160}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
