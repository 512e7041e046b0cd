// Time against n (40 .. 1e5) for each lumped-mass variant: the paper's ring pinned at
// 180 deg, the 9 lowest elastic modes; n = 40 on both paths (dense SVD and sparse
// shift-invert Lanczos), larger n on the automatic (sparse) path. Repetitions give medians:
//   bench_lumped_modes --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// Counters: unknowns (dimension of the eigenproblem), system_order (of the factorized
// mixed system), factor_nnz and nnz_per_unknown = factor_nnz / system_order (constant =
// O(n) memory for the factors), peak_rss_MB of the process so far (monotone;
// the cases run in increasing n within a variant, so at each n it bounds that case's
// peak), omega1 (convergence at a glance) and the solver's max_residual.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <map>
#include <string>

#include "lumped_mass/modes.hpp"
#include "tests/support/paper.hpp"

namespace {

using ringtest::pinned_ring;

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // Linux: KB
}

void BM_LumpedModes(benchmark::State& state) {
  ring::LumpedOptions o;
  o.variant = static_cast<ring::LumpedOptions::Variant>(state.range(0));
  o.n = static_cast<int>(state.range(1));
  const auto method = static_cast<lumped::Method>(state.range(2));
  const ring::RingSpec spec = pinned_ring();
  ring::ModalResult r;
  for (auto _ : state) {
    r = lumped::compute_modes(spec, o, 9, method);
    benchmark::DoNotOptimize(r.omega.data());
  }
  state.counters["unknowns"] = static_cast<double>(r.unknowns);
  const auto it = r.model.find("factor_nonzeros");
  if (it != r.model.end()) {
    const double nnz = static_cast<double>(std::get<long long>(it->second));
    const double order = static_cast<double>(std::get<long long>(r.model.at("system_order")));
    state.counters["system_order"] = order;
    state.counters["factor_nnz"] = nnz;
    state.counters["nnz_per_unknown"] = nnz / order;
  }
  state.counters["peak_rss_MB"] = peak_rss_mb();
  state.counters["omega1"] = r.omega[0];
  state.counters["max_residual"] = r.max_residual.value();
  state.SetLabel(ring::to_string(o.variant) + (std::get<std::string>(r.model.at("method")) == "dense" ? " dense" : " sparse"));
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (int v = 0; v < 3; ++v) {
    b->Args({v, 40, static_cast<int>(lumped::Method::dense)});
    b->Args({v, 40, static_cast<int>(lumped::Method::sparse)});
    for (int n : {160, 640, 2560, 10240, 40960, 100000}) b->Args({v, n, static_cast<int>(lumped::Method::automatic)});
  }
}

BENCHMARK(BM_LumpedModes)->Apply(Sizes)->ArgNames({"variant", "n", "method"})->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
