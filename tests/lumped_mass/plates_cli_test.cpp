// Rigid plates ([plates]) through the command, as a user runs it: `ringvib static SCENE --solver
// lumped --json` on a scene written here (the paper's ring, free, perfectly plastic with
// Mp R / EI = 1e-4, crushed by plates at 90 deg to an approach of R), and a refusal's exit 2.
//
// Oracle: DeRuntz & Hodge's rigid-plastic crushing (tests/support/plastic_ring.hpp,
// PinchedPlasticRing::plates_load, plates_contact_length), which the chain meets within l / R in
// the force and one link per side in the contact length (plates_test.cpp says why; at n = 64 at
// c = R: 0.964 of the force and 9.81 m against 10.47 m, measured).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <string>

#include "../compare/cli.hpp"
#include "tests/support/plastic_ring.hpp"

namespace {

using ringtest::ringvib;

constexpr double kRadius = 10.0, kE = 2.1e11, kDiameter = 0.12;
constexpr int kN = 64;

double EI() { return kE * M_PI * std::pow(kDiameter, 4) / 64.0; }
double Mp() { return 1e-4 * EI() / kRadius; }

/// The paper's ring, perfectly plastic (resultant law), the chain with n = 64 and `variant`, and
/// the plates at 90 deg approaching by R; [static] with path = true.
std::string plates_scene(const std::string& variant = "chain") {
  const std::string dir = ringtest::temp_dir(), file = dir + "/plates-crush.toml";
  ringtest::write(file,
                  "title = \"The crushed ring, lumped\"\n"
                  "[ring]\nradius = 10.0\nE = 2.1e11\nrho = 7.8e3\n"
                  "section = { shape = \"circle\", diameter = 0.12 }\n"
                  "plastic = { moment = " + std::to_string(Mp()) + " }\n"
                  "[plates]\naxis = 90.0\ntravel = 10.0\n"
                  "[lumped]\nn = " + std::to_string(kN) + "\nvariant = \"" + variant + "\"\n"
                  "[static]\nsolvers = [\"lumped\"]\nrecord = [90.0]\npath = true\n");
  return file;
}

// "reaction" = [~0, -F] with F within l / R of DeRuntz & Hodge's load at c = R, "contact_length"
// both plates alike within 2 l of theirs; every path point carries both, the last the end's, and
// the first (rest) none.
TEST(LumpedPlatesCli, ForceAndContactLengthInTheJson) {
  const auto r = ringvib("static " + plates_scene() + " --solver lumped --json -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  using Pair = std::array<double, 2>;
  const ringtest::PinchedPlasticRing o{kRadius, EI(), Mp()};
  const double c = kRadius, l = 2.0 * M_PI * kRadius / kN, P = o.plates_load(c), L = o.plates_contact_length(c);
  const Pair reaction = j.at("reaction").get<Pair>(), length = j.at("contact_length").get<Pair>();
  ::testing::Test::RecordProperty("force_over_deruntz_hodge", std::to_string(-reaction[1] / P));
  ::testing::Test::RecordProperty("contact_length_m", std::to_string(length[0]));
  EXPECT_NEAR(-reaction[1] / P, 1.0, l / kRadius);
  EXPECT_LT(std::abs(reaction[0]), 1e-6 * P);
  EXPECT_NEAR(length[0], L, 2.0 * l);
  EXPECT_NEAR(length[1], length[0], 1e-9 * L);
  const auto& path = j.at("path");
  ASSERT_GT(path.size(), 20u);
  EXPECT_EQ(path.back().at("reaction").get<Pair>(), reaction);
  EXPECT_EQ(path.back().at("contact_length").get<Pair>(), length);
  EXPECT_EQ(path.front().at("reaction").get<Pair>(), Pair{});
  EXPECT_EQ(path.front().at("contact_length").get<Pair>(), Pair{});
}

// The frames' statics take plates at the end of the path only: static.path = true with them is
// refused, exit 2, naming [plates] and saying which variant takes both.
TEST(LumpedPlatesCli, TheFramesRefuseThePlatesAlongAPath) {
  const auto r = ringvib("static " + plates_scene("frame") + " --solver lumped -q");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("plates"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("chain"), std::string::npos) << r.err;
}

}  // namespace
