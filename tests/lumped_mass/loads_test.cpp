// The nonlinear lumped chain's loads (several point loads, uniform pressure of each kind,
// gravity) and terms (further pins, clamp, springs, point masses, foundation) in statics and
// response, against oracles outside the code:
//  - closed forms of the inextensible thin ring by Fourier series (derived below), which the
//    chain must approach at a fitted order 2;
//  - the exact answer of the polygon: uniform pressure does not move the inextensible chain;
//  - the independent elastica (tests/support/elastica.hpp) and the multibody chain, the same
//    physical model in segment angles (multibody/attachments.hpp takes the same terms);
//  - balance laws: the ground's force against the weight, the energy balance of the response
//    and its mean against the statics.
//
// ## Fourier series of the inextensible ring (used by several tests)
// Displacements symmetric about the polar axis phi = 0 of a ring of radius R:
//   w = sum_k a_k cos k phi (radial, outward), v = -sum_k (a_k / k) sin k phi (tangential),
// k >= 1, which keeps every element's length to first order (w + dv/dphi = 0; k = 0 cannot).
// The energies are diagonal in k, 1/2 E_k a_k^2 with
//   E_k = pi [EI (k^2 - 1)^2 / R^3 + R (k_r + k_t / k^2) - p f_k]
// from bending, EI / (2 R^3) int (w'' + w)^2 dphi; the foundation, R / 2 int (k_r w^2 + k_t
// v^2) dphi; and the second-order potential of a pressure p (positive inward) on the ring
// compressed by the hoop force -p R. With the exact inextensibility to second order,
// int w dphi = -1/(2R) int (w' - v)^2 dphi:
//   follower (potential p A): Delta A = 1/2 int (w^2 - w'^2) dphi  ->  f_k = k^2 - 1;
//   dead (potential -p R int w dphi)                                 ->  f_k = (k^2 - 1)^2 / k^2;
//   central (potential p R int |x| dphi, |x| = R + w + v^2 / (2R))  ->  f_k = k^2 - 2,
// whose buckling pressures min_k (k^2 - 1)^2 / f_k EI/R^3 are the classical 3, 4 and 4.5 EI/R^3
// (Timoshenko & Gere; Simitses). A point force F at phi_0 has the generalized force
// F . (w_k r + v_k t)(phi_0) on mode k, and a_k = Q_k / E_k.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "lumped_mass/checks.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/elastica.hpp"
#include "support/paper.hpp"

