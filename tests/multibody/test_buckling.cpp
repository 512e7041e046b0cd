// Linear buckling of the chain (multibody/buckling.hpp). Oracles: the closed-form critical
// pressures of the thin inextensible ring on a pin and a roller (ring/closed_form.hpp,
// pinned_ring_critical_pressure: Levy 1884, Timoshenko & Gere sec. 7.3-7.4, with the
// supports' rigid motion derived there), the chain's measured order of convergence, and a
// 2 x 2 pencil solved by hand for the shared eigen step (modal/buckling.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "modal/buckling.hpp"
#include "multibody/buckling.hpp"
#include "multibody/modes.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"
#include "ring/closed_form.hpp"
#include "support/convergence.hpp"
#include "support/mirror.hpp"
#include "support/paper.hpp"
#include "support/preload.hpp"
#include "support/bracket.hpp"

namespace {

using Kind = ring::Pressure::Kind;

ring::BucklingOptions pressure(Kind kind, double value = 1.0, int count = 4) {
  ring::BucklingOptions b;
  b.loads.pressure = {value, kind};
  b.count = count;
  return b;
}

std::vector<double> factors(const ring::RingSpec& spec, int n, const ring::BucklingOptions& b) {
  ring::MultibodyOptions o;
  o.n = n;
  return multibody::compute_buckling(spec, o, b).factors;
}

// The chain's lowest factor under each kind of pressure converges to the closed form at
// second order (the chain's O(1/n^2), multibody/README.md); observed orders within 0.15 of
// 2 (Richardson's asymptotic range is reached from n = 40 on for the n = 2 wave), and the
// error at n = 160 below 0.1 % (what O(1/n^2) leaves: ~ (pi/n)^2 / 3).
TEST(MultibodyBuckling, PressureOfEachKindConvergesToTheClosedFormAtSecondOrder) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    const double exact = ring::closed_form::pinned_ring_critical_pressure(spec, kind);
    const std::vector<int> ns{40, 80, 160};
    std::vector<double> err;
    for (int n : ns) err.push_back(std::abs(factors(spec, n, pressure(kind))[0] - exact) / exact);
    SCOPED_TRACE(static_cast<int>(kind));
    EXPECT_LT(err[2], 1e-3);
    const auto samples = ringtest::in_n(ns, err);
    for (std::size_t i = 0; i + 1 < 3; ++i)  // each refinement's two-point order
      EXPECT_TRUE(ringtest::OrderNear(ringtest::subset(samples, {i, i + 1}), 2.0, 0.15));
  }
}

// Follower pressure does no work on a rigid motion: both n = 2 shapes buckle together (a
// double factor to round-off: the chain is symmetric about the diameter through the pin).
// Dead pressure: the shape in phase with the pin needs a translation only and keeps Levy's
// 4 EI/R^3; the odd waves need none of the rotation, n = 3 at 9 EI/R^3 (p_n = n^2 EI/R^3).
TEST(MultibodyBuckling, TheHigherFactorsAreTheOtherWavesOfTheClosedForm) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const double unit = spec.EI() / std::pow(spec.radius, 3);
  const std::vector<double> f = factors(spec, 160, pressure(Kind::follower));
  EXPECT_NEAR(f[1] / f[0], 1.0, 1e-9);
  EXPECT_NEAR(f[2] / unit, 8.0, 8.0 * 2e-3);  // n = 3: (n^2 - 1), the same O(1/n^2) error as above times n^2/4
  const std::vector<double> d = factors(spec, 160, pressure(Kind::dead));
  EXPECT_NEAR(d[1] / unit, 4.0, 4.0 * 1e-3);
  EXPECT_NEAR(d[2] / unit, 9.0, 9.0 * 2e-3);
  EXPECT_NEAR(d[3] / d[2], 1.0, 1e-9);
}

// Statically determinate supports leave the follower factor where they are put, and the
// factors are inverse to the load: the loads enter linearly.
TEST(MultibodyBuckling, FactorsScaleInverselyWithTheLoadAndIgnoreWhereTheSupportsAre) {
  ring::RingSpec turned = ringtest::pin_roller_ring();  // pin 180, roller 0
  const double a = factors(ringtest::pin_270_roller_90(), 80, pressure(Kind::follower))[0];
  EXPECT_NEAR(factors(turned, 80, pressure(Kind::follower))[0] / a, 1.0, 1e-9);
  EXPECT_NEAR(factors(ringtest::pin_270_roller_90(), 80, pressure(Kind::follower, 250.0))[0] * 250.0 / a, 1.0, 1e-12);
}

