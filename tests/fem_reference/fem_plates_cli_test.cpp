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

/// The two numbers of the JSON array after `key`.
std::array<double, 2> pair_after(const std::string& out, const std::string& key) {
  const auto at = out.find(key);
  if (at == std::string::npos) return {NAN, NAN};
  const auto open = out.find('[', at), comma = out.find(',', open);
  return {std::stod(out.substr(open + 1)), std::stod(out.substr(comma + 1))};
}

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
