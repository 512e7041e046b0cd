// The lumped chain on an arch (ring.arc = [from, to]): an open chain of n links from `from`
// to `to` (lumped_mass/model.hpp), its ends taking the supports.
//
// Oracles:
//  - the exact frequencies of the inextensible circular arch (the chain's continuum limit):
//    tests/support/arch.hpp (archtest::arch_omegas, EA = infinity: the transfer matrix);
//  - its mode shapes, and its frequencies once more: inextensible_arch.hpp, a 6 x 6
//    end-condition determinant on the exponential solutions of the arch's sixth-order
//    equation, written for this suite (the two oracles agree to 1e-9 below);
//  - the rigid-mode count of RingSpec::rigid_modes() (the planar rigid motions the supports
//    leave);
//  - DaDeppo & Schmidt (1975), the deep circular arch (215 deg, one end clamped, the other
//    pinned, a load at the apex): limit load P R^2 / EI = 8.97 for the inextensible arch;
//    archtest::deep_arch_limit() (tests/support/arch.hpp) gives it to 8.97308997 by shooting
//    on the inextensible elastica.
// Convergence orders are fitted by tests/support/convergence.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common.hpp"
#include "inextensible_arch.hpp"
#include "lumped_mass/buckling.hpp"
#include "lumped_mass/checks.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "ring/sampling.hpp"
#include "support/arch.hpp"
#include "support/convergence.hpp"
#include "support/refusal.hpp"

namespace {

using End = inextensible::End;

/// The paper's ring material and section on the arch [from, to], its ends held as asked (a
/// clamp is a pinned point whose rotation is held too).
ring::RingSpec arch(double from, double to, End a, End b) {
  ring::RingSpec s = ringtest::free_ring();
  s.arc = ring::Arc{from, to};
  std::vector<double> pinned;
  if (a != End::free) pinned.push_back(from);
  if (b != End::free) pinned.push_back(to);
  if (!pinned.empty()) {
    s.supports.pin = ring::wrap_degrees(pinned[0]);
    for (std::size_t i = 1; i < pinned.size(); ++i) s.supports.pins.push_back(ring::wrap_degrees(pinned[i]));
  }
  if (a == End::clamped) s.supports.clamp = ring::wrap_degrees(from);
  if (b == End::clamped) s.supports.clamp = ring::wrap_degrees(to);
  return s;
}

archtest::End to_archtest(End e) {
  return e == End::free ? archtest::End::free : e == End::pinned ? archtest::End::pinned : archtest::End::clamped;
}

struct ArchCase {
  const char* name;
  double from, to;
  End a, b;
  double ceiling;  ///< on the finest relative error (n = 256): the measured largest of the three x 3
};

class LumpedArchModes : public ::testing::TestWithParam<ArchCase> {};

// The chain's three lowest frequencies converge at order 2 in l = R alpha / n to the exact
// inextensible arch's (the chain is a central difference scheme inside; a clamp's half hinge
// 2 EI/l puts the end link's midpoint rotation l/2 from the wall, also second order).
// Tolerance 0.1 on the order: the fitted orders over n = 32 .. 256 are 1.969 to 2.009
// (measured, 18 frequencies); the ceilings are the largest measured finest error of each case
// times 3 (1.8e-6 to 9.5e-5 measured).
TEST_P(LumpedArchModes, ConvergeAtOrderTwoToTheExactInextensibleArch) {
  const ArchCase& c = GetParam();
  const ring::RingSpec spec = arch(c.from, c.to, c.a, c.b);
  archtest::Arch oracle;  // R = EI = rhoA = 1: the frequencies in sqrt(EI / (rho A R^4))
  oracle.alpha = (c.to - c.from) * M_PI / 180.0;
  oracle.start = to_archtest(c.a);
  oracle.end = to_archtest(c.b);
  const std::vector<double> exact = archtest::arch_omegas(oracle, 3);
  ASSERT_EQ(exact.size(), 3u);
  const std::vector<int> ns{32, 64, 128, 256};
  std::vector<std::vector<double>> errors(3);
  for (int n : ns) {
    const ring::ModalResult r = lumped::compute_modes(spec, lumptest::options(n, lumptest::kChain), 3);
    EXPECT_EQ(r.rigid_modes, spec.rigid_modes()) << "n = " << n;
    ASSERT_EQ(r.omega.size(), 3u);
    for (int k = 0; k < 3; ++k)
      errors[k].push_back(std::abs(r.omega[k] / spec.bending_frequency_scale() - exact[k]) / exact[k]);
  }
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors[k]), 2.0, 0.1, c.ceiling)) << c.name << " mode " << k + 1;
}

