// Rigid plates ([plates]) in the CalculiX column's statics: ring::PlatePair's penalty as
// nonlinear SPRINGA elements from every facing beam node to a plate node driven along the
// plates' normal and tied to the beam node along the plates (calculix/deck.hpp, plates_block).
//
// The oracles:
// - the elastic pinch's closed form (Roark's ring case 1), P = c / ((pi/4 - 2/pi) R^3 / EI),
//   with the bricks' extension and shear (the thick ring's factors, kGA = EA/2: 1.245e-4 below
//   the thin form on the paper ring, calculix_driven_test.cpp), at a small approach where the
//   ring touches each plate at one node;
// - the same column's driven pinch (static.displacement, the existing fixture);
// - DeRuntz & Hodge's rigid–plastic crushing between plates (tests/support/plastic_ring.hpp,
//   plates_load and plates_contact_length), with B32R's brick expansion as measured in
//   calculix/README.md ("Plasticity").
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "calculix/ccx.hpp"
#include "calculix/dat.hpp"
#include "calculix/deck.hpp"
#include "calculix/statics.hpp"
#include "internal_energy.hpp"
#include "ring/errors.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/plastic_ring.hpp"

namespace {

#define REQUIRE_CCX()                                                                                  \
  if (calculix::find_ccx().empty()) GTEST_SKIP() << "ccx is not on the PATH (Debian package calculix-ccx; " \
                                                    "scripts/install-deps.sh installs it)"

ring::CalculixOptions b32r(int elements) {
  ring::CalculixOptions o;
  o.element = ring::CalculixOptions::Element::b32r;
  o.elements = elements;
  return o;
}

/// The wall's own stiffness through its depth, E A^2 / (12 I): the scene's default penalty.
double default_stiffness(const ring::RingSpec& s) { return s.E * s.A() * s.A() / (12.0 * s.I()); }

/// The paper ring crushed along the vertical (axis 90 deg) by `travel` at load factor 1.
ring::StaticOptions plates(const ring::RingSpec& s, double travel, int steps, std::vector<double> history = {},
                           double axis = 90.0) {
  ring::StaticOptions st;
  st.plates = ring::StaticOptions::Plates{axis, travel, default_stiffness(s)};
  st.record = {axis, axis + 90.0};
  st.history = std::move(history);
  st.path = true;
  st.steps = steps;
  return st;
}

double thick_ring_force(const ring::RingSpec& s, double c) {
  const double alpha = s.I() / (s.A() * s.radius * s.radius), beta = 2.0 * alpha;
  const double k1 = 1.0 - alpha + beta, k2 = 1.0 - alpha;
  return c / ((M_PI / 4.0 * k1 - 2.0 / M_PI * k2 * k2) * std::pow(s.radius, 3) / s.EI());
}

/// The rows of a .dat's blocks "forces (fx,fy,fz) for set NAME and time t" at the last time:
/// node -> (fx, fy).
std::vector<std::array<double, 3>> last_forces(const std::string& dat, const std::string& set) {
  std::vector<std::array<double, 3>> rows;
  std::istringstream in(dat);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("for set") != std::string::npos) {
      inside = line.find("forces (fx,fy,fz) for set " + set + " ") != std::string::npos;
      if (inside) rows.clear();
      continue;
    }
    std::istringstream s(line);
    double node, fx, fy, fz;
    if (inside && (s >> node >> fx >> fy >> fz)) rows.push_back({node, fx, fy});
  }
  return rows;
}

/// The row of the last block "total force (fx,fy,fz) for set NAME and time t": (fx, fy).
std::array<double, 2> last_total(const std::string& dat, const std::string& set) {
  std::array<double, 2> f{NAN, NAN};
  std::istringstream in(dat);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("for set") != std::string::npos) {
      inside = line.find("total force (fx,fy,fz) for set " + set + " ") != std::string::npos;
      continue;
    }
    std::istringstream s(line);
    double fx, fy, fz;
    if (inside && (s >> fx >> fy >> fz)) f = {fx, fy};
  }
  return f;
}

