// Displacement control through the command (`ringvib static SCENE --solver multibody --json`):
// the paper's ring pinned at 270 deg, the point at 90 driven down by c = 1e-5 R, written by the
// test. Oracle: the thin elastic ring's pinching force P = c / ((pi/4 - 2/pi) R^3 / EI)
// (tests/support/plastic_ring.hpp), which the chain reaches at order 2 in 1/n
// (test_driven_statics.cpp). A combination the chain does not take is refused with exit 2
// naming static.displacement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/cli.hpp"

using ringtest::ringvib;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kR = 10.0, kE = 2.1e11, kRho = 7.8e3, kD = 0.12;
const double kEI = kE * kPi * std::pow(kD, 4) / 64.0;
constexpr double kClosing = 1e-5 * kR;

std::string ring_toml() {
  std::ostringstream s;
  s.precision(17);
  s << "[ring]\nradius = " << kR << "\nE = " << kE << "\nrho = " << kRho
    << "\nsection = { shape = \"circle\", diameter = " << kD << " }\n";
  return s.str();
}

std::string scene(const std::string& name, const std::string& supports, const std::string& extra = "") {
  const std::string dir = ringtest::temp_dir();
  std::ostringstream s;
  s.precision(17);
  s << ring_toml() << extra << "[supports]\n" << supports << "[multibody]\nn = 128\n"
    << "[static]\nsolvers = [\"multibody\"]\nsteps = 2\nrecord = [90.0, 0.0]\n"
    << "displacement = { at = 90.0, value = [0.0, " << -kClosing << "] }\n";
  ringtest::write(dir + "/" + name, s.str());
  return dir + "/" + name;
}

TEST(DrivenCli, TheReactionIsTheClosedFormPinch) {
  const auto r = ringvib("static " + scene("driven.toml", "pin = 270.0\n") + " --solver multibody --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("reaction")) << r.out;
  const double exact = kClosing / ((kPi / 4.0 - 2.0 / kPi) * kR * kR * kR / kEI);
  // test_driven_statics.cpp: order 2 in 1/n, 1.92e-3 measured at n = 128; 4e-3 bounds it and
  // the O(c / R) = 1e-5 nonlinearity.
  EXPECT_NEAR(-j["reaction"][1].get<double>(), exact, 4e-3 * exact);
  EXPECT_NEAR(j["reaction"][0].get<double>(), 0.0, 1e-9 * exact);
}

// The free ring on a foundation (k_r = 500, k_t = 300 N/m^2: every rigid motion held without a
// pin), its point at 90 driven: the multibody chain's reaction against the lumped chain's on the
// same scene (n = 128 both), another implementation of the hinged chain (Cartesian hinges, the
// foundation on the hinges' displacements: lumped_mass/terms.hpp) with the drive as its own
// constraint rows: they agree to the Newton tolerance, 3.4e-12 measured, bound 1e-8. A ring held by
// a radial foundation and the driven point alone is refused by the key.
TEST(DrivenCli, ADrivenFreeRingOnAFoundationAgreesWithTheLumpedChain) {
  const std::string file =
      scene("free.toml", "", "[foundation]\nradial = 500.0\ntangential = 300.0\n[lumped]\nn = 128\n");
  double reaction[2][2];
  const char* solvers[2] = {"multibody", "lumped"};
  for (int k = 0; k < 2; ++k) {
    const auto r = ringvib("static " + file + " --solver " + solvers[k] + " --json");
    ASSERT_EQ(r.code, 0) << solvers[k] << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    reaction[k][0] = j["reaction"][0].get<double>();
    reaction[k][1] = j["reaction"][1].get<double>();
  }
  std::printf("[ free driven cli ] multibody %.12e, lumped %.12e N: %.3e\n", reaction[0][1], reaction[1][1],
              reaction[1][1] / reaction[0][1] - 1.0);
  ASSERT_LT(reaction[0][1], 0.0);
  EXPECT_NEAR(reaction[1][1] / reaction[0][1], 1.0, 1e-8);
  EXPECT_NEAR(reaction[0][0], 0.0, 1e-9 * std::abs(reaction[0][1]));
  const auto r = ringvib("static " + scene("radial.toml", "", "[foundation]\nradial = 500.0\n") +
                         " --solver multibody --json");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("static.displacement"), std::string::npos) << r.err;
}

}  // namespace
