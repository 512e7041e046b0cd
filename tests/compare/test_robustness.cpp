// The exit-code contract held against hostile but realistic use, through the binary:
// every input problem is exit 2 naming the key or option, found before anything is
// computed or written; a signal during the write phase leaves no temporary file; a
// folder holds one run's files. The oracle is the contract of docs/commands.md ("Exit codes",
// "What run --out DIR writes").
#include <gtest/gtest.h>

#include <signal.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <utility>
#include <vector>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "cli.hpp"
#include "support/paper.hpp"

using ringtest::ringvib;
using ringtest::exists;
using ringtest::source;

namespace {

void expect_input_error(const ringtest::Run& r, const std::string& names) {
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << "message does not name " << names << ": " << r.err;
}

// Class 1: shipped scenes without modes used to crash `table` (SIGSEGV); a dotted key of
// 50,000 parts overflowed the TOML parser's stack.
TEST(Robustness, NoCrashOnScenesWithoutModesOrDeepNesting) {
  for (const char* scene : {"scenes/paper1990-forced.toml", "scenes/paper1990-static.toml"}) {
    expect_input_error(ringvib("table " + source(scene)), "modes");
    expect_input_error(ringvib("table " + source(scene) + " --format csv"), "modes");
    expect_input_error(ringvib("converge " + source(scene)), "modes");
  }
  const std::string dir = ringtest::temp_dir();
  std::string deep = "a";
  for (int i = 0; i < 50000; ++i) deep += ".a";
  ringtest::write(dir + "/deep.toml", "[" + deep + "]\nx = 1\n");
  expect_input_error(ringvib("run " + dir + "/deep.toml"), "line 1");
  ringtest::write(dir + "/deep2.toml", deep + " = 1\n");
  expect_input_error(ringvib("run " + dir + "/deep2.toml"), "line 1");
}

// Class 2: output paths are checked before the computation and named as the user gave
// them; the scene is never overwritten.
TEST(Robustness, OutputPathsCheckedUpFront) {
  const std::string dir = ringtest::temp_dir();
  const std::string scene = dir + "/forced.toml";
  ringtest::write(scene, ringtest::source_text("scenes/paper1990-forced.toml"));
  const std::string before = ringtest::source_text("scenes/paper1990-forced.toml");
  expect_input_error(ringvib("run " + source("scenes/paper1990-multibody.toml") + " --junit /proc/x/j.xml"),
                     "--junit /proc/x/j.xml");
  expect_input_error(ringvib("run " + source("scenes/paper1990-multibody.toml") + " --junit " + dir), "--junit");
  expect_input_error(ringvib("respond " + scene + " --csv " + dir), "--csv");
  expect_input_error(ringvib("respond " + scene + " --csv " + dir + "/missing/x.csv"), "--csv");
  expect_input_error(ringvib("respond " + scene + " --csv " + scene), "scene file itself");
  std::ifstream f(scene);
  std::stringstream now;
  now << f.rdbuf();
  EXPECT_EQ(now.str(), before);
  ringtest::write(dir + "/afile", "x");
  expect_input_error(ringvib("run " + source("scenes/paper1990-multibody.toml") + " --out " + dir + "/afile/out"),
                     "--out");
  expect_input_error(ringvib("run " + source("scenes/paper1990-multibody.toml") + " --out /proc/x"), "--out");
  EXPECT_FALSE(exists(dir + "/afile/out"));
}

// Class 3: input errors that used to be found late, inside a solver, or not at all.
TEST(Robustness, InputErrorsNameTheSceneKey) {
  const std::string forced = source("scenes/paper1990-forced.toml");
  const std::string dir = ringtest::temp_dir();
  expect_input_error(ringvib("run " + forced + " --out " + dir + "/o --set response.dt=10"), "response.dt");
  EXPECT_FALSE(exists(dir + "/o"));  // nothing created
  expect_input_error(ringvib("run " + forced + " --set response.t_end=1e9"), "response.t_end");
  expect_input_error(ringvib("run " + forced + " --set supports.roller=179.999999999999"), "supports.roller");
  expect_input_error(ringvib("run " + forced + " --set response.at=179.999999999999"), "response.at");
  expect_input_error(ringvib("run " + forced + " --set response.at=-180.000000000001"), "response.at");
  // An integrator a solver does not offer is an input error, not another scheme.
  expect_input_error(ringvib("respond " + forced + " --solver lumped --set response.integrator=generalized-alpha"),
                     "generalized-alpha");
  expect_input_error(ringvib("respond " + forced + " --solver fem --set response.integrator=energy-momentum"),
                     "energy-momentum");
  expect_input_error(ringvib("run " + dir), "folder");
  expect_input_error(ringvib("run /dev/zero"), "larger than");
  expect_input_error(ringvib("frobnicate " + forced), "unknown subcommand 'frobnicate'");
  const auto count = ringvib("modes " + source("scenes/paper1990-multibody.toml") + " --solver multibody --count 0");
  EXPECT_EQ(count.code, 2);
  EXPECT_LT(count.err.size(), 200u) << count.err;  // no 309-digit DBL_MAX
  expect_input_error(ringvib("run " + forced + " --set 'ring.radius=20\nbogus=1'"), "--set ring.radius");
}

// Class 4: the cost guard refuses what no machine this runs on can finish, naming the
// key and the estimate, before any solve; --max-memory and --force move the budget.
TEST(Robustness, CostGuardRefusesAbsurdRequests) {
  const std::string mb = source("scenes/paper1990-multibody.toml");
  expect_input_error(ringvib("modes " + mb + " --solver multibody --set multibody.n=100000000"), "multibody.n");
  expect_input_error(ringvib("modes " + mb + " --solver multibody --set multibody.n=20000 --set multibody.method=dense"),
                     "GiB");
  expect_input_error(ringvib("run " + source("scenes/paper1990-forced.toml") +
                             " --set response.dt=1e-7 --set response.t_end=9"),
                     "response.t_end");
  // A small budget refuses even the paper's n = 40; --force goes ahead.
  expect_input_error(ringvib("modes " + mb + " --solver multibody --max-memory 1e-6"), "--max-memory");
  EXPECT_EQ(ringvib("modes " + mb + " --solver multibody --max-memory 1e-6 --force").code, 0);
}

// What a run needs of its environment and of its discretization is refused
// before anything is computed, naming the cause (exit 2, nothing on stdout). A CalculiX
// column with TMPDIR=/nonexistent computed the other columns, then exited 3; 10^4 FE
// elements of degree 12 were refused after 10 s and 707 MB of assembly (and without the
// plug-in, refused as a plug-in that cannot be loaded instead of as too fine). Oracles:
// the file system (the folder does not exist) and the measured precision limit
// (fem_reference/checks.hpp, kPrecisionLimit).
TEST(Robustness, EnvironmentAndPrecisionLimitRefusedBeforeComputing) {
  const std::string paper = source("scenes/paper1990.toml");
  const auto fine = ringvib("modes " + paper + " --solver fem --set fem.degree=12 --set fem.elements=10000");
  expect_input_error(fine, "fem.elements (=10000)");
  EXPECT_NE(fine.err.find("double precision"), std::string::npos) << fine.err;
  EXPECT_TRUE(fine.out.empty()) << fine.out;
  if (ringtest::shell("command -v ccx").empty())
    GTEST_SKIP() << "no ccx on the PATH (calculix-ccx): the TMPDIR case needs it";
  const auto tmp = ringvib("table " + source("scenes/paper1990-calculix.toml"), "TMPDIR=/nonexistent");
  expect_input_error(tmp, "TMPDIR");
  EXPECT_NE(tmp.err.find("/nonexistent"), std::string::npos) << tmp.err;
  EXPECT_TRUE(tmp.out.empty()) << tmp.out;  // no column computed, no table printed
}

// Class 5: a re-run replaces the earlier run's files (and keeps the user's own).
TEST(Robustness, AFolderHoldsOneRunsFiles) {
  const std::string out = ringtest::temp_dir() + "/out";
  ASSERT_EQ(ringvib("run " + source("scenes/paper1990-static.toml") + " --out " + out).code, 0);
  EXPECT_TRUE(exists(out + "/static.json"));
  ringtest::write(out + "/notes.txt", "mine");
  ASSERT_EQ(ringvib("run " + source("scenes/paper1990-multibody.toml") + " --out " + out).code, 0);
  EXPECT_FALSE(exists(out + "/static.json"));
  EXPECT_FALSE(exists(out + "/static_shapes.png"));
  EXPECT_TRUE(exists(out + "/table.csv"));
  EXPECT_TRUE(exists(out + "/notes.txt"));
  EXPECT_EQ(ringtest::leftovers(out + "/.."), "");
}

// Class 5, signals during the write phase: test_files.cpp, AnInterruptedRunPublishesNothing.

}  // namespace