// The elastic ring at a small approach c = 1e-4 R: the plates' force converges to the
// closed form's pinching force at B32R's order under a point constraint, as the driven
// pinch does (calculix_driven_test: order 2.6 over 10-40 elements).
// Why c = 1e-4 R and the default penalty (not 1e3 times it): ccx computes a spring's
// elongation from coordinates of magnitude R, so the spring force carries the round-off
// k w ulp(R) (k w ~ 1e11 N/m at the first-contact node: ~2e-4 N, measured as a quantum of
// 2^-11 N in the printed forces); at c = 1e-5 R (1.4 N) that is 1e-4 of the force, and 1e3 k
// would make it 0.1. The penalty's sinking at the default k is F / (k w) ~ 2e-10 m, 2e-7 of c
// (bounded below). NLGEOM's softening of the pushed ring is 7.4e-5 at c = 1e-4 R
// (calculix_driven_test's header), below the 40-element error.
TEST(CalculixPlates, ElasticSmallApproachConvergesToThePinchingForce) {
  REQUIRE_CCX();
  const ring::RingSpec spec = ringtest::free_ring();
  const double c = 1e-4 * spec.radius, P = thick_ring_force(spec, c);
  const std::vector<int> ns = {10, 20, 40};
  std::vector<double> errors;
  for (int n : ns) {
    const ring::StaticOptions st = plates(spec, c, 2);
    const ring::StaticResult r = calculix::solve_static(spec, b32r(n), st);
    ASSERT_LT(r.reaction[1], 0.0) << "plate 0 (above) pushes the ring down, " << n << " elements";
    EXPECT_LT(std::abs(r.reaction[0]), 1e-9 * P) << "frictionless: no force along the plates, " << n;
    // The first contact point goes down with the plate by c / 2 less the sinking F / (k w),
    // w = L / 3 the end node's share: 2e-7 of c at 10 elements.
    const double w = 2.0 * M_PI * spec.radius / n / 3.0, sinking = P / (default_stiffness(spec) * w);
    EXPECT_LT(sinking, 1e-6 * c) << n;
    EXPECT_NEAR(r.displacements[0].uy, -0.5 * c + sinking, 1e-6 * c) << n;
    // One node touches each plate: the contact length is the part of the chords to the
    // neighbours where the (linear) gap is closed, of the order of the sinking over the
    // neighbours' gap, far below a node spacing.
    EXPECT_LT(r.contact_length[0], 1e-3 * w) << n;
    errors.push_back(std::abs(-r.reaction[1] / P - 1.0));
    std::printf("  %d elements: force %.7g N, closed form %.7g N, error %.3e, contact %.3e m\n", n, -r.reaction[1],
                P, -r.reaction[1] / P - 1.0, r.contact_length[0]);
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors), 2.6, 0.4, 1.5e-3));
}

// The two plates' forces are equal and opposite, and the two no-slide rows carry ~0 (the
// symmetric crushing leaves them unloaded): the deck run by hand with the beam nodes' RF
// printed. Along an oblique axis (36 deg, an element end as 90 deg is at 20 elements), where the plate nodes' *TRANSFORM and the no-slide
// *EQUATION are exercised, the force is the axis's case turned.
TEST(CalculixPlates, PlatesForcesAreOppositeAndTheNoSlideRowsCarryNothing) {
  REQUIRE_CCX();
  const ring::RingSpec spec = ringtest::free_ring();
  const double c = 1e-4 * spec.radius;
  for (double axis : {90.0, 36.0}) {
    const ring::StaticOptions st = plates(spec, c, 2, {}, axis);
    const ring::CalculixOptions o = b32r(20);
    const calculix::Deck written = calculix::static_deck(spec, o, st);
    std::string deck = written.text;
    std::vector<double> touching;  // the beam nodes (1-based) at axis and axis + 180
    for (std::size_t k = 0; k < written.node_angles.size(); ++k) {
      const double off = ring::wrap_degrees(written.node_angles[k] - axis);
      if (std::abs(off) < 1e-9 || std::abs(off - 180.0) < 1e-9 || std::abs(off - 360.0) < 1e-9)
        touching.push_back(static_cast<double>(k + 1));
    }
    ASSERT_EQ(touching.size(), 2u);
    const auto end = deck.rfind("*END STEP");
    ASSERT_NE(end, std::string::npos);
    deck.insert(end, "*NODE PRINT, NSET=NALL\nRF\n");
    const calculix::RunOutput out = calculix::run(deck, {o.timeout, o.threads});
    // (The reader takes one forces block, the driven node's: the plates' totals read here.)
    const std::array<std::array<double, 2>, 2> f{last_total(out.dat, "NPLATE0"), last_total(out.dat, "NPLATE1")};
    const double F = std::hypot(f[0][0], f[0][1]);
    EXPECT_NEAR(f[1][0], -f[0][0], 1e-6 * F) << axis;
    EXPECT_NEAR(f[1][1], -f[0][1], 1e-6 * F) << axis;
    // Along -d_0.
    const double a = axis * M_PI / 180.0;
    EXPECT_NEAR(f[0][0] / F, -std::cos(a), 1e-7) << axis;
    EXPECT_NEAR(f[0][1] / F, -std::sin(a), 1e-7) << axis;
    // The beam nodes' RF along e = (-sin, cos) at the nodes at axis and axis + 180: the
    // no-slide rows' forces.
    const auto rf = last_forces(out.dat, "NALL");
    double slide = 0.0;
    for (const auto& row : rf)
      if (row[0] == touching[0] || row[0] == touching[1]) slide = std::max(slide, std::abs(-std::sin(a) * row[1] + std::cos(a) * row[2]));
    EXPECT_LT(slide, 1e-6 * F) << axis;
    std::printf("  axis %g: F = %.7g N, no-slide %.2e N\n", axis, F, slide);
  }
}