TEST(MultibodyBuckling, RefusesWhatItCannotDo) {
  ring::MultibodyOptions sparse;
  sparse.method = ring::MultibodyOptions::Method::sparse;
  EXPECT_THROW(multibody::check_buckling(ringtest::pin_270_roller_90(), sparse, pressure(Kind::follower)), std::invalid_argument);
  // A pinned ring without a roller turns freely under a pressure.
  EXPECT_THROW(multibody::check_buckling(ringtest::pinned_ring(270.0), {}, pressure(Kind::follower)),
               std::invalid_argument);
  ring::RingSpec thick = ringtest::pin_270_roller_90();
  thick.theory = ring::Theory::timoshenko;  // buckling takes it, on the dense path only
  EXPECT_THROW(multibody::check_buckling(thick, sparse, pressure(Kind::follower)), std::invalid_argument);
}

// The Timoshenko chain's buckling under follower pressure (its statics' condensed stiffness,
// multibody/sections.hpp). Oracle, derived here for the inextensible ring with shear: in the
// wave k the centroid line turns by beta = (1 - k^2) sin(k theta) / R (v = sin k theta,
// w = -k cos k theta); the section turns by psi = Psi sin(k theta), the shear angle is
// psi - beta, and minimizing EI/2 (psi'/R)^2 + kGA/2 (psi - beta)^2 over Psi leaves the
// Euler ring's bending energy divided by 1 + k^2 EI / (kGA R^2). The pressure's work acts on
// the centroid line alone, so p_cr = (k^2 - 1) EI/R^3 / (1 + k^2 EI / (kGA R^2)), k = 2, the
// Euler ring's 3 EI/R^3 (Levy 1884; Timoshenko & Gere sec. 7.4) reduced by the shear
// flexibility (0.9608 on this ring, depth/R = 0.2). The chain converges to it at order 2
// (the Euler chain's, above): 0.79, 0.20, 0.049 % at n = 40, 80, 160 measured. With the
// shear stiffness 1e6 times larger the chain is the Euler-Bernoulli chain to 1e-6.
TEST(MultibodyBuckling, TheTimoshenkoChainConvergesToTheShearReducedCriticalPressure) {
  ring::RingSpec thick = ringtest::pin_270_roller_90();
  thick.radius = 0.1;
  thick.theory = ring::Theory::timoshenko;
  thick.section.shape = ring::Section::Shape::rectangle;
  thick.section.width = 0.01;
  thick.section.height = 0.02;
  const double EI = thick.EI(), R = thick.radius, shear = EI / (thick.kGA() * R * R);
  const double exact = 3.0 * EI / std::pow(R, 3) / (1.0 + 4.0 * shear);
  const std::vector<int> ns{40, 80, 160};
  std::vector<double> err;
  for (int n : ns) err.push_back(std::abs(factors(thick, n, pressure(Kind::follower, 1.0, 1))[0] / exact - 1.0));
  EXPECT_LT(err[2], 1e-3);
  const auto samples = ringtest::in_n(ns, err);
  for (std::size_t i = 0; i + 1 < 3; ++i)  // each refinement's two-point order
    EXPECT_TRUE(ringtest::OrderNear(ringtest::subset(samples, {i, i + 1}), 2.0, 0.15));
  // The shear-stiff limit: the Euler-Bernoulli chain's factor, to the size of EI / (kGA R^2).
  ring::RingSpec stiff = thick;
  stiff.shear_coefficient = 1e6 * thick.kappa();
  ring::RingSpec euler = thick;
  euler.theory = ring::Theory::euler_bernoulli;
  const double fe = factors(euler, 40, pressure(Kind::follower, 1.0, 1))[0];
  EXPECT_NEAR(factors(stiff, 40, pressure(Kind::follower, 1.0, 1))[0] / fe, 1.0, 4.0 * shear * 1e-6 * 10);
}

// (K_0 + lambda K_1) x = 0 with K_0 = diag(2, 1), K_1 = diag(-1, 0.5): lambda = 2 (and
// -2, which buckles under the load reversed); asking for two positive factors is refused.
TEST(ModalBuckling, TheLowestPositiveFactorsOfATwoByTwoPencil) {
  Eigen::MatrixXd K0(2, 2), K1(2, 2);
  K0 << 2.0, 0.0, 0.0, 1.0;
  K1 << -1.0, 0.0, 0.0, 0.5;
  const modal::CriticalFactors c = modal::critical_factors(K0, K1, 1, "test");
  EXPECT_NEAR(c.factors[0], 2.0, 1e-14);
  EXPECT_NEAR(std::abs(c.vectors(1, 0)), 0.0, 1e-14);
  EXPECT_THROW(modal::critical_factors(K0, K1, 2, "test"), std::invalid_argument);
  Eigen::MatrixXd singular = K0;
  singular(1, 1) = 0.0;
  EXPECT_THROW(modal::critical_factors(singular, K1, 1, "test"), std::invalid_argument);
}

}  // namespace

