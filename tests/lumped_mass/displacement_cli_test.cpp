// Displacement control through the command, as a user runs it: `ringvib static SCENE --solver
// lumped --json` on a scene written here (the paper's ring pinned at 270 deg, the point at 90 deg
// driven down by static.displacement), and a refusal's exit 2.
//
// Oracle: the inextensible ring's pinching force for a closing c, P = c / ((pi/4 - 2/pi) R^3 /
// EI) (Roark's ring case 1; tests/support/plastic_ring.hpp, PinchedPlasticRing), which the
// chain meets at order 2 in n (displacement_test.cpp: 7.6e-3 at n = 64).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <string>

#include "../compare/cli.hpp"

namespace {

using ringtest::ringvib;

constexpr double kRadius = 10.0, kE = 2.1e11, kDiameter = 0.12;
constexpr double kPi = 3.14159265358979323846;

double EI() { return kE * kPi * std::pow(kDiameter, 4) / 64.0; }

/// The paper's ring, `supports` and `extra` (TOML lines), the chain with n = 64, and [static]
/// driving 90 deg by [0, -closing] m, recorded at 90 deg; `more`: further TOML sections before
/// [static], `also`: further [static] lines.
std::string driven_scene(double closing, const std::string& supports, const std::string& extra, bool path,
                         const std::string& more = "", const std::string& also = "") {
  const std::string dir = ringtest::temp_dir(), file = dir + "/driven-pinch.toml";
  ringtest::write(file,
                  "title = \"The driven pinch, lumped\"\n"
                  "[ring]\nradius = 10.0\nE = 2.1e11\nrho = 7.8e3\n"
                  "section = { shape = \"circle\", diameter = 0.12 }\n" +
                      extra + "[supports]\n" + supports + "[lumped]\nn = 64\n" + more +
                      "[static]\nsolvers = [\"lumped\"]\nrecord = [90.0]\n"
                      "displacement = { at = 90.0, value = [0.0, " +
                      std::to_string(-closing) + "] }\n" + (path ? "path = true\n" : "") + also);
  return file;
}

// Closing 1e-6 R: "reaction" is [~0, -P] within the chain's error at n = 64 (7.6e-3 measured;
// bound 1e-2), and every path point carries its reaction, the last one the end's.
TEST(LumpedDisplacementCli, TheReactionIsThePinchingForce) {
  const double c = 1e-6 * kRadius, P = c / ((kPi / 4.0 - 2.0 / kPi) * std::pow(kRadius, 3) / EI());
  const auto r = ringvib("static " + driven_scene(c, "pin = 270.0\n", "", true) + " --solver lumped --json -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  using Pair = std::array<double, 2>;
  const Pair reaction = j.at("reaction").get<Pair>();
  EXPECT_NEAR(-reaction[1] / P, 1.0, 1e-2);
  EXPECT_LT(std::abs(reaction[0]), 1e-9 * P);
  const auto& path = j.at("path");
  ASSERT_GT(path.size(), 2u);
  EXPECT_EQ(path.back().at("reaction").get<Pair>(), reaction);
  EXPECT_EQ(path.front().at("reaction").get<Pair>(), Pair{});
}

// The semicircular arch pinned at both ends (ring.arc = [0, 180]), its crown driven down by
// 1e-6 R: the lumped chain's reaction against the multibody chain's from the same scene, both at
// n = 64. They are the same hinged chain in other unknowns (Cartesian hinges here, segment
// angles there: vs_multibody_test.cpp) with the drive as other constraint rows, so they agree to
// the Newton tolerance: 3.5e-11 measured, bound 1e-8. The crown's x reaction vanishes by
// symmetry (1e-11 of the y measured). And loads beside the drive still exit 2 naming
// static.displacement (the scene reader's rule).
TEST(LumpedDisplacementCli, ADrivenArchAgreesWithTheMultibodyChain) {
  const double c = 1e-6 * kRadius;
  const std::string arch = "pin = 0.0\npins = [180.0]\n", arc = "arc = [0.0, 180.0]\n";
  const std::string file = driven_scene(c, arch, arc, false, "[multibody]\nn = 64\n");
  using Pair = std::array<double, 2>;
  Pair reaction[2];
  const char* solvers[2] = {"lumped", "multibody"};
  for (int k = 0; k < 2; ++k) {
    const auto r = ringvib("static " + file + " --solver " + solvers[k] + " --json -q");
    ASSERT_EQ(r.code, 0) << solvers[k] << ": " << r.err;
    reaction[k] = nlohmann::json::parse(r.out).at("reaction").get<Pair>();
  }
  ::testing::Test::RecordProperty("lumped_over_multibody_minus_1",
                                  std::to_string(reaction[0][1] / reaction[1][1] - 1.0));
  ASSERT_LT(reaction[1][1], 0.0);
  EXPECT_NEAR(reaction[0][1] / reaction[1][1], 1.0, 1e-8);
  EXPECT_LT(std::abs(reaction[0][0]), 1e-8 * std::abs(reaction[0][1]));
  const std::string loaded = driven_scene(c, arch, arc, false, "", "at = 45.0\nforce = [1.0, 0.0]\n");
  const auto r = ringvib("static " + loaded + " --solver lumped -q");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("static.displacement"), std::string::npos) << r.err;
}

}  // namespace