// The same column driven (static.displacement at 90 deg by c, pinned at 270: the existing
// fixture) and crushed by the plates by c: the same force. The differences: the plates' sinking
// (2e-7 of c, above), and the supports: the drive holds the section's mean displacement by
// MPCs, a spring pulls on the section's corners (ccx's gen3dconnect), which the section made
// rigid across its width carries alike.
TEST(CalculixPlates, PlatesAndTheDrivenPinchGiveTheSameForce) {
  REQUIRE_CCX();
  const double c = 1e-4 * 10.0;
  const ring::StaticResult driven =
      calculix::solve_static(ringtest::driven_plastic_ring(std::nullopt), b32r(20), ringtest::driven_pinch(c, {}, 2));
  const ring::RingSpec spec = ringtest::free_ring();
  const ring::StaticResult crushed = calculix::solve_static(spec, b32r(20), plates(spec, c, 2));
  std::printf("  driven %.7g N, plates %.7g N, ratio - 1 = %.3e\n", driven.reaction[1], crushed.reaction[1],
              crushed.reaction[1] / driven.reaction[1] - 1.0);
  EXPECT_NEAR(crushed.reaction[1] / driven.reaction[1], 1.0, 1e-4);
}

/// The crushed tube of the plastic tests: the paper ring's radius, a rectangle 0.1 x 0.12 m as
/// given (the fibre law of calculix_plastic_test), sigma_y so that Mp R / EI = mp, perfectly
/// plastic, no supports.
ring::RingSpec fibre_tube(double mp) {
  ring::RingSpec s = ringtest::free_ring();
  s.section.shape = ring::Section::Shape::rectangle;
  s.section.width = 0.1;
  s.section.height = 0.12;
  ring::Plastic p;
  p.law = ring::Plastic::Law::fibre;
  p.stress = mp * s.EI() / s.radius / (s.section.width * s.section.height * s.section.height / 4.0);
  s.plastic = p;
  return s;
}

double plastic_moment(const ring::RingSpec& s) {
  return s.plastic->stress * s.section.width * s.section.height * s.section.height / 4.0;
}

ring::CalculixOptions as_given(int elements) {
  ring::CalculixOptions o = b32r(elements);
  o.section = ring::CalculixOptions::Section::as_given;
  return o;
}

