// The ringvib command as a user meets it: exit codes, messages, nothing written on bad
// input, the JSON contracts of docs/commands.md, and "skip what a scene doesn't need".
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "support/paper.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

/// The shipped multibody-only scene (23 modes, gated against the paper's column).
const std::string kMultibodyOnly = ringtest::source_text("scenes/paper1990-multibody.toml");

TEST(Cli, HelpListsSubcommands) {
  const auto r = ringvib("--help");
  EXPECT_EQ(r.code, 0);
  for (const char* sub : {"run", "table", "modes", "respond", "static", "converge"})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
  EXPECT_EQ(ringvib("--version").code, 0);
  EXPECT_EQ(ringvib("modes --help").code, 0);
}

TEST(Cli, UsageErrorsExit2) {
  EXPECT_EQ(ringvib("").code, 2);
  EXPECT_EQ(ringvib("frobnicate").code, 2);
  EXPECT_EQ(ringvib("modes " + source("scenes/free-ring.toml")).code, 2);  // --solver missing
  EXPECT_EQ(ringvib("modes " + source("scenes/free-ring.toml") + " --solver sap5").code, 2);
}

// Every bad input: exit 2, one message naming the file and the key, no output written.
TEST(Cli, BadScenesExit2AndWriteNothing) {
  const std::string dir = ringtest::temp_dir();
  struct Case { std::string from, to, key; };
  const std::vector<Case> cases = {
      {"radius = 10.0", "radius = -10.0", "ring.radius"},
      {"[multibody]\nn = 40", "[multibody]\nn = 2", "multibody.n"},
      {"count = 23", "count = 0", "modes.count"},
      {"[modes]", "[modse]", "modse"},
      {"solvers = [\"multibody\"]", "solvers = [\"sap5\"]", "modes.solvers"},
      {"diameter = 0.12", "diameter = \"big\"", "ring.section.diameter"},
      {"pin = 180.0", "pin = 180.0\nroller = 180.0", "supports.roller"},
      {"[ring]", "[ring", "line"},
  };
  for (const auto& c : cases) {
    std::string text = kMultibodyOnly;
    text.replace(text.find(c.from), c.from.size(), c.to);
    const std::string scene = dir + "/bad.toml";
    ringtest::write(scene, text);
    const std::string out = dir + "/out";
    const auto r = ringvib("run " + scene + " --out " + out + " --junit " + dir + "/j.xml");
    EXPECT_EQ(r.code, 2) << c.to << "\n" << r.err;
    EXPECT_NE(r.err.find(scene), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << "message does not name " << c.key << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(system(("test -e " + out).c_str()), 0) << "an output folder was created for " << c.to;
    EXPECT_NE(system(("test -e " + dir + "/j.xml").c_str()), 0);
  }
  const auto missing = ringvib("table " + dir + "/nope.toml");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find(dir + "/nope.toml"), std::string::npos);
  const auto set = ringvib("modes " + source("scenes/free-ring.toml") + " --solver multibody --set multibody.n=x y");
  EXPECT_EQ(set.code, 2);
}

// docs/commands.md: {"solver", "model": {...}, "rigid_modes", "omega": [ascending], "seconds"};
// modes.count = 9 computes 9 modes, and --count 3 three.
// Code_Aster's validation case SDLL11 (free thin ring: R = 0.1 m, 10 x 5 mm section, 5 mm
// in the plane, E = 72 GPa, rho = 2700 kg/m^3): every elastic frequency is double, and
// each solver returns its own basis of each pair. Paired member by member the table said
// "Lowest MAC 0.74" for frequencies that agree to 1e-12; paired as subspaces (Table,
// DoubleFrequenciesArePairedAsSubspaces) every pairing is exact: MAC 1.000 to the
// table's four digits, and each pair marked as such.
TEST(Cli, AFreeRingsDoubleFrequenciesPairAsSubspaces) {
  const std::string dir = ringtest::temp_dir(), scene = dir + "/sdll11.toml";
  ringtest::write(scene, R"(title = "SDLL11 free thin ring"
[ring]
radius = 0.1
E = 72e9
rho = 2700
section = { shape = "rectangle", width = 0.01, height = 0.005 }
[multibody]
n = 120
[lumped]
n = 120
[modes]
count = 10
solvers = ["multibody", "lumped", "fem"]
)");
  const auto r = ringvib("table " + scene);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Lowest MAC of any paired mode: 1.000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("compared as a subspace"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("?"), std::string::npos) << r.out;
}

