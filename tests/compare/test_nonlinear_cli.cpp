// The nonlinear comparison through the binary, on the shipped compare scenes: two
// independent solvers of the same chain (multibody in segment angles, lumped in
// Cartesian hinge positions) and the geometrically exact FE beam with its converged
// reference. Oracles: the chains' statics agree to round-off (the same equilibrium);
// their forced responses differ by the rotary inertia the lumped chain leaves out and
// by each integrator's O(dt^2) error, which at the paper's dt = 0.01 s is below 0.5 % of
// the loaded point's peak (measured 0.04 %); both chains converge to the FE reference
// at second order in n; the contracts of docs/commands.md (JSON keys, single-solver outputs,
// gates, files).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

const nlohmann::json* row(const nlohmann::json& t, double point, const std::string& q) {
  for (const auto& r : t["rows"])
    if (r["point"] == point && r["quantity"] == q) return &r;
  return nullptr;
}

TEST(NonlinearCli, StaticsOfTwoSolversAgreeToRoundOff) {
  const auto r = ringvib("static " + source("scenes/paper1990-static-compare.toml") + " --format json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto t = nlohmann::json::parse(r.out);
  EXPECT_EQ(t["analysis"], "static");
  EXPECT_EQ(t["base"], "multibody");
  const auto* u = row(t, 0.0, "u");
  ASSERT_NE(u, nullptr);
  EXPECT_NEAR((*u)["lumped_diff_pct"].get<double>(), 0.0, 1e-9);
  EXPECT_GT((*u)["multibody"].get<double>(), 1.5);  // the 20 kN squeeze shortens AC by 1.58 m
  EXPECT_TRUE((*row(t, 180.0, "u"))["lumped_diff_pct"].is_null());  // the pin does not move
  // One solver picked: today's object plus "solver".
  const auto one = ringvib("static " + source("scenes/paper1990-static-compare.toml") + " --solver lumped --json");
  ASSERT_EQ(one.code, 0) << one.err;
  const auto j = nlohmann::json::parse(one.out);
  EXPECT_EQ(j["solver"], "lumped");
  for (const char* k : {"displacements", "steps", "newton_iterations"}) EXPECT_TRUE(j.contains(k)) << k;
}

TEST(NonlinearCli, ResponsesOfTwoSolversAgreeWithinTheirModelDifference) {
  const std::string scene = source("scenes/paper1990-forced-compare.toml");
  const auto r = ringvib("respond " + scene + " --format json --set response.t_end=1.5");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto t = nlohmann::json::parse(r.out);
  EXPECT_EQ(t["analysis"], "response");
  const auto* peak = row(t, 0.0, "peak_u");
  ASSERT_NE(peak, nullptr);
  EXPECT_LT(std::abs((*peak)["lumped_diff_pct"].get<double>()), 0.5);
  // One solver with --csv: today's columns.
  const std::string csv = ringtest::temp_dir() + "/h.csv";
  ASSERT_EQ(ringvib("respond " + scene + " --solver lumped --set response.t_end=0.1 --csv " + csv).code, 0);
  std::ifstream f(csv);
  std::string header;
  std::getline(f, header);
  EXPECT_EQ(header,
            "t,ux_0,uy_0,ux_90,uy_90,ux_180,uy_180,ux_270,uy_270,kinetic,strain,work,energy_error,"
            "constraint_residual,newton_iterations");
  // Several solvers and --csv: which history is meant is ambiguous: exit 2.
  EXPECT_EQ(ringvib("respond " + scene + " --csv " + csv).code, 2);
}

// A free ring held by its foundation alone (the tyre ring of scenes/tyre-ring.toml, no
// support) under a 100 N step load at 0 deg: every solver integrates it (the scene reader
// used to refuse it, and the multibody chain's angle integrators took the free chain's
// translation for two more angles in the inertia: its peak came out 24 % high). The chains
// are one discrete model, so their peaks differ only by the lumped chain's missing rotary
// inertia and the two integrators' O(dt^2) (lowest mode w dt = 0.14: ~0.2 %), below 0.5 %;
// the FE beam (40 cubic elements) differs by the chains' O(1/n^2) at n = 80 (0.43 %
// measured), below 1 %. The peaks fall at the same grid time.
TEST(NonlinearCli, AFreeRingOnAFoundationRespondsInEverySolver) {
  std::ifstream in(source("scenes/tyre-ring.toml"));
  std::stringstream toml;
  toml << in.rdbuf()
       << "\n[response]\nsolvers = [\"multibody\", \"lumped\", \"fem\"]\nat = 0.0\nforce = [-100.0, 0.0]\n"
          "dt = 2e-4\nt_end = 0.02\nrecord = [0.0, 90.0]\n";
  const std::string scene = ringtest::temp_dir() + "/tyre-response.toml";
  std::ofstream(scene) << toml.str();
  const auto r = ringvib("respond " + scene + " --format json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto t = nlohmann::json::parse(r.out);
  for (double point : {0.0, 90.0}) {
    const auto* peak = row(t, point, "peak_u");
    ASSERT_NE(peak, nullptr);
    EXPECT_LT(std::abs((*peak)["lumped_diff_pct"].get<double>()), 0.5) << point;
    EXPECT_LT(std::abs((*peak)["fem_diff_pct"].get<double>()), 1.0) << point;
    const auto* when = row(t, point, "t_peak");
    ASSERT_NE(when, nullptr);
    EXPECT_EQ((*when)["multibody"], (*when)["lumped"]) << point;
  }
  // The chain's energy-conserving integrator in hinge positions (its own coordinates, which
  // always had the translation right) agrees with its Newmark in angles: the peak |u| at
  // 0 deg within the two integrators' O(dt^2), 0.5 %.
  auto peak = [&](const std::string& integrator) {
    const auto one = ringvib("respond " + scene + " --solver multibody --set 'response.integrator=\"" + integrator +
                             "\"'");
    EXPECT_EQ(one.code, 0) << one.err;
    std::istringstream csv(one.out);
    std::string line;
    std::getline(csv, line);  // t,ux_0,uy_0,...
    double p = 0.0;
    while (std::getline(csv, line)) {
      std::istringstream cells(line);
      std::string t, ux, uy;
      std::getline(cells, t, ',');
      std::getline(cells, ux, ',');
      std::getline(cells, uy, ',');
      p = std::max(p, std::hypot(std::stod(ux), std::stod(uy)));
    }
    return p;
  };
  const double newmark = peak("newmark"), em = peak("energy-momentum");
  EXPECT_NEAR(em, newmark, 5e-3 * newmark);
}

// Gates on the nonlinear comparison: a bound the difference meets passes, a tighter one
// fails (exit 1) and names the point; both land in the JUnit file.
TEST(NonlinearCli, GatesOnTheComparison) {
  const std::string scene = source("scenes/paper1990-static-compare.toml");
  const std::string dir = ringtest::temp_dir();
  const auto pass = ringvib("run " + scene + " --set 'gates.lumped={max = 1e-6, analysis = \"static\", against = " +
                            "\"multibody\"}' --junit " + dir + "/j.xml --out " + dir + "/out");
  EXPECT_EQ(pass.code, 0) << pass.err << pass.out;
  EXPECT_NE(pass.out.find("PASS lumped vs multibody, static |u|"), std::string::npos) << pass.out;
  std::ifstream report(dir + "/out/report.md");
  std::stringstream md;
  md << report.rdbuf();
  EXPECT_NE(md.str().find("static_shapes.png"), std::string::npos);
  std::ifstream table(dir + "/out/static_table.json");
  EXPECT_TRUE(table.good());
  // A response gate against the other solver, tighter than their 0.04 % difference.
  const auto fail = ringvib("run " + source("scenes/paper1990-forced-compare.toml") +
                            " --set response.t_end=1.5 --set 'gates.multibody={max = 1e-4, analysis = \"response\", "
                            "against = \"lumped\"}'");
  EXPECT_EQ(fail.code, 1) << fail.err;
  EXPECT_NE(fail.out.find("FAIL multibody vs lumped, response peak |u|"), std::string::npos) << fail.out;
  // A reference the scene does not compute cannot be gated against: exit 2.
  EXPECT_EQ(ringvib("run " + scene + " --set static.reference=false --set 'gates.lumped={max = 1, analysis = \"static\"}'").code, 2);
}

// Cross-validation against the FE reference (the converged geometrically exact beam).
// The chains are second-order discretizations of the inextensible rod, the FE beam is
// extensible (EA effect ~ EI/(EA R^2) = 1e-5 here): the chains' error against the
// reference must fall by 4 from n = 40 to n = 80. Statics: fitted order 2 +- 0.3
// (measured errors 1.97 % and 0.49 % at C). The peak at C of the forced response also
// carries each integrator's dt error (0.1 % at dt = 0.01 s) and the reference's own
// (fem.response_tolerance, 0.1 %): e(80) must lie within 0.2 percentage points of
// e(40) / 4 (measured multibody 1.91 % -> 0.38 %, lumped 1.87 % -> 0.40 %); the FE beam at 40 cubic elements is within 0.3 % of its reference in both (measured
// 0.00 % and 0.12 %, the latter Newmark's dt error).
// The statics and the response are two cases, so that ctest runs them side by side.
class ChainsAgainstTheFeReference : public ::testing::TestWithParam<std::string> {};

TEST_P(ChainsAgainstTheFeReference, ConvergeAtSecondOrder) {
  {
    const std::string analysis = GetParam();
    const std::string scene = source(analysis == "static" ? "scenes/paper1990-static-compare.toml"
                                                          : "scenes/paper1990-forced-compare.toml");
    const std::string command = analysis == "static" ? "static " : "respond ";
    const std::string quantity = analysis == "static" ? "u" : "peak_u";
    auto errors = [&](int n) {
      const auto r = ringvib(command + scene + " --format json --set multibody.n=" + std::to_string(n) +
                             " --set lumped.n=" + std::to_string(n));
      EXPECT_EQ(r.code, 0) << r.err;
      const auto t = nlohmann::json::parse(r.out);
      const auto* u = row(t, 0.0, quantity);
      EXPECT_NE(u, nullptr);
      return std::array<double, 3>{(*u)["multibody_error_pct"].get<double>(), (*u)["lumped_error_pct"].get<double>(),
                                   (*u)["fem_error_pct"].get<double>()};
    };
    const auto e40 = errors(40), e80 = errors(80);
    for (int s = 0; s < 2; ++s) {
      if (analysis == "static")  // the two-point order over n = 40, 80
        EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{40, 80}, {std::abs(e40[s]), std::abs(e80[s])}), 2.0,
                                        0.3))
            << "solver " << s << ": " << e40[s] << " % -> " << e80[s] << " %";
      else
        EXPECT_NEAR(e80[s], e40[s] / 4.0, 0.2) << "solver " << s << ": " << e40[s] << " % -> " << e80[s] << " %";
    }
    EXPECT_LT(std::abs(e40[2]), 0.3) << analysis;
  }
}
INSTANTIATE_TEST_SUITE_P(NonlinearCli, ChainsAgainstTheFeReference, ::testing::Values("static", "response"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
