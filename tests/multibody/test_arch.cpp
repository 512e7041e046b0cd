// The chain on an arch (ring.arc; multibody/chain.hpp, "The arch"): the open chain of n
// segments from `from` to `to`, its ends pinned or clamped.
//
// Oracles:
// - linear modes: the inextensible circular arch's frequencies by its exact transfer matrix
//   (tests/support/arch.hpp, archtest::arch_omegas, no shared code), for pinned-pinned and
//   clamped-pinned arches; the chain converges to them at order 2 in 1/n (fitted by
//   tests/support/convergence.hpp);
// - rigid modes: RingSpec::rigid_modes() (an arch with one pin keeps the rotation about it);
// - nonlinear statics: DaDeppo & Schmidt's deep arch (1975: 215 degrees, clamped at one end,
//   pinned at the other, a point load at the apex), limit load P R^2 / EI = 8.97 published,
//   8.97308997 by shooting on the inextensible elastica (archtest::deep_arch_limit), at order
//   2 in 1/n;
// - response: the chain's own linear modal superposition with the same integrator
//   (modal_superposition.hpp), the deviation falling with the load.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "multibody/backend.hpp"
#include "multibody/checks.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/modes.hpp"
#include "multibody/static_equilibria.hpp"
#include "multibody/statics.hpp"
#include "ring/spec.hpp"
#include "tests/multibody/common.hpp"
#include "tests/multibody/modal_superposition.hpp"
#include "tests/support/arch.hpp"
#include "tests/support/convergence.hpp"
#include "tests/support/paper.hpp"

namespace {

using mbtest::sci;
constexpr double kPi = 3.14159265358979323846;

/// The paper's ring cut to the arch [from, to], pinned at `from`; `to` pinned as well
/// (`to_pinned`), and `from` clamped (`clamp_from`).
ring::RingSpec arch(double from, double to, bool clamp_from, bool to_pinned = true) {
  ring::RingSpec s = ringtest::free_ring();
  s.arc = ring::Arc{from, to};
  s.supports.pin = from;
  if (clamp_from) s.supports.clamp = from;
  if (to_pinned) s.supports.pins = {to};
  return s;
}

/// Omega = rho A R^4 omega^2 / EI of the chain's `count` lowest modes.
std::vector<double> chain_omega2(const ring::RingSpec& spec, int n, int count) {
  const ring::ModalResult r = multibody::compute_modes(spec, mbtest::dense_chain(n), count);
  std::vector<double> out;
  for (double w : r.omega) out.push_back(w * w * spec.rhoA() * std::pow(spec.radius, 4) / spec.EI());
  return out;
}

struct ArchCase {
  const char* name;
  double from, to;
  bool clamp_from;
};

class ArchModes : public ::testing::TestWithParam<ArchCase> {};

// The chain's three lowest frequencies against the inextensible arch's, n = 24 .. 96
// (pieces of 5 .. 1.25 degrees on a 120 degree arch, 8.96 .. 2.24 deg on the 215 degree one).
TEST_P(ArchModes, ConvergeAtOrderTwoToTheInextensibleArch) {
  const ArchCase c = GetParam();
  const ring::RingSpec spec = arch(c.from, c.to, c.clamp_from);
  archtest::Arch a;  // inextensible (EA infinite), no rotary inertia: the chain's limit
  a.R = spec.radius;
  a.alpha = (c.to - c.from) * kPi / 180.0;
  a.EI = spec.EI();
  a.rhoA = spec.rhoA();
  a.start = c.clamp_from ? archtest::End::clamped : archtest::End::pinned;
  a.end = archtest::End::pinned;
  std::vector<double> exact;
  for (double w : archtest::arch_omegas(a, 3)) exact.push_back(w * w * spec.rhoA() * std::pow(spec.radius, 4) / spec.EI());
  const std::vector<int> ns{24, 48, 96};
  std::vector<std::vector<double>> errors(3);
  for (int n : ns) {
    const std::vector<double> w2 = chain_omega2(spec, n, 3);
    for (int k = 0; k < 3; ++k) errors[k].push_back(std::abs(w2[k] - exact[k]) / exact[k]);
  }
  for (int k = 0; k < 3; ++k) {
    RecordProperty(std::string(c.name) + "_mode" + std::to_string(k + 1) + "_finest_error", sci(errors[k].back()));
    RecordProperty(std::string(c.name) + "_mode" + std::to_string(k + 1) + "_order",
                   sci(ringtest::fit_order(ringtest::in_n(ns, errors[k])).order));
    // Order 2 (chain.hpp: the chain's length is the arch's, the hinge springs EI/l); 0.15: the
    // spread of the chains' fitted orders over three refinements on the ring (test_modes.cpp).
    // Ceiling: the chain's error is O((l/R)^2) with a constant below 1 (the ring's), l/R = 0.037
    // at n = 96 on the 215-degree arch: 2e-3 bounds it.
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors[k]), 2.0, 0.15, 2e-3))
        << c.name << " mode " << k + 1 << ", exact Omega = " << exact[k];
  }
}

