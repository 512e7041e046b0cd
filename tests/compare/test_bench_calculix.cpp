// `ringvib bench` with calculix among response.solvers: CalculiX goes on
// the nonlinear run-time-against-error figure through the registry like any solver, its
// elements and dt refined together (dt = response.dt x 40 / elements, the rule under which
// its peak at C converges, docs/measured.md "calculix"), its time the wall time of writing
// the deck, running ccx and reading it back. Skips without ccx.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli.hpp"

using ringtest::ringvib;
using ringtest::source;

TEST(BenchCalculix, CalculixIsACurveOfTheResponseFigure) {
  if (ringtest::shell("command -v ccx").empty())
    GTEST_SKIP() << "ccx is not on the PATH (Debian package calculix-ccx; scripts/install-deps.sh)";
  const std::string dir = ringtest::temp_dir();
  // The half-sine pulse over its first 0.1 s (5 increments of dt = 0.02 s at 20 elements):
  // measured 0.036 % from the converged FE reference, below the sweep's floor
  // (fem.response_tolerance = 1e-3, i.e. 0.1 %), so the sweep stops after one ccx run.
  const auto r = ringvib("bench " + source("scenes/paper1990-forced-compare.toml") + " -q --out " + dir +
                         "/out --set 'response.solvers=[\"fem\", \"calculix\"]' --set response.t_end=0.1"
                         " --set 'response.history=\"half-sine\"' --set response.period=1.0");
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream csv(dir + "/out/bench_response.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line, "analysis,solver,size,seconds_median,repeats,error_pct,reference_m");
  int calculix_rows = 0;
  while (std::getline(csv, line)) {
    std::stringstream s(line);
    std::string analysis, solver, size, seconds, repeats, error;
    std::getline(s, analysis, ',');
    std::getline(s, solver, ',');
    std::getline(s, size, ',');
    std::getline(s, seconds, ',');
    std::getline(s, repeats, ',');
    std::getline(s, error, ',');
    if (solver != "calculix") continue;
    ++calculix_rows;
    EXPECT_EQ(size, "20") << line;
    EXPECT_GT(std::stod(seconds), 0.0) << line;
    EXPECT_LT(std::stod(error), 0.1) << line;  // %, the floor that ended the sweep
  }
  EXPECT_EQ(calculix_rows, 1);
  EXPECT_NE(r.out.find("calculix"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/bench_response.png"));
  std::filesystem::remove_all(dir);
}