INSTANTIATE_TEST_SUITE_P(
    Ends, LumpedArchModes,
    ::testing::Values(ArchCase{"pinned_pinned_180", 30.0, 210.0, End::pinned, End::pinned, 2e-4},  // 6.1e-5
                      ArchCase{"clamped_pinned_180", 30.0, 210.0, End::clamped, End::pinned, 1.5e-4},  // 4.8e-5
                      ArchCase{"pinned_clamped_240", -100.0, 140.0, End::pinned, End::clamped, 2e-4},  // 6.9e-5
                      ArchCase{"pinned_pinned_60", 60.0, 120.0, End::pinned, End::pinned, 3e-4},  // 9.5e-5
                      ArchCase{"cantilever_90", 0.0, 90.0, End::clamped, End::free, 7e-5},  // 2.2e-5
                      ArchCase{"pin_free_120", 200.0, 320.0, End::pinned, End::free, 2e-4}),  // 6.7e-5
    [](const auto& info) { return std::string(info.param.name); });

// The shapes (ring::sample_arc of the n + 1 nodes) are the exact modes: MAC against the
// inextensible arch's (u, w) at the stations on the arch, 0 at the stations off it. The
// MAC's defect is of the order of the shapes' squared error (the model's and the linear
// interpolation's between nodes; measured 1 - MAC = 9.8e-8, 5.1e-7, 1.7e-6 at n = 128 for the
// clamped-pinned semicircle's three modes; bound 1e-5).
TEST(LumpedArch, ModeShapesAreTheExactArchsAndZeroOffTheArc) {
  const ring::RingSpec spec = arch(30.0, 210.0, End::clamped, End::pinned);
  const inextensible::Arch exact_arch{M_PI, End::clamped, End::pinned};
  const std::vector<double> exact = inextensible::frequencies(exact_arch, 3);
  ASSERT_EQ(exact.size(), 3u);
  // The two oracles (the exponentials' determinant here, the transfer matrix of
  // tests/support/arch.hpp) agree: each claims ~1e-12.
  archtest::Arch transfer;
  transfer.alpha = M_PI;
  transfer.start = archtest::End::clamped;
  const std::vector<double> other = archtest::arch_omegas(transfer, 3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(exact[k], other[k], 1e-9 * other[k]) << "mode " << k + 1;
  const ring::ModalResult r = lumped::compute_modes(spec, lumptest::options(128, lumptest::kChain), 3);
  ASSERT_EQ(r.shapes.size(), 3u);
  const int stations = static_cast<int>(r.shapes[0].radial.size());
  for (int k = 0; k < 3; ++k) {
    std::vector<double> theta;
    std::vector<int> on;
    for (int i = 0; i < stations; ++i) {
      const double a = 360.0 * i / stations;  // the stations: whole degrees from 0 (ring/sampling.hpp)
      if (a >= 30.0 && a <= 210.0) {
        theta.push_back((a - 30.0) * M_PI / 180.0);
        on.push_back(i);
      } else {
        EXPECT_EQ(r.shapes[k].radial[i], 0.0) << "station " << a;
        EXPECT_EQ(r.shapes[k].tangential[i], 0.0) << "station " << a;
      }
    }
    std::vector<double> u, w;
    inextensible::shape(exact_arch, exact[k], theta, u, w);
    ring::ModeShape e;
    e.radial.assign(stations, 0.0);
    e.tangential.assign(stations, 0.0);
    for (std::size_t j = 0; j < on.size(); ++j) {
      e.radial[on[j]] = w[j];
      e.tangential[on[j]] = u[j];
    }
    EXPECT_GT(ring::mac(r.shapes[k], e), 1.0 - 1e-5) << "mode " << k + 1;
  }
}

// The rigid modes are RingSpec::rigid_modes(): a free arch 3, an arch on one pin 1 (it turns
// about the pin), a cantilever and a pinned-pinned arch none (the chain's solve checks its
// count of zero eigenvalues against it; compute_modes throws when they differ).
TEST(LumpedArch, RigidModesAreThoseTheSupportsLeave) {
  const struct {
    End a, b;
    int rigid;
  } cases[] = {{End::free, End::free, 3}, {End::pinned, End::free, 1}, {End::clamped, End::free, 0},
               {End::pinned, End::pinned, 0}};
  for (const auto& c : cases) {
    const ring::RingSpec spec = arch(45.0, 165.0, c.a, c.b);
    ASSERT_EQ(spec.rigid_modes(), c.rigid);
    const ring::ModalResult r = lumped::compute_modes(spec, lumptest::options(24, lumptest::kChain), 2);
    EXPECT_EQ(r.rigid_modes, c.rigid);
    EXPECT_EQ(r.omega.size(), 2u);
  }
}

// DaDeppo & Schmidt's deep arch (215 deg from -17.5 to 197.5 deg, clamped at `from`, pinned
// at `to`, a dead load down at the apex, 90 deg) on static.path: the path rises to a located
// limit point and snaps past it (the load falls), and the limit load converges at order 2 in
// n to the elastica's P R^2 / EI = 8.97308997 (archtest::deep_arch_limit). Measured: 8.76171,
// 8.91995, 8.95978 at n = 20, 40, 80 (relative errors 2.4e-2, 5.9e-3, 1.5e-3: fitted order
// 1.99); order tolerance 0.1, the ceiling twice the finest error measured. The full load is
// 10 EI/R^2: above the limit, so that the path passes it (it ends where the arch's links
// touch, a result of static.path).
TEST(LumpedArch, DeepArchLimitLoadConvergesToTheElasticasAtOrderTwo) {
  const double exact = archtest::deep_arch_limit().load;
  const ring::RingSpec spec = arch(-17.5, 197.5, End::clamped, End::pinned);
  const double full = 10.0;  // P R^2 / EI
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -full * spec.EI() / (spec.radius * spec.radius)}}};
  st.record = {90.0};
  st.path = true;
  const std::vector<int> ns{20, 40, 80};
  std::vector<double> errors;
  for (int n : ns) {
    const lumped::StaticDetail d = lumped::solve_static_detail(spec, lumptest::options(n, lumptest::kChain), st);
    ASSERT_TRUE(std::isfinite(d.limit)) << "n = " << n << ": no limit point; the path ended: " << d.result.end;
    errors.push_back(std::abs(d.limit * full - exact) / exact);
    // Through the limit: every accepted equilibrium at or below it, and some beyond it with
    // the load fallen (the snap) while the apex went on down.
    double highest = 0.0, lowest_after = INFINITY;
    bool past = false;
    for (const ring::PathPoint& p : d.result.path) {
      highest = std::max(highest, p.load_factor);
      past = past || p.load_factor >= d.limit - 0.05;
      if (past) lowest_after = std::min(lowest_after, p.load_factor);
    }
    EXPECT_LE(highest, d.limit + 1e-9) << "n = " << n;  // the located maximum (to 1e-6 of a step)
    EXPECT_LT(lowest_after, 0.9 * d.limit) << "n = " << n;
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors), 2.0, 0.1, 3e-3));
}