INSTANTIATE_TEST_SUITE_P(Arches, ArchModes,
                         ::testing::Values(ArchCase{"pinned_pinned_120", 30.0, 150.0, false},
                                           ArchCase{"clamped_pinned_120", 30.0, 150.0, true},
                                           ArchCase{"clamped_pinned_215", -17.5, 197.5, true}),
                         [](const auto& info) { return std::string(info.param.name); });

// The rigid-mode count is the spec's: none pinned-pinned or clamped-pinned, the rotation about
// a single pin, none clamped-free. Shapes vanish at the stations off the arch.
TEST(ArchModes, RigidModesAreTheSpecs) {
  for (const ring::RingSpec& spec : {arch(30.0, 150.0, false), arch(30.0, 150.0, true),
                                     arch(30.0, 150.0, false, false), arch(30.0, 150.0, true, false)}) {
    const ring::ModalResult r = multibody::compute_modes(spec, mbtest::dense_chain(24), 3);
    EXPECT_EQ(r.rigid_modes, spec.rigid_modes());
    ASSERT_EQ(r.shapes.size(), 3u);
    for (const ring::ModeShape& s : r.shapes)
      for (int deg : {0, 10, 29, 151, 200, 359}) {
        EXPECT_EQ(s.radial.at(deg), 0.0) << "station " << deg << " is off the arch";
        EXPECT_EQ(s.tangential.at(deg), 0.0) << "station " << deg << " is off the arch";
      }
  }
}

/// DaDeppo & Schmidt's deep arch: 215 degrees symmetric about the apex at 90 degrees,
/// clamped at -17.5, pinned at 197.5.
ring::RingSpec deep_arch() { return arch(-17.5, 197.5, true); }

/// The chain's limit load P R^2 / EI under the apex load, following the path with the
/// continuation driver to its first maximum (paths::Trace::limit).
double deep_arch_limit(int n) {
  const ring::RingSpec spec = deep_arch();
  const double P = 10.0;  // P R^2 / EI at load factor 1, above the limit
  ring::Loads loads;
  loads.points = {{90.0, {0.0, -P * spec.EI() / (spec.radius * spec.radius)}}};
  ring::MultibodyOptions o = mbtest::dense_chain(n);
  const multibody::Chain chain(spec, o, 90.0);
  auto eq = multibody::detail::angle_equilibrium(chain, spec, loads, spec.section.depth());
  paths::Continuation policy;
  policy.steps = 10;
  policy.max_arc_steps = 300;
  const paths::Trace t = paths::follow(*eq, {eq->rest(), 0.0}, policy);
  return t.limit * P;
}

TEST(ArchStatics, DeepArchLimitLoadConvergesAtOrderTwoToDaDeppo) {
  const double exact = archtest::deep_arch_limit().load;  // 8.97308997 (DaDeppo & Schmidt: 8.97)
  const std::vector<int> ns{20, 40, 80, 160};
  std::vector<double> errors;
  for (int n : ns) {
    const double limit = deep_arch_limit(n);
    RecordProperty("limit_n" + std::to_string(n), sci(limit));
    errors.push_back(std::abs(limit - exact) / exact);
  }
  RecordProperty("limit_order", sci(ringtest::fit_order(ringtest::in_n(ns, errors)).order));
  // Order 2 (0.15: as the modes'); the chain's error at n = 160 is O((l/R)^2), l/R = 0.023,
  // with a constant below 1 (the modes'): 5e-4 bounds it.
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors), 2.0, 0.15, 5e-4));
}

