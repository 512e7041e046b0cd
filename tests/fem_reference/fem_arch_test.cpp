// The FE beam on an arch (ring.arc, issue 48): the curved elements from arc.from to arc.to
// without the ring's periodic wrap, the ends taking the supports.
//
// Oracles (tests/support/arch.hpp, written from the mechanics without any solver's code):
//  - natural frequencies of pinned-pinned and clamped-pinned arches by the exact transfer
//    matrix of the curved Euler-Bernoulli beam (extensible and inextensible; ~1e-12);
//  - DaDeppo & Schmidt's deep arch (215 deg, clamped-pinned, apex load) by shooting on the
//    inextensible elastica: limit P R^2/EI = 8.97308997;
//  - the rigid-mode count of spec.rigid_modes() (free-free 3, pinned-free 1, pinned-pinned 0);
//  - fitted orders (support/convergence.hpp): the form is consistent, eigenvalues converge
//    like h^(2(p-1)) (fem_reference/README.md), as on the ring.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "fem_reference/modes.hpp"
#include "fem_reference/nonlinear.hpp"
#include "fem_reference/buckling.hpp"
#include "fem_reference/checks.hpp"
#include "ring/errors.hpp"
#include "support/arch.hpp"
#include "support/paper.hpp"
#include "support/convergence.hpp"
#include "support/refusal.hpp"

namespace {

constexpr double kDeg = M_PI / 180.0;

/// The paper's section on an arch of radius R = 10 m from `from` to `to` (degrees).
ring::RingSpec arch(double from, double to) {
  ring::RingSpec s = ringtest::free_ring();
  s.arc = ring::Arc{from, to};
  return s;
}

/// Pins both ends; `clamp_from`: the `from` end clamped.
ring::RingSpec pinned_arch(double from, double to, bool clamp_from = false) {
  ring::RingSpec s = arch(from, to);
  s.supports.pin = from;
  s.supports.pins = {to};
  if (clamp_from) s.supports.clamp = from;
  return s;
}

/// The oracle's arch of the same spec: theta from 0 to the span.
archtest::Arch oracle(const ring::RingSpec& s, archtest::End start, archtest::End end, bool extensible) {
  archtest::Arch a;
  a.R = s.radius;
  a.alpha = s.arc->span() * kDeg;
  a.EI = s.EI();
  a.EA = extensible ? s.EA() : std::numeric_limits<double>::infinity();
  a.rhoA = s.rhoA();
  a.start = start;
  a.end = end;
  return a;
}

ring::FemOptions fe_options(int elements, int degree, bool extensible = true) {
  ring::FemOptions o;
  o.elements = elements;
  o.degree = degree;
  o.extensible = extensible;
  return o;
}

double worst_error(const std::vector<double>& fe, const std::vector<double>& exact) {
  double e = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) e = std::max(e, std::abs(fe.at(i) / exact[i] - 1.0));
  return e;
}

std::string digits(double x) {
  std::ostringstream o;
  o << std::setprecision(4) << x;
  return o.str();
}

}  // namespace

// Pinned-pinned arches of three openings, extensible: the five lowest frequencies against
// the transfer matrix. 16 elements of degree 8 (as fine as the reference's first steps):
// within 1e-9 (the oracle's ~1e-12 and the refined eigen-solve's round-off ~1e-12 below).
TEST(FemArch, PinnedArchesMeetTheTransferMatrix) {
  for (double span : {60.0, 180.0, 270.0}) {
    const ring::RingSpec s = pinned_arch(30.0, 30.0 + span);
    ASSERT_EQ(s.rigid_modes(), 0);
    const auto exact = archtest::arch_omegas(oracle(s, archtest::End::pinned, archtest::End::pinned, true), 5);
    const ring::ModalResult r = fem::compute_modes(s, fe_options(16, 8), 5);
    EXPECT_EQ(r.rigid_modes, 0);
    const double e = worst_error(r.omega, exact);
    RecordProperty("pinned_error_" + std::to_string(static_cast<int>(span)), digits(e));
    EXPECT_LT(e, 1e-9) << "span " << span;
  }
}