namespace {

// The statics past the critical pressure: the chain's path stays circular (a uniform
// pressure does no work on the inextensible chain) and turns unstable where linear
// buckling said, which the continuation driver reports as a bifurcation (exit 3 in the
// command) instead of a circular "equilibrium": for each kind, lambda_1 / 1.5 lies in the
// bracket.
TEST(MultibodyBuckling, StaticsPastTheCriticalPressureEndAtTheBifurcation) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  ring::MultibodyOptions o;
  o.n = 40;
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    const double critical = multibody::compute_buckling(spec, o, pressure(kind)).factors[0];
    ring::StaticOptions st;
    st.loads.pressure = {1.5 * critical, kind};
    try {
      multibody::solve_static(spec, o, st);
      ADD_FAILURE() << "no bifurcation reported";
    } catch (const ring::NumericalError& e) {
      const std::string m = e.what();
      const auto bracket = ringtest::bifurcation_bracket(m);
      ASSERT_TRUE(bracket) << m;
      const auto [low, high] = *bracket;
      EXPECT_LE(low, 1.0 / 1.5 + 1e-9) << m;
      EXPECT_GE(high, 1.0 / 1.5 - 1e-9) << m;
      // Near the branch point Newton's 1e-12 tolerance on the angles fails as the tangent
      // turns singular (measured: within 1e-5 of it at n = 40), which bounds the bracket.
      EXPECT_LT(high - low, 1e-4) << m;
    }
  }
}

}  // namespace

namespace {

ring::StaticOptions collapse(double squeeze) {
  ring::StaticOptions st;
  st.loads.pressure = {6.0 * ringtest::pin_270_roller_90().EI() / std::pow(ringtest::pin_270_roller_90().radius, 3), Kind::follower};
  st.loads.points = {{0.0, {-squeeze, 0.0}}, {180.0, {squeeze, 0.0}}};
  st.path = true;
  return st;
}

// The path to contact (static.path): a ring under a follower pressure of 6 EI/R^3 with a
// small squeeze that selects the buckled shape's orientation (an imperfection: without it
// the pair of n = 2 directions is lost at once and the shape may turn freely on a pin and
// a roller). The path passes the buckling load and ends, as a result, where opposite sides
// come within the section depth: the located touch's clearance is zero to the bisection's
// 1e-6 of a step, and the contact load converges at the chain's order 2 (fitted over
// n = 40, 80, 160: within 0.3 of 2). Its value, p R^3 / EI = 5.21 for a squeeze of 1e-3 p R
// at a depth of R / 83, lies below the 5.247 of the centrelines' touch of the perfect thin
// ring (Flaherty, Keller & Rubinow 1972), as the touch at a clearance of one depth must.
TEST(MultibodyBuckling, ThePathToContactEndsAsAResultAndConvergesAtSecondOrder) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  std::vector<double> end;
  for (int n : {40, 80, 160}) {
    ring::MultibodyOptions o;
    o.n = n;
    o.method = ring::MultibodyOptions::Method::dense;
    const ring::StaticResult r = multibody::solve_static(spec, o, collapse(100.0));
    ASSERT_EQ(r.end.rfind("contact", 0), 0u) << r.end;
    EXPECT_NE(r.end.find("0.12"), std::string::npos) << r.end;  // the located touch: one depth apart
    ASSERT_GT(r.path.size(), 5u);
    EXPECT_EQ(r.path.front().load_factor, 0.0);
    EXPECT_DOUBLE_EQ(r.path.back().load_factor, r.end_load);
    EXPECT_GT(r.path.back().ovalisation, 1.5);  // opposite sides nearly meet: about 2 - 2 depth / R
    end.push_back(r.end_load * 6.0);
  }
  // The two-point order of the successive differences (of one sign: a monotone approach).
  EXPECT_GT((end[1] - end[0]) * (end[2] - end[1]), 0.0) << end[0] << " " << end[1] << " " << end[2];
  EXPECT_TRUE(ringtest::OrderNear(
      ringtest::in_n(std::vector<int>{40, 80}, {std::abs(end[1] - end[0]), std::abs(end[2] - end[1])}), 2.0, 0.3))
      << end[0] << " " << end[1] << " " << end[2];
  const double limit = end[2] + (end[2] - end[1]) / 3.0;  // Richardson, order 2
  EXPECT_GT(limit, 3.0);
  EXPECT_LT(limit, 5.247);
}