// What the chain does not take on an arch is refused naming ring.arc (exit 2 through the
// driver): the modes under load, a pressure in the statics and the response, the dead and
// central pressures, buckling under point loads or with an end that is not pinned, the
// frames and a roller.
TEST(LumpedArch, WhatTheChainDoesNotTakeOnAnArchIsRefusedByKey) {
  const ring::RingSpec spec = arch(0.0, 180.0, End::pinned, End::pinned);
  const ring::LumpedOptions chain = lumptest::options(16, lumptest::kChain);
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -1.0}}};
  ring::BucklingOptions b;
  b.loads = st.loads;
  ring::ResponseOptions r;
  r.loads = st.loads;
  EXPECT_EQ(ringtest::refused_key([&] { lumped::check_preloaded_modes(spec, chain, st); }), "ring.arc");
  for (auto kind : {ring::Pressure::Kind::follower, ring::Pressure::Kind::dead, ring::Pressure::Kind::central}) {
    ring::StaticOptions pressed;
    pressed.loads.pressure = {1.0, kind};
    EXPECT_EQ(ringtest::refused_key([&] { lumped::check_static(spec, chain, pressed); }), "ring.arc");
    ring::ResponseOptions pushed;
    pushed.loads.pressure = {1.0, kind};
    EXPECT_EQ(ringtest::refused_key([&] { lumped::check_response(spec, chain, pushed); }), "ring.arc");
    if (kind == ring::Pressure::Kind::follower) continue;
    ring::BucklingOptions buckled;
    buckled.loads.pressure = {1.0, kind};
    EXPECT_EQ(ringtest::refused_key([&] { lumped::check_buckling(spec, chain, buckled); }), "ring.arc");
  }
  ring::BucklingOptions follower;
  follower.loads.pressure = {1.0, ring::Pressure::Kind::follower};
  EXPECT_EQ(ringtest::refused_key([&] { lumped::check_buckling(arch(0.0, 180.0, End::clamped, End::free), chain, follower); }),
            "ring.arc");
  for (auto v : {lumptest::kFrame, lumptest::kConsistent, ring::LumpedOptions::Variant::timoshenko_frame}) {
    EXPECT_EQ(ringtest::refused_key([&] { lumped::check_modes(spec, lumptest::options(16, v)); }), "ring.arc");
    EXPECT_EQ(ringtest::refused_key([&] { lumped::compute_modes(spec, lumptest::options(16, v), 2); }), "ring.arc");
  }
  ring::RingSpec rolled = spec;
  rolled.supports.pins.clear();
  rolled.supports.roller = 180.0;
  EXPECT_EQ(ringtest::refused_key([&] { lumped::check_modes(rolled, chain); }), "ring.arc");
  // And what it takes passes its checks: the modes, the statics and the response under point
  // loads, buckling under a follower pressure with both ends pinned.
  EXPECT_NO_THROW(lumped::check_modes(spec, chain));
  EXPECT_NO_THROW(lumped::check_static(spec, chain, st));
  EXPECT_EQ(ringtest::refused_key([&] { lumped::check_buckling(spec, chain, b); }), "ring.arc");  // point loads
  EXPECT_NO_THROW(lumped::check_buckling(spec, chain, follower));
  EXPECT_NO_THROW(lumped::check_response(spec, chain, r));
}