namespace {

using ringtest::IsClose;
using Kind = ring::Pressure::Kind;

constexpr int kTerms = 200000;  // Fourier terms: the tails fall as k^-3 (< 1e-16 relative)

ring::LumpedOptions chain(int n) {
  ring::LumpedOptions o;
  o.n = n;
  return o;
}

std::string sci(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3e", x);
  return b;
}

std::string list(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += sci(x) + " ";
  return s;
}

/// f_k of the pressure's second-order potential (file comment).
double pressure_factor(Kind kind, double k) {
  const double k2 = k * k;
  switch (kind) {
    case Kind::follower: return k2 - 1.0;
    case Kind::dead: return (k2 - 1.0) * (k2 - 1.0) / k2;
    case Kind::central: return k2 - 2.0;
  }
  return 0.0;
}

/// The squeeze of the paper's section 5 in the linear limit: the ring pinned at 180 deg, a
/// roller at 0 deg (along the x axis), a force (-P, 0) at 0 deg; on a pressure p of `kind`
/// and a foundation (k_r, k_t). Returns u_x at 0 deg. With phi from 0 deg, the load has
/// Q_k = -P on every mode, the pin's reaction (R_x, 0) at phi = pi has Q_k = -R_x (-1)^k, and
/// the pin holds: u_x(pi) = -sum_k a_k (-1)^k = 0. With d = R_x - P, odd k have
/// a_k = d / E_k and even k a_k = -(2P + d) / E_k, so d = -2P S_e / (S_o + S_e) with S_o, S_e
/// the sums of 1/E_k over odd and even k (d = 0 when E_1 = 0: a rigid translation, held by the
/// pin alone), and u_x(0) = sum_k a_k = -2 (2P + d) S_e.
double squeezed(const ring::RingSpec& s, double P, double p, Kind kind) {
  const double R = s.radius, EI = s.EI();
  double So = 0.0, Se = 0.0;
  bool rigid = false;
  for (int k = 1; k <= kTerms; ++k) {
    const double k2 = double(k) * k;
    const double E = M_PI * (EI * (k2 - 1) * (k2 - 1) / (R * R * R) +
                             R * (s.foundation.radial + s.foundation.tangential / k2) - p * pressure_factor(kind, k));
    if (k == 1 && std::abs(E) < 1e-300) {
      rigid = true;
      continue;
    }
    (k % 2 ? So : Se) += 1.0 / E;
  }
  const double d = rigid ? 0.0 : -2.0 * P * Se / (So + Se);
  return -2.0 * (2.0 * P + d) * Se;
}

ring::StaticOptions squeeze(double P, double p, Kind kind) {
  ring::StaticOptions st;
  st.loads.points = {{0.0, {-P, 0.0}}};
  st.loads.pressure = {p, kind};
  st.steps = 4;
  st.record = {0.0, 90.0, 180.0, 270.0};
  return st;
}

double max_node_move(const ring::StaticResult& r, const ring::RingSpec& s, int n) {
  const double rho = 2.0 * M_PI * s.radius / n / (2.0 * std::sin(M_PI / n));
  double worst = 0.0;
  for (int k = 0; k < n; ++k) {
    const double a = (*s.supports.pin + 360.0 * k / n) * M_PI / 180.0;
    worst = std::max(worst, std::hypot(r.node_x[k] - rho * std::cos(a), r.node_y[k] - rho * std::sin(a)));
  }
  return worst;
}

// The polygon's exact answer: on the rest n-gon every uniform pressure is the same inward
// force p l cos(pi/n) at every hinge, balanced exactly by the links' compression
// p rho cos(pi/n) (lumped_mass/loads.hpp), so the inextensible chain does not move, for every
// kind, below the buckling pressure (here half of the lowest, the follower's 3 EI/R^3), also on
// a foundation (which then carries nothing: the continuum's u_r = -p / (EA/R^2 + k_r) with
// EA -> infinity). The Newton corrections stop at 1e-12 R (nonlinear.hpp): the bound.
TEST(LumpedLoads, UniformPressureDoesNotMoveTheChain) {
  for (bool foundation : {false, true})
    for (Kind kind : {Kind::follower, Kind::dead, Kind::central})
      for (int n : {12, 40, 160}) try {
        ring::RingSpec s = ringtest::pin_roller_ring();
        if (foundation) s.foundation = {10.0 * s.EI() / std::pow(s.radius, 4), 0.0};
        const double p = 1.5 * s.EI() / std::pow(s.radius, 3);
        SCOPED_TRACE(ring::to_string(kind) + " n = " + std::to_string(n) + (foundation ? " foundation" : ""));
        const auto r = lumped::solve_static(s, chain(n), squeeze(0.0, p, kind));
        EXPECT_LT(max_node_move(r, s, n), 1e-12 * s.radius) << ring::to_string(kind) << " n = " << n;
      } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
      }
}

// The pressures' load stiffness: a small squeeze P on the ring under a pressure p = 1.5 EI/R^3
// (half the follower's buckling pressure; the k = 2 mode is amplified by 2, 1.6 and 1.5 for
// follower, dead and central) must give the Fourier series of the prestressed ring
// (squeezed()), approached at order 2 (fitted over n = 40, 80, 160 within 0.15: the chain is a
// central scheme, lumped_mass/README.md). P R^2 / EI = 1e-6 keeps the geometric nonlinearity at
// ~1e-7 relative, below the finest discretization error (~1e-4) by three decades.
TEST(LumpedLoads, PressureLoadStiffnessMatchesTheFourierSeries) {
  const ring::RingSpec s = ringtest::pin_roller_ring();
  const double P = 1e-6 * s.EI() / (s.radius * s.radius), p = 1.5 * s.EI() / std::pow(s.radius, 3);
  const double bare = squeezed(s, P, 0.0, Kind::dead);
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    const double exact = squeezed(s, P, p, kind);
    EXPECT_GT(std::abs(exact / bare - 1.0), 0.1) << "the pressure must matter";
    std::vector<double> ns = {40, 80, 160}, err;
    for (double n : ns)
      err.push_back(ringtest::rel(lumped::solve_static(s, chain(int(n)), squeeze(P, p, kind)).displacements[0].ux, exact));
    const auto samples = ringtest::in_n(ns, err);  // the order in h = 2 pi R / n
    RecordProperty("order_" + ring::to_string(kind), std::to_string(ringtest::fit_order(samples).order));
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.15, 2e-3)) << ring::to_string(kind);
  }
  // The three kinds differ by far more than the finest error: the test tells them apart.
  EXPECT_GT(ringtest::rel(squeezed(s, P, p, Kind::dead), squeezed(s, P, p, Kind::central)), 0.02);
}

