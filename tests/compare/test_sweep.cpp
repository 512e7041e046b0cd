// `ringvib sweep` through the binary: a 12-case sweep gives the same rows serially, on
// two threads and on two MPI ranks (apart from the timing column); a case that fails is
// a row and the sweep completes; --resume runs only what is missing; each row agrees
// with the single-scene command for the same overrides (the oracle: `ringvib static`).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

const std::string kVary =
    " --vary 'multibody.n=[20, 40, 80]' --vary 'static.force=[[-1e4, 0.0], [-2e4, 0.0], [-3e4, 0.0], [-4e4, 0.0]]'";

/// The CSV without the `seconds` column (the only one that differs between runs).
std::string without_timing(const std::string& csv) {
  std::istringstream in(csv);
  std::ostringstream out;
  int seconds = -1;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::string cur;
    bool q = false;
    for (char c : line) {
      if (c == '"') q = !q;
      if (c == ',' && !q) {
        f.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    f.push_back(cur);
    if (seconds < 0)
      for (std::size_t i = 0; i < f.size(); ++i)
        if (f[i] == "seconds") seconds = static_cast<int>(i);
    for (std::size_t i = 0; i < f.size(); ++i)
      if (static_cast<int>(i) != seconds) out << f[i] << "|";
    out << "\n";
  }
  return out.str();
}

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(Sweep, SerialThreadedAndMpiRunsAgree) {
  const std::string scene = source("scenes/paper1990-static.toml");
  const auto serial = ringvib("sweep " + scene + kVary + " -j 1");
  ASSERT_EQ(serial.code, 0) << serial.err;
  // 12 cases x 4 recorded points, and the header.
  EXPECT_EQ(std::count(serial.out.begin(), serial.out.end(), '\n'), 1 + 12 * 4);
  const auto threaded = ringvib("sweep " + scene + kVary + " -j 2");
  ASSERT_EQ(threaded.code, 0) << threaded.err;
  EXPECT_EQ(without_timing(serial.out), without_timing(threaded.out));
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) GTEST_SKIP() << "mpirun is not installed";
  const std::string mpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -np 2 --oversubscribe " +
                             ringtest::ringvib_path() + " sweep " + scene + kVary + " 2>/dev/null";
  std::string out;
  if (FILE* p = popen(mpirun.c_str(), "r")) {
    char buf[4096];
    for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    EXPECT_EQ(pclose(p), 0);
  }
  EXPECT_EQ(without_timing(serial.out), without_timing(out));
}

// Oracle: `ringvib static` with the same overrides (one solve, the same code path as a
// user's single run) prints the same displacement to round-off.
TEST(Sweep, RowsAgreeWithTheSingleSceneCommand) {
  const std::string scene = source("scenes/paper1990-static.toml");
  const auto sweep = ringvib("sweep " + scene + " --vary 'multibody.n=[40]' --vary 'static.force=[[-3e4, 0.0]]'");
  ASSERT_EQ(sweep.code, 0) << sweep.err;
  const auto single = ringvib("static " + scene + " --set multibody.n=40 --set 'static.force=[-3e4, 0.0]' --json");
  ASSERT_EQ(single.code, 0) << single.err;
  const auto j = nlohmann::json::parse(single.out);
  const double ux = j["displacements"][0]["ux"], uy = j["displacements"][0]["uy"];
  std::istringstream in(sweep.out);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);  // case 0, u at 0 deg
  const auto last_quote = first.rfind('"');
  std::istringstream rest(first.substr(last_quote + 2));
  std::string solver, analysis, quantity, value;
  std::getline(rest, solver, ',');
  std::getline(rest, analysis, ',');
  std::getline(rest, quantity, ',');
  std::getline(rest, value, ',');
  EXPECT_EQ(quantity, "u at 0.000 deg");
  EXPECT_NEAR(std::stod(value), std::hypot(ux, uy), 1e-14 * std::hypot(ux, uy));
}

TEST(Sweep, AFailingCaseIsARowAndTheSweepCompletes) {
  const std::string scene = source("scenes/paper1990-static.toml");
  // 5e5 N is far past the load at which the ring touches itself (P R^2 / EI ~ 7.5).
  const auto r = ringvib("sweep " + scene + " --vary 'static.force=[[-2e4, 0.0], [-5e5, 0.0], [-3e4, 0.0]]'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("numerical-failure"), std::string::npos);
  EXPECT_NE(r.out.find("touches itself"), std::string::npos);
  EXPECT_NE(r.out.find("\n2,"), std::string::npos) << "the case after the failure ran";
  // A bad value in any case is an input error before anything runs.
  const auto bad = ringvib("sweep " + scene + " --vary 'multibody.n=[40, 3]'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("multibody.n=3"), std::string::npos) << bad.err;
}

TEST(Sweep, ResumeRunsOnlyTheMissingCases) {
  const std::string scene = source("scenes/paper1990-static.toml");
  const std::string out = ringtest::temp_dir() + "/sweep";
  const auto first = ringvib("sweep " + scene + " --vary 'static.force=[[-1e4, 0.0], [-5e5, 0.0]]' --out " + out);
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_NE(first.err.find("2 cases, 2 run, 0 resumed"), std::string::npos) << first.err;
  // The failed case runs again; the good one is kept.
  const auto again = ringvib("sweep " + scene + " --vary 'static.force=[[-1e4, 0.0], [-5e5, 0.0]]' --out " + out +
                             " --resume");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.err.find("2 cases, 1 run, 1 resumed"), std::string::npos) << again.err;
  const std::string csv = read(out + "/sweep.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 4 + 1);
  EXPECT_NE(read(out + "/sweep.json").find("\"keys\""), std::string::npos);
}

}  // namespace
