// static.path for the lumped chain: the equilibrium path through a bifurcation (branch
// switching along the tangent's least stable direction) to the ring's touch, which ends the
// path as a result (paths/continuation.hpp; lumped_mass/nonlinear.cpp's ChainStatics).
//
// Oracles: the multibody chain (multibody::solve_static), the same discrete model in segment
// angles, followed by the same driver and its touch located to the same 1e-6 of a step; the
// chain's own linear buckling (lumped::compute_buckling) for the branch point, as in
// tests/multibody/test_buckling.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common.hpp"
#include "lumped_mass/buckling.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "multibody/statics.hpp"

namespace {

using Kind = ring::Pressure::Kind;

ring::RingSpec held_ring() {
  ring::RingSpec s = ringtest::pinned_ring(270.0);
  s.supports.roller = 90.0;
  return s;
}

/// scenes/ring-collapse.toml: follower pressure 6 EI/R^3 and a squeeze of 100 N along 0-180.
ring::StaticOptions collapse() {
  const ring::RingSpec spec = held_ring();
  ring::StaticOptions st;
  st.loads.pressure = {6.0 * spec.EI() / std::pow(spec.radius, 3), Kind::follower};
  st.loads.points = {{0.0, {-100.0, 0.0}}, {180.0, {100.0, 0.0}}};
  st.record = {0.0, 180.0};
  st.path = true;
  return st;
}

TEST(LumpedPath, MeasureCollapse) {
  const ring::RingSpec spec = held_ring();
  for (int n : {40, 80, 160}) {
    const ring::StaticResult r = lumped::solve_static(spec, lumptest::options(n, lumptest::kChain), collapse());
    ring::MultibodyOptions o;
    o.n = n;
    o.method = ring::MultibodyOptions::Method::dense;
    const ring::StaticResult m = multibody::solve_static(spec, o, collapse());
    std::printf("n=%d lumped %.9f (%s) steps %d ov %.6f | multibody %.9f (%s) steps %d ov %.6f | rel %.3e  lumped %.2fs\n", n,
                r.end_load, r.end.c_str(), r.steps, r.path.back().ovalisation, m.end_load, m.end.c_str(), m.steps,
                m.path.back().ovalisation, std::abs(r.end_load - m.end_load) / m.end_load, r.seconds);
  }
}

TEST(LumpedPath, MeasureDead) {
  const ring::RingSpec spec = held_ring();
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, Kind::dead};
  b.count = 1;
  const double crit = lumped::compute_buckling(spec, lumptest::options(40, lumptest::kChain), b).factors[0];
  ring::StaticOptions st;
  st.loads.pressure = {1.5 * crit, Kind::dead};
  st.path = true;
  const ring::StaticResult r = lumped::solve_static(spec, lumptest::options(40, lumptest::kChain), st);
  std::printf("branch points %zu first %.9f (1/1.5 = %.9f) end %s at %.6f\n", r.branch_points.size(),
              r.branch_points.empty() ? -1.0 : r.branch_points[0], 1 / 1.5, r.end.c_str(), r.end_load);
}

}  // namespace
