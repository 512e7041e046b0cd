// The FE beam crushed between rigid plates through the command: `ringvib static SCENE --solver fem
// --json` on the paper's ring between plates at 90 and 270 deg approaching by c = 1e-3 R, the
// JSON's "reaction" against the pinch's closed form P = c / ((pi/4 - 2/pi) R^3 / EI)
// (tests/support/plastic_ring.hpp) and its "contact_length" against the point contact it should be;
// static.path = true carrying them at every path point; what the beam does not offer with plates
// (fem.reference) refused with exit 2 naming plates.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "compare/cli.hpp"
#include "support/json_text.hpp"
#include "support/paper.hpp"
#include "support/plastic_ring.hpp"

namespace {

std::string write_scene(const std::string& text) {
  const std::string dir = ringtest::temp_dir(), path = dir + "/plates.toml";
  ringtest::write(path, text);
  return path;
}

/// The paper's ring between plates at 90 and 270 deg approaching by `travel` (m), 32 cubic
/// elements, the default penalty.
std::string plates_scene(double travel, const std::string& extra = "") {
  return "title = \"plates\"\n" + ringtest::paper_ring_toml() + "[fem]\nelements = 32\ndegree = 3\n" + extra +
         "[plates]\naxis = 90.0\ntravel = " + std::to_string(travel) +
         "\n[static]\nsolvers = [\"fem\"]\nsteps = 4\nrecord = [90.0, 0.0]\n";
}

using ringtest::pair_after;

}  // namespace

TEST(FemPlatesCli, ReactionMeetsThePinchClosedForm) {
  const ring::RingSpec spec = ringtest::driven_plastic_ring(std::nullopt);
  const ringtest::PinchedPlasticRing o{spec.radius, spec.EI(), 0.0};
  const double c = 1e-3 * spec.radius;
  const ringtest::Run r = ringtest::ringvib("static " + write_scene(plates_scene(c)) + " --solver fem --json");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const std::array<double, 2> reaction = pair_after(r.out, "\"reaction\"");
  const std::array<double, 2> contact = pair_after(r.out, "\"contact_length\"");
  const double P = c / o.elastic_closing(1.0);
  // FemPlates.ElasticForceConvergesToThePinchClosedForm: 8.2e-4 from the closed form (the
  // geometric softening at c / R = 1e-3, the membrane's 4.5e-5; 32 cubic cells 1.7e-5 more);
  // bound 1.5e-3 as there.
  EXPECT_NEAR(-reaction[1] / P, 1.0, 1.5e-3) << r.out;
  EXPECT_NEAR(reaction[0] / P, 0.0, 1e-6) << r.out;  // symmetric about the vertical diameter
  // An elastic ring touches each plate at a point (the penalty's contact, ~(4 EI / k)^(1/4) =
  // 0.08 m here, is found between the vertex and the next sample, 1/32 of a cell away): both
  // lengths alike and below that sample spacing, 2 pi R / (32 * 32) = 0.061 m.
  EXPECT_GE(contact[0], 0.0) << r.out;
  EXPECT_LT(contact[0], 2.0 * M_PI * spec.radius / (32 * 32)) << r.out;
  EXPECT_NEAR(contact[1], contact[0], 1e-9) << r.out;
}

TEST(FemPlatesCli, TheReferenceRefinementIsRefusedByTheKey) {
  const ringtest::Run r =
      ringtest::ringvib("static " + write_scene(plates_scene(1e-2, "reference = true\n")) + " --solver fem --json");
  EXPECT_EQ(r.code, 2) << r.err << r.out;
  EXPECT_NE(r.err.find("plates"), std::string::npos) << r.err;
}

// static.path = true: every path point carries its contact lengths and force (4 load steps and
// rest: 5 points), and the last point's force is the result's.
TEST(FemPlatesCli, ThePathCarriesTheContactLengths) {
  const double c = 1e-2;
  const ringtest::Run r =
      ringtest::ringvib("static " + write_scene(plates_scene(c)) + " --solver fem --json --set static.path=true");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  int lengths = 0;
  for (auto at = r.out.find("\"contact_length\""); at != std::string::npos; at = r.out.find("\"contact_length\"", at + 1))
    ++lengths;
  EXPECT_GE(lengths, 6) << r.out;  // the result's and the path's five
  const std::string last_point = r.out.substr(r.out.rfind("\"load_factor\""));
  const std::array<double, 2> at_end = pair_after(last_point, "\"reaction\"");
  const std::array<double, 2> result = pair_after(r.out.substr(r.out.rfind("\"reaction\"")), "\"reaction\"");
  EXPECT_LT(at_end[1], 0.0) << r.out;  // the upper plate pushes down
  EXPECT_NEAR(at_end[1], result[1], 1e-9 * std::abs(result[1])) << r.out;
}