// Linear buckling of pinned arches under uniform follower pressure (the pressure on the
// links, its potential the area between the chain and the fixed chord: loads.hpp) against
// Timoshenko & Gere's q R^3 / EI = pi^2 / alpha^2 - 1 (alpha half the opening;
// archtest::pinned_follower_pressure): the lowest critical factor of the pressure
// EI / R^3 converges at order 2 in n, its shape antisymmetric about the crown. Measured: the
// relative errors 1.28e-2, 3.2e-3, 8.0e-4 at n = 16, 32, 64 for each of the 120, 180 and 240
// deg arches (7.8976, 2.9616, 1.2340 at n = 16 against 8, 3, 1.25); order tolerance 0.1, the
// ceiling twice the finest error.
TEST(LumpedArch, PinnedArchBucklesUnderFollowerPressureAtTimoshenkosLoad) {
  for (double opening : {120.0, 180.0, 240.0}) {
    const ring::RingSpec spec = arch(90.0 - opening / 2.0, 90.0 + opening / 2.0, End::pinned, End::pinned);
    const double exact = archtest::pinned_follower_pressure(opening / 2.0 * M_PI / 180.0);
    ring::BucklingOptions b;
    b.loads.pressure = {spec.EI() / std::pow(spec.radius, 3), ring::Pressure::Kind::follower};
    b.count = 1;
    const std::vector<int> ns{16, 32, 64};
    std::vector<double> errors;
    for (int n : ns) {
      const ring::BucklingResult r = lumped::compute_buckling(spec, lumptest::options(n, lumptest::kChain), b);
      ASSERT_EQ(r.factors.size(), 1u);
      errors.push_back(std::abs(r.factors[0] - exact) / exact);
      // Antisymmetric about the crown (90 deg): radial at 90 - a and 90 + a opposite.
      ASSERT_EQ(r.shapes.size(), 1u);
      const auto& w = r.shapes[0].radial;
      EXPECT_NEAR(w[60], -w[120], 1e-6) << "n = " << n;
    }
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors), 2.0, 0.1, 1.6e-3)) << opening << " deg";
  }
}

