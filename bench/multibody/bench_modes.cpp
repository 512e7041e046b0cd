// Time of the 23 lowest modes of the paper's ring (pinned, rotary inertia on) on the
// dense path, n = 40, 160, 640, 2000, and the sparse path from n = 40 to 10^6 (with the
// process's peak RSS; run one n per process for a per-n peak, docs/measured.md);
// phases timed separately (assembly + reduction, then the whole compute_modes). Run, Release build:
//   build/bin/bench_multibody_modes --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include "multibody/modes.hpp"
#include "tests/support/paper.hpp"

namespace {

using ringtest::pinned_ring;

void BM_ComputeModes23(benchmark::State& st) {
  const ring::RingSpec s = pinned_ring();
  ring::MultibodyOptions o;
  o.n = static_cast<int>(st.range(0));
  o.rotary_inertia = st.range(1) != 0;
  o.method = st.range(2) ? ring::MultibodyOptions::Method::sparse : ring::MultibodyOptions::Method::dense;
  double solver_seconds = 0;
  ring::ModalResult r;
  for (auto _ : st) {
    r = multibody::compute_modes(s, o, 23);
    benchmark::DoNotOptimize(r.omega.data());
    solver_seconds += r.seconds;
  }
  st.counters["unknowns"] = static_cast<double>(r.unknowns);
  st.counters["solver_s"] = benchmark::Counter(solver_seconds, benchmark::Counter::kAvgIterations);
  st.counters["omega1"] = r.omega[0];
  // Peak resident set of the whole process so far (Linux: KiB): per-n only when one n
  // runs per process (--benchmark_filter), as in docs/measured.md.
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  st.counters["peak_rss_MiB"] = static_cast<double>(u.ru_maxrss) / 1024.0;
}
BENCHMARK(BM_ComputeModes23)
    ->ArgsProduct({{40, 160, 320, 640, 2000}, {1}, {0}})
    ->Args({640, 0, 0})
    ->Args({2000, 0, 0})
    ->Args({40, 1, 1})
    ->Args({160, 1, 1})
    ->Args({320, 1, 1})
    ->Args({640, 1, 1})
    ->Args({2000, 1, 1})
    ->Args({10000, 1, 1})
    ->Args({100000, 1, 1})
    ->Args({1000000, 1, 1})
    ->ArgNames({"n", "rot", "sparse"})
    ->Unit(benchmark::kMillisecond);

// The sparse path's two eigensolvers side by side on the same O(n) shifted solve (23
// modes, pinned paper ring, rotary inertia): lib = 0 the hand-written Lanczos
// (multibody/lanczos.hpp), lib = 1 the eigen layer's Spectra Lanczos (modal/lanczos.hpp).
void BM_SparseEigensolver(benchmark::State& st) {
  const ring::RingSpec s = pinned_ring();
  ring::MultibodyOptions o;
  o.n = static_cast<int>(st.range(0));
  o.method = ring::MultibodyOptions::Method::sparse;
  const auto which = st.range(1) ? multibody::SparseEigensolver::library : multibody::SparseEigensolver::hand_written;
  double solver_seconds = 0;
  multibody::ModalSolution sol;
  for (auto _ : st) {
    sol = multibody::solve_modes(s, o, 23, which);
    benchmark::DoNotOptimize(sol.result.omega.data());
    solver_seconds += sol.result.seconds;
  }
  st.counters["solver_s"] = benchmark::Counter(solver_seconds, benchmark::Counter::kAvgIterations);
  st.counters["omega1"] = sol.result.omega[0];
  st.counters["backward_error"] = sol.backward_error;
}
BENCHMARK(BM_SparseEigensolver)
    ->ArgsProduct({{2000, 10000, 100000, 1000000}, {0, 1}})
    ->ArgNames({"n", "lib"})
    ->Unit(benchmark::kMillisecond);

void BM_Linearize(benchmark::State& st) {
  const ring::RingSpec s = pinned_ring();
  ring::MultibodyOptions o;
  o.n = static_cast<int>(st.range(0));
  const multibody::Chain c(s, o);
  for (auto _ : st) {
    auto lm = multibody::linearize(c, o.dependent);
    benchmark::DoNotOptimize(lm.K0.data());
  }
}
BENCHMARK(BM_Linearize)->Arg(40)->Arg(160)->Arg(640)->Arg(2000)->ArgName("n")->Unit(benchmark::kMillisecond);

}  // namespace