// A simple bifurcation (dead pressure: the out-of-phase shape alone) is passed by branch
// switching: the path leaves at the critical load the chain's linear buckling gives (to
// the bracket, 1e-4) and goes on to the touch.
TEST(MultibodyBuckling, ThePathSwitchesOntoTheBranchAtASimpleBifurcation) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  ring::MultibodyOptions o;
  o.n = 40;
  ring::StaticOptions st;
  st.loads.pressure = {1.5 * multibody::compute_buckling(spec, o, pressure(Kind::dead)).factors[0], Kind::dead};
  st.path = true;
  st.record = {0.0, 180.0};
  const ring::StaticResult r = multibody::solve_static(spec, o, st);
  ASSERT_EQ(r.branch_points.size(), 1u) << r.end;
  EXPECT_NEAR(r.branch_points[0], 1.0 / 1.5, 1e-4);
  EXPECT_EQ(r.end.rfind("contact", 0), 0u) << r.end;
  // From the other side of the pitchfork (static.branch = "negative"; the ring and the load
  // are symmetric about the y axis): the same path mirrored, the same touch.
  // The touch is bisected to 1e-6 of the arc step on either side, each with its own
  // rounding (measured: 6e-9 and 9e-9 of the load in the two chains, 3e-10 and 4e-10 of |u|).
  ringtest::expect_the_other_side_mirrors(
      r, st, [&](const ring::StaticOptions& s) { return multibody::solve_static(spec, o, s); }, 1e-7, 1e-8);
}

}  // namespace

namespace {

// Frequencies under load (modes.preload = "static"): about the equilibrium of a follower
// pressure f lambda_1 (the circle: the inextensible chain does not move) the tangent is
// K_0 + f lambda_1 K_1 (multibody/buckling.hpp), so the lowest omega^2 falls from the
// unloaded chain's (to the eigensolvers' 1e-10) to zero at the critical pressure, linearly
// there, and the line through f = 0.5 and 0.75 meets zero within 2 % of f = 1 (the
// curvature the supports' rigid motion adds, through the mass, to the n = 2 pair).
TEST(MultibodyBuckling, FrequenciesUnderLoadFallToZeroAtTheCriticalPressure) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  ring::MultibodyOptions o;
  o.n = 40;
  o.method = ring::MultibodyOptions::Method::dense;
  const double critical = multibody::compute_buckling(spec, o, pressure(Kind::follower)).factors[0];
  auto omega2 = [&](double f) {
    ring::StaticOptions st;
    st.loads.pressure = {f * critical, Kind::follower};
    const double w = multibody::compute_modes_under_load(spec, o, st, 2).omega[0];
    return w * w;
  };
  const double unloaded = std::pow(multibody::compute_modes(spec, o, 2).omega[0], 2);
  EXPECT_NEAR(omega2(1e-9) / unloaded, 1.0, 1e-8);
  // Near the zero the fall is linear: omega^2 at 0.999 is a tenth of that at 0.99 (to the
  // curvature over 1 %: measured 0.0996).
  EXPECT_LT(omega2(0.999) / unloaded, 2e-3);
  EXPECT_NEAR(omega2(0.999) / omega2(0.99), 0.1, 0.002);
  const double a = omega2(0.5), b = omega2(0.75);
  EXPECT_LT(b, a);
  const double zero = 0.75 + b / (a - b) * 0.25;  // where the line through the two meets 0
  EXPECT_NEAR(zero, 1.0, 0.02) << a / unloaded << " " << b / unloaded;
}


// Frequencies under load against the closed form: the free ring on a foundation under a
// follower pressure (support/preload.hpp). The chain's error at n = 80 is its O(1/n^2)
// discretization (measured: 7.7e-4 for the rotation held by k_t, the foundation lumped at
// the hinges; 2.9e-4 for the ovals; 1.85e-3 in the slope of their omega^2).
TEST(MultibodyBuckling, FrequenciesUnderLoadMeetTheClosedFormOfTheRingOnAFoundation) {
  ring::MultibodyOptions o;
  o.n = 80;
  o.method = ring::MultibodyOptions::Method::dense;
  o.rotary_inertia = false;
  ringtest::expect_the_closed_form_under_pressure(
      [&](const ring::RingSpec& s, const ring::StaticOptions& st, int count) {
        return multibody::compute_modes_under_load(s, o, st, count);
      },
      1e-3, 3e-3);
}

}  // namespace