// The command's path (solve_static with static.path): through the limit point and on, the
// apex recorded; its largest load factor is the limit the driver located (above, n = 40).
TEST(ArchStatics, DeepArchPathPassesTheLimitPoint) {
  const ring::RingSpec spec = deep_arch();
  ring::StaticOptions st;
  const double P = 10.0;
  st.loads.points = {{90.0, {0.0, -P * spec.EI() / (spec.radius * spec.radius)}}};
  st.steps = 10;
  st.path = true;
  st.record = {90.0, 197.5};
  const ring::StaticResult r = multibody::solve_static(spec, mbtest::dense_chain(40), st);
  double most = 0.0;
  for (const ring::PathPoint& p : r.path) most = std::max(most, p.load_factor);
  RecordProperty("path_points", static_cast<int>(r.path.size()));
  RecordProperty("path_end", r.end);
  // The located limit is a point of the path within 1e-6 of a step; the accepted points come
  // within a step's load change of it: 1 % of the limit bounds that at n = 40.
  EXPECT_NEAR(most * P, deep_arch_limit(40), 0.01 * deep_arch_limit(40));
  // The pinned end does not move (its rows), to round-off of the hinge positions.
  for (const ring::PathPoint& p : r.path) {
    EXPECT_LT(std::hypot(p.displacements.at(1).ux, p.displacements.at(1).uy), 1e-9 * spec.radius);
  }
  // The apex has gone down past the limit.
  EXPECT_LT(r.path.back().displacements.at(0).uy, 0.0);
}

/// The collapse load (P R / Mp) of a two-hinged arch under a point load at its apex, its
/// centre line through the points at the polar angles `deg` (symmetric about the apex at 90
/// degrees, the ends first and last) on the circle of radius rho R, by the static theorem of
/// limit analysis (small displacements, rigid-perfectly plastic): with the thrust H the moment
/// is M = P m - H y, m the simply supported span's (P/2)(half span - |x|), y the height above
/// the springing line; on straight pieces between the points M is linear, so its extremes are
/// at the points, and the collapse load makes min_H max_k |M_k| = Mp. max_k |M_k| is convex in
/// H (a maximum of affine functions), minimized by golden section to round-off.
double two_hinged_collapse(const std::vector<double>& deg, double rho) {
  std::vector<double> m, y;
  const double half_span = rho * std::cos(deg.front() * kPi / 180.0), base = rho * std::sin(deg.front() * kPi / 180.0);
  for (double d : deg) {
    const double a = d * kPi / 180.0;
    m.push_back(0.5 * (half_span - std::abs(rho * std::cos(a))));
    y.push_back(rho * std::sin(a) - base);
  }
  auto worst = [&](double H) {
    double w = 0.0;
    for (std::size_t i = 0; i < m.size(); ++i) w = std::max(w, std::abs(m[i] - H * y[i]));
    return w;
  };
  double a = 0.0, b = 10.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 200; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (worst(c) < worst(d))
      b = d;
    else
      a = c;
  }
  return 1.0 / worst(0.5 * (a + b));
}

/// The chain's collapse load (P R / Mp) of the pinned 120-degree arch [30, 150] with the
/// resultant law, Mp R / EI = `ratio`, the first maximum of the path under the apex load
/// (paths::Trace::limit).
double chain_collapse(int n, double reference, double ratio) {
  ring::RingSpec spec = arch(30.0, 150.0, false);
  const double Mp = ratio * spec.EI() / spec.radius;
  spec.plastic = ring::Plastic{};
  spec.plastic->moment = Mp;
  const double P = 1.5 * reference;  // P R / Mp at load factor 1: past the collapse
  ring::Loads loads;
  loads.points = {{90.0, {0.0, -P * Mp / spec.radius}}};
  const multibody::Chain chain(spec, mbtest::dense_chain(n), 90.0);
  auto eq = multibody::detail::angle_equilibrium(chain, spec, loads, spec.section.depth());
  paths::Continuation policy;
  policy.steps = 30;
  policy.max_arc_steps = 200;
  const paths::Trace t = paths::follow(*eq, {eq->rest(), 0.0}, policy);
  return t.limit * P;
}