// A free thick ring (depth/R = 0.3) whose 64 modes the O(n) Lanczos of the chain took from a
// Krylov space that filled all 320 unknowns: it printed frequencies with a relative residual
// of 1.0 and exit 0. Whatever that path does, a printed answer is an eigen-solution (residual
// within modal::kAcceptedResidual, 1e-2) or the run fails with exit 3.
TEST(Robustness, NoEigenpairsPrintedThatAreNotEigenpairs) {
  const auto r = ringvib("modes " + source("scenes/thick-ring-study.toml") +
                         " --solver multibody --set multibody.method='\"sparse\"' "
                         "--set 'ring.section={shape = \"rectangle\", width = 0.05, height = 0.3}' --json -q");
  if (r.code == 0) {
    const auto at = r.out.find("\"max_residual\"");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_LE(std::stod(r.out.substr(r.out.find(':', at) + 1)), 1e-2) << r.out;
  } else {
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("not eigenpairs"), std::string::npos) << r.err;
  }
}

/// Lower-cased, so that "nan", "-nan", "NaN" and "inf" are all found.
static std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Found by a robustness probe: the paper's ring on a pin at 270 and a roller at 90 with a foundation
// of 1e300 or 1e200 N/m^2, or E = 1e300 Pa, exited 0 printing "max relative eigen-residual
// -nan" (its frequencies ~700 times the closed form): the residual and the backward error
// overflowed to NaN, which the acceptance comparisons let through. Values whose products
// overflow are refused by the scale rule (docs/scenes.md, "The scale rule") with exit 2 naming the
// key, before anything is solved or written; nothing non-finite is printed. Oracle: the
// exit-code contract (docs/commands.md, "Exit codes").
TEST(Robustness, ValuesWhoseProductsOverflowAreRefusedNotPrintedAsNaN) {
  const std::string pin_roller = source("scenes/paper1990.toml") +
                                 " --solver multibody --set supports.pin=270.0 --set supports.roller=90.0";
  const std::string out = ringtest::temp_dir() + "/out";
  for (const auto& [set, key] : std::vector<std::pair<std::string, std::string>>{
           {"foundation.radial=1e300", "foundation.radial"},
           {"foundation.radial=1e200", "foundation.radial"},
           {"foundation.tangential=1e200", "foundation.tangential"},
           {"ring.E=1e300", "ring.E"},
           {"ring.rho=1e-300", "ring.rho"},
           {"'supports.springs=[{at = 0.0, kx = 1e300}]'", "supports.springs[1].kx"},
           {"'masses=[{at = 0.0, mass = 1e300}]'", "masses[1].mass"}}) {
    const auto r = ringvib("modes " + pin_roller + " --set " + set);
    expect_input_error(r, key);
    EXPECT_EQ(lower(r.out).find("nan"), std::string::npos) << set << ": " << r.out;
    EXPECT_EQ(lower(r.out).find("inf"), std::string::npos) << set << ": " << r.out;
    const auto run = ringvib("run " + source("scenes/paper1990-multibody.toml") + " --out " + out + " --set " + set);
    expect_input_error(run, key);
    EXPECT_FALSE(exists(out)) << set;
  }
  // Inside the window the same ring is solved, and what is printed is finite: a foundation
  // of 1e6 N/m^2 (about 470 EI/R^4, a stiff soil) and the paper's ring itself.
  for (const std::string& set : {"foundation.radial=1e6", "ring.E=2.1e11"}) {
    const auto r = ringvib("modes " + pin_roller + " --set " + set);
    EXPECT_EQ(r.code, 0) << set << ": " << r.err;
    EXPECT_EQ(lower(r.out).find("nan"), std::string::npos) << set << ": " << r.out;
  }
}