TEST(Cli, ModesJsonContract) {
  const std::string dir = ringtest::temp_dir();
  ringtest::write(dir + "/mb.toml", kMultibodyOnly);
  const auto r = ringvib("modes " + dir + "/mb.toml --solver multibody --json --count 9");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["solver"], "multibody");
  EXPECT_EQ(j["rigid_modes"], 1);  // pinned: rotation about the pin (docs/paper.md, check 2)
  EXPECT_EQ(j["model"]["n"], 40);
  ASSERT_EQ(j["omega"].size(), 9u);
  for (std::size_t i = 1; i < 9; ++i) EXPECT_LE(j["omega"][i - 1].get<double>(), j["omega"][i].get<double>());
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  const auto k = nlohmann::json::parse(ringvib("modes " + dir + "/mb.toml --solver multibody --json --count 3").out);
  EXPECT_EQ(k["omega"].size(), 3u);
  EXPECT_EQ(ringvib("modes " + dir + "/mb.toml --solver multibody --count 38").code, 2);  // n - 3 = 37
}

// max_residual has one definition (ring/results.hpp): the 2-norm relative residual, and
// every result names its norm; the chains report that definition itself.
TEST(Cli, ModesJsonNamesTheResidualNorm) {
  for (const char* solver : {"multibody", "lumped"}) {
    const auto r = ringvib("modes " + source("scenes/free-ring.toml") + " --solver " + solver + " --json --count 4");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["residual_norm"], "2-norm") << solver;
    EXPECT_GE(j["max_residual"].get<double>(), 0.0) << solver;
    EXPECT_LT(j["max_residual"].get<double>(), 1e-6) << solver;  // n = 40: far above any floor
  }
}

// A multibody-only scene never loads the FE module: with the module path pointing at
// nothing it still succeeds, while a scene that needs FE then fails with exit 2.
TEST(Cli, MultibodyOnlySceneNeverLoadsFe) {
  const std::string dir = ringtest::temp_dir();
  ringtest::write(dir + "/mb.toml", kMultibodyOnly);
  const std::string no_fe = "RINGVIB_FEM_MODULE=/nonexistent/libringvib_fem.so";
  const auto ok = ringvib("run " + dir + "/mb.toml --out " + dir + "/out", no_fe);
  EXPECT_EQ(ok.code, 0) << ok.err;
  const auto fe = ringvib("modes " + dir + "/mb.toml --solver fem", no_fe);
  EXPECT_EQ(fe.code, 2);
  EXPECT_NE(fe.err.find("/nonexistent/libringvib_fem.so"), std::string::npos) << fe.err;
}

TEST(Cli, RunWritesReportAndFigures) {
  const std::string dir = ringtest::temp_dir();
  ringtest::write(dir + "/mb.toml", kMultibodyOnly);
  const auto r = ringvib("run " + dir + "/mb.toml --out " + dir + "/out --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"report.md", "table.csv", "table.json", "modes_multibody.json", "modes_multibody.csv",
                        "shapes_multibody.csv", "mode_shapes.png", "mode_shapes.gp", "mode_shapes.dat"})
    EXPECT_EQ(system(("test -s " + dir + "/out/" + f).c_str()), 0) << f;
  // No temporary file is left behind.
  EXPECT_NE(system(("ls " + dir + "/out | grep -q tmp-").c_str()), 0);
}

}  // namespace
