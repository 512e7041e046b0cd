// The lumped chain's arch through the command, as a user runs it: `ringvib modes SCENE
// --solver lumped` and `ringvib static SCENE` (lumped in static.solvers) on a scene with
// ring.arc, written here (DaDeppo & Schmidt's deep arch on the paper's ring's material).
//
// Oracles: tests/support/arch.hpp, the exact inextensible arch's frequencies
// (archtest::arch_omegas) and the elastica's equilibrium under an apex load below the limit
// (archtest::deep_arch_under); the refusal by key (exit 2 naming ring.arc).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "../compare/cli.hpp"
#include "support/arch.hpp"

namespace {

using ringtest::ringvib;

constexpr double kRadius = 10.0, kE = 2.1e11, kRho = 7.8e3, kDiameter = 0.12;
constexpr double kPi = 3.14159265358979323846;

double EI() { return kE * kPi * std::pow(kDiameter, 4) / 64.0; }
double rhoA() { return kRho * kPi * kDiameter * kDiameter / 4.0; }

/// The deep arch: 215 degrees from -17.5 (clamped) to 197.5 (pinned), a dead load
/// `load` EI/R^2 down at the apex (90 degrees), the chain with n links.
std::string deep_arch_scene(double load, int n, bool path, const std::string& extra = "") {
  const std::string dir = ringtest::temp_dir(), file = dir + "/deep-arch.toml";
  ringtest::write(file, "title = \"The deep arch, lumped\"\n"
                        "[ring]\nradius = 10.0\nE = 2.1e11\nrho = 7.8e3\n"
                        "section = { shape = \"circle\", diameter = 0.12 }\narc = [-17.5, 197.5]\n"
                        "[supports]\npin = -17.5\npins = [197.5]\nclamp = -17.5\n"
                        "[lumped]\nn = " + std::to_string(n) + "\n"
                        "[modes]\ncount = 3\nsolvers = [\"lumped\"]\n"
                        "[static]\nsolvers = [\"lumped\"]\nat = 90.0\nforce = [0.0, " +
                        std::to_string(-load * EI() / (kRadius * kRadius)) + "]\nrecord = [90.0]\n" +
                        (path ? "path = true\n" : "") + extra);
  return file;
}

// The modes: exit 0, the three lowest frequencies within the chain's O(l^2) of the exact
// inextensible arch's (archtest::arch_omegas, the scene's R, EI, rho A). Measured at n = 64:
// -8.2e-4, -9.7e-4, -5.5e-4; bound 2e-3 (the largest error of arch_test.cpp's arches at n = 64,
// 9.5e-5 x 16 = 1.5e-3).
TEST(LumpedArchCli, ModesOfTheDeepArchMeetTheExactArchs) {
  const auto r = ringvib("modes " + deep_arch_scene(8.0, 64, false) + " --solver lumped --json -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const std::vector<double> omega = j.at("omega").get<std::vector<double>>();
  archtest::Arch a;
  a.R = kRadius;
  a.alpha = 215.0 * kPi / 180.0;
  a.EI = EI();
  a.rhoA = rhoA();
  a.start = archtest::End::clamped;
  a.end = archtest::End::pinned;
  const std::vector<double> exact = archtest::arch_omegas(a, 3);
  ASSERT_EQ(omega.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(omega[k] / exact[k], 1.0, 2e-3) << "mode " << k + 1;
}

// The statics under 8 EI/R^2 (below the limit 8.973): the apex's displacement against the
// elastica's on the rising branch, within the chain's O(l^2) at n = 40: measured (dx, dy) off
// by (-1.7e-3, -6.7e-3) R of (-0.563, -0.946) R; bound 2e-2 R.
TEST(LumpedArchCli, StaticsOfTheDeepArchMeetTheElastica) {
  const archtest::DeepArchPoint e = archtest::deep_arch_under(8.0);
  const auto r = ringvib("static " + deep_arch_scene(8.0, 40, false) + " --solver lumped --json -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const auto& d = j.at("displacements").at(0);
  EXPECT_EQ(d.at("angle").get<double>(), 90.0);
  EXPECT_NEAR(d.at("ux").get<double>() / kRadius, e.apex_dx, 2e-2);
  EXPECT_NEAR(d.at("uy").get<double>() / kRadius, e.apex_dy, 2e-2);
  // And as the scene asks, lumped in static.solvers: the command without --solver.
  const auto all = ringvib("static " + deep_arch_scene(8.0, 40, false) + " -q");
  EXPECT_EQ(all.code, 0) << all.err;
}

// static.path under 10 EI/R^2 goes through the limit point: the path's load rises to about
// 0.897 (the limit within the chain's 5.9e-3 at n = 40 and the path's last accepted step
// before it) and falls past it.
TEST(LumpedArchCli, ThePathPassesTheLimitPoint) {
  const auto r = ringvib("static " + deep_arch_scene(10.0, 40, true) + " --solver lumped --json -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const auto& path = j.at("path");
  ASSERT_GT(path.size(), 5u);
  double highest = 0.0, after = INFINITY;
  for (const auto& p : path) {
    const double s = p.at("load_factor").get<double>();
    if (s > highest) highest = s, after = INFINITY;
    after = std::min(after, s);
  }
  EXPECT_GT(highest, 0.85);
  EXPECT_LT(highest, 0.8973 + 1e-3);
  EXPECT_LT(after, 0.8 * highest);
}

// What the chain does not take on an arch exits 2 naming ring.arc: the modes under load.
TEST(LumpedArchCli, ModesUnderLoadOfAnArchAreRefusedByKey) {
  const auto r = ringvib("modes " + deep_arch_scene(8.0, 40, false) + " --solver lumped -q --set modes.preload=\"static\"");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("ring.arc"), std::string::npos) << r.err;
}

}  // namespace
