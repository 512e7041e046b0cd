// The multibody chain with the terms beyond the paper's ring (multibody/attachments.hpp):
// the foundation and a point mass against closed forms, springs against the supports they
// tend to, rigid-mode counts against the supports' rows, a clamp by its convergence order.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "multibody/attachments.hpp"
#include "multibody/modes.hpp"
#include "multibody/statics.hpp"
#include "ring/closed_form.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/ring_receptance.hpp"
#include "tests/multibody/common.hpp"
#include "tests/multibody/ring_oracle.hpp"

namespace {

using mbtest::foundation_spectrum;
using mbtest::on_foundation;
using ringtest::IsClose;

ring::ModalResult modes(const ring::RingSpec& spec, int n, int count, bool rotary_inertia = false) {
  ring::MultibodyOptions o;
  o.n = n;
  o.rotary_inertia = rotary_inertia;
  return multibody::compute_modes(spec, o, count);
}



// The chain converges to the inextensible ring at order 2 in 1/n (docs/solvers.md): with the
// foundation lumped at the hinges it must still do so, toward the closed form.
TEST(MultibodyAttachments, FoundationConvergesToTheClosedFormAtOrderTwo) {
  const ring::RingSpec spec = on_foundation();
  const int count = 13;  // k = 0 and the pairs k = 1 .. 6
  const std::vector<double> exact = foundation_spectrum(spec, count);
  std::vector<std::vector<double>> err;
  for (int n : {40, 80, 160}) {
    const ring::ModalResult r = modes(spec, n, count);
    ASSERT_EQ(r.rigid_modes, 0) << "the foundation holds every rigid motion";
    std::vector<double> e;
    for (int i = 0; i < count; ++i) e.push_back(ringtest::rel(r.omega[i], exact[i]));
    err.push_back(e);
  }
  for (int i = 0; i < count; ++i) {
    if (i == 1 || i == 2) {  // k = 1, the translations: lumped foundation and chain mass are exact for them
      EXPECT_LT(err[2][i], 1e-12) << "mode " << i + 1;
      continue;
    }
    // The two-point order over n = 80, 160; ceiling at n = 160: the chain's error
    // (2 pi/n)^2 k^2 / 12-like, at most ~3e-3 for k = 6.
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{80, 160}, {err[1][i], err[2][i]}), 2.0, 0.15, 5e-3))
        << "mode " << i + 1;
  }
}

// A point mass m0 at 0 deg splits each pair of the free ring: to first order in m0 the
// mode moving tangentially there drops by m0 / (pi R rho A (k^2 + 1)) in omega^2, the one
// moving radially by k^2 times that (closed_form::point_mass_shift).
TEST(MultibodyAttachments, PointMassSplitsEachPairAsFirstOrderPerturbationSays) {
  ring::RingSpec spec = ringtest::free_ring();
  const double ring_mass = 2.0 * M_PI * spec.radius * spec.rhoA();
  const double m0 = 1e-3 * ring_mass;
  const int n = 160, count = 8;  // pairs k = 2 .. 5
  const ring::ModalResult bare = modes(spec, n, count);
  spec.masses.push_back({0.0, m0, 0.0});
  const ring::ModalResult loaded = modes(spec, n, count);
  ASSERT_EQ(loaded.rigid_modes, 3) << "a point mass holds nothing";
  for (int k = 2; k <= 5; ++k) {
    const auto [tangential, radial] = ring::closed_form::point_mass_shift(spec, m0, k);
    const int lo = 2 * (k - 2), hi = lo + 1;  // the radial member moves more, so it is lower
    const double d_lo = std::pow(loaded.omega[lo] / bare.omega[lo], 2) - 1.0;
    const double d_hi = std::pow(loaded.omega[hi] / bare.omega[hi], 2) - 1.0;
    // Second order: (k^2 * 2e-3)^2 <= 2.6e-3 relative of the shift at k = 5, plus the
    // chain's O((2 pi k / n)^2 / 12) ~ 1e-3 relative error of the mode shapes: 1 % of the shift.
    EXPECT_TRUE(IsClose(d_lo, radial, 1e-2)) << "k = " << k;
    EXPECT_TRUE(IsClose(d_hi, tangential, 1e-2)) << "k = " << k;
  }
}

