// Linear buckling through the ringvib command (scenes/ring-buckling.toml): every solver's
// critical pressures and the converged reference against the closed forms of the thin ring
// on a pin and a roller (ring/closed_form.hpp, pinned_ring_critical_pressure), the table's
// pairing, the report's files, and the refusals (exit 2, the key named).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ring/closed_form.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

const std::string kScene = "scenes/ring-buckling.toml";

double unit() {
  const ring::RingSpec s = ringtest::pin_270_roller_90();
  return s.EI() / std::pow(s.radius, 3);
}

// One solver: its factors are the critical pressures (the scene's pressure is 1 N/m), also
// given in EI/R^3; the multibody chain at n = 80 within its measured O(1/n^2) error (0.21 %
// at n = 80 for the n = 2 wave: tests/multibody/test_buckling.cpp) of the closed form.
TEST(BucklingCli, OneSolverPrintsItsFactorsAndTheCriticalPressures) {
  const auto r = ringvib("buckling " + source(kScene) + " --solver multibody -q");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("p_cr R^3/EI"), std::string::npos) << r.out;
  const auto j = ringvib("buckling " + source(kScene) + " --solver multibody --json -q");
  ASSERT_EQ(j.code, 0) << j.err;
  const auto f = nlohmann::json::parse(j.out)["factors"];
  ASSERT_EQ(f.size(), 4u);
  EXPECT_NEAR(f[0].get<double>() / (3.0 * unit()), 1.0, 3e-3);
  EXPECT_NEAR(f[1].get<double>() / f[0].get<double>(), 1.0, 1e-9);
}

TEST(BucklingCli, RefusesWhatCannotWorkNamingTheKey) {
  const std::string dir = ringtest::temp_dir();
  const std::string base = ringtest::source_text(kScene);
  struct Case {
    std::string name, sets, key;
  };
  const std::vector<Case> cases = {
      {"count", "--set buckling.count=100000 --set 'buckling.solvers=[\"multibody\"]' --set buckling.reference=false",
       "buckling.count"},
      {"calculix", "--set 'buckling.solvers=[\"calculix\"]' --set buckling.reference=false", "buckling.solvers"},
      {"sparse", "--set 'buckling.solvers=[\"multibody\"]' --set buckling.reference=false --set multibody.method=sparse",
       "sparse"},
  };
  for (const Case& c : cases) {
    const auto r = ringvib("buckling " + source(kScene) + " -q " + c.sets);
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << c.name << ": " << r.err;
  }
  // A ring without a roller, and a [buckling] with no load and no [static] to take them from.
  std::string no_roller = base;
  no_roller.replace(no_roller.find("roller = 90.0"), 13, "");
  ringtest::write(dir + "/a.toml", no_roller);
  const auto a = ringvib("buckling " + dir + "/a.toml -q --set 'buckling.solvers=[\"multibody\"]' --set buckling.reference=false");
  EXPECT_EQ(a.code, 2);
  EXPECT_NE(a.err.find("supports.roller"), std::string::npos) << a.err;
  std::string no_load = base;
  no_load.replace(no_load.find("pressure = {"), no_load.find('\n', no_load.find("pressure = {")) - no_load.find("pressure = {"),
                  "");
  ringtest::write(dir + "/b.toml", no_load);
  const auto b = ringvib("buckling " + dir + "/b.toml -q --set 'buckling.solvers=[\"multibody\"]' --set buckling.reference=false");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("buckling.loads"), std::string::npos) << b.err;
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

// Two point loads squeezing the ring bend it before it buckles (u_1 != 0), where K_1 holds
// displacement terms. The two chains are one discrete model in two sets of coordinates
// (segment angles with an analytic K_1; hinge positions with K_1 by Richardson-extrapolated
// differences, lumped_mass/buckling.hpp), so their factors agree up to the rounding of the
// latter: measured 2e-10 at n = 40 and 1e-8 at n = 80; 1e-7 leaves a factor 10.
TEST(BucklingCli, TheTwoChainsAgreeUnderPointLoadsThatBendTheRing) {
  const auto r = ringvib("buckling " + source(kScene) + " --format json -q --set buckling.reference=false " +
                         "--set 'buckling.solvers=[\"multibody\", \"lumped\"]' --set buckling.pressure.value=0.0 " +
                         "--set 'buckling.loads=[{at = 0.0, force = [-1.0, 0.0]}, {at = 180.0, force = [1.0, 0.0]}]'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    EXPECT_GT(row["lumped_mac"].get<double>(), 0.999);
    EXPECT_LT(std::abs(row["lumped_diff_pct"].get<double>()), 1e-5);  // percent: 1e-7 relative
  }
}

}  // namespace