// The foundation (radial and tangential) in statics against the same series: k_r = 10 EI/R^4,
// k_t = 5 EI/R^4 lift the k = 1 mode, so the pin's reaction differs from P (d != 0).
TEST(LumpedLoads, FoundationMatchesTheFourierSeries) {
  ring::RingSpec s = ringtest::pin_roller_ring();
  s.foundation = {10.0 * s.EI() / std::pow(s.radius, 4), 5.0 * s.EI() / std::pow(s.radius, 4)};
  const double P = 1e-6 * s.EI() / (s.radius * s.radius);
  const double exact = squeezed(s, P, 0.0, Kind::dead);
  EXPECT_GT(ringtest::rel(exact, squeezed(ringtest::pin_roller_ring(), P, 0.0, Kind::dead)), 0.05);
  std::vector<double> ns = {40, 80, 160}, err;
  for (double n : ns)
    err.push_back(ringtest::rel(lumped::solve_static(s, chain(int(n)), squeeze(P, 0.0, Kind::dead)).displacements[0].ux, exact));
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, err), 2.0, 0.15, 2e-3));
}

// Several point loads: two opposite forces P at 90 and 270 deg pinch the ring pinned at 180 and
// on a roller at 0 deg (self-equilibrated: the supports carry nothing). That is the elastica's
// diametral problem (tests/support/elastica.hpp) turned by 90 deg, deep in the nonlinear range
// (P R^2/EI = 2): order 2 over n = 40, 80, 160 (within 0.1, as the one-load test in
// nonlinear_test.cpp) for both diameters.
TEST(LumpedLoads, SeveralPointLoadsConvergeToTheElastica) {
  const ring::RingSpec s = ringtest::pin_roller_ring();
  const double p = 2.0, P = p * s.EI() / (s.radius * s.radius);
  const elastica::DiametralResult exact = elastica::diametral(p);
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -P}}, {270.0, {0.0, P}}};
  st.steps = 20;
  st.record = {0.0, 90.0, 180.0, 270.0};
  std::vector<double> ns = {40, 80, 160}, e_along, e_across;
  for (double n : ns) {
    const auto r = lumped::solve_static(s, chain(int(n)), st);
    const double along = -(r.displacements[1].uy - r.displacements[3].uy) / s.radius;
    const double across = (r.displacements[0].ux - r.displacements[2].ux) / s.radius;
    e_along.push_back(ringtest::rel(along, exact.along));
    e_across.push_back(ringtest::rel(across, exact.across));
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, e_along), 2.0, 0.1)) << "along";
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, e_across), 2.0, 0.1)) << "across";
}

