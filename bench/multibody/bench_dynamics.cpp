// Time per step of multibody::respond at n = 40, 160, 640 for both
// integrators, and the whole 500-step paper scene (target: under 50 ms). The
// same on the dense and the O(n) sparse path (second argument 0 = dense, 1 = sparse)
// at n = 40, 160, 640, 2560, 10000 (dense only up to 640: 51 ms/step there, O(n^3)),
// and n = 10^4 for the first 100 steps (BM_LongRunSparse; the target is 1000
// steps well under a minute, which is NOT met: the Newton iteration is O(n), ~5 ms at
// n = 10^4, but under the point step load the iterations per step grow with n (20-60,
// with step halving), and a 1000-step newmark run took over 8 min of CPU).
// Scene: the paper ring (R = 10 m, circle d = 0.12 m, steel), pin at 180 deg, roller at
// 0 deg, a 20 kN step force at 0 deg toward the pin, dt = 0.01 s. Counters: steps per
// run, Newton iterations per step, unknowns n. Run with
//   bench_multibody_dynamics --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "multibody/dynamics.hpp"

namespace {

using Integrator = ring::ResponseOptions::Integrator;

ring::RingSpec paper_ring() {
  ring::RingSpec s;
  s.section.shape = ring::Section::Shape::circle;
  s.section.diameter = 0.12;
  s.supports.pin = 180.0;
  s.supports.roller = 0.0;
  return s;
}

ring::ResponseOptions scene(Integrator integrator, double t_end) {
  ring::ResponseOptions r;
  r.load.angle = 0.0;
  r.load.force = {-20e3, 0.0};
  r.dt = 0.01;
  r.t_end = t_end;
  r.integrator = integrator;
  r.record = {0.0, 90.0, 180.0, 270.0};
  return r;
}

/// Per step: a run of `steps` steps of dt = 0.01 s from rest, time divided by steps
/// (the first steps of the 20 kN scene, where the motion is fastest).
void time_per_step(benchmark::State& state, Integrator integrator) {
  ring::MultibodyOptions o;
  o.n = static_cast<int>(state.range(0));
  o.method = state.range(1) ? ring::MultibodyOptions::Method::sparse
                            : ring::MultibodyOptions::Method::dense;
  const int steps = o.n <= 40 ? 100 : (o.n <= 160 ? 20 : (o.n <= 640 || state.range(1) ? 10 : 4));
  const ring::ResponseOptions r = scene(integrator, 0.01 * steps);
  double iterations = 0.0;
  long done = steps;
  for (auto _ : state) {
    ring::TimeHistory th;
    // A run that stops (IntegrationFailure): count the steps it made.
    try {
      th = multibody::respond(paper_ring(), o, r);
    } catch (const multibody::IntegrationFailure& f) {
      th = f.partial();
    }
    done = std::max<long>(1, static_cast<long>(th.t.size()) - 1);
    iterations = std::accumulate(th.newton_iterations.begin(), th.newton_iterations.end(), 0.0);
    benchmark::DoNotOptimize(th.ux.data());
  }
  state.counters["n"] = o.n;
  state.counters["steps_done"] = double(done);
  state.counters["newton_per_step"] = iterations / done;
  state.counters["step"] = benchmark::Counter(done * double(state.iterations()),
                                              benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_StepNewmark(benchmark::State& s) { time_per_step(s, Integrator::newmark); }
void BM_StepGeneralizedAlpha(benchmark::State& s) { time_per_step(s, Integrator::generalized_alpha); }
void step_args(benchmark::internal::Benchmark* b) {
  for (int n : {40, 160, 640}) b->Args({n, 0});
  for (int n : {40, 80, 160, 320, 640, 2560, 10000}) b->Args({n, 1});
}
BENCHMARK(BM_StepNewmark)->Apply(step_args)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepGeneralizedAlpha)->Apply(step_args)->Unit(benchmark::kMillisecond);
// energy-momentum has one (O(n)) path: hinge positions, sparse LU.
void BM_StepEnergyMomentum(benchmark::State& s) { time_per_step(s, Integrator::energy_momentum); }
BENCHMARK(BM_StepEnergyMomentum)
    ->Args({40, 1})->Args({640, 1})->Args({1000, 1})->Args({2560, 1})->Args({10000, 1})
    ->Unit(benchmark::kMillisecond);

/// n = 10^4 on the sparse path, `range(0)` steps of the 20 kN scene: total time.
void long_run(benchmark::State& state, Integrator integrator) {
  ring::MultibodyOptions o;
  o.n = 10000;
  o.method = ring::MultibodyOptions::Method::sparse;
  const ring::ResponseOptions r = scene(integrator, 0.01 * state.range(0));
  double iterations = 0.0, worst_g = 0.0, t_reached = 0.0;
  for (auto _ : state) {
    ring::TimeHistory th;
    // A run that stops with IntegrationFailure: time and count what was integrated.
    try {
      th = multibody::respond(paper_ring(), o, r);
    } catch (const multibody::IntegrationFailure& f) {
      th = f.partial();
    }
    t_reached = th.t.back();
    iterations = std::accumulate(th.newton_iterations.begin(), th.newton_iterations.end(), 0.0);
    for (double g : th.constraint_residual) worst_g = std::max(worst_g, g);
    benchmark::DoNotOptimize(th.ux.data());
  }
  state.counters["t_reached"] = t_reached;
  state.counters["steps"] = double(std::lround(t_reached / 0.01));
  state.counters["newton_per_step"] = iterations / std::max(1.0, t_reached / 0.01);
  state.counters["max_constraint_residual"] = worst_g;
}
void BM_LongRunSparseNewmark(benchmark::State& s) { long_run(s, Integrator::newmark); }
void BM_LongRunSparseGeneralizedAlpha(benchmark::State& s) { long_run(s, Integrator::generalized_alpha); }
void BM_LongRunEnergyMomentum(benchmark::State& s) { long_run(s, Integrator::energy_momentum); }
BENCHMARK(BM_LongRunSparseNewmark)->Arg(100)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_LongRunSparseGeneralizedAlpha)->Arg(100)->Unit(benchmark::kSecond)->Iterations(1);
// The target: the whole 1000-step run at n = 10^4 in under 30 s.
BENCHMARK(BM_LongRunSparseNewmark)->Arg(1000)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_LongRunEnergyMomentum)->Arg(1000)->Unit(benchmark::kSecond)->Iterations(1);

/// The whole paper scene: n = 40, 500 steps (5 s). Target < 50 ms.
void paper_scene(benchmark::State& state, Integrator integrator) {
  ring::MultibodyOptions o;
  o.n = 40;
  const ring::ResponseOptions r = scene(integrator, 5.0);
  for (auto _ : state) {
    const ring::TimeHistory th = multibody::respond(paper_ring(), o, r);
    benchmark::DoNotOptimize(th.ux.data());
  }
}
void BM_PaperSceneNewmark(benchmark::State& s) { paper_scene(s, Integrator::newmark); }
void BM_PaperSceneGeneralizedAlpha(benchmark::State& s) { paper_scene(s, Integrator::generalized_alpha); }
BENCHMARK(BM_PaperSceneNewmark)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PaperSceneGeneralizedAlpha)->Unit(benchmark::kMillisecond);

}  // namespace