// ring.plastic on an arch: the interior hinges' resultant law (bending.hpp). The chain is a
// pinned polygon whose moments between hinges are linear, so its collapse load is the limit
// analysis of that polygon (hinges at 30 + 120 k / n degrees on the circle of radius
// Rp = l / (2 sin(span / 2n)), l = R span / n: chain.hpp's rule), up to the geometric
// nonlinearity that the limit analysis leaves out (the collapse's rotations are ~Mp R / EI).
// The polygons' limit tends to the continuous arch's (recorded, not asserted: the second
// plastic hinge's point, 35.26 deg from the apex, is 0.74 deg from a hinge for n = 20, 40, 80
// alike, so the sampling error does not fall smoothly with n).
TEST(ArchStatics, PlasticCollapseIsTheLimitAnalysisOfThePolygon) {
  const double span = 120.0 * kPi / 180.0;
  std::vector<double> fine;
  for (int i = 0; i <= 20000; ++i) fine.push_back(30.0 + 120.0 * i / 20000.0);
  const double continuous = two_hinged_collapse(fine, 1.0);
  RecordProperty("limit_analysis_arch", sci(continuous));
  for (int n : {20, 40, 80}) {
    std::vector<double> hinges;
    for (int k = 0; k <= n; ++k) hinges.push_back(30.0 + 120.0 * k / n);
    const double rho = (span / n) / (2.0 * std::sin(span / (2.0 * n)));
    const double polygon = two_hinged_collapse(hinges, rho);
    RecordProperty("limit_analysis_polygon_n" + std::to_string(n), sci(polygon));
    for (double ratio : {1e-4, 1e-6}) {
      const double chain = chain_collapse(n, polygon, ratio);
      const double error = std::abs(chain - polygon) / polygon;
      RecordProperty("collapse_n" + std::to_string(n) + "_ratio" + sci(ratio), sci(error));
      // Geometry: the collapse's rotations are ~Mp R / EI, the load's change from them of that
      // order: measured 0.757 Mp R / EI at both ratios and every n (linear in Mp, so geometric);
      // bound Mp R / EI, plus 1e-8 for the limit's location (regula falsi, 1e-6 of a step).
      EXPECT_LT(error, ratio + 1e-8) << "n = " << n << ", Mp R / EI = " << ratio;
    }
  }
}

/// The load factor of the first bifurcation of the pinned 120-degree arch [30, 150] under the
/// uniform pressure `p` (N/m) of `kind` on the n-segment chain (paths::Trace::bifurcation_*,
/// the bracket's middle), or NaN when the path ends otherwise.
double pressure_bifurcation(int n, double p, ring::Pressure::Kind kind) {
  const ring::RingSpec spec = arch(30.0, 150.0, false);
  ring::Loads loads;
  loads.pressure.value = p;
  loads.pressure.kind = kind;
  const multibody::Chain chain(spec, mbtest::dense_chain(n));
  auto eq = multibody::detail::angle_equilibrium(chain, spec, loads, spec.section.depth());
  paths::Continuation policy;
  policy.steps = 10;
  const paths::Trace t = paths::follow(*eq, {eq->rest(), 0.0}, policy);
  if (t.end != paths::Trace::End::bifurcation) return std::nan("");
  return 0.5 * (t.bifurcation_low + t.bifurcation_high);
}

// Uniform follower pressure on the pinned arch: the circle is its funicular (the inextensible
// arch stays at rest, compressed), and it buckles at Timoshenko & Gere's q R^3 / EI =
// pi^2 / alpha^2 - 1 (alpha half the opening: 8 for 120 degrees; archtest::
// pinned_follower_pressure), where the statics' path meets its bifurcation.
TEST(ArchStatics, FollowerPressureBucklesThePinnedArchAtTimoshenkoAndGere) {
  const ring::RingSpec spec = arch(30.0, 150.0, false);
  const double exact = archtest::pinned_follower_pressure(60.0 * kPi / 180.0);
  RecordProperty("timoshenko_gere", sci(exact));
  const double scale = spec.EI() / std::pow(spec.radius, 3);
  const std::vector<int> ns{24, 48, 96};
  std::vector<double> errors;
  for (int n : ns) {
    const double q = pressure_bifurcation(n, 1.5 * exact * scale, ring::Pressure::Kind::follower) * 1.5 * exact;
    RecordProperty("critical_n" + std::to_string(n), sci(q));
    errors.push_back(std::abs(q - exact) / exact);
  }
  RecordProperty("critical_order", sci(ringtest::fit_order(ringtest::in_n(ns, errors)).order));
  // Order 2 as the modes' (0.15); the bracket is 1e-6 of a load step (continuation.hpp), far below.
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors), 2.0, 0.15, 2e-3));
}