// The terms in large displacements: a further pin, the clamp, an elastic support (kx, ky, kr)
// and the foundation, under P R^2/EI = 2, against multibody::solve_static, the same model (its
// terms in multibody/attachments.hpp, the same conventions) in segment angles written
// independently. Both solve the same equations to ~1e-12 R: 1e-9 relative, as the one-load
// comparison in nonlinear_test.cpp.
TEST(LumpedLoads, TermsEqualTheMultibodyChainInLargeDisplacements) {
  const double EI = ringtest::free_ring().EI(), R = 10.0;
  ring::RingSpec clamped = ringtest::pinned_ring(180.0);
  clamped.supports.clamp = 180.0;
  clamped.supports.springs = {{90.0, 5.0 * EI / (R * R * R), 2.0 * EI / (R * R * R), 3.0 * EI / R}};
  clamped.foundation = {2.0 * EI / std::pow(R, 4), 1.0 * EI / std::pow(R, 4)};
  ring::RingSpec pinned = ringtest::pin_roller_ring();
  pinned.supports.pins = {270.0};
  pinned.supports.springs = {{45.0, 0.0, 0.0, 10.0 * EI / R}};
  for (const ring::RingSpec& s : {clamped, pinned}) {
    ring::StaticOptions st;
    st.loads.points = {{45.0, {-2.0 * EI / (R * R), -1.0 * EI / (R * R)}}};
    st.steps = 10;
    st.record = {0.0, 45.0, 90.0, 135.0, 270.0};
    ring::MultibodyOptions mo;
    mo.n = 40;
    mo.rotary_inertia = false;
    const auto a = lumped::solve_static(s, chain(40), st);
    const auto b = multibody::solve_static(s, mo, st);
    const double scale = std::hypot(b.displacements[1].ux, b.displacements[1].uy);
    EXPECT_GT(scale, 0.05 * R) << "large displacements";
    for (std::size_t q = 0; q < st.record.size(); ++q) {
      EXPECT_TRUE(IsClose(a.displacements[q].ux, b.displacements[q].ux, 0.0, 1e-9 * scale)) << st.record[q];
      EXPECT_TRUE(IsClose(a.displacements[q].uy, b.displacements[q].uy, 0.0, 1e-9 * scale)) << st.record[q];
    }
  }
}

/// The ring pinned at the top (90 deg) with a roller at the bottom (270 deg, on the vertical
/// line through the pin): under a load symmetric about the vertical the bottom does not move
/// sideways, so the roller carries nothing and this is the ring hung from a pin at the top.
ring::RingSpec hung_ring() {
  ring::RingSpec s = ringtest::pinned_ring(90.0);
  s.supports.roller = 270.0;
  return s;
}

// (a) The ground's force balances the weight of the ring and of the point masses, in large
// displacements (the paper's ring under 9.81 m/s^2 sags by rho A g R^4/EI ~ 0.4 R... times the
// series' 0.47) and with springs and a foundation sharing the load: the supports' multipliers
// and the terms' forces, summed, against 2 pi R rho A g + sum m g. The equilibrium holds to the
// Newton tolerance, ~1e-12 R times a stiffness EI / l^3 ~ 1e-10 of the weight: 1e-9.
TEST(LumpedLoads, GroundForceBalancesTheWeight) {
  ring::RingSpec s = hung_ring();
  s.masses = {{270.0, 500.0, 0.0}, {0.0, 200.0, 50.0}};
  s.supports.springs = {{180.0, 1e4, 2e4, 0.0}};
  s.foundation = {50.0, 20.0};
  ring::StaticOptions st;
  st.loads.gravity = {0.0, -9.81};
  st.steps = 10;
  st.record = {270.0};
  const auto d = lumped::solve_static_detail(s, chain(40), st);
  const double weight = (2.0 * M_PI * s.radius * s.rhoA() + 700.0) * 9.81;
  EXPECT_LT(d.result.displacements[0].uy, -0.05 * s.radius) << "large displacements";
  EXPECT_TRUE(IsClose(d.ground_force[1], weight, 1e-9));
  EXPECT_LT(std::abs(d.ground_force[0]), 1e-9 * weight);
}

