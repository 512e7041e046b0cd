// Time per step of multibody::respond (issue 7) at n = 40, 160, 640 for both
// integrators, and the whole 500-step paper scene (target: under 50 ms).
// Scene: the paper ring (R = 10 m, circle d = 0.12 m, steel), pin at 180 deg, roller at
// 0 deg, a 20 kN step force at 0 deg toward the pin, dt = 0.01 s. Counters: steps per
// run, Newton iterations per step, unknowns n. Run with
//   bench_multibody_dynamics --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

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
  const int steps = o.n <= 40 ? 100 : (o.n <= 160 ? 20 : 4);
  const ring::ResponseOptions r = scene(integrator, 0.01 * steps);
  double iterations = 0.0;
  for (auto _ : state) {
    const ring::TimeHistory th = multibody::respond(paper_ring(), o, r);
    iterations = std::accumulate(th.newton_iterations.begin(), th.newton_iterations.end(), 0.0);
    benchmark::DoNotOptimize(th.ux.data());
  }
  state.counters["n"] = o.n;
  state.counters["newton_per_step"] = iterations / steps;
  state.counters["step"] = benchmark::Counter(steps * double(state.iterations()),
                                              benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_StepNewmark(benchmark::State& s) { time_per_step(s, Integrator::newmark); }
void BM_StepGeneralizedAlpha(benchmark::State& s) { time_per_step(s, Integrator::generalized_alpha); }
BENCHMARK(BM_StepNewmark)->Arg(40)->Arg(160)->Arg(640)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepGeneralizedAlpha)->Arg(40)->Arg(160)->Arg(640)->Unit(benchmark::kMillisecond);

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