// Clamped-pinned, extensible and inextensible (fem.extensible = false: Richardson in 1/beta
// from EA = beta EI/R^2 and 2 beta, beta = 1e6, modes.hpp), against the transfer matrix with
// EA and with EA = infinity. Measured: extensible 9.8e-14; inextensible 2.3e-9, which is the
// extrapolation's own O(beta^-2) remainder: the transfer matrix extrapolated the same way
// from beta and 2 beta is 2.255e-9 off the exact inextensible arch too, and the FE meets
// that extrapolated value to 1e-12.
TEST(FemArch, ClampedPinnedArchMeetsTheTransferMatrix) {
  const ring::RingSpec s = pinned_arch(-17.5, 197.5, true);
  const archtest::End clamped = archtest::End::clamped, pinned = archtest::End::pinned;
  const auto extensible = archtest::arch_omegas(oracle(s, clamped, pinned, true), 5);
  const double e = worst_error(fem::compute_modes(s, fe_options(16, 8), 5).omega, extensible);
  RecordProperty("clamped_pinned_error_extensible", digits(e));
  EXPECT_LT(e, 1e-9);
  const auto inextensible = archtest::arch_omegas(oracle(s, clamped, pinned, false), 5);
  archtest::Arch a = oracle(s, clamped, pinned, true);
  const double beta = 1e6 * s.EI() / (s.radius * s.radius);
  a.EA = beta;
  const auto w1 = archtest::arch_omegas(a, 5);
  a.EA = 2.0 * beta;
  const auto w2 = archtest::arch_omegas(a, 5);
  std::vector<double> extrapolated;
  for (int i = 0; i < 5; ++i) extrapolated.push_back(std::sqrt(2.0 * w2[i] * w2[i] - w1[i] * w1[i]));
  const std::vector<double> fe = fem::compute_modes(s, fe_options(16, 8, false), 5).omega;
  const double to_limit = worst_error(fe, inextensible), to_extrapolated = worst_error(fe, extrapolated);
  RecordProperty("clamped_pinned_error_inextensible", digits(to_limit));
  RecordProperty("clamped_pinned_error_inextensible_vs_extrapolated_oracle", digits(to_extrapolated));
  EXPECT_LT(to_extrapolated, 1e-9);
  // The O(beta^-2) remainder of the oracle's own extrapolation (2.3e-9) with a margin.
  EXPECT_LT(to_limit, 1e-8);
}

// The order in h: cubic elements (p = 3) converge like h^(2(p-1)) = h^4 on the arch as on
// the ring (a consistent form: the ends add no inconsistency). 4, 8, 16, 32 elements.
TEST(FemArch, FrequenciesConvergeAtTheRingsOrder) {
  const ring::RingSpec s = pinned_arch(-17.5, 197.5, true);
  const auto exact = archtest::arch_omegas(oracle(s, archtest::End::clamped, archtest::End::pinned, true), 3);
  std::vector<int> n{8, 16, 32, 64};
  std::vector<double> e;
  for (int k : n) e.push_back(worst_error(fem::compute_modes(s, fe_options(k, 3), 3).omega, exact));
  const ringtest::Order p = ringtest::fit_order(ringtest::in_n(n, e));
  RecordProperty("order_p3", digits(p.order));
  RecordProperty("error_64x3", digits(e.back()));
  // Expected 4 (2(p - 1)); 0.3: the pre-asymptotic spread of the ring's measured fits.
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(n, e), 4.0, 0.3));
}

// Rigid modes by the supports (spec.rigid_modes()): free-free 3, one pin 1; the FE finds
// that many (near-)zero pairs below the elastic ones, and the elastic frequencies of the
// free-pinned arch meet the transfer matrix.
TEST(FemArch, RigidModesFollowTheSupports) {
  ring::RingSpec free = arch(0.0, 150.0);
  ASSERT_EQ(free.rigid_modes(), 3);
  const auto exact_free = archtest::arch_omegas(oracle(free, archtest::End::free, archtest::End::free, true), 4);
  const ring::ModalResult rf = fem::compute_modes(free, fe_options(16, 8), 4);
  EXPECT_EQ(rf.rigid_modes, 3);
  EXPECT_LT(worst_error(rf.omega, exact_free), 1e-8);
  ring::RingSpec one = arch(0.0, 150.0);
  one.supports.pin = 150.0;
  ASSERT_EQ(one.rigid_modes(), 1);
  const auto exact_one = archtest::arch_omegas(oracle(one, archtest::End::free, archtest::End::pinned, true), 4);
  const ring::ModalResult r1 = fem::compute_modes(one, fe_options(16, 8), 4);
  EXPECT_EQ(r1.rigid_modes, 1);
  EXPECT_LT(worst_error(r1.omega, exact_one), 1e-8);
}