// The fibre law crushed to c = 0.3 R at 20 elements against DeRuntz & Hodge's rigid–plastic
// tube. Mp R / EI = 1e-2, not the 1e-4 of the point-load tests: ccx's perfectly plastic bricks
// take increments of a few times the closing at collapse (measured at 1e-4: 222 increments and
// 27 s to 0.1 R; at 1e-2: 63 increments to 0.3 R); the elastic offset, of order Mp R^2 / EI =
// 1e-2 R in the approach, is then what the rigid–plastic oracle leaves out.
// What the column differs by (calculix/README.md, "Rigid plates"): B32R's section law flat at
// 0.933 Mp with hinges held near the elements' Gauss points (the driven plateau at 20
// elements: 1.057 P_c), and a contact that spreads from node to node (every 9 degrees at 20
// elements) instead of continuously: between two nodes' first touches the last one acts as a
// point load whose mechanism falls, so the force saws about plates_load (measured to c = R:
// 0.917 to 1.153 of it), and its integral, the plates' work, follows DeRuntz & Hodge's
// dissipation 8 Mp asin(c / D) within 4 % (measured 0.962 .. 1.014 over 0.1 .. 1 R).
TEST(CalculixPlates, FibreTubeCrushedFollowsDeRuntzAndHodge) {
  REQUIRE_CCX();
  const ring::RingSpec spec = fibre_tube(1e-2);
  const double R = spec.radius, Mp = plastic_moment(spec), travel = 0.3 * R;
  const ringtest::PinchedPlasticRing oracle{R, spec.EI(), Mp};
  const ring::StaticResult r = calculix::solve_static(spec, as_given(20), plates(spec, travel, 15));
  ASSERT_GE(r.path.size(), 10u);
  double work = 0.0, c0 = 0.0, f0 = 0.0, lowest = INFINITY, highest = 0.0;
  const double spacing = M_PI * R / 20.0;  // between beam nodes
  for (const auto& p : r.path) {
    const double c = p.load_factor * travel, F = -p.reaction[1];
    work += 2.0 * 0.5 * (F + f0) * 0.5 * (c - c0);  // both plates, each moving by c / 2
    c0 = c;
    f0 = F;
    if (c < 0.05 * R) continue;  // past the elastic–plastic knee (closing at collapse 0.011 R)
    const double ratio = F / oracle.plates_load(c);
    lowest = std::min(lowest, ratio);
    highest = std::max(highest, ratio);
    // The work against the dissipation: measured 0.972 .. 0.985 to 0.3 R.
    EXPECT_NEAR(work / (8.0 * Mp * std::asin(c / (2.0 * R))), 0.98, 0.025) << "c = " << c;
    // The contact: to a node spacing at each end (its extent steps from node to node, and lags
    // while the last node to touch acts as a point load: measured to c = R, -3.4 .. +1.8 m).
    EXPECT_NEAR(p.contact_length[0], oracle.plates_contact_length(c), 2.0 * spacing) << "c = " << c;
    EXPECT_NEAR(p.contact_length[1], p.contact_length[0], 1e-6 * R) << "c = " << c;
    std::printf("  c/R %.3f  F / plates_load %.4f  work / 8 Mp asin %.4f  contact %.3f m (DH %.3f)\n", c / R, ratio,
                work / (8.0 * Mp * std::asin(c / (2.0 * R))), p.contact_length[0], oracle.plates_contact_length(c));
  }
  // The saw: measured 0.925 .. 1.033 to 0.3 R.
  EXPECT_GT(lowest, 0.90);
  EXPECT_LT(highest, 1.10);
  EXPECT_TRUE(std::isnan(r.dissipated)) << "ccx prints no plastic work";
}

// The energy identity: the work of both plates, the trapezoid sum of each plate's force times
// its travel (s travel / 2 along -d_p), is the ring's internal energy, elastic and dissipated
// together (ccx's total, *EL PRINT ELSE of the ring's elements, appended to the column's deck as
// calculix_driven_test does), plus the penalty's energy, which is below 1e-8 of it (the
// sinking F / (k w) ~ 1e-8 m against travels of metres). ccx does not split the internal
// energy, so the dissipated part is not read (NaN). Tolerance 2e-3: the trapezoid rule's
// error where a node comes into contact or the ring yields (measured below).
TEST(CalculixPlates, FibreTubeWorkOfThePlatesIsTheInternalEnergy) {
  REQUIRE_CCX();
  const ring::RingSpec spec = fibre_tube(1e-2);
  const double travel = 0.1 * spec.radius;
  const ring::CalculixOptions o = as_given(20);
  const auto [dat, energy] =
      ccxtest::run_with_internal_energy(calculix::static_deck(spec, o, plates(spec, travel, 5)).text, o,
                                        calculix::node_count(spec, o));
  ASSERT_EQ(energy.size(), dat.all.size());
  double work = 0.0, s0 = 0.0, f0 = 0.0, f1 = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < dat.all.size(); ++i) {
    const auto& inc = dat.all[i];
    // Plate 0 moves by -d_0 = (0, -1) s travel / 2, plate 1 by +d_0.
    const double ds = 0.5 * travel * (inc.time - s0);
    work += 0.5 * (-inc.plates[0][1] - f0) * ds + 0.5 * (inc.plates[1][1] + f1) * ds;
    s0 = inc.time;
    f0 = inc.plates[0][1];
    f1 = inc.plates[1][1];
    worst = std::max(worst, std::abs(work / energy[i] - 1.0));
    EXPECT_NEAR(work / energy[i], 1.0, 2e-3) << "increment " << i + 1 << " of " << dat.all.size();
  }
  std::printf("  %zu increments, work %.6g J, internal energy %.6g J, worst %.2e\n", dat.all.size(), work,
              energy.back(), worst);
  // Most of it dissipated: DeRuntz & Hodge's 8 Mp asin(c / D) is 97 % of it (above).
  EXPECT_GT(work, 0.9 * 8.0 * plastic_moment(spec) * std::asin(travel / (2.0 * spec.radius)));
}

