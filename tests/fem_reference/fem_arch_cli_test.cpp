// The FE beam's arch through the command: `ringvib modes SCENE --solver fem` and `ringvib static
// SCENE` with fem in static.solvers on DaDeppo & Schmidt's deep arch (215 deg, clamped at
// -17.5 deg, pinned at 197.5 deg), and the analyses that take no arch yet refused by ring.arc
// with exit 2. Oracles: tests/support/arch.hpp (the transfer matrix, the elastica).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "compare/cli.hpp"
#include "support/arch.hpp"
#include "support/paper.hpp"

namespace {

/// The paper's ring's section (R = 10 m, d = 0.12 m) as the deep arch, 20 elements of degree 4.
std::string deep_arch_scene(const std::string& analyses) {
  return "title = \"deep arch\"\n" + ringtest::paper_ring_toml() +
         "arc = [-17.5, 197.5]\n[supports]\nclamp = -17.5\npins = [197.5]\n[fem]\nelements = 20\ndegree = 4\n" +
         analyses;
}

std::string write_scene(const std::string& text) {
  const std::string dir = ringtest::temp_dir(), path = dir + "/arch.toml";
  ringtest::write(path, text);
  return path;
}

}  // namespace

TEST(FemArchCli, ModesOfTheDeepArch) {
  const std::string scene = write_scene(deep_arch_scene("[modes]\ncount = 3\nsolvers = [\"fem\"]\n"));
  const ringtest::Run r = ringtest::ringvib("modes " + scene + " --solver fem --json");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  // The lowest frequency of the clamped-pinned arch (transfer matrix, extensible; EI, rho A of
  // the paper's section): printed with 6 digits or more.
  archtest::Arch a;
  a.R = 10.0;
  a.alpha = 215.0 * M_PI / 180.0;
  const double d = 0.12, area = M_PI * d * d / 4, inertia = M_PI * std::pow(d, 4) / 64;
  a.EI = 2.1e11 * inertia;
  a.EA = 2.1e11 * area;
  a.rhoA = 7.8e3 * area;
  a.start = archtest::End::clamped;
  a.end = archtest::End::pinned;
  const double omega = archtest::arch_omegas(a, 1).at(0);
  const std::string key = "\"omega\"";
  const auto at = r.out.find(key);
  ASSERT_NE(at, std::string::npos) << r.out;
  const double fe = std::stod(r.out.substr(r.out.find('[', at) + 1));
  // 20 quartic elements: order 6, ~1e-9 measured in FemArch; 1e-6 leaves the print's rounding.
  EXPECT_NEAR(fe / omega, 1.0, 1e-6) << r.out.substr(at, 200);
}

TEST(FemArchCli, StaticsOfTheDeepArchBelowItsLimit) {
  // P R^2/EI = 8 (EI = 2.1e11 pi 0.12^4 / 64 = 2.1375e6 N m^2): the rising branch.
  const double EI = 2.1e11 * M_PI * std::pow(0.12, 4) / 64, P = 8.0 * EI / 100.0;
  const std::string scene = write_scene(deep_arch_scene(
      "[static]\nsolvers = [\"fem\"]\nat = 90.0\nforce = [0.0, -" + std::to_string(P) + "]\nsteps = 20\nrecord = [90.0]\n"));
  const ringtest::Run r = ringtest::ringvib("static " + scene + " --solver fem --json");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const archtest::DeepArchPoint exact = archtest::deep_arch_under(8.0);
  const auto at = r.out.find("\"uy\"");
  ASSERT_NE(at, std::string::npos) << r.out;
  const double uy = std::stod(r.out.substr(r.out.find(':', at) + 1));
  // The extensible beam of slenderness 333 and the inextensible elastica differ by ~1e-4 of
  // the apex displacement (FemArch.DeepArchApexMeetsTheElastica measures it); 1e-3 here.
  EXPECT_NEAR(uy / (10.0 * exact.apex_dy), 1.0, 1e-3) << r.out.substr(at, 200);
}

TEST(FemArchCli, TheTimoshenkoModelRefusesAnArchByTheKey) {
  std::string text = deep_arch_scene("[modes]\ncount = 3\nsolvers = [\"fem\"]\n");
  text.replace(text.find("arc = "), 0, "theory = \"timoshenko\"\n");
  const ringtest::Run r = ringtest::ringvib("modes " + write_scene(text) + " --solver fem");
  EXPECT_EQ(r.code, 2) << r.err << r.out;
  EXPECT_NE(r.err.find("ring.arc"), std::string::npos) << r.err;
}

// static.path = true through the limit point (P R^2/EI = 10 asked, beyond the limit): the path
// passes the limit, the apex snaps down and the run ends, exit 0, where the loaded part comes
// within a section depth of the pinned end (contact: a result of the path). The largest load
// factor on the path is the limit's: the elastica's 8.97309 / 10 within 2e-3 (20 quartic
// elements: 1.8e-4 of discretization, 1.4e-4 of extensibility, FemArch; the accepted points
// next to the maximum lie within 1e-5 of it; measured 0.897217).
TEST(FemArchCli, StaticPathThroughTheDeepArchsLimit) {
  const double EI = 2.1e11 * M_PI * std::pow(0.12, 4) / 64, P = 10.0 * EI / 100.0;
  const std::string scene = write_scene(deep_arch_scene("[static]\nsolvers = [\"fem\"]\nat = 90.0\nforce = [0.0, -" +
                                                        std::to_string(P) + "]\nsteps = 20\npath = true\nrecord = [90.0]\n"));
  const ringtest::Run r = ringtest::ringvib("static " + scene + " --solver fem --json");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("\"end\": \"contact"), std::string::npos) << r.out.substr(0, 400);
  double top = 0.0;
  const std::string key = "\"load_factor\":";
  for (auto at = r.out.find(key); at != std::string::npos; at = r.out.find(key, at + 1))
    top = std::max(top, std::stod(r.out.substr(at + key.size())));
  EXPECT_NEAR(10.0 * top / archtest::deep_arch_limit().load, 1.0, 2e-3) << top;
}