// fem.reference on an arch: the p/h refinement converges and its estimate bounds the error
// against the transfer matrix.
TEST(FemArch, ReferenceOnAnArch) {
  const ring::RingSpec s = pinned_arch(-17.5, 197.5, true);
  const auto exact = archtest::arch_omegas(oracle(s, archtest::End::clamped, archtest::End::pinned, true), 4);
  ring::FemOptions o = fe_options(8, 3);
  o.reference = true;
  o.tolerance = 1e-9;
  const ring::ModalResult r = fem::compute_modes(s, o, 4);
  const double e = worst_error(r.omega, exact);
  RecordProperty("reference_error", digits(e));
  RecordProperty("reference_estimate", digits(r.error_estimate));
  EXPECT_LT(e, 1e-9);
  // The shapes: zero off the arch, nonzero on it.
  const auto& w = r.shapes.at(0).radial;
  double off = 0.0, on = 0.0;
  for (int st = 0; st < static_cast<int>(w.size()); ++st) {
    const double a = ring::station_angle(st);
    (s.arc->contains(a) ? on : off) = std::max(s.arc->contains(a) ? on : off, std::abs(w[st]));
  }
  EXPECT_EQ(off, 0.0);
  EXPECT_GT(on, 0.1);
}

namespace {

/// DaDeppo & Schmidt's deep arch (archtest::detail::DeepArch): 215 deg about the apex at
/// 90 deg, clamped at -17.5 deg (arc.from), pinned at 197.5 deg, an apex load P = p EI/R^2
/// straight down; `diameter` sets the slenderness (R = 10 m).
ring::RingSpec deep_arch(double diameter = 0.12) {
  ring::RingSpec s = pinned_arch(-17.5, 197.5, true);
  s.section.diameter = diameter;
  return s;
}

ring::StaticOptions apex_load(const ring::RingSpec& s, double p) {
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -p * s.EI() / (s.radius * s.radius)}}};
  st.record = {90.0};
  st.steps = 20;
  return st;
}

/// The limit load P R^2/EI of one discretization (trace_static's located maximum of the
/// load factor under an apex load of 10 EI/R^2, beyond the limit), the path cut off 40 arc
/// steps after it.
double fe_limit(const ring::RingSpec& s, const ring::FemOptions& o) {
  fem::ContinuationOptions c;
  c.max_arc_steps = 40;
  const fem::StaticPath path = fem::trace_static(s, o, apex_load(s, 10.0), c);
  EXPECT_TRUE(std::isfinite(path.limit_load_factor)) << path.failure;
  return 10.0 * path.limit_load_factor;
}

}  // namespace

// The deep arch's limit load, inextensible (fem.extensible = false: Richardson in 1/beta of
// the limit, nonlinear.hpp) against the elastica's 8.97308997 (archtest::deep_arch_limit, 2e-10).
// p-convergence on 20 elements, measured: 7.3e-3 (p = 3), 1.8e-4 (4), 9.1e-7 (5), 3.1e-8 (6);
// the test runs p = 4 and 6 (6 s); 1e-7 bounds p = 6 (its change from p = 5 is 8.8e-7, the
// contraction ~30 per degree).
TEST(FemArch, DeepArchLimitMeetsTheElastica) {
  const double exact = archtest::deep_arch_limit().load;
  const ring::RingSpec s = deep_arch();
  std::vector<double> e;
  for (int p : {4, 6}) {
    e.push_back(std::abs(fe_limit(s, fe_options(20, p, false)) / exact - 1.0));
    RecordProperty("deep_arch_limit_error_20x" + std::to_string(p), digits(e.back()));
  }
  EXPECT_LT(e.front(), 1e-3);
  EXPECT_LT(e.back(), 1e-7);
}

