// `ringvib sweep` through the binary: a 12-case sweep gives the same rows serially, on
// two threads and on two MPI ranks (apart from the timing column); a case that fails is
// a row and the sweep completes; --resume runs only what is missing; each row agrees
// with the single-scene command for the same overrides (the oracle: `ringvib static`).
// --vary lists are TOML: quoted strings, multi-line lists, floats as they read back; a key
// given twice or inside another is refused; a case's value wins over --set.
#include <gtest/gtest.h>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "support/paper.hpp"

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

// ---- --vary values are TOML ----

/// `s` single-quoted for the shell that runs ringvib.
std::string sh(const std::string& s) {
  std::string o = "'";
  for (char c : s) o += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return o + "'";
}

/// The rows of a CSV text (RFC 4180: fields in double quotes may hold commas and "").
std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(cur);
      cur.clear();
    } else if (c == '\n') {
      rows.back().push_back(cur);
      cur.clear();
      rows.emplace_back();
    } else {
      cur += c;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

/// The column named `name` of CSV rows (header first).
std::vector<std::string> column(const std::vector<std::vector<std::string>>& rows, const std::string& name) {
  std::vector<std::string> v;
  const auto& head = rows.at(0);
  const auto at = std::find(head.begin(), head.end(), name) - head.begin();
  EXPECT_LT(static_cast<std::size_t>(at), head.size()) << "no column " << name;
  for (std::size_t i = 1; i < rows.size(); ++i) v.push_back(rows[i].at(static_cast<std::size_t>(at)));
  return v;
}

/// |u| at the first recorded point from `ringvib static SCENE SET --json`.
double static_u(const std::string& scene, const std::string& set) {
  const auto r = ringvib("static " + scene + " " + set + " --json");
  EXPECT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  return std::hypot(j["displacements"][0]["ux"].get<double>(), j["displacements"][0]["uy"].get<double>());
}

bool exists(const std::string& path) { return access(path.c_str(), F_OK) == 0; }

TEST(SweepVary, AKeyGivenTwiceOrInsideAnotherIsRefusedBeforeAnything) {
  const std::string scene = source("scenes/paper1990-static.toml");
  const std::string out = ringtest::temp_dir() + "/out";
  // Before: two multibody.n columns, and rows labelled 40 computed with 160.
  for (const std::string second : {"'multibody.n=[160]'", "' multibody . n =[160]'"}) {
    const auto r = ringvib("sweep " + scene + " --vary 'multibody.n=[40, 80]' --vary " + second + " --out " + out);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--vary multibody.n: given twice"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(exists(out)) << "nothing is written";
  }
  // ring.section (a whole table) and ring.section.diameter (one key of it) in one case.
  const auto nested = ringvib("sweep " + scene + " --vary 'ring.section=[{diameter = 0.1}]' --vary " +
                              "'ring.section.diameter=[0.2]' --out " + out);
  EXPECT_EQ(nested.code, 2) << nested.err;
  EXPECT_NE(nested.err.find("--vary ring.section.diameter: overlaps --vary ring.section"), std::string::npos)
      << nested.err;
  EXPECT_FALSE(exists(out));
}

TEST(SweepVary, QuotedStringsReachTheCaseScene) {
  const std::string dir = ringtest::temp_dir();
  const std::string scene = dir + "/lumped.toml";
  ringtest::write(scene, "title = \"lumped modes\"\n" + ringtest::paper_ring_toml() + R"([supports]
pin = 180.0
[lumped]
n = 40
[modes]
count = 5
solvers = ["lumped"]
)");
  // The scene reader's own message echoes the value it read: the escaped quote arrived.
  const auto quote = ringvib("sweep " + scene + " --vary " + sh(R"(lumped.variant=["chain", "fr\"ame"])"));
  EXPECT_EQ(quote.code, 2) << quote.err;
  EXPECT_NE(quote.err.find(R"(got "fr"ame")"), std::string::npos) << quote.err;
  // An escape that TOML resolves: "fr\u0061me" is "frame", and the rows are the frame
  // model's frequencies (oracle: `ringvib modes` with --set lumped.variant=frame).
  const auto swept = ringvib("sweep " + scene + " --vary " + sh(R"(lumped.variant=["fr\u0061me"])"));
  ASSERT_EQ(swept.code, 0) << swept.err;
  const auto rows = csv_rows(swept.out);
  const auto single = ringvib("modes " + scene + " --solver lumped --set lumped.variant=frame --json");
  ASSERT_EQ(single.code, 0) << single.err;
  const auto omega = nlohmann::json::parse(single.out)["omega"];
  const auto values = column(rows, "value");
  ASSERT_EQ(values.size(), omega.size());
  for (std::size_t i = 0; i < values.size(); ++i)  // the same solve: equal to round-off
    EXPECT_NEAR(std::stod(values[i]), omega[i].get<double>(), 1e-14 * omega[i].get<double>());
  EXPECT_EQ(column(rows, "lumped.variant"), std::vector<std::string>(omega.size(), "\"frame\""));
  // A string with a quote in it, as TOML text in the key column.
  const auto title = ringvib("sweep " + source("scenes/paper1990-static.toml") + " --vary " +
                             sh(R"(title=["a\"b", "c"])"));
  ASSERT_EQ(title.code, 0) << title.err;
  const auto titles = column(csv_rows(title.out), "title");
  EXPECT_EQ(std::set<std::string>(titles.begin(), titles.end()), (std::set<std::string>{R"("a\"b")", R"("c")"}));
}

TEST(SweepVary, MultiLineListsAndFloatsAsTheyReadBack) {
  const std::string scene = source("scenes/paper1990-static.toml");
  const auto r = ringvib("sweep " + scene + " --vary 'static.force=[\n  [-1e4, 0.0],  # light\n  [-3e4, 0.0],\n]'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 1u + 2 * 4);  // 2 cases x 4 recorded points
  EXPECT_EQ(rows[5][1], "[-30000.0, 0.0]");  // case 1, u at 0 deg
  EXPECT_EQ(rows[5][4], "u at 0.000 deg");
  const double u = static_u(scene, "--set 'static.force=[-3e4, 0.0]'");
  EXPECT_NEAR(std::stod(rows[5][5]), u, 1e-14 * u);
  // 0.1 stays 0.1 (the shortest text that reads back to the same double), and the case
  // ran with it.
  const auto d = ringvib("sweep " + scene + " --vary 'ring.section.diameter=[0.1]'");
  ASSERT_EQ(d.code, 0) << d.err;
  const auto drows = csv_rows(d.out);
  EXPECT_EQ(drows[1][1], "0.1");
  const double ud = static_u(scene, "--set ring.section.diameter=0.1");
  EXPECT_NEAR(std::stod(drows[1][5]), ud, 1e-14 * ud);
}

TEST(SweepVary, TheCaseValueWinsOverSetAndTheTableSaysSo) {
  const std::string scene = source("scenes/paper1990-static.toml");
  const auto r = ringvib("sweep " + scene + " --set multibody.n=20 --vary 'multibody.n=[40]'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  EXPECT_EQ(rows[1][1], "40");
  const double u40 = static_u(scene, "--set multibody.n=40"), u20 = static_u(scene, "--set multibody.n=20");
  ASSERT_GT(std::abs(u40 - u20), 1e-6 * u40) << "the two chains must differ for this test to tell them apart";
  EXPECT_NEAR(std::stod(rows[1][5]), u40, 1e-14 * u40);
}

TEST(SweepVary, ARecordListOf1001AnglesRuns) {
  // 1001 decimal points on one line, and a comment ruler of 1001 dots: not nesting.
  std::string record;
  for (int i = 0; i < 1001; ++i) record += (i ? ", " : "") + std::to_string(9 * (i % 40)) + ".0";
  std::string text = read(source("scenes/paper1990-static.toml"));
  text = "# " + std::string(1001, '.') + "\n" + text.substr(0, text.find("record = ")) + "record = [" + record + "]\n";
  const std::string scene = ringtest::temp_dir() + "/record.toml";
  ringtest::write(scene, text);
  const auto r = ringvib("sweep " + scene + " --vary 'multibody.n=[40]'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 1u + 1001);
  EXPECT_EQ(column(rows, "status"), std::vector<std::string>(1001, "ok"));
}

// ---- under mpirun: failures of every rank counted, signals ----

/// The launcher prefix for two ranks (root allowed in CI containers; two ranks on a
/// machine with fewer cores), or "" when mpirun is not installed.
std::string mpirun_prefix() {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) return "";
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -np 2 --oversubscribe";
}

/// The processes whose parent is `parent` (from /proc).
std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> v;
  if (DIR* d = opendir("/proc")) {
    while (const dirent* e = readdir(d)) {
      const pid_t pid = static_cast<pid_t>(std::atoi(e->d_name));
      if (pid <= 0) continue;
      const std::string stat = read("/proc/" + std::string(e->d_name) + "/stat");
      const auto close = stat.rfind(')');  // "pid (comm) state ppid ..."
      if (close == std::string::npos) continue;
      std::istringstream rest(stat.substr(close + 1));
      std::string state;
      long ppid = 0;
      if (rest >> state >> ppid && ppid == parent) v.push_back(pid);
    }
    closedir(d);
  }
  return v;
}

/// True when one of the ranks under `launcher` runs rank 0's case thread (named
/// "ringvib-cases", started once MPI has started on every rank: compare/sweep_mpi.hpp).
bool cases_running(pid_t launcher) {
  for (const pid_t rank : children_of(launcher)) {
    const std::string tasks = "/proc/" + std::to_string(rank) + "/task";
    if (DIR* d = opendir(tasks.c_str())) {
      bool found = false;
      while (const dirent* e = readdir(d)) found |= read(tasks + "/" + e->d_name + "/comm") == "ringvib-cases\n";
      closedir(d);
      if (found) return true;
    }
  }
  return false;
}

TEST(SweepMpi, EveryFailedCaseIsCountedWhicheverRankRanIt) {
  const std::string mpirun = mpirun_prefix();
  if (mpirun.empty()) GTEST_SKIP() << "mpirun is not installed";
  // 5e5 N and more are far past the load at which the ring touches itself (P R^2 / EI ~ 7.5):
  // every case fails. Eight cases of ~ 0.05 s each: both ranks get some.
  const auto r = ringvib("sweep " + source("scenes/paper1990-static.toml") +
                             " --vary 'static.force=[[-5e5, 0.0], [-6e5, 0.0], [-7e5, 0.0], [-8e5, 0.0], [-9e5, 0.0], "
                             "[-1e6, 0.0], [-2e6, 0.0], [-3e6, 0.0]]'",
                         mpirun);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("8 cases, 8 run, 0 resumed, 8 failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("every case of the sweep failed"), std::string::npos) << r.err;
}

// A signal to the ranks ends mpirun with 128 + signal (Open MPI reports the first rank
// that died of a signal that way); a signal to mpirun itself ends it with 1, Open MPI's
// own abort code (compare/sweep_mpi.cpp). Either way nothing is published and the
// folder the run made is removed.
TEST(SweepMpi, ASignalPublishesNothingAndEndsWith128PlusSignalWhenItReachesTheRanks) {
  const std::string mpirun = mpirun_prefix();
  if (mpirun.empty()) GTEST_SKIP() << "mpirun is not installed";
  const auto probe = ringvib("sweep " + source("scenes/paper1990-static.toml") + " --vary 'multibody.n=[40]'", mpirun);
  if (probe.err.find("on 2 MPI ranks") == std::string::npos) GTEST_SKIP() << "ringvib is built without MPI";
  const std::string base = ringtest::temp_dir();
  // 200 cases of dense chains (n = 400 ... 1196): minutes of work, stopped long before.
  std::string list;
  for (int i = 0; i < 200; ++i) list += (i ? ", " : "") + std::to_string(400 + 4 * i);
  int run = 0;
  for (const int sig : {SIGTERM, SIGINT}) {
    for (const bool to_mpirun : {false, true}) {
      const std::string out = base + "/run" + std::to_string(run++);
      const pid_t pid = ringtest::spawn({"mpirun", "-np", "2", "--oversubscribe", ringtest::ringvib_path(), "sweep",
                                         source("scenes/paper1990-static.toml"), "--vary",
                                         "multibody.n=[" + list + "]", "--out", out, "-q"},
                                        {{"OMPI_ALLOW_RUN_AS_ROOT", "1"}, {"OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1"}});
      // Wait until the cases run (an event, not a time: the limit only stops a hang).
      // Not earlier: ranks that die while they start MPI can leave mpirun 4.1.4 hanging
      // in its own shutdown (compare/sweep_mpi.cpp).
      bool running = false;
      const auto start = std::chrono::steady_clock::now();
      while (!running && std::chrono::steady_clock::now() - start < std::chrono::seconds(120)) {
        running = cases_running(pid);
        int st = 0;
        if (!running && waitpid(pid, &st, WNOHANG) == pid) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      ASSERT_TRUE(running) << "the sweep never started its cases";
      if (to_mpirun) {
        kill(pid, sig);
      } else {
        for (const pid_t rank : children_of(pid)) kill(rank, sig);
      }
      // mpirun sends SIGKILL 2 s after a signal at the latest; a minute is a hang.
      const int status = ringtest::wait_bounded(pid, 60.0);
      ASSERT_NE(status, -1) << "mpirun did not end within 60 s of the signal (killed)";
      ASSERT_TRUE(WIFEXITED(status)) << status;
      if (to_mpirun)
        EXPECT_TRUE(WEXITSTATUS(status) == 1 || WEXITSTATUS(status) == 128 + sig)
            << "signal " << sig << " to mpirun: exit " << WEXITSTATUS(status);
      else
        EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << "signal " << sig << " to the ranks";
      EXPECT_FALSE(exists(out)) << "signal " << sig << (to_mpirun ? " to mpirun" : " to the ranks")
                                << ": the folder the run made is left";
    }
  }
}

// `sweep --ranks 2` starts mpirun itself, so that a signal to ringvib (Ctrl-C in its
// terminal, kill) ends the sweep with 128 + signal like a serial run; a signal to mpirun
// itself ends Open MPI's mpirun with 1 whatever the ranks do (the test above).
TEST(SweepMpi, TheRanksLauncherEndsWith128PlusSignalAndPublishesNothing) {
  if (mpirun_prefix().empty()) GTEST_SKIP() << "mpirun is not installed";
  const auto probe = ringvib("sweep " + source("scenes/paper1990-static.toml") + " --vary 'multibody.n=[40]' --ranks 2",
                             "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1");
  if (probe.err.find("built without MPI") != std::string::npos) GTEST_SKIP() << "ringvib is built without MPI";
  ASSERT_EQ(probe.code, 0) << probe.err;
  EXPECT_NE(probe.err.find("on 2 MPI ranks"), std::string::npos) << probe.err;
  const std::string base = ringtest::temp_dir();
  std::string list;
  for (int i = 0; i < 200; ++i) list += (i ? ", " : "") + std::to_string(400 + 4 * i);
  int run = 0;
  for (const int sig : {SIGINT, SIGTERM}) {
    const std::string out = base + "/run" + std::to_string(run++);
    const pid_t pid = ringtest::spawn({ringtest::ringvib_path(), "sweep", source("scenes/paper1990-static.toml"), "--vary",
                                       "multibody.n=[" + list + "]", "--out", out, "-q", "--ranks", "2"},
                                      {{"OMPI_ALLOW_RUN_AS_ROOT", "1"},
                                       {"OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1"},
                                       {"OMPI_MCA_rmaps_base_oversubscribe", "1"}});
    // The ranks are mpirun's children, mpirun the launcher's child.
    bool running = false;
    const auto start = std::chrono::steady_clock::now();
    while (!running && std::chrono::steady_clock::now() - start < std::chrono::seconds(120)) {
      for (const pid_t mpirun : children_of(pid)) running |= cases_running(mpirun);
      int st = 0;
      if (!running && waitpid(pid, &st, WNOHANG) == pid) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_TRUE(running) << "the sweep never started its cases";
    kill(pid, sig);
    const int status = ringtest::wait_bounded(pid, 60.0);
    ASSERT_NE(status, -1) << "the launcher did not end within 60 s of the signal (killed)";
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << "signal " << sig << " to the launcher";
    EXPECT_FALSE(exists(out)) << "signal " << sig << ": the folder the run made is left";
  }
  // Without mpirun on PATH, --ranks is refused up front, naming the option.
  const auto none = ringvib("sweep " + source("scenes/paper1990-static.toml") + " --vary 'multibody.n=[40]' --ranks 2",
                            "PATH=/nonexistent");
  EXPECT_EQ(none.code, 2) << none.err;
  EXPECT_NE(none.err.find("--ranks"), std::string::npos) << none.err;
}

}  // namespace
