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

}  // namespace
