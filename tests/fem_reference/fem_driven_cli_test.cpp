// The FE beam's displacement control through the command: `ringvib static SCENE --solver fem
// --json` on the paper's ring pinned at 270 deg with the point at 90 deg driven down
// (static.displacement), the JSON's "reaction" against the pinch's closed form
// P = c / ((pi/4 - 2/pi) R^3 / EI) (tests/support/plastic_ring.hpp); a driven point the beam
// cannot place refused with exit 2 naming static.displacement.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "compare/cli.hpp"
#include "support/json_text.hpp"
#include "support/paper.hpp"
#include "support/plastic_ring.hpp"

namespace {

std::string write_scene(const std::string& text) {
  const std::string dir = ringtest::temp_dir(), path = dir + "/driven.toml";
  ringtest::write(path, text);
  return path;
}

/// The paper's ring pinned at 270 deg, 90 deg driven down by `closing` (m), 32 cubic elements.
std::string driven_scene(double closing, const std::string& extra = "") {
  return "title = \"driven pinch\"\n" + ringtest::paper_ring_toml() +
         "[supports]\npin = 270.0\n[fem]\nelements = 32\ndegree = 3\n" + extra +
         "[static]\nsolvers = [\"fem\"]\nsteps = 2\nrecord = [90.0, 0.0]\ndisplacement = { at = 90.0, value = [0.0, -" +
         std::to_string(closing) + "] }\n";
}

using ringtest::pair_after;

}  // namespace

TEST(FemDrivenCli, ReactionMeetsThePinchClosedForm) {
  const ring::RingSpec spec = ringtest::driven_plastic_ring(std::nullopt);
  const ringtest::PinchedPlasticRing o{spec.radius, spec.EI(), 0.0};
  const double c = 1e-4;  // m: 1e-5 R, the small closing of FemDriven.ElasticReactionConvergesToTheClosedForm
  const ringtest::Run r = ringtest::ringvib("static " + write_scene(driven_scene(c)) + " --solver fem --json");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const std::array<double, 2> reaction = pair_after(r.out, "\"reaction\"");
  const double P = c / o.elastic_closing(1.0);
  // 32 cubic elements: 3.8e-5 from the closed form (FemDriven: the membrane's share 4.5e-5, the
  // geometric c / R = 1e-5, the mesh's 1.7e-5 of the other sign); bound 1e-4 as FemDriven's.
  EXPECT_NEAR(-reaction[1] / P, 1.0, 1e-4) << r.out;
  EXPECT_NEAR(reaction[0] / P, 0.0, 1e-6) << r.out;  // symmetric about the vertical diameter
}

TEST(FemDrivenCli, ADrivenPointOffTheVerticesIsRefusedByTheKey) {
  // 32 elements from the pin at 270 deg: vertices every 11.25 deg, none at 95.
  std::string text = driven_scene(1e-4);
  text.replace(text.find("at = 90.0"), 9, "at = 95.0");
  const ringtest::Run r = ringtest::ringvib("static " + write_scene(text) + " --solver fem --json");
  EXPECT_EQ(r.code, 2) << r.err << r.out;
  EXPECT_NE(r.err.find("static.displacement"), std::string::npos) << r.err;
}