/// The hung ring under its weight q = rho A g and a point weight W at the bottom (file
/// comment's series with phi from the pin, 90 deg): the weight has q_r = -q cos phi,
/// q_t = q sin phi, only k = 1 (Q_1 = -2 pi R q); the pin's reaction 2 pi R q + W upward has
/// Q_k = 2 pi R q + W on every mode, W at the bottom Q_k = W (-1)^k. So Q_1 = 0 (equilibrium:
/// k = 1 is the rigid translation, fixed by w(0) = sum a_k = 0), and for k >= 2
/// a_k = (2 pi R q + W (1 + (-1)^k)) / E_k, E_k = pi EI (k^2 - 1)^2 / R^3.
/// Returns {u_x, u_y} at `deg` (0 or 270 deg).
std::array<double, 2> hung(const ring::RingSpec& s, double g, double W, double deg) {
  const double R = s.radius, q = s.rhoA() * g, EI = s.EI();
  std::vector<double> a(kTerms + 1, 0.0);
  double sum = 0.0;
  for (int k = 2; k <= kTerms; ++k) {
    const double k2 = double(k) * k;
    a[k] = (2.0 * M_PI * R * q + W * (1.0 + (k % 2 ? -1.0 : 1.0))) / (M_PI * EI * (k2 - 1) * (k2 - 1) / (R * R * R));
    sum += a[k];
  }
  a[1] = -sum;
  const double phi = (deg - 90.0) * M_PI / 180.0, th = deg * M_PI / 180.0;
  double w = 0.0, v = 0.0;
  for (int k = 1; k <= kTerms; ++k) {
    w += a[k] * std::cos(k * phi);
    v -= a[k] / k * std::sin(k * phi);
  }
  return {w * std::cos(th) - v * std::sin(th), w * std::sin(th) + v * std::cos(th)};
}

// (b) The linear limit against the series: the bottom sinks by (pi^2/4 - 2) q R^4/EI for the
// ring's weight (the series' closed sum: 4 sum over even k of 1/(k^2-1)^2 = pi^2/4 - 2) and
// (pi/4 - 2/pi) W R^3/EI for a point weight (the classical diametral formula); the side point
// moves by the series. g = 1e-5 m/s^2: the geometric nonlinearity ~1e-6 relative. The chain's
// order fitted over n = 40, 80, 160, 320 within 0.1 of 2 (point masses weigh on their hinge).
TEST(LumpedLoads, HungRingConvergesToTheFourierSeries) {
  const double g = 1e-5;
  for (double m0 : {0.0, 2000.0}) {
    ring::RingSpec s = hung_ring();
    if (m0 > 0) s.masses = {{270.0, m0, 0.0}};
    const double W = m0 * g, R = s.radius;
    const auto bottom = hung(s, g, W, 270.0), side = hung(s, g, 0.0, 0.0);
    const double closed = -(M_PI * M_PI / 4.0 - 2.0) * s.rhoA() * g * std::pow(R, 4) / s.EI() -
                          (M_PI / 4.0 - 2.0 / M_PI) * W * R * R * R / s.EI();
    EXPECT_TRUE(IsClose(bottom[1], closed, 1e-12));
    EXPECT_LT(std::abs(bottom[0]), 1e-15 * std::abs(closed));
    ring::StaticOptions st;
    st.loads.gravity = {0.0, -g};
    st.steps = 2;
    st.record = {270.0, 0.0};
    std::vector<double> ns = {40, 80, 160, 320}, e_bottom, e_side_x, e_side_y;
    for (double n : ns) {
      const auto r = lumped::solve_static(s, chain(int(n)), st);
      e_bottom.push_back(ringtest::rel(r.displacements[0].uy, bottom[1]));
      if (m0 == 0.0) {
        e_side_x.push_back(ringtest::rel(r.displacements[1].ux, side[0]));
        e_side_y.push_back(ringtest::rel(r.displacements[1].uy, side[1]));
      }
    }
    const auto samples = ringtest::in_n(ns, e_bottom);
    RecordProperty(m0 > 0 ? "order_with_mass" : "order_ring_weight", std::to_string(ringtest::fit_order(samples).order));
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.1, 1e-3)) << "m0 = " << m0;
    if (m0 == 0.0) {
      EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, e_side_x), 2.0, 0.1)) << "side, x";
      EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, e_side_y), 2.0, 0.1)) << "side, y";
    }
  }
}

/// The hung ring with every term: point masses (one with rotary inertia, beside a rotational
/// spring that its chain convention couples to it), an elastic support and a foundation.
ring::RingSpec hung_ring_with_terms() {
  ring::RingSpec s = hung_ring();
  s.masses = {{270.0, 500.0, 0.0}, {0.0, 200.0, 400.0}};
  s.supports.springs = {{0.0, 0.0, 0.0, 1e5}, {180.0, 2e3, 1e3, 0.0}};
  s.foundation = {20.0, 10.0};
  return s;
}