// Under dead pressure (constant forces p n0 l / 2 at each end of every segment) the rest polygon
// is itself in equilibrium (the forces at each interior hinge are radial and equal, the
// segments carry them as a uniform compression): nothing moves below the first bifurcation.
TEST(ArchStatics, DeadPressureLeavesThePinnedArchAtRest) {
  const ring::RingSpec spec = arch(30.0, 150.0, false);
  ring::StaticOptions st;
  st.loads.pressure.value = 2.0 * spec.EI() / std::pow(spec.radius, 3);  // a quarter of the follower's critical
  st.loads.pressure.kind = ring::Pressure::Kind::dead;
  st.record = {60.0, 90.0, 120.0};
  const ring::StaticResult r = multibody::solve_static(spec, mbtest::dense_chain(24), st);
  EXPECT_GE(r.steps, 1);
  ASSERT_EQ(r.displacements.size(), 3u);
  // Round-off of the hinge positions (R = 10 m): 1e-12 m.
  for (const ring::PointDisplacement& d : r.displacements) {
    EXPECT_LT(std::abs(d.ux), 1e-12) << d.angle;
    EXPECT_LT(std::abs(d.uy), 1e-12) << d.angle;
  }
}

/// A step load F (N) down at the apex (90 deg) of an arch, dt = 2.5 ms for 1.5 s (about two
/// periods of the lowest mode of the 120-degree arches), the apex and 60 deg recorded.
ring::ResponseOptions apex_step(double F, ring::ResponseOptions::Integrator integrator) {
  ring::ResponseOptions r;
  r.loads.points = {{90.0, {0.0, -F}}};
  r.history.kind = ring::LoadHistory::Kind::step;
  r.integrator = integrator;
  r.dt = 0.0025;
  r.t_end = 1.5;
  r.record = {90.0, 60.0};
  return r;
}

class ArchResponse : public ::testing::TestWithParam<ring::ResponseOptions::Integrator> {};

