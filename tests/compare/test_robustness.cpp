// The exit-code contract held against hostile but realistic use, through the binary:
// every input problem is exit 2 naming the key or option, found before anything is
// computed or written; a signal during the write phase leaves no temporary file; a
// folder holds one run's files. The oracle is the README's contract ("Exit codes",
// "What run --out DIR writes").
#include <gtest/gtest.h>

#include <signal.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
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