// The extensible beam's limit against the inextensible elastica's, three slendernesses
// R / r = 333, 167, 83 (d = 0.12, 0.24, 0.48 m on R = 10 m): the difference is the axial
// strain's, O((r/R)^2) (the membrane compliance EI / (EA R^2) = (r/R)^2 enters the energy
// linearly), so its fitted order in r/R is 2.
TEST(FemArch, ExtensibleLimitDiffersLikeTheSlendernessSquared) {
  const double exact = archtest::deep_arch_limit().load;
  std::vector<double> h, e;
  for (double d : {0.12, 0.24, 0.48}) {
    const ring::RingSpec s = deep_arch(d);
    const double limit = fe_limit(s, fe_options(20, 6, true));
    h.push_back(1.0 / s.slenderness());
    e.push_back(std::abs(limit / exact - 1.0));
    RecordProperty("extensible_limit_d" + std::to_string(static_cast<int>(d * 100)), digits(limit));
    RecordProperty("extensible_difference_d" + std::to_string(static_cast<int>(d * 100)), digits(e.back()));
  }
  // Measured: 1.41e-4, 5.63e-4, 2.24e-3 (P_ext = P_elastica (1 - 15.6 (r/R)^2)), order 1.996.
  EXPECT_LT(e.front(), 2e-4);
  const ringtest::Samples samples = ringtest::in_h(h, e);
  RecordProperty("slenderness_order", digits(ringtest::fit_order(samples).order));
  EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.1));
}

// static.path = true through the limit point (paths::follow with branch switching): the path
// is reported, its largest load factor is the located limit, the apex goes on down past it.
TEST(FemArch, DeepArchPathThroughTheLimit) {
  const ring::RingSpec s = deep_arch();
  ring::StaticOptions st = apex_load(s, 10.0);
  st.path = true;
  fem::ContinuationOptions c;
  c.max_arc_steps = 40;
  const fem::StaticPath path = fem::trace_static(s, fe_options(20, 4), st, c);
  ASSERT_TRUE(std::isfinite(path.limit_load_factor)) << path.failure;
  double top = 0.0;
  std::size_t at_top = 0;
  for (std::size_t k = 0; k < path.points.size(); ++k)
    if (path.points[k].load_factor > top) top = path.points[at_top = k].load_factor;
  EXPECT_LE(top, path.limit_load_factor + 1e-12);
  ASSERT_LT(at_top + 2, path.points.size());
  EXPECT_LT(path.points.back().load_factor, path.limit_load_factor);
  EXPECT_LT(path.points.back().displacement[1], path.points[at_top].displacement[1]);
}

// The apex displacement on the rising branch under P R^2/EI = 8 (inextensible) against the
// elastica's (archtest::deep_arch_under, O(h^4) shooting, steps = 2000: ~1e-10).
TEST(FemArch, DeepArchApexMeetsTheElastica) {
  const archtest::DeepArchPoint exact = archtest::deep_arch_under(8.0);
  const ring::RingSpec s = deep_arch();
  for (bool extensible : {false, true}) {
    const ring::StaticResult r = fem::solve_static(s, fe_options(20, 6, extensible), apex_load(s, 8.0));
    ASSERT_EQ(r.displacements.size(), 1u);
    const double dx = r.displacements[0].ux / s.radius, dy = r.displacements[0].uy / s.radius;
    const double e = std::hypot(dx - exact.apex_dx, dy - exact.apex_dy) / std::hypot(exact.apex_dx, exact.apex_dy);
    RecordProperty(std::string("apex_error_") + (extensible ? "extensible" : "inextensible"), digits(e));
    EXPECT_LT(e, extensible ? 1e-3 : 1e-6);
  }
}

// Linear buckling of a pinned-pinned arch under uniform follower pressure against Timoshenko
// & Gere (sec. 7.5; archtest::pinned_follower_pressure): q R^3/EI = pi^2/alpha^2 - 1, alpha
// half the opening, for the inextensible arch (fem.extensible = false: the factors
// extrapolated in 1/beta, buckling.hpp). Openings 60, 120, 180 deg, 16 elements of degree 6:
// measured 1.4e-8, 3.1e-9, 9.4e-11 (the shallowest arch the farthest: the extrapolation's
// O(beta^-2), as in the modes); 1e-6 leaves a margin of 70.
TEST(FemArch, PinnedArchBucklesUnderFollowerPressureAsTimoshenkoAndGere) {
  for (double span : {60.0, 120.0, 180.0}) {
    const ring::RingSpec s = pinned_arch(90.0 - span / 2, 90.0 + span / 2);
    ring::BucklingOptions b;
    b.loads.pressure.value = s.EI() / std::pow(s.radius, 3);
    b.loads.pressure.kind = ring::Pressure::Kind::follower;
    b.count = 1;
    const double exact = archtest::pinned_follower_pressure(span / 2 * kDeg);
    const ring::BucklingResult r = fem::compute_buckling(s, fe_options(16, 6, false), b);
    const double e = std::abs(r.factors.at(0) / exact - 1.0);
    RecordProperty("follower_buckling_error_" + std::to_string(static_cast<int>(span)), digits(e));
    EXPECT_LT(e, 1e-6) << "span " << span << ": " << r.factors.at(0) << " against " << exact;
  }
}

