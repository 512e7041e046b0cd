// Rigid plates through the command (`ringvib static SCENE --solver multibody --json`): the free
// paper ring crushed between plates at axis 90 deg by c = 1e-4 R, written by the test. Oracle:
// the thin elastic ring's pinching force P = c / ((pi/4 - 2/pi) R^3 / EI)
// (tests/support/plastic_ring.hpp), which the chain reaches at order 2 in 1/n (test_plates.cpp:
// 1.96e-3 at n = 128); the contact length at such an approach is the one touching hinge's, far
// below a segment. Both formulations give it. A combination the chain does not take (plates that
// back off) is refused with exit 2 naming plates.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/cli.hpp"

using ringtest::ringvib;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kR = 10.0, kE = 2.1e11, kRho = 7.8e3, kD = 0.12;
const double kEI = kE * kPi * std::pow(kD, 4) / 64.0;
constexpr double kTravel = 1e-4 * kR;

std::string scene(const std::string& name, const std::string& method, const std::string& history = "") {
  const std::string dir = ringtest::temp_dir();
  std::ostringstream s;
  s.precision(17);
  s << "[ring]\nradius = " << kR << "\nE = " << kE << "\nrho = " << kRho
    << "\nsection = { shape = \"circle\", diameter = " << kD << " }\n"
    << "[multibody]\nn = 128\nmethod = \"" << method << "\"\n"
    << "[static]\nsolvers = [\"multibody\"]\nsteps = 2\nrecord = [90.0, 0.0]\n" << history
    << "[plates]\naxis = 90.0\ntravel = " << kTravel << "\n";
  ringtest::write(dir + "/" + name, s.str());
  return dir + "/" + name;
}

TEST(PlatesCli, TheForceIsTheClosedFormPinch) {
  const auto r = ringvib("static " + scene("plates.toml", "dense") + " --solver multibody --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("reaction")) << r.out;
  ASSERT_TRUE(j.contains("contact_length")) << r.out;
  const double exact = kTravel / ((kPi / 4.0 - 2.0 / kPi) * kR * kR * kR / kEI);
  // Order 2 in 1/n, 1.96e-3 measured at n = 128 (test_plates.cpp); 4e-3 bounds it, the O(c / R)
  // nonlinearity (~1e-4) and the default penalty's sinking (~1e-6).
  EXPECT_NEAR(-j["reaction"][1].get<double>(), exact, 4e-3 * exact);
  EXPECT_NEAR(j["reaction"][0].get<double>(), 0.0, 1e-9 * exact);
  // One touching hinge per plate: the contact's extent is below a segment (2 pi R / 128), equal
  // on both plates (DeRuntz & Hodge's flat part, 2 R asin(c / 2R) = c, is below it too).
  const double l = 2.0 * kPi * kR / 128.0;
  for (int p = 0; p < 2; ++p) {
    EXPECT_GE(j["contact_length"][p].get<double>(), 0.0);
    EXPECT_LT(j["contact_length"][p].get<double>(), l);
  }
}

// The O(n) path (hinge positions) gives the same force (test_plates.cpp: to a few k l ulp(R)).
TEST(PlatesCli, TheOrderNPathGivesTheSameForce) {
  const auto a = ringvib("static " + scene("plates_dense.toml", "dense") + " --solver multibody --json");
  const auto b = ringvib("static " + scene("plates_sparse.toml", "sparse") + " --solver multibody --json");
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const double fa = nlohmann::json::parse(a.out)["reaction"][1].get<double>();
  const double fb = nlohmann::json::parse(b.out)["reaction"][1].get<double>();
  // The penalty's resolution, k l ulp(R) ~ 2e-4 N at n = 128 (E A^2 / (12 I) = 2.2e11 N/m^2),
  // against a force of 14 N: 1e-4 of it bounds a few quanta.
  EXPECT_NEAR(fb, fa, 1e-4 * std::abs(fa));
}

// Plates that back off (a decreasing static.history) are refused (checks.cpp says why).
TEST(PlatesCli, RetreatingPlatesAreRefusedNamingPlates) {
  const auto r = ringvib("static " + scene("plates_back.toml", "dense", "history = [1.0, 0.5]\n") +
                         " --solver multibody --json");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("plates"), std::string::npos) << r.err;
}

}  // namespace