// A spring of stiffness ks in place of a constraint perturbs omega^2 by O(1/ks): ten times
// stiffer, ten times closer to the pinned (or clamped) ring.
TEST(MultibodyAttachments, StiffSpringsTendToThePinAndTheClampAtTheRateOneOverK) {
  const int n = 40, count = 6;
  ring::RingSpec pinned_twice = ringtest::pinned_ring(180.0);
  pinned_twice.supports.pins = {0.0};
  ring::RingSpec clamped = ringtest::pinned_ring(180.0);
  clamped.supports.clamp = 180.0;
  const ring::ModalResult pins = modes(pinned_twice, n, count), clamp = modes(clamped, n, count);
  EXPECT_EQ(pins.rigid_modes, 0);
  EXPECT_EQ(clamp.rigid_modes, 0);
  auto gap = [&](const ring::ModalResult& held, double k, bool rotation) {
    ring::RingSpec s = ringtest::pinned_ring(180.0);
    if (rotation) s.supports.springs = {{180.0, 0.0, 0.0, k}};
    else s.supports.springs = {{0.0, k, k, 0.0}};
    const ring::ModalResult r = modes(s, n, count);
    double g = 0.0;
    for (int i = 0; i < count; ++i) g = std::max(g, ringtest::rel(r.omega[i], held.omega[i]));
    return g;
  };
  // Scales: EI/R^3 = 2.1e3 N/m for the translation, EI/R = 2.1e5 N m for the rotation.
  const double t1 = gap(pins, 1e9, false), t2 = gap(pins, 1e10, false);
  const double r1 = gap(clamp, 1e11, true), r2 = gap(clamp, 1e12, true);
  EXPECT_NEAR(t1 / t2, 10.0, 0.5) << t1 << " " << t2;
  EXPECT_NEAR(r1 / r2, 10.0, 0.5) << r1 << " " << r2;
  EXPECT_LT(t2, 1e-5);
  EXPECT_LT(r2, 1e-5);
}

// The rigid modes the chain finds are those the supports leave (RingSpec::rigid_modes),
// counted here by hand from the rigid motions each support stops.
TEST(MultibodyAttachments, RigidModesAreTheMotionsTheSupportsLeave) {
  struct Case {
    const char* what;
    ring::RingSpec spec;
    int rigid;
  };
  std::vector<Case> cases;
  ring::RingSpec s = ringtest::free_ring();
  s.foundation.radial = 100.0;
  cases.push_back({"radial foundation: the rotation stays free", s, 1});
  s = ringtest::free_ring();
  s.supports.springs = {{0.0, 1e4, 0.0, 0.0}};
  cases.push_back({"one spring along x: y and the rotation stay free", s, 2});
  s = ringtest::pinned_ring(180.0);
  s.supports.springs = {{0.0, 1e4, 0.0, 0.0}};
  cases.push_back({"pin at 180, kx at 0: the rotation about the pin moves 0 deg along y only", s, 1});
  s = ringtest::pinned_ring(180.0);
  s.supports.springs = {{0.0, 0.0, 1e4, 0.0}};
  cases.push_back({"pin at 180, ky at 0: holds the rotation about the pin", s, 0});
  s = ringtest::pinned_ring(180.0);
  s.supports.springs = {{90.0, 0.0, 0.0, 1e5}};
  cases.push_back({"pin and a rotational spring: holds the rotation", s, 0});
  for (const Case& c : cases) {
    EXPECT_EQ(c.spec.rigid_modes(), c.rigid) << c.what;
    EXPECT_EQ(modes(c.spec, 40, 4).rigid_modes, c.rigid) << c.what;
  }
}

// The terms' gradient and Hessian against central differences of their energy, on a chain
// moved far from rest (angles perturbed by 0.2 rad), free and pinned, with every term.
TEST(MultibodyAttachments, GradientAndHessianAreThoseOfTheEnergy) {
  for (bool free : {true, false}) {
    ring::RingSpec spec = free ? ringtest::free_ring() : ringtest::pinned_ring(0.0);
    spec.foundation = {500.0, 300.0};
    spec.supports.springs = {{90.0, 1e4, 2e4, 3e5}};
    if (!free) spec.supports.clamp = 0.0;
    ring::MultibodyOptions o;
    o.n = 12;
    const multibody::Chain chain(spec, o);
    const multibody::detail::Attachments terms(chain, spec);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> d(-0.2, 0.2);
    multibody::Vector q = chain.q0();
    for (int i = 0; i < q.size(); ++i) q[i] += d(rng);
    multibody::Vector g = multibody::Vector::Zero(q.size());
    multibody::Matrix H = multibody::Matrix::Zero(q.size(), q.size());
    Eigen::Ref<multibody::Matrix> h_ref(H);
    terms.add_stiffness(q, g, &h_ref);
    const double h = 1e-5;  // central differences: truncation h^2 E'''/6, about 1e-10 of the scale
    for (int j = 0; j < q.size(); ++j) {
      multibody::Vector qp = q, qm = q;
      qp[j] += h;
      qm[j] -= h;
      EXPECT_NEAR(g[j], (terms.energy(qp) - terms.energy(qm)) / (2 * h), 1e-6 * (1.0 + g.cwiseAbs().maxCoeff())) << j;
      multibody::Vector gp = multibody::Vector::Zero(q.size()), gm = gp;
      terms.add_stiffness(qp, gp, nullptr);
      terms.add_stiffness(qm, gm, nullptr);
      const multibody::Vector col = (gp - gm) / (2 * h);
      EXPECT_LT((H.col(j) - col).cwiseAbs().maxCoeff(), 1e-6 * (1.0 + H.cwiseAbs().maxCoeff()))
          << "free " << free << " column " << j;
    }
  }
}