namespace {

// The shipped scene, each kind of pressure: the converged FE reference is the extensible
// ring's, above the inextensible closed form by 5 to 9 I/(A R^2) = 9e-6 (measured:
// docs/measured.md, "fem_reference: linear buckling"), so within 12 I/(A R^2); the chains at n = 80
// within their O(1/n^2) error of it (measured 0.11 to 0.21 %: 0.25 % bound), the FE column
// (40 cubic elements, order 2(p - 1) = 4) within 0.02 % of its reference (measured 0.00 %).
// Dead pressure's second factor is Levy's 4 EI/R^3 (the shape in phase with the pin).
TEST(BucklingCli, EverySolverAndTheReferenceMeetTheClosedForms) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const double iar2 = 9e-6;
  for (const auto& [kind, name] : {std::pair{ring::Pressure::Kind::follower, "follower"},
                                   std::pair{ring::Pressure::Kind::dead, "dead"},
                                   std::pair{ring::Pressure::Kind::central, "central"}}) {
    const auto r = ringvib("buckling " + source(kScene) + " --format json -q --set buckling.pressure.kind='\"" +
                           std::string(name) + "\"'");
    ASSERT_EQ(r.code, 0) << name << ": " << r.err;
    const auto rows = nlohmann::json::parse(r.out)["rows"];
    ASSERT_EQ(rows.size(), 4u);
    const double exact = ring::closed_form::pinned_ring_critical_pressure(spec, kind);
    const auto& first = rows[0];
    EXPECT_NEAR(first["reference"].get<double>() / exact - 1.0, 0.0, 12 * iar2) << name;
    EXPECT_GT(first["reference"].get<double>(), exact) << name;  // stretching the ring costs energy: above
    for (const char* chain : {"multibody", "lumped"})
      EXPECT_LT(std::abs(first[chain].get<double>() / exact - 1.0), 2.5e-3) << name << " " << chain;
    for (const auto& row : rows) {
      EXPECT_LT(std::abs(row["fem_error_pct"].get<double>()), 0.02) << name;
      EXPECT_GT(row["fem_mac"].get<double>(), 0.99) << name;
    }
    if (kind == ring::Pressure::Kind::dead) {
      EXPECT_NEAR(rows[1]["reference"].get<double>() / (4.0 * unit()) - 1.0, 0.0, 12 * iar2);
    }
  }
}

// run --out writes the buckling table's files, every solver's factors and the figure.
TEST(BucklingCli, RunWritesTheBucklingReport) {
  const std::string dir = ringtest::temp_dir();
  const auto r = ringvib("run " + source(kScene) + " -q --out " + dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"report.md", "buckling_table.csv", "buckling_table.json", "buckling_multibody.json",
                        "buckling_lumped.json", "buckling_fem.json", "buckling_reference.json", "buckling_shapes.png"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

// Frequencies under load through the command, and their refusals: the chain's lowest
// frequency about the equilibrium of a follower pressure falls as sqrt(1 - p / p_cr) does
// near the critical pressure (the line through p = 0.5 and 0.75 p_cr meets zero within
// 2 %: tests/multibody/test_buckling.cpp); here it falls, the two chains agree, the FE beam
// agrees within the chain's error, a variant or solver without it refuses it by name, and a
// scene without [static] has nothing to preload.
TEST(BucklingCli, FrequenciesUnderLoadFallAndTheOthersRefuse) {
  const std::string dir = ringtest::temp_dir();
  const std::string scene = dir + "/pre.toml";
  ringtest::write(scene, ringtest::source_text(kScene).substr(0, ringtest::source_text(kScene).find("[buckling]")) +
                             "[modes]\nsolvers = [\"multibody\"]\ncount = 2\npreload = \"static\"\n\n"
                             "[static]\npressure = { value = 1.0, kind = \"follower\" }\n");
  auto lowest = [&](double p) {
    const auto r = ringvib("modes " + scene + " --solver multibody --json -q --set static.pressure.value=" +
                           std::to_string(p));
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out)["omega"][0].get<double>();
  };
  const double critical = 3.0 * unit();
  EXPECT_LT(lowest(0.9 * critical), 0.5 * lowest(0.01 * critical));
  // The lumped chain is the same discrete model in hinge positions: the same frequency
  // under load (to 1e-11 in tests/lumped_mass/preload_test.cpp; 1e-9 leaves the JSON's
  // printed digits room); its lumped frame has massless rotations and is refused.
  const std::string half = " --json -q --set static.pressure.value=" + std::to_string(0.5 * critical);
  const auto chain = ringvib("modes " + scene + " --solver lumped --set multibody.rotary_inertia=false" + half);
  const auto mb = ringvib("modes " + scene + " --solver multibody --set multibody.rotary_inertia=false" + half);
  ASSERT_EQ(chain.code, 0) << chain.err;
  ASSERT_EQ(mb.code, 0) << mb.err;
  const double wl = nlohmann::json::parse(chain.out)["omega"][0].get<double>();
  const double wm = nlohmann::json::parse(mb.out)["omega"][0].get<double>();
  EXPECT_NEAR(wl / wm, 1.0, 1e-9);
  const auto frame = ringvib("modes " + scene + " --solver lumped -q --set lumped.variant='\"frame\"'");
  EXPECT_EQ(frame.code, 2);
  EXPECT_NE(frame.err.find("lumped.variant"), std::string::npos) << frame.err;
  // The FE beam (extensible) within the chain's O(1/n^2) error of it (0.25 % at n = 80 for
  // the lowest mode: tests/fem_reference/fem_preload_test.cpp fits the order 2); CalculiX's
  // deck has no preload and says so before ccx is looked for.
  const auto fe = ringvib("modes " + scene + " --solver fem --set fem.elements=16 --set fem.degree=6" + half);
  ASSERT_EQ(fe.code, 0) << fe.err;
  EXPECT_NEAR(nlohmann::json::parse(fe.out)["omega"][0].get<double>() / wm, 1.0, 5e-3);
  const auto ccx = ringvib("modes " + scene + " --solver calculix -q");
  EXPECT_EQ(ccx.code, 2);
  EXPECT_NE(ccx.err.find("modes.preload"), std::string::npos) << ccx.err;
  std::string no_static = ringtest::source_text(kScene);
  no_static = no_static.substr(0, no_static.find("[buckling]")) + "[modes]\npreload = \"static\"\n";
  ringtest::write(dir + "/b.toml", no_static);
  const auto b = ringvib("table " + dir + "/b.toml -q");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("modes.preload"), std::string::npos) << b.err;
  std::filesystem::remove_all(dir);
}