// The steel tube of scenes/tube-crushing.toml with the path on (no history): R = 0.1 m, a
// 50 x 10 mm wall of the fibre law, sigma_y = 250 MPa (Mp = sigma_y b h^2 / 4 = 312.5 N m),
// crushed by the plates to half its diameter (travel 0.1 m), 40 steps, against DeRuntz & Hodge
// (plates_load, plates_contact_length at c = D / 2: 14.43 kN, 0.1047 m). At the FE settings that
// reach the full load: 32 cubic cells (0.9 s). The scene's own 40 cells of degree 5 stall at
// load factor 0.207 (and 40 cubic at 0.61, 32 of degree 4 at 0.15, 48 cubic at 0.49): points
// and fibres yield and unload within an arc corrector, their tangent jumping, and its Newton
// cycles (corrections ~5e-9 m repeating with period 4); the resultant law with hardening 1e-2
// or 1e-3 reaches the full load there, and widening the penalty's tangent band changes nothing
// (fem_reference/README.md, "Rigid plates").
TEST(FemPlatesCli, TheTubeIsCrushedToHalfItsDiameterAsDeRuntzAndHodge) {
  const double R = 0.1, b = 0.05, h = 0.01, sigma_y = 2.5e8, E = 2.1e11;
  const double Mp = sigma_y * b * h * h / 4.0, EI = E * b * h * h * h / 12.0;
  const ringtest::PinchedPlasticRing o{R, EI, Mp};
  const double c = 0.1;
  const std::string scene =
      "title = \"tube\"\n[ring]\nradius = 0.1\nE = 2.1e11\nrho = 7.8e3\n"
      "section = { shape = \"rectangle\", width = 0.05, height = 0.01 }\nplastic = { stress = 2.5e8 }\n"
      "[fem]\nelements = 32\ndegree = 3\n[plates]\naxis = 90.0\ntravel = 0.1\n"
      "[static]\nsolvers = [\"fem\"]\nsteps = 40\npath = true\nrecord = [90.0, 0.0, 180.0]\n";
  const ringtest::Run r = ringtest::ringvib("static " + write_scene(scene) + " --solver fem --json");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("\"end_load\": 1.0"), std::string::npos) << r.out;
  // The result's keys come in order: contact_length before the path, reaction after it.
  const std::array<double, 2> contact = pair_after(r.out, "\"contact_length\"");
  const std::array<double, 2> reaction = pair_after(r.out.substr(r.out.rfind("\"reaction\"")), "\"reaction\"");
  // Measured -3.5e-3 from the rigid-plastic force (14379.6 N against 14433.8 N): the
  // elastic-plastic ring lags the rigid-plastic curve by its elastic closing (Mp R / EI =
  // 3.6e-2 here) and the fibre law stays below Mp at a finite curvature; the penalty's rule
  // (8 Simpson pieces per cell) adds its first-order swing (1.3e-2 at 16 cells of degree 5,
  // half that at 32 cells). Bound 1e-2.
  EXPECT_NEAR(-reaction[1] / o.plates_load(c), 1.0, 1e-2) << r.out;
  EXPECT_NEAR(reaction[0] / o.plates_load(c), 0.0, 1e-9) << r.out;  // symmetric about the axis
  // Measured +1.0e-3 m (0.10573 m against 0.10472 m); bound: one spacing of the penalty's rule,
  // 2 pi R / (32 cells x 8 pieces) = 2.45e-3 m, where the contact front is resolved.
  EXPECT_NEAR(contact[0], o.plates_contact_length(c), 2.0 * M_PI * R / (32 * 8)) << r.out;
  EXPECT_NEAR(contact[1], contact[0], 1e-9) << r.out;
}

// The same tube with the plates withdrawn by 2 mm (static.history = [1.0, 0.98]): the ring
// unloads elastically. Its springback under the force at the full load P1 is about the pinch's
// elastic closing (pi/4 - 2/pi) P1 R^3 / EI = 2.45 mm, more than the 2 mm, so it stays on the
// plates (a longer withdrawal, [1.0, 0.97], leaves them and stalls: this beam holds no centre
// row yet) and the force falls by about 2 mm times the pinch's stiffness, 11.76 kN (measured:
// 14379.6 -> 2801.4 N, a fall 1.5 % below; the crushed ring is no longer the circle of the
// closed form, and its flats on the plates stiffen it). Bound: 5 % of the fall; no plastic work added (below).
TEST(FemPlatesCli, TheWithdrawnTubeSpringsBackElastically) {
  const double R = 0.1, b = 0.05, h = 0.01, E = 2.1e11, EI = E * b * h * h * h / 12.0;
  const ringtest::PinchedPlasticRing o{R, EI, 2.5e8 * b * h * h / 4.0};
  const std::string scene =
      "title = \"tube\"\n[ring]\nradius = 0.1\nE = 2.1e11\nrho = 7.8e3\n"
      "section = { shape = \"rectangle\", width = 0.05, height = 0.01 }\nplastic = { stress = 2.5e8 }\n"
      "[fem]\nelements = 32\ndegree = 3\n[plates]\naxis = 90.0\ntravel = 0.1\n"
      "[static]\nsolvers = [\"fem\"]\nsteps = 40\npath = true\nrecord = [90.0, 0.0, 180.0]\n";
  const std::string path = write_scene(scene);
  const ringtest::Run full = ringtest::ringvib("static " + path + " --solver fem --json");
  const ringtest::Run back = ringtest::ringvib("static " + path + " --solver fem --json --set 'static.history=[1.0, 0.98]'");
  ASSERT_EQ(full.code, 0) << full.err << full.out;
  ASSERT_EQ(back.code, 0) << back.err << back.out;
  const double P1 = -pair_after(full.out.substr(full.out.rfind("\"reaction\"")), "\"reaction\"")[1];
  const double P2 = -pair_after(back.out.substr(back.out.rfind("\"reaction\"")), "\"reaction\"")[1];
  const double fall = 2e-3 / o.elastic_closing(1.0);
  EXPECT_GT(P2, 0.0) << back.out;  // still on the plates
  EXPECT_NEAR((P1 - P2) / fall, 1.0, 5e-2) << full.out << back.out;
  // The result's plastic work (its first "dissipated", before the path's): measured 1262.366 J
  // and 1262.385 J, 1.5e-5 more (the few points that still yield as the arc turns at the top).
  auto work = [](const std::string& out) {
    const auto at = out.find("\"dissipated\"");
    return at == std::string::npos ? NAN : std::stod(out.substr(out.find(':', at) + 1));
  };
  EXPECT_NEAR(work(back.out) / work(full.out), 1.0, 1e-4) << full.out << back.out;
}