// A step of gravity (g = 1e-3 m/s^2: u/R ~ 4e-5, nearly linear) on the hung ring with every
// term. From rest, each mode oscillates about the static deflection, u(t) = u_s - sum_j c_j
// cos(w_j t) (the midpoint rule keeps that form with its own frequencies), so the mean over T
// differs from u_s by at most sum_j |c_j| / (w_j T) <= 2 max_t |u - u_s| / (w_1 T) (the factor 2
// for sum |c_j| against the largest swing, which the symmetric lowest mode dominates), w_1 the
// lowest frequency of the same model (lumped::compute_modes). T = 60 s, about 40 periods.
// The energy balance: the midpoint rule conserves T + V - W exactly for quadratic energies and
// constant loads; what remains comes from the parts of the energies beyond quadratic (the
// hinge springs' and the clamp-like rotations' atan2, the point inertia's rotation), a fraction
// ~u/R = 4e-5 of the energy, times the step's error on it: bound 1e-6 of the work (measured
// 6.1e-10; the mean 0.30 of its bound).
TEST(LumpedLoads, GravityStepOscillatesAboutTheStaticsWithItsEnergyBalanced) {
  const ring::RingSpec s = hung_ring_with_terms();
  const double g = 1e-3;
  ring::StaticOptions st;
  st.loads.gravity = {0.0, -g};
  st.steps = 1;
  st.record = {270.0, 0.0};
  const auto stat = lumped::solve_static(s, chain(40), st);
  ring::ResponseOptions r;
  r.loads.gravity = {0.0, -g};
  r.dt = 0.02;
  r.t_end = 60.0;
  r.integrator = ring::ResponseOptions::Integrator::midpoint;
  r.record = {270.0, 0.0};
  const auto h = lumped::respond(s, chain(40), r);
  const double w1 = lumped::compute_modes(s, chain(40), 1).omega.at(0);
  double worst = 0.0;  // |mean - u_s| over its bound
  for (int q = 0; q < 2; ++q)
    for (int c = 0; c < 2; ++c) {
      const auto& u = c ? h.uy[q] : h.ux[q];
      const double us = c ? stat.displacements[q].uy : stat.displacements[q].ux;
      double mean = 0.0, swing = 0.0;
      for (std::size_t k = 1; k < u.size(); ++k) mean += u[k] / double(u.size() - 1);
      for (double x : u) swing = std::max(swing, std::abs(x - us));
      if (std::abs(us) < 1e-3 * std::abs(stat.displacements[0].uy)) continue;  // ~0 by symmetry
      worst = std::max(worst, std::abs(mean - us) / (2.0 * swing / (w1 * r.t_end)));
      EXPECT_LT(std::abs(mean - us), 2.0 * swing / (w1 * r.t_end)) << "point " << q << " component " << c << ": mean "
                                                                    << mean << " static " << us;
      EXPECT_GT(swing, 0.5 * std::abs(us)) << "a step load makes it swing";
    }
  RecordProperty("mean_over_bound", sci(worst));
  double work = 0.0, error = 0.0;
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    work = std::max(work, std::abs(h.work[k]));
    error = std::max(error, std::abs(h.energy_error[k]));
  }
  RecordProperty("gravity_energy_error_over_work", sci(error / work));
  EXPECT_LT(error, 1e-6 * work);
  // The weight's work at the end equals the weight times the drop of the centre of mass: with
  // V + T = W, and W > 0 as the ring sinks.
  EXPECT_GT(h.work.back(), 0.0);
}