// bench on a path to contact (scenes/ring-collapse.toml, static.path): the error of the load
// at which the ring touches, per solver and size. The reference is the reference solver's
// own path at 2 and 4 times its size (fem.elements = 10 here: 20 and 40 cubic elements; the
// 40 touch at 0.868359, tests/fem_reference/fem_path_test.cpp); the chain's error falls at
// its order 2 (within 0.3: the reference's own 2e-4 is 1/13 of the n = 80 error) and its
// sizes stop once the error is below the reference's change (0.36 % from 20 to 40).
TEST(BucklingCli, BenchMeasuresTheLoadAtWhichThePathTouches) {
  const std::string dir = ringtest::temp_dir();
  std::string text = ringtest::source_text("scenes/ring-collapse.toml");
  text = text.substr(0, text.find("\n[buckling]"));
  ringtest::write(dir + "/c.toml", text);
  const auto r = ringvib("bench " + dir + "/c.toml -q --out " + dir + "/out --set 'static.solvers=[\"multibody\"]' "
                         "--set fem.elements=10");
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream csv(dir + "/out/bench_contact.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "analysis,solver,size,seconds_median,repeats,error_pct,reference_m");
  std::vector<double> error;
  double reference = 0.0;
  while (std::getline(csv, line)) {
    std::stringstream row(line);
    std::vector<std::string> cell;
    for (std::string c; std::getline(row, c, ',');) cell.push_back(c);
    ASSERT_EQ(cell.size(), 7u) << line;
    EXPECT_EQ(cell[0], "contact");
    EXPECT_EQ(cell[1], "multibody");
    EXPECT_EQ(std::stoi(cell[2]), 20 << error.size());
    error.push_back(std::stod(cell[5]));
    reference = std::stod(cell[6]);
  }
  ASSERT_EQ(error.size(), 3u);  // 20, 40, 80: the last below the reference's change
  EXPECT_NEAR(reference, 0.868359, 1e-6);
  // Each refinement's two-point order (the errors of one sign).
  EXPECT_GT(error[0] * error[1], 0.0);
  EXPECT_GT(error[1] * error[2], 0.0);
  const auto samples = ringtest::in_n(std::vector<int>{20, 40, 80}, {std::abs(error[0]), std::abs(error[1]), std::abs(error[2])});
  EXPECT_TRUE(ringtest::OrderNear(ringtest::subset(samples, {0, 1}), 2.0, 0.3));
  EXPECT_TRUE(ringtest::OrderNear(ringtest::subset(samples, {1, 2}), 2.0, 0.3));
  std::ifstream txt(dir + "/out/bench_contact.txt");
  std::stringstream t;
  t << txt.rdbuf();
  EXPECT_NE(t.str().find("touches itself"), std::string::npos) << t.str();
  EXPECT_NE(t.str().find("fem at elements = 40"), std::string::npos) << t.str();
  std::filesystem::remove_all(dir);
}

}  // namespace
