// Time per step of multibody::respond for every integrator, on the dense and the O(n)
// sparse path (second argument 0 = dense, 1 = sparse): n = 40, 160, 640 dense (O(n^3)
// per factorization: 51 ms/step at 640), n = 40 .. 10^4 sparse, over the first steps of
// the scene (the hardest: the motion is fastest there). The whole 1000-step run (10 s of
// the scene) at n = 10^3 and 10^4 for every integrator (BM_LongRun): the targets
// are <= 4 Newton iterations per step and under 30 s at 10^4, and t(10^4) / t(10^3) <= 12
// (the ratio of the two runs' times, same simulated time). The whole 500-step paper scene
// at n = 40 (target: under 50 ms).
// Scene: the paper ring (R = 10 m, circle d = 0.12 m, steel), pin at 180 deg, roller at
// 0 deg, a 20 kN step force at 0 deg toward the pin, dt = 0.01 s. Counters: steps per
// run, Newton iterations per step, unknowns n. Run with
//   bench_multibody_dynamics --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "multibody/dynamics.hpp"
#include "tests/support/paper.hpp"

namespace {

using Integrator = ring::ResponseOptions::Integrator;

using ringtest::pin_roller_ring;

ring::ResponseOptions scene(Integrator integrator, double t_end) {
  ring::ResponseOptions r;
  r.loads.points = {{0.0, {-20e3, 0.0}}};
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
      th = multibody::respond(pin_roller_ring(), o, r);
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
  for (int n : {40, 80, 120, 160, 640}) b->Args({n, 0});  // 80 .. 160: the crossover (multibody/backend.hpp)
  for (int n : {40, 80, 120, 160, 320, 640, 1000, 2560, 10000}) b->Args({n, 1});
}
BENCHMARK(BM_StepNewmark)->Apply(step_args)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepGeneralizedAlpha)->Apply(step_args)->Unit(benchmark::kMillisecond);
// energy-momentum has one (O(n)) path: hinge positions, banded KKT matrix.
void BM_StepEnergyMomentum(benchmark::State& s) { time_per_step(s, Integrator::energy_momentum); }
BENCHMARK(BM_StepEnergyMomentum)
    ->Args({40, 1})->Args({640, 1})->Args({1000, 1})->Args({2560, 1})->Args({10000, 1})
    ->Unit(benchmark::kMillisecond);

/// n = range(0) on the O(n) path, range(1) steps of the 20 kN scene: total time.
void long_run(benchmark::State& state, Integrator integrator) {
  ring::MultibodyOptions o;
  o.n = static_cast<int>(state.range(0));
  o.method = ring::MultibodyOptions::Method::sparse;
  const ring::ResponseOptions r = scene(integrator, 0.01 * state.range(1));
  double iterations = 0.0, worst_g = 0.0, t_reached = 0.0, balance = 0.0;
  for (auto _ : state) {
    ring::TimeHistory th;
    // A run that stops with IntegrationFailure: time and count what was integrated.
    try {
      th = multibody::respond(pin_roller_ring(), o, r);
    } catch (const multibody::IntegrationFailure& f) {
      th = f.partial();
    }
    t_reached = th.t.back();
    iterations = std::accumulate(th.newton_iterations.begin(), th.newton_iterations.end(), 0.0);
    for (double g : th.constraint_residual) worst_g = std::max(worst_g, g);
    double max_w = 0.0, max_e = -HUGE_VAL;
    for (size_t i = 0; i < th.t.size(); ++i) {
      max_w = std::max(max_w, std::abs(th.work[i]));
      max_e = std::max(max_e, th.energy_error[i]);
    }
    balance = max_w > 0.0 ? max_e / max_w : 0.0;
    benchmark::DoNotOptimize(th.ux.data());
  }
  state.counters["n"] = o.n;
  state.counters["t_reached"] = t_reached;
  state.counters["steps"] = double(std::lround(t_reached / 0.01));
  state.counters["newton_per_step"] = iterations / std::max(1.0, t_reached / 0.01);
  state.counters["max_constraint_residual"] = worst_g;
  state.counters["max_balance_over_work"] = balance;  // > 0: energy gained
}
void BM_LongRunNewmark(benchmark::State& s) { long_run(s, Integrator::newmark); }
void BM_LongRunGeneralizedAlpha(benchmark::State& s) { long_run(s, Integrator::generalized_alpha); }
void BM_LongRunEnergyMomentum(benchmark::State& s) { long_run(s, Integrator::energy_momentum); }
void long_run_args(benchmark::internal::Benchmark* b) {
  b->Args({1000, 1000})->Args({10000, 1000})->Unit(benchmark::kSecond)->Iterations(1);
}
BENCHMARK(BM_LongRunNewmark)->Apply(long_run_args);
BENCHMARK(BM_LongRunGeneralizedAlpha)->Apply(long_run_args);
BENCHMARK(BM_LongRunEnergyMomentum)->Apply(long_run_args);

/// The whole paper scene: n = 40, 500 steps (5 s). Target < 50 ms.
void paper_scene(benchmark::State& state, Integrator integrator) {
  ring::MultibodyOptions o;
  o.n = 40;
  const ring::ResponseOptions r = scene(integrator, 5.0);
  for (auto _ : state) {
    const ring::TimeHistory th = multibody::respond(pin_roller_ring(), o, r);
    benchmark::DoNotOptimize(th.ux.data());
  }
}
void BM_PaperSceneNewmark(benchmark::State& s) { paper_scene(s, Integrator::newmark); }
void BM_PaperSceneGeneralizedAlpha(benchmark::State& s) { paper_scene(s, Integrator::generalized_alpha); }
BENCHMARK(BM_PaperSceneNewmark)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PaperSceneGeneralizedAlpha)->Unit(benchmark::kMillisecond);

}  // namespace