// A rising history [0.5, 1] (one *STEP per leg) ends where one step to 1 ends (the elastic
// ring: no path dependence). Tolerance 5e-4 on the force: the springs' round-off, k w ulp(R),
// a few 1e-4 N on 14 N, and ccx's Newton stopping elsewhere on another path (measured 1.4e-4);
// 1e-4 on the side's displacement. A falling leg is refused by key.
TEST(CalculixPlates, ARisingHistoryEndsWhereOneStepEndsAndAReturnIsRefused) {
  REQUIRE_CCX();
  const ring::RingSpec spec = ringtest::free_ring();
  const double c = 1e-4 * spec.radius;
  const ring::StaticResult legs = calculix::solve_static(spec, b32r(20), plates(spec, c, 2, {0.5, 1.0}));
  const ring::StaticResult once = calculix::solve_static(spec, b32r(20), plates(spec, c, 2));
  EXPECT_EQ(legs.end, "end of the history");
  EXPECT_NEAR(legs.reaction[1] / once.reaction[1], 1.0, 5e-4);
  EXPECT_NEAR(legs.displacements[1].ux, once.displacements[1].ux, 1e-4 * std::abs(once.displacements[1].ux));
  try {
    calculix::check_static(spec, b32r(20), plates(spec, c, 2, {1.0, 0.9}));
    ADD_FAILURE() << "a return leg was taken";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "static.history");
  }
}

// The deck (no ccx needed): a spring and a plate node for every beam node facing a plate (all
// but the two at axis +- 90), the first contact nodes' window, the no-slide rows; and the
// refusals by key.
TEST(CalculixPlates, TheDeckHasASpringPerFacingNodeAndRefusesWhatItCannotWrite) {
  const ring::RingSpec spec = ringtest::free_ring();
  const calculix::Deck d = calculix::static_deck(spec, b32r(10), plates(spec, 1.0, 2));
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (auto at = d.text.find(what); at != std::string::npos; at = d.text.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("TYPE=SPRINGA"), 18u) << "20 nodes less the two at 0 and 180 deg";
  EXPECT_EQ(count(", NONLINEAR"), 18u);
  EXPECT_EQ(count("*TRANSFORM, NSET=NPLATES"), 1u);
  EXPECT_EQ(count("NPLATE0, 2, 2, "), 1u);
  EXPECT_EQ(count("*NODE PRINT, NSET=NPLATE0, TOTALS=ONLY"), 1u);
  // The two first-contact nodes' windows (two rows above the kink at 0).
  EXPECT_EQ(count("\n0.0, 0.0\n"), 2u);
  auto refused = [&](const ring::RingSpec& s, const ring::CalculixOptions& o, const std::string& key) {
    try {
      calculix::static_deck(s, o, plates(s, 1.0, 2));
      ADD_FAILURE() << "not refused: " << key;
    } catch (const ring::InputError& e) {
      EXPECT_EQ(e.key(), key);
    }
  };
  ring::CalculixOptions b31 = b32r(10);
  b31.element = ring::CalculixOptions::Element::b31;
  refused(spec, b31, "calculix.element");
  refused(ringtest::pinned_ring(270.0), b32r(10), "plates");
  ring::RingSpec off = spec;
  off.free_anchor = 5.0;  // no node at 90 deg
  refused(off, b32r(10), "plates.axis");
}

// Measuring (by hand: --gtest_also_run_disabled_tests): the fibre tube crushed to c = R at 20
// and 40 elements, the numbers of calculix/README.md ("Rigid plates"). 129 s together.
TEST(CalculixPlates, DISABLED_FibreTubeCrushedToTheRadius) {
  REQUIRE_CCX();
  const ring::RingSpec spec = fibre_tube(1e-2);
  const double R = spec.radius, Mp = plastic_moment(spec), travel = R;
  const ringtest::PinchedPlasticRing oracle{R, spec.EI(), Mp};
  for (int n : {20, 40}) {
    const ring::StaticResult r = calculix::solve_static(spec, as_given(n), plates(spec, travel, 50));
    double work = 0.0, c0 = 0.0, f0 = 0.0;
    for (const auto& p : r.path) {
      const double c = p.load_factor * travel, F = -p.reaction[1];
      work += (F + f0) * 0.5 * (c - c0);
      c0 = c;
      f0 = F;
      if (c > 0.0)
        std::printf("  %d  c/R %.3f  F/plates_load %.4f  work/8Mp asin %.4f  contact %.3f (DH %.3f)  top %.4f\n", n,
                    c / R, F / oracle.plates_load(c), work / (8.0 * Mp * std::asin(c / (2.0 * R))),
                    p.contact_length[0], oracle.plates_contact_length(c), p.displacements[0].uy);
    }
  }
}

}  // namespace
