// The chain under the loads beyond one point load (multibody/loading.hpp): pressure of each
// kind, gravity, several point loads. Oracles: the derivatives of the load potential by
// central differences, the closed forms of the pressurized and the hanging thin ring
// (ring/closed_form.hpp, Fourier series derived there), and the chain's fitted order.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "multibody/chain.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/loading.hpp"
#include "multibody/statics.hpp"
#include "ring/closed_form.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "tests/multibody/common.hpp"

namespace {

using multibody::Matrix;
using multibody::Vector;
using Kind = ring::Pressure::Kind;

ring::Loads every_load(Kind kind) {
  ring::Loads l;
  l.points = {{0.0, {-3e3, 1e3}}, {90.0, {0.0, -2e3}}};
  l.pressure = {4e3, kind};
  l.gravity = {1.0, -9.81};
  return l;
}

/// A deformed, non-closing configuration: the derivatives hold for any q.
Vector perturbed(const multibody::Chain& c) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  Vector q = c.q0();
  for (int i = 0; i < q.size(); ++i) q[i] += i < c.n() ? d(gen) : 0.1 * d(gen);
  return q;
}

// Forces = -dPi/dq and the load stiffness = d2Pi/dq2, by central differences (h = 1e-6:
// truncation O(h^2) ~ 1e-12 against round-off ~ 1e-16 |Pi| / h ~ 1e-10 relative; 1e-6 leaves room).
TEST(MultibodyLoading, ForcesAndStiffnessAreTheDerivativesOfThePotential) {
  for (const bool pinned : {true, false})
    for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
      ring::RingSpec spec = pinned ? ringtest::pinned_ring(180.0) : ringtest::free_ring();
      spec.masses = {{270.0, 50.0, 0.0}};
      ring::MultibodyOptions o;
      o.n = 12;
      const multibody::Chain c(spec, o, 0.0);
      const multibody::detail::Loading load(c, spec, every_load(kind), "static");
      const Vector q = perturbed(c);
      const double h = 1e-6;
      const Vector f = load.forces(q);
      Matrix H = Matrix::Zero(c.dofs(), c.dofs());
      load.add_stiffness(q, 1.0, H);
      double fscale = f.cwiseAbs().maxCoeff(), hscale = H.cwiseAbs().maxCoeff();
      for (int i = 0; i < c.dofs(); ++i) {
        Vector a = q, b = q;
        a[i] += h;
        b[i] -= h;
        const double dpi = (load.potential(a) - load.potential(b)) / (2 * h);
        EXPECT_NEAR(-dpi, f[i], 1e-6 * fscale) << "dof " << i << ", pinned " << pinned << ", " << ring::to_string(kind);
        const Vector df = (load.forces(a) - load.forces(b)) / (2 * h);
        for (int j = 0; j < c.dofs(); ++j)
          EXPECT_NEAR(-df[j], H(j, i), 1e-6 * hscale) << "(" << j << ", " << i << "), " << ring::to_string(kind);
      }
      EXPECT_NEAR(load.potential(c.q0()), 0.0, 1e-9 * fscale) << "the potential is counted from rest";
    }
}

// A uniform pressure of any kind leaves the inextensible chain where it is: the regular
// polygon is an equilibrium with its links in compression (exact, by symmetry).
TEST(MultibodyLoading, UniformPressureDoesNotMoveTheInextensibleChain) {
  const ring::RingSpec spec = ringtest::pin_roller_ring();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    ring::StaticOptions st;
    st.loads.pressure = {0.5 * ring::closed_form::critical_pressure(spec, kind), kind};
    st.steps = 2;
    st.record = {0.0, 45.0, 90.0, 270.0};
    ring::MultibodyOptions o;
    o.n = 40;
    const ring::StaticResult r = multibody::solve_static(spec, o, st);
    for (const auto& d : r.displacements) EXPECT_LT(std::hypot(d.ux, d.uy), 1e-12 * spec.radius) << ring::to_string(kind);
  }
}

/// Errors at n = 40, 80, 160; the order is the two-point one of the last refinement.
struct Fit {
  std::vector<double> err;
  ringtest::Samples last_two() const { return ringtest::in_n(std::vector<int>{80, 160}, {err[1], err[2]}); }
};