// A large response under every load at once (two point loads, follower or central pressure at
// a third of the buckling pressure, gravity) with every term: the work of the pressure and of
// gravity is counted, so the balance T + V - W stays at the midpoint rule's O(dt^2) level on
// non-quadratic energies (nonlinear_test.cpp measures 1e-6 of the work on the paper's scene);
// halving dt must shrink it by about 4 (order 2 fitted over dt = 0.02, 0.01, 0.005 s within
// 0.5; measured 2.00, errors 3.6e-6, 9.1e-7, 2.3e-7 of the work with follower pressure): bound
// 1e-4 of the work, as the one-load test.
TEST(LumpedLoads, ResponseCountsTheWorkOfPressureAndGravity) {
  const ring::RingSpec s = hung_ring_with_terms();
  for (Kind kind : {Kind::follower, Kind::central}) {
    std::vector<double> dts = {0.02, 0.01, 0.005}, err;
    for (double dt : dts) {
      ring::ResponseOptions r;
      r.loads.points = {{0.0, {-1e4, 0.0}}, {180.0, {0.0, 5e3}}};
      r.loads.pressure = {1.0 * s.EI() / std::pow(s.radius, 3), kind};
      r.loads.gravity = {0.0, -9.81};
      r.history.kind = ring::LoadHistory::Kind::ramp;
      r.history.period = 0.5;
      r.dt = dt;
      r.t_end = 2.0;
      r.record = {270.0};
      const auto h = lumped::respond(s, chain(40), r);
      double work = 0.0, error = 0.0;
      for (std::size_t k = 0; k < h.t.size(); ++k) {
        work = std::max(work, std::abs(h.work[k]));
        error = std::max(error, std::abs(h.energy_error[k]));
      }
      EXPECT_LT(error, 1e-4 * work) << ring::to_string(kind) << " dt = " << dt;
      err.push_back(error / work);
    }
    // The order in dt from the first and the last step (two points, as measured).
    const auto samples = ringtest::in_h({dts[0], dts[2]}, {err[0], err[2]});
    RecordProperty("energy_order_" + ring::to_string(kind), std::to_string(ringtest::fit_order(samples).order));
    RecordProperty("energy_error_" + ring::to_string(kind), list(err));
    EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.5)) << list(err);
  }
}

// What has no meaning is std::invalid_argument naming the key, from the checks the driver calls
// before any solver runs (exit 2).
TEST(LumpedLoads, RefusesWhatHasNoMeaning) {
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  const ring::RingSpec s = ringtest::pin_roller_ring();
  ring::StaticOptions st = squeeze(1e3, 0.0, Kind::dead);
  st.loads.points.push_back({5.0, {0.0, 1.0}});  // not a hinge of n = 40
  EXPECT_NE(message([&] { lumped::check_static(s, chain(40), st); }).find("static.loads[2].at"), std::string::npos);
  st.loads.points.back().angle = 180.0;  // the pin
  EXPECT_NE(message([&] { lumped::check_static(s, chain(40), st); }).find("acts at the pin"), std::string::npos);
  ring::StaticOptions nan = squeeze(1e3, std::nan(""), Kind::follower);
  EXPECT_NE(message([&] { lumped::check_static(s, chain(40), nan); }).find("static.pressure"), std::string::npos);
  ring::LumpedOptions frame = chain(40);
  frame.variant = ring::LumpedOptions::Variant::frame;
  // The lumped frame takes statics (the corotational frame) but, its rotations massless, no
  // response.
  EXPECT_NO_THROW(lumped::check_static(s, frame, squeeze(0.0, 1.0, Kind::dead)));
  ring::ResponseOptions response;
  response.loads = squeeze(0.0, 1.0, Kind::dead).loads;
  EXPECT_NE(message([&] { lumped::check_response(s, frame, response); }).find("lumped.variant"), std::string::npos);
  // Turning about the pin is free without a roller or a term against it.
  EXPECT_NE(message([&] { lumped::check_static(ringtest::pinned_ring(), chain(40), squeeze(1e3, 0.0, Kind::dead)); })
                .find("roller"),
            std::string::npos);
  ring::RingSpec off = s;
  off.masses = {{4.0, 1.0, 0.0}};
  EXPECT_NE(message([&] { lumped::check_response(off, chain(40), ring::ResponseOptions{}); }).find("masses[1]"),
            std::string::npos);
  // A clamp and a spring hold the pinned ring without a roller: accepted.
  ring::RingSpec clamped = ringtest::pinned_ring();
  clamped.supports.clamp = 180.0;
  EXPECT_NO_THROW(lumped::check_static(clamped, chain(40), squeeze(1e3, 0.0, Kind::dead)));
}

}  // namespace