// A follower pressure on an arch with an end that can move is refused by ring.arc: its
// potential holds only where neither end moves (beam_potential.hpp).
TEST(FemArch, FollowerPressureNeedsBothEndsHeld) {
  ring::RingSpec s = arch(0.0, 120.0);
  s.supports.pin = 0.0;
  s.supports.clamp = 0.0;
  ring::BucklingOptions b;
  b.loads.pressure.value = 1e3;
  b.count = 1;
  EXPECT_EQ(ringtest::refused_key([&] { fem::check_buckling(s, fe_options(16, 4), b); }), "ring.arc");
  b.loads.pressure.kind = ring::Pressure::Kind::dead;
  EXPECT_EQ(ringtest::refused_key([&] { fem::check_buckling(s, fe_options(16, 4), b); }), "");
}

// What the FE beam does not take on an arch is refused by the key ring.arc (exit 2): the
// Timoshenko model and the Reissner beam, the polygon, the plastic statics.
TEST(FemArch, RefusesWhatItDoesNotTakeByTheKey) {
  ring::RingSpec s = pinned_arch(0.0, 120.0);
  s.theory = ring::Theory::timoshenko;
  EXPECT_EQ(ringtest::refused_key([&] { fem::check_modes(s, fe_options(16, 4)); }), "ring.arc");
  s.theory = ring::Theory::euler_bernoulli;
  ring::FemOptions polygon = fe_options(16, 4);
  polygon.geometry = ring::FemOptions::Geometry::polygon;
  EXPECT_EQ(ringtest::refused_key([&] { fem::check_modes(s, polygon); }), "ring.arc");
  s.plastic = ring::Plastic{};
  s.plastic->moment = 1e4;
  ring::StaticOptions st;
  st.loads.points = {{60.0, {0.0, -1e3}}};
  EXPECT_EQ(ringtest::refused_key([&] { fem::check_static(s, fe_options(16, 4), st); }), "ring.arc");
}

// The forced response on an arch: the deep arch under an apex load ramped to P R^2/EI = 8
// over ten periods of its lowest mode, then held, with mass-proportional Rayleigh damping
// (critical for that mode): the apex settles on the elastica's equilibrium
// (archtest::deep_arch_under; the extensible beam lies 3.6e-5 from it, DeepArchApexMeetsTheElastica).
// And the energy balance T + V + D - W stays at the Newton tolerance's level.
TEST(FemArch, DeepArchResponseSettlesOnTheElastica) {
  const ring::RingSpec s = deep_arch();
  archtest::Arch a = oracle(s, archtest::End::clamped, archtest::End::pinned, true);
  const double omega = archtest::arch_omegas(a, 1).at(0), period = 2.0 * M_PI / omega;
  ring::ResponseOptions rs;
  rs.loads = apex_load(s, 8.0).loads;
  rs.history.kind = ring::LoadHistory::Kind::ramp;
  rs.history.period = 10.0 * period;
  rs.dt = period / 40.0;
  rs.t_end = 20.0 * period;
  rs.rayleigh_mass = 2.0 * omega;
  rs.record = {90.0};
  const ring::TimeHistory h = fem::respond(s, fe_options(20, 4), rs);
  const archtest::DeepArchPoint exact = archtest::deep_arch_under(8.0);
  const double dx = h.ux.at(0).back() / s.radius, dy = h.uy.at(0).back() / s.radius;
  const double e = std::hypot(dx - exact.apex_dx, dy - exact.apex_dy) / std::hypot(exact.apex_dx, exact.apex_dy);
  RecordProperty("response_apex_error", digits(e));
  EXPECT_LT(e, 1e-3);
}

// The VTU output of an arch's modes: the n cells as an open curve (ring_vtu.cpp), written
// with each mode's Cartesian displacement.
TEST(FemArch, WritesTheModesOfAnArchToVtu) {
  const ring::RingSpec s = pinned_arch(-17.5, 197.5, true);
  char dir[] = "/tmp/fem-arch-vtu-XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string file = fem::write_vtu(s, fe_options(8, 3), 2, dir);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("<VTKFile"), std::string::npos);
  EXPECT_NE(text.str().find("displacement_1_omega_"), std::string::npos);
}