// Two opposite forces along a diameter of a ring that carries half its critical pressure:
// the shortening against the linear Fourier series about the pressurized circle (each
// kind's own load stiffness, and for the central kind the pin's reaction to the load's
// restraint of the translation, closed_form.hpp). Measured at n = 160: 1.6e-3 (follower),
// 1.5e-3 (dead), 1.3e-3 (central); the extrapolated chain meets the series to 1e-5. P is small (shortening ~1e-6 R) so that the
// series' linearity in P holds to ~1e-6; the chain converges at order 2 (as its modes).
TEST(MultibodyLoading, SqueezeUnderPressureMeetsTheSeriesOfEachKind) {
  ring::RingSpec spec = ringtest::pinned_ring(270.0);
  spec.supports.roller = 90.0;
  const double P = 1e-6 * spec.EI() / (spec.radius * spec.radius);
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    const ring::Pressure pressure{0.5 * ring::closed_form::critical_pressure(spec, kind), kind};
    const double exact = ring::closed_form::diametral_load_under_pressure(spec, P, pressure).along;
    const double unpressurized = ring::closed_form::diametral_load(spec, P).along;
    ASSERT_GT(exact, 1.3 * unpressurized) << "half the critical pressure amplifies the n = 2 response";
    ring::StaticOptions st;
    st.loads.points = {{0.0, {-P, 0.0}}, {180.0, {P, 0.0}}};
    st.loads.pressure = pressure;
    st.steps = 4;
    st.record = {0.0, 180.0};
    Fit fit;
    for (int n : {40, 80, 160}) {
      ring::MultibodyOptions o;
      o.n = n;
      const ring::StaticResult r = multibody::solve_static(spec, o, st);
      const double along = r.displacements[1].ux - r.displacements[0].ux;
      fit.err.push_back(std::abs(along - exact) / exact);
    }
    EXPECT_TRUE(ringtest::OrderNear(fit.last_two(), 2.0, 0.2, 2e-3)) << ring::to_string(kind) << ": errors " << fit.err[0]
                                                                    << " " << fit.err[1] << " " << fit.err[2];
  }
}

// A ring hanging from a pin under its own weight (no roller: gravity holds the rotation):
// the sag and the shrinking of the diameter across against the series of the thin ring
// (closed_form.hpp; Roark's 0.4674 and 0.4292 q R^4/EI). g is scaled so that the sag is
// ~1e-6 R (linear limit); the chain converges at order 2.
TEST(MultibodyLoading, HangingRingMeetsTheSelfWeightSeries) {
  const ring::RingSpec spec = ringtest::pinned_ring(90.0);
  ASSERT_EQ(ring::static_rigid_modes(spec, ring::Loads{{}, {}, {0.0, -1.0}}), 0);
  ASSERT_EQ(ring::static_rigid_modes(spec, ring::Loads{{}, {}, {0.0, 1.0}}), 1) << "standing on its pin: unstable";
  const ring::StaticOptions st = mbtest::hanging_statics(spec, 1e-6);
  const auto exact = ring::closed_form::hanging_ring_self_weight(spec, -st.loads.gravity[1]);
  Fit sag, across;
  for (int n : {40, 80, 160}) {
    ring::MultibodyOptions o;
    o.n = n;
    const ring::StaticResult r = multibody::solve_static(spec, o, st);
    sag.err.push_back(std::abs(-r.displacements[2].uy - exact.sag) / exact.sag);
    across.err.push_back(std::abs(r.displacements[1].ux - r.displacements[0].ux - exact.across) / exact.across);
    EXPECT_NEAR(r.displacements[0].uy, r.displacements[1].uy, 1e-14 * spec.radius) << "symmetric about the vertical";
  }
  // Ceiling on the sag: the chain's O((2 pi / n)^2), 1.2e-3 measured at n = 160.
  EXPECT_TRUE(ringtest::OrderNear(sag.last_two(), 2.0, 0.2, 2e-3)) << "sag: " << sag.err[0] << " " << sag.err[1] << " "
                                                                   << sag.err[2];
  EXPECT_TRUE(ringtest::OrderNear(across.last_two(), 2.0, 0.2)) << "across: " << across.err[0] << " " << across.err[1]
                                                                << " " << across.err[2];
}

// The O(n) statics takes every load (tests/multibody/test_statics_terms.cpp), and "auto"
// takes it above the crossover; the Timoshenko chain's shear angles it has not: refused when
// forced, naming the key, and "auto" keeps that dense.
TEST(MultibodyLoading, TheSparseStaticsRefusesWhatItCannotAssemble) {
  ring::RingSpec spec = ringtest::pin_roller_ring();
  ring::StaticOptions st;
  st.loads.pressure = {1.0, Kind::follower};
  st.record = {0.0};
  ring::MultibodyOptions o;
  o.n = 4000;
  EXPECT_EQ(multibody::backend(o, spec, st.loads, multibody::Analysis::statics), multibody::Backend::banded);
  spec.theory = ring::Theory::timoshenko;
  EXPECT_EQ(multibody::backend(o, spec, st.loads, multibody::Analysis::statics), multibody::Backend::dense);
  o.n = 40;
  o.method = ring::MultibodyOptions::Method::sparse;
  try {
    multibody::solve_static(spec, o, st);
    ADD_FAILURE() << "the O(n) statics took the Timoshenko chain";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ring.theory"), std::string::npos) << e.what();
  }
}