// Gravity on an arch: the ground holds the arch's whole weight, rho A R alpha g (the n links'
// midpoint masses: an end node carries half a link's, an interior one a whole link's), to the
// Newton tolerance (bound 1e-9 of the weight), and a symmetric arch (pinned-pinned, 120 deg
// about the vertical) sags symmetrically: its crown moves straight down (|ux| below 1e-12 of
// its uy: mirror symmetry), its two quarter points mirror each other.
TEST(LumpedArch, GravityIsTheArchsWeightAndSymmetric) {
  const ring::RingSpec spec = arch(30.0, 150.0, End::pinned, End::pinned);
  ring::StaticOptions st;
  st.loads.gravity = {0.0, -9.81};
  st.record = {60.0, 90.0, 120.0};
  const lumped::StaticDetail d = lumped::solve_static_detail(spec, lumptest::options(24, lumptest::kChain), st);
  const double weight = spec.rhoA() * spec.radius * (120.0 * M_PI / 180.0) * 9.81;
  EXPECT_NEAR(d.ground_force[0], 0.0, 1e-9 * weight);
  EXPECT_NEAR(d.ground_force[1], weight, 1e-9 * weight);
  const auto& u = d.result.displacements;
  ASSERT_EQ(u.size(), 3u);
  EXPECT_LT(u[1].uy, 0.0);
  EXPECT_LE(std::abs(u[1].ux), 1e-12 * std::abs(u[1].uy));
  EXPECT_NEAR(u[0].ux, -u[2].ux, 1e-12 * std::abs(u[1].uy));
  EXPECT_NEAR(u[0].uy, u[2].uy, 1e-12 * std::abs(u[1].uy));
}

// The deep arch's equilibrium under 6 EI/R^2 on the rising branch (0.67 of the limit): the
// apex's displacement converges at order 2 in n to the elastica's (archtest::deep_arch_under).
// Measured errors (dx, dy) / R: (3.7e-3, 1.4e-2), (9.3e-4, 3.6e-3), (2.3e-4, 8.9e-4) at
// n = 24, 48, 96 (fitted 2.00); order tolerance 0.1, ceilings twice the finest.
TEST(LumpedArch, DeepArchEquilibriumConvergesToTheElasticasAtOrderTwo) {
  const ring::RingSpec spec = arch(-17.5, 197.5, End::clamped, End::pinned);
  const archtest::DeepArchPoint e = archtest::deep_arch_under(6.0);
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -6.0 * spec.EI() / (spec.radius * spec.radius)}}};
  st.record = {90.0};
  const std::vector<int> ns{24, 48, 96};
  std::vector<double> ex, ey;
  for (int n : ns) {
    const ring::StaticResult q = lumped::solve_static(spec, lumptest::options(n, lumptest::kChain), st);
    ASSERT_EQ(q.displacements.size(), 1u);
    ex.push_back(std::abs(q.displacements[0].ux / spec.radius - e.apex_dx));
    ey.push_back(std::abs(q.displacements[0].uy / spec.radius - e.apex_dy));
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, ex), 2.0, 0.1, 5e-4)) << "apex dx";
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, ey), 2.0, 0.1, 2e-3)) << "apex dy";
}