// A small radial point load F at 0 deg on the free ring on a foundation against the
// inextensional Fourier series (mbtest::foundation_point_load_series). The chain's statics
// converge to it at order 2.
TEST(MultibodyAttachments, StaticsOnAFoundationConvergeToTheFourierSeries) {
  ring::RingSpec spec = ringtest::free_ring();
  spec.foundation = {500.0, 300.0};
  const double F = 1.0;  // N: w ~ 6e-5 m = 6e-6 R, geometric nonlinearity -0.12 w/R ~ 7e-7 relative (measured)
  const double exact = mbtest::foundation_point_load_series(spec, F);
  ring::StaticOptions st;
  st.loads.points = {{0.0, {0.0, 0.0}}};
  st.loads.points.at(0).force = {F, 0.0};
  st.steps = 1;
  st.record = {0.0};
  std::vector<double> err;
  for (int n : {80, 160, 320}) {
    ring::MultibodyOptions o;
    o.n = n;
    const ring::StaticResult r = multibody::solve_static(spec, o, st);
    err.push_back(ringtest::rel(r.displacements[0].ux, exact));
  }
  // The two-point order over n = 160, 320.
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{160, 320}, {err[1], err[2]}), 2.0, 0.15, 1e-3));
}

// Two pins and a clamp hold the ring without a roller: the pinned points stay where they are
// (to the Newton tolerance) while the loaded crown moves with the load.
TEST(MultibodyAttachments, StaticsWithPinsAndAClampHoldThePinnedPoints) {
  ring::RingSpec spec = ringtest::pinned_ring(180.0);
  spec.supports.pins = {0.0};
  spec.supports.clamp = 180.0;
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, 0.0}}};
  st.loads.points.at(0).force = {0.0, -2e4};
  st.steps = 4;
  st.record = {0.0, 90.0, 180.0};
  ring::MultibodyOptions o;
  o.n = 40;
  const ring::StaticResult r = multibody::solve_static(spec, o, st);
  EXPECT_LT(std::hypot(r.displacements[0].ux, r.displacements[0].uy), 1e-10) << "the second pin moved";
  EXPECT_LT(std::hypot(r.displacements[2].ux, r.displacements[2].uy), 1e-12) << "the pin moved";
  EXPECT_LT(r.displacements[1].uy, 0.0) << "the crown moves with the load";
}

receptance::Ring continuum(const ring::RingSpec& spec) { return {spec.radius, spec.EI(), spec.rhoA()}; }

/// Fitted order between the two finest of three meshes, and the finest error, of the chain's
/// frequencies (no rotary inertia: the continuum has none) against `exact`.
void expect_order_two(const ring::RingSpec& spec, const std::vector<double>& exact, int count) {
  std::vector<std::vector<double>> err;
  for (int n : {80, 160, 320}) {
    const ring::ModalResult r = modes(spec, n, count);
    std::vector<double> e;
    for (int i = 0; i < count; ++i) e.push_back(ringtest::rel(r.omega[i], exact[i]));
    err.push_back(e);
  }
  for (int i = 0; i < count; ++i) {
    // Ceiling: (2 pi k / n)^2 / 12-like at n = 320.
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{160, 320}, {err[1][i], err[2][i]}), 2.0, 0.15, 3e-3))
        << "mode " << i + 1;
  }
}

// The oracle itself: a point mass far heavier than the ring pins the ring there.
TEST(RingReceptance, AnInfiniteMassIsAPin) {
  const ring::RingSpec spec = ringtest::free_ring();
  const receptance::Ring c = continuum(spec);
  const std::vector<double> heavy = receptance::point_mass_omegas(c, 1e9 * c.total_mass(), 8);
  const std::vector<double> pinned = oracle::pinned_ring_omegas(spec.radius, spec.EI(), spec.rhoA(), 8);
  for (int i = 0; i < 8; ++i) EXPECT_TRUE(IsClose(heavy[i], pinned[i], 1e-8)) << "mode " << i + 1;
}

// A point mass of 5 % of the ring's mass (far beyond first order): the chain converges to the
// receptance oracle of the continuous ring at order 2.
TEST(MultibodyAttachments, PointMassConvergesToTheReceptanceOracle) {
  ring::RingSpec spec = ringtest::free_ring();
  const double m0 = 0.05 * continuum(spec).total_mass();
  spec.masses.push_back({0.0, m0, 0.0});
  expect_order_two(spec, receptance::point_mass_omegas(continuum(spec), m0, 10), 10);
}

// No closed form for a ring clamped at one point: the chain converges to the receptance
// oracle (w = v = beta = 0 at the clamp) at order 2.
TEST(MultibodyAttachments, ClampedRingConvergesToTheReceptanceOracle) {
  ring::RingSpec spec = ringtest::pinned_ring(0.0);
  spec.supports.clamp = 0.0;
  // Six modes: the eighth has errors of 2e-5 and 4e-6 at n = 160 and 320, a fitted 2.2 (two
  // error terms of opposite sign); at n = 640 .. 1280 every one of the six fits 2.00.
  expect_order_two(spec, receptance::clamped_omegas(continuum(spec), 6), 6);
}

}  // namespace