// A pressure pulse of each kind with gravity and two point loads (the dense Newmark path):
// the undamped balance T + V - W, W the loads' work from their potential, stays within the
// energy guard's 1 % of the work (ring/energy_guard.hpp; average acceleration conserves a
// quadratic energy exactly, so what remains is the O(dt^2) of the non-quadratic part),
// and halves by about 4 when dt halves (order 2).
TEST(MultibodyLoading, APressurePulseKeepsTheEnergyBalance) {
  const ring::RingSpec spec = ringtest::pin_roller_ring();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    std::vector<double> drift;
    for (double dt : {0.02, 0.01}) {
      ring::ResponseOptions r;
      r.loads.points = {{0.0, {-5e3, 0.0}}, {90.0, {0.0, -5e3}}};
      r.loads.pressure = {0.5 * ring::closed_form::critical_pressure(spec, kind), kind};
      r.loads.gravity = {0.0, -9.81};
      r.history = {ring::LoadHistory::Kind::half_sine, 0.5};
      r.dt = dt;
      r.t_end = 1.0;
      r.record = {0.0, 90.0};
      ring::MultibodyOptions o;
      o.n = 40;
      const ring::TimeHistory h = multibody::respond(spec, o, r);
      double work = 0.0, worst = 0.0;
      for (std::size_t k = 0; k < h.t.size(); ++k) {
        work = std::max(work, std::abs(h.work[k]));
        worst = std::max(worst, std::abs(h.kinetic[k] + h.strain[k] - h.work[k]));
      }
      ASSERT_GT(work, 0.0);
      EXPECT_LT(worst, 1e-2 * work) << ring::to_string(kind) << ", dt = " << dt;
      drift.push_back(worst / work);
    }
    EXPECT_GT(drift[0] / drift[1], 3.0) << ring::to_string(kind) << ": " << drift[0] << " " << drift[1];
  }
}

// The dense response with the stiffness terms (a clamp at the pin, a spring, a foundation)
// under a step of gravity and pressure: undamped, T + V - W (V with the terms' energy) stays
// within the guard's 1 %; heavily damped (Rayleigh a = 20/s: an overdamped mode decays at
// least as e^(-3.4 t) at omega^2 >= 57/s^2, the others as e^(-10 t); e^-50 at t = 15 s) it
// comes to rest at the static equilibrium of
// the continuation driver (the same terms, another driver and another equation), within the
// Newton tolerances' 1e-6; with a point mass too.
TEST(MultibodyLoading, ResponseWithTermsKeepsTheBalanceAndSettlesOnTheStatics) {
  ring::RingSpec spec = ringtest::pinned_ring(180.0);
  spec.supports.clamp = 180.0;
  spec.supports.springs = {{0.0, 2e3, 0.0, 0.0}};
  spec.foundation = {5e3, 5e3};  // every mode at omega^2 >= k/(rho A) = 57/s^2
  ring::Loads loads;             // displacements of 6 to 20 cm: nonlinear, far from round-off
  loads.gravity = {0.0, -9.81};
  loads.pressure = {500.0, Kind::follower};
  ring::MultibodyOptions o;
  o.n = 40;
  ring::ResponseOptions r;
  r.loads = loads;
  r.dt = 0.01;
  r.t_end = 2.0;
  r.record = {0.0, 90.0};
  const ring::TimeHistory h = multibody::respond(spec, o, r);
  double work = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    work = std::max(work, std::abs(h.work[k]));
    worst = std::max(worst, std::abs(h.kinetic[k] + h.strain[k] - h.work[k]));
  }
  EXPECT_LT(worst, 1e-2 * work) << worst << " of " << work;
  r.rayleigh_mass = 20.0;
  r.t_end = 15.0;
  const ring::TimeHistory d = multibody::respond(spec, o, r);
  ring::StaticOptions st;
  st.loads = loads;
  st.steps = 4;
  st.record = r.record;
  const ring::StaticResult s = multibody::solve_static(spec, o, st);
  for (std::size_t i = 0; i < st.record.size(); ++i) {
    const double scale = std::hypot(s.displacements[i].ux, s.displacements[i].uy);
    ASSERT_GT(scale, 0.0);
    EXPECT_NEAR(d.ux[i].back(), s.displacements[i].ux, 1e-6 * scale) << st.record[i];
    EXPECT_NEAR(d.uy[i].back(), s.displacements[i].uy, 1e-6 * scale) << st.record[i];
  }
  // A point mass (with a rotary inertia) changes the motion, not where the damped motion
  // settles: the statics' equilibrium with its weight, to the same 1e-6.
  spec.masses = {{90.0, 10.0, 2.0}};
  const ring::TimeHistory dm = multibody::respond(spec, o, r);
  const ring::StaticResult sm = multibody::solve_static(spec, o, st);
  for (std::size_t i = 0; i < st.record.size(); ++i) {
    const double scale = std::hypot(sm.displacements[i].ux, sm.displacements[i].uy);
    EXPECT_NEAR(dm.ux[i].back(), sm.displacements[i].ux, 1e-6 * scale) << st.record[i];
    EXPECT_NEAR(dm.uy[i].back(), sm.displacements[i].uy, 1e-6 * scale) << st.record[i];
  }
}

}  // namespace