// The response on an arch: the deep arch under a load ramped slowly (10 s; its lowest period
// is 1.3 s) to 6 EI/R^2 and held, with mass-proportional damping (a = 2 1/s: the motion decays
// like e^-t), settles at the chain's own equilibrium under that load (solve_static, the
// elastica's within O(l^2): the test above): measured 5.5e-8 R apart at 25 s, bound 1e-6 R;
// the links hold to the Newton tolerance throughout.
TEST(LumpedArch, ASlowDampedRampSettlesAtTheEquilibrium) {
  const ring::RingSpec spec = arch(-17.5, 197.5, End::clamped, End::pinned);
  ring::ResponseOptions r;
  r.loads.points = {{90.0, {0.0, -6.0 * spec.EI() / (spec.radius * spec.radius)}}};
  r.history.kind = ring::LoadHistory::Kind::ramp;
  r.history.period = 10.0;
  r.dt = 0.02;
  r.t_end = 25.0;
  r.integrator = ring::ResponseOptions::Integrator::midpoint;
  r.rayleigh_mass = 2.0;
  r.record = {90.0};
  const ring::TimeHistory h = lumped::respond(spec, lumptest::options(24, lumptest::kChain), r);
  ASSERT_FALSE(h.t.empty());
  EXPECT_NEAR(h.t.back(), 25.0, 1e-9);
  ring::StaticOptions st;
  st.loads = r.loads;
  st.record = {90.0};
  const ring::StaticResult q = lumped::solve_static(spec, lumptest::options(24, lumptest::kChain), st);
  EXPECT_NEAR(h.ux[0].back(), q.displacements[0].ux, 1e-6 * spec.radius);
  EXPECT_NEAR(h.uy[0].back(), q.displacements[0].uy, 1e-6 * spec.radius);
  for (double c : h.constraint_residual) EXPECT_LT(c, 1e-9 * spec.radius);
}

// ring.plastic on an arch (the interior hinges' law, bending.hpp): a cantilever arch (90 deg,
// clamped at `from` = 0 deg, free at 90 deg) under a dead load F down at its tip, the
// resultant law with no hardening. Limit analysis: the moment F R cos(theta) is largest at
// the clamp, so the arch collapses at F = Mp / R. The chain's clamp is the elastic half hinge
// (terms.hpp), so its first plastic hinge is node 1, F rho cos(alpha / n) = Mp: its limit
// differs from Mp / R by O(l^2) (rho = R (1 + O(l^2)), cos = 1 - O(l^2)); the statics end
// there, past the limit point (ring::NumericalError naming its load factor). Mp R / EI = 1e-5:
// the displacement before collapse changes the lever by O(1e-5). The path (static.path) turns
// at a located limit there (the hinge's lever grows as the mechanism swings; far on it shrinks
// and the load rises again, so the full load is reached). Measured: the limit 5.0e-6 (relative)
// below the chain's mechanism load Mp / (rho cos(alpha / n)) at n = 16, 32, 64 (the lever's
// change before collapse, O(Mp R / EI)), bound 10 % of that load's distance from Mp / R
// (4.4e-3, 1.1e-3, 2.8e-4), which falls at fitted order 2.00 (tolerance 0.1).
TEST(LumpedArch, PlasticCantileverArchCollapsesAtItsLimitLoad) {
  ring::RingSpec spec = arch(0.0, 90.0, End::clamped, End::free);
  const double Mp = 1e-5 * spec.EI() / spec.radius;
  spec.plastic = ring::Plastic{};
  spec.plastic->moment = Mp;
  const double full = 1.5 * Mp / spec.radius;  // above the collapse load
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -full}}};
  st.path = true;  // the mechanism swings on and its lever shrinks: the load rises past 1.5 Mp / R
  const std::vector<int> ns{16, 32, 64};
  std::vector<double> errors;
  for (int n : ns) {
    const lumped::StaticDetail d = lumped::solve_static_detail(spec, lumptest::options(n, lumptest::kChain), st);
    ASSERT_TRUE(std::isfinite(d.limit)) << "n = " << n << ": no limit point; the path ended: " << d.result.end;
    const double limit = d.limit;
    const double F = limit * full, collapse = Mp / spec.radius;
    const double alpha = M_PI / 2.0, l = spec.radius * alpha / n, rho = l / (2.0 * std::sin(alpha / (2.0 * n)));
    const double chain = Mp / (rho * std::cos(alpha / n));  // the chain's own mechanism
    std::printf("[ plastic arch ] n = %d: limit %.9e, chain mechanism %.9e, Mp / R %.9e\n", n, F, chain, collapse);
    EXPECT_NEAR(F, chain, 0.1 * std::abs(chain - collapse)) << "n = " << n;
    errors.push_back(std::abs(F / collapse - 1.0));
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors), 2.0, 0.1));
}

}  // namespace