// The response under a small step load is the chain's linear modal superposition with the same
// integrator mode by mode (modal_superposition.hpp: the modes of solve_modes, an independent
// linearization and eigensolver); what is left is the geometric nonlinearity, which falls
// with the load (a tenth of the load leaves a tenth of it).
TEST_P(ArchResponse, SmallStepLoadIsTheModalSuperposition) {
  for (const ring::RingSpec& spec : {arch(30.0, 150.0, false), arch(30.0, 150.0, true)}) {
    const ring::ResponseOptions r = apex_step(20.0, GetParam()), r10 = apex_step(2.0, GetParam());
    const ring::TimeHistory th = multibody::respond(spec, mbtest::dense_chain(24), r);
    const ring::TimeHistory th10 = multibody::respond(spec, mbtest::dense_chain(24), r10);
    const mbtest::Linear same = mbtest::modal_superposition(spec, 24, r, th.t, true);
    const mbtest::Linear same10 = mbtest::modal_superposition(spec, 24, r10, th10.t, true);
    for (int p : {0, 1}) {
      const double d = mbtest::relative_deviation(th, same, p), d10 = mbtest::relative_deviation(th10, same10, p);
      const std::string tag = std::string(spec.supports.clamp ? "clamped" : "pinned") + "_" +
                              std::to_string(static_cast<int>(r.record[p]));
      RecordProperty("vs_same_" + tag, sci(d));
      RecordProperty("vs_same_tenth_" + tag, sci(d10));
      // As the ring's (test_dynamics.cpp): the first correction is quadratic in the
      // displacement, so its relative size is linear in the load: ratio 10, band 8 .. 12 for
      // the next-order terms; and small (1e-3 of the peak at 20 N, as the ring's bound).
      EXPECT_LT(d, 1e-3) << tag;
      EXPECT_GT(d / d10, 8.0) << tag;
      EXPECT_LT(d / d10, 12.0) << tag;
    }
    // The pinned far end stays put: its rows hold to round-off.
    for (double g : th.constraint_residual) EXPECT_LT(g, 1e-12 * spec.radius);
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, ArchResponse,
                         ::testing::Values(ring::ResponseOptions::Integrator::newmark,
                                           ring::ResponseOptions::Integrator::generalized_alpha),
                         [](const auto& info) {
                           return info.param == ring::ResponseOptions::Integrator::newmark ? "newmark"
                                                                                            : "generalized_alpha";
                         });

/// The message of the std::invalid_argument that `f` throws ("" if none).
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// What the chain does not take on an arch is refused before computing, naming ring.arc and
// the key (checks.cpp); "auto" is dense for an arch whatever n (backend.hpp).
TEST(ArchChecks, RefuseByKey) {
  const ring::RingSpec base = arch(30.0, 150.0, false);
  ring::MultibodyOptions o = mbtest::dense_chain(24);
  auto modes_refusal = [&](const ring::RingSpec& s, const ring::MultibodyOptions& opt) {
    return refusal([&] { multibody::check_modes(s, opt); });
  };
  ring::MultibodyOptions sparse = o;
  sparse.method = ring::MultibodyOptions::Method::sparse;
  ring::MultibodyOptions paper = o;
  paper.dependent = ring::MultibodyOptions::Dependent::paper;
  ring::RingSpec timo = base, roller = base, springs = base, masses = base, foundation = base;
  timo.theory = ring::Theory::timoshenko;
  roller.supports.roller = 90.0;
  springs.supports.springs = {{90.0, 1e3, 0.0, 0.0}};
  masses.masses = {{90.0, 1.0, 0.0}};
  foundation.foundation.radial = 100.0;
  const std::pair<std::string, std::string> cases[] = {
      {modes_refusal(base, sparse), "multibody.method"},     {modes_refusal(base, paper), "multibody.dependent"},
      {modes_refusal(timo, o), "ring.theory"},                {modes_refusal(roller, o), "supports.roller"},
      {modes_refusal(springs, o), "supports.springs"},        {modes_refusal(masses, o), "masses"},
      {modes_refusal(foundation, o), "foundation"}};
  for (const auto& [message, key] : cases) {
    EXPECT_NE(message.find("ring.arc"), std::string::npos) << message;
    EXPECT_NE(message.find(key), std::string::npos) << message;
  }
  // Pressure needs both ends pinned; gravity is refused.
  ring::StaticOptions st;
  st.loads.pressure.value = 1e3;
  st.loads.pressure.kind = ring::Pressure::Kind::dead;
  const std::string pressure = refusal([&] { multibody::check_static(arch(30.0, 150.0, true, false), o, st); });
  EXPECT_NE(pressure.find("static.pressure"), std::string::npos) << pressure;
  EXPECT_NE(pressure.find("ring.arc"), std::string::npos) << pressure;
  EXPECT_EQ(refusal([&] { multibody::check_static(base, o, st); }), "");
  ring::StaticOptions gravity;
  gravity.loads.gravity = {0.0, -9.81};
  const std::string weight = refusal([&] { multibody::check_static(base, o, gravity); });
  EXPECT_NE(weight.find("static.gravity"), std::string::npos) << weight;
  // An arch held by one pin turns about it under a point load: refused, naming the ends' keys.
  ring::StaticOptions point;
  point.loads.points = {{90.0, {0.0, -1e3}}};
  const std::string rigid = refusal([&] { multibody::check_static(arch(30.0, 150.0, false, false), o, point); });
  EXPECT_NE(rigid.find("supports.pin"), std::string::npos) << rigid;
  // ring.plastic: the statics take it on pinned ends, not with a clamp (its half-hinge is
  // elastic); the response refuses it.
  ring::RingSpec plastic = arch(30.0, 150.0, true);
  plastic.plastic = ring::Plastic{};
  plastic.plastic->moment = 1e3;
  const std::string clamp = refusal([&] { multibody::check_static(plastic, o, point); });
  EXPECT_NE(clamp.find("supports.clamp"), std::string::npos) << clamp;
  plastic.supports.clamp.reset();
  EXPECT_EQ(refusal([&] { multibody::check_static(plastic, o, point); }), "");
  ring::ResponseOptions response;
  response.loads = point.loads;
  const std::string respond = refusal([&] { multibody::check_response(plastic, o, response); });
  EXPECT_NE(respond.find("ring.plastic"), std::string::npos) << respond;
  ring::MultibodyOptions automatic = o;
  automatic.method = ring::MultibodyOptions::Method::automatic;
  automatic.n = 2000;
  EXPECT_EQ(multibody::backend(automatic, base, 3), multibody::Backend::dense);
  EXPECT_EQ(multibody::backend(automatic, base, point), multibody::Backend::dense);
}

}  // namespace
