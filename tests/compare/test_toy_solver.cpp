// Adding a solver is its folder and one registry entry (docs/DESIGN "A solver is a
// plug-in"): a fourth, toy solver with a two-key option schema, added through the
// registry's API (cmp::add_solver), runs `ringvib modes SCENE --solver toy` in-process
// through the library entry point the program uses (cmp::run_command over cmp::cmd_modes),
// with its keys read, defaulted and checked by the scene reader like the built-in solvers'.
// Its frequencies are the free inextensible ring's closed form (ring/closed_form.hpp), so
// the oracle is not the code under test: what is tested is that the keys reach it.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "compare/commands.hpp"
#include "compare/registry.hpp"
#include "ring/closed_form.hpp"
#include "ring/errors.hpp"

namespace {

/// The toy's [toy] section: what its folder would declare (toy/options.cpp).
const ring::OptionSchema& toy_schema() {
  static const ring::OptionSchema s = [] {
    ring::OptionSchema x("toy", "A toy column: the free inextensible ring in closed form.");
    x.declare_integer("n", 8, 4, 1000, "pieces around the ring; every support and load point must be a node");
    x.declare_number("scale", 1.0, 0.0, 10.0, "a factor on every frequency", true);
    return x;
  }();
  return s;
}

/// The toy keeps no option struct in ring::Scene: it reads what the reader read.
ring::OptionValues toy_values(const ring::Scene& s) {
  const auto it = s.options.find("toy");
  return it != s.options.end() ? it->second : ring::defaults(toy_schema());
}

/// The toy's one registry entry: k = 2, 2, 3, 3, ... of the free ring, times toy.scale.
cmp::SolverEntry toy_entry() {
  cmp::SolverEntry e;
  e.name = "toy";
  e.label = "toy";
  e.size_key = "toy.n";
  e.size_name = "n";
  e.options = toy_schema();
  e.size = [](const ring::Scene& s) { return static_cast<int>(toy_values(s).integer("n")); };
  e.elastic_modes = [](const ring::Scene& s) -> long long { return 2 * toy_values(s).integer("n") - 3; };
  e.inextensible = [](const ring::Scene&) { return true; };
  e.curve = [](const ring::Scene&) { return std::string("toy"); };
  e.modes = [](const ring::Scene& s, int count) {
    ring::ModalResult r;
    r.solver = "toy";
    r.model["n"] = toy_values(s).integer("n");
    r.rigid_modes = 3;
    r.max_residual.reset();  // a closed form has no eigen-residual
    const double scale = toy_values(s).number("scale");
    for (int i = 0; i < count; ++i)
      r.omega.push_back(scale * ring::closed_form::free_ring_inextensional(s.ring, 2 + i / 2));
    return r;
  };
  return e;
}

/// The toy in the registry for one test, and out of it after (other tests see four solvers).
class ToySolver : public ::testing::Test {
 protected:
  void SetUp() override { cmp::add_solver(toy_entry()); }
  void TearDown() override { cmp::remove_solver("toy"); }

  struct Result {
    int code = -1;
    std::string out, err;
  };

  /// `ringvib modes SCENE --solver toy --set ...`, in-process.
  static Result modes(const std::string& scene, const std::vector<std::string>& set = {}) {
    cmp::CommonArgs a;
    a.scene = scene;
    a.set = set;
    a.quiet = true;
    std::ostringstream err;
    testing::internal::CaptureStdout();
    Result r;
    r.code = cmp::run_command(
        a.scene, [&] { return cmp::cmd_modes(a, "toy", std::nullopt, false, ""); }, err);
    r.out = testing::internal::GetCapturedStdout();
    r.err = err.str();
    return r;
  }

  static std::string scene(const std::string& toy_section) {
    const std::string dir = ringtest::temp_dir();
    const std::string path = dir + "/toy.toml";
    ringtest::write(path,
                    "title = \"toy\"\n[ring]\nradius = 10.0\nE = 2.1e11\nrho = 7.8e3\nsection = { diameter = 0.12 }\n"
                    "[modes]\ncount = 4\nsolvers = [\"toy\"]\n" +
                        toy_section);
    return path;
  }
};

TEST_F(ToySolver, ModesRunWithItsKeysDefaultedAndGiven) {
  const std::string path = scene("[toy]\nn = 12\n");
  const ring::Scene s = cmp::load_scene(path);
  EXPECT_EQ(s.options.at("toy").integer("n"), 12);
  EXPECT_EQ(s.options.at("toy").number("scale"), 1.0);  // the schema's default

  const Result r = modes(path);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("toy: n=12"), std::string::npos) << r.out;

  // The frequencies are the closed form's (rtol 1e-14: the same formula, scaled by exactly 1 or 2).
  const ring::ModalResult base = cmp::solve_modes(s, "toy", 4);
  ASSERT_EQ(base.omega.size(), 4u);
  const double k2 = ring::closed_form::free_ring_inextensional(s.ring, 2);
  EXPECT_NEAR(base.omega[0], k2, 1e-14 * k2);
  EXPECT_NEAR(base.omega[3], ring::closed_form::free_ring_inextensional(s.ring, 3), 1e-14 * k2);
  const ring::ModalResult doubled = cmp::solve_modes(cmp::load_scene(path, {"toy.scale=2"}), "toy", 4);
  EXPECT_NEAR(doubled.omega[0], 2.0 * k2, 1e-14 * k2);
}

TEST_F(ToySolver, ABadValueOfItsKeyExitsTwoNamingTheKey) {
  const std::string path = scene("[toy]\nscale = -1.0\n");
  const Result r = modes(path);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("toy.scale (line"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("expected a number in (0, 10], got -1"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;

  const Result set = modes(scene(""), {"toy.n=2"});
  EXPECT_EQ(set.code, 2);
  EXPECT_NE(set.err.find("toy.n (from --set)"), std::string::npos) << set.err;
  EXPECT_NE(set.err.find("expected an integer in [4, 1000], got 2"), std::string::npos) << set.err;
}

TEST_F(ToySolver, AnUnknownKeyOfItsSectionSuggestsTheNearest) {
  const Result r = modes(scene("[toy]\nscal = 2.0\n"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("toy.scal"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'scale'?"), std::string::npos) << r.err;
}

TEST_F(ToySolver, ItsSectionIsInTheSceneReference) {
  const std::string md = cmp::keys_markdown();
  EXPECT_NE(md.find("### `[toy]`"), std::string::npos);
  EXPECT_NE(md.find("| `toy.scale` | | 1 | (0, 10] | a factor on every frequency |"), std::string::npos) << md;
}

TEST(ToySolverRemoved, TheRegistryIsTheBuiltInOneAgain) {
  EXPECT_EQ(cmp::find_solver("toy"), nullptr);
  EXPECT_EQ(cmp::scene_schema().find("toy"), nullptr);
  EXPECT_THROW(cmp::parse_scene("[ring]\n[toy]\nn = 8\n", "t.toml"), ring::InputError);
  EXPECT_EQ(cmp::keys_markdown().find("[toy]"), std::string::npos);
}

TEST(ToySolverRemoved, ANameTakenIsRefused) {
  cmp::SolverEntry e = toy_entry();
  e.name = "multibody";
  EXPECT_THROW(cmp::add_solver(e), std::invalid_argument);
  EXPECT_THROW(cmp::remove_solver("multibody"), std::invalid_argument);  // built-in solvers stay
}

}  // namespace
