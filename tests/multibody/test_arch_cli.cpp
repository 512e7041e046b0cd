// The arch through the command (`ringvib modes SCENE --solver multibody`, `ringvib static
// SCENE`): DaDeppo & Schmidt's deep arch (215 degrees, clamped at -17.5, pinned at 197.5, the
// apex load at 90) written by the test. Oracles: its lowest frequency against the inextensible
// arch (tests/support/arch.hpp), the path's largest load against DaDeppo & Schmidt's limit
// (archtest::deep_arch_limit: 8.97309), both within the chain's discretization error at
// n = 40 (measured in test_arch.cpp);
// a refusal names ring.arc with exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/cli.hpp"
#include "support/arch.hpp"

using ringtest::ringvib;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kR = 10.0, kE = 2.1e11, kRho = 7.8e3, kD = 0.12;
const double kEI = kE * kPi * std::pow(kD, 4) / 64.0;
const double kRhoA = kRho * kPi * kD * kD / 4.0;
constexpr double kLoad = 10.0;  // P R^2 / EI at load factor 1: above the limit

std::string deep_arch_scene() {
  const std::string dir = ringtest::temp_dir();
  std::ostringstream s;
  s.precision(17);
  s << "[ring]\nradius = " << kR << "\nE = " << kE << "\nrho = " << kRho
    << "\nsection = { shape = \"circle\", diameter = " << kD << " }\narc = [-17.5, 197.5]\n"
    << "[supports]\npin = -17.5\nclamp = -17.5\npins = [197.5]\n"
    << "[multibody]\nn = 40\n"
    << "[modes]\ncount = 3\nsolvers = [\"multibody\"]\n"
    << "[static]\nsolvers = [\"multibody\"]\nat = 90.0\nforce = [0.0, " << -kLoad * kEI / (kR * kR)
    << "]\nsteps = 10\npath = true\nrecord = [90.0, 197.5]\n";
  ringtest::write(dir + "/deep-arch.toml", s.str());
  return dir + "/deep-arch.toml";
}

TEST(ArchCli, ModesOfTheDeepArch) {
  const std::string scene = deep_arch_scene();
  const auto r = ringvib("modes " + scene + " --solver multibody --json --count 3");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["rigid_modes"], 0);  // clamped-pinned: RingSpec::rigid_modes()
  ASSERT_EQ(j["omega"].size(), 3u);
  archtest::Arch a;
  a.R = kR;
  a.alpha = 215.0 * kPi / 180.0;
  a.EI = kEI;
  a.rhoA = kRhoA;
  a.start = archtest::End::clamped;
  a.end = archtest::End::pinned;
  const double exact = archtest::arch_omegas(a, 1)[0], w = j["omega"][0].get<double>();
  // test_arch.cpp: omega^2 within 8.6e-4 at n = 96 at order 2, so about 5e-3 at n = 40 (2.5e-3
  // in omega); 1e-2 bounds it.
  EXPECT_NEAR(w, exact, 1e-2 * exact);
}

TEST(ArchCli, StaticPathThroughTheLimitPoint) {
  const std::string scene = deep_arch_scene();
  const auto r = ringvib("static " + scene + " --solver multibody --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("path"));
  double most = 0.0;
  for (const auto& p : j["path"]) most = std::max(most, p["load_factor"].get<double>());
  // The chain's limit at n = 40 is 8.920 (test_arch.cpp), 0.6 % below the elastica's: 1 % bounds
  // both the discretization and the step between accepted points.
  const double exact = archtest::deep_arch_limit().load;
  EXPECT_NEAR(most * kLoad, exact, 0.01 * exact);
}

TEST(ArchCli, ForcedSparseIsRefusedNamingTheArch) {
  const std::string scene = deep_arch_scene();
  const auto r = ringvib("modes " + scene + " --solver multibody --set multibody.method=\"sparse\"");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("ring.arc"), std::string::npos) << r.err;
}

}  // namespace
