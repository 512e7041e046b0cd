// The calculix column through the binary: exit 2 without ccx (naming the solver and the
// package), exit 3 with ccx's last lines when it fails or outlasts its timeout, the job
// folder removed on every exit including a signal, and `export-deck` writing the deck the
// column runs (the same frequencies when ccx runs it by hand).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>
#include <utility>
#include <vector>

#include "compare/cli.hpp"
#include "support/paper.hpp"

namespace {

using ringtest::ringvib;

const std::string kScene = "title = \"paper ring, calculix\"\n" + ringtest::paper_ring_toml() + R"([supports]
pin = 180.0
[calculix]
elements = 40
[modes]
count = 8
solvers = ["calculix"]
)";

struct Fixture {
  std::string dir = ringtest::temp_dir();
  std::string tmp = dir + "/tmp", bin = dir + "/bin", scene = dir + "/scene.toml";
  Fixture() {
    mkdir(tmp.c_str(), 0755);
    mkdir(bin.c_str(), 0755);
    ringtest::write(scene, kScene);
  }
  ~Fixture() { std::system(("rm -rf " + dir).c_str()); }
  /// A program named ccx in bin/ running `body` (sh).
  void fake_ccx(const std::string& body) const {
    ringtest::write(bin + "/ccx", "#!/bin/sh\n" + body + "\n");
    chmod((bin + "/ccx").c_str(), 0755);
  }
  /// The environment of a run: TMPDIR (where the job folder goes) and PATH.
  std::string env(const std::string& path) const { return "TMPDIR=" + tmp + " PATH=" + path; }
};

TEST(CalculixCli, WithoutCcxOnThePathExit2NamesTheSolverAndThePackage) {
  Fixture f;
  const auto r = ringvib("modes " + f.scene + " --solver calculix", f.env(f.bin));  // bin/ holds no ccx
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("calculix"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("calculix-ccx"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(f.scene), std::string::npos) << r.err;  // the file too
  EXPECT_TRUE(ringtest::empty_dir(f.tmp));
}

TEST(CalculixCli, AFailingCcxIsExit3WithItsLastLinesAndNoFolderLeft) {
  Fixture f;
  f.fake_ccx("echo 'reading the deck'\necho '*ERROR reading *NODE: a fake failure'\nexit 201");
  const auto r = ringvib("modes " + f.scene + " --solver calculix", f.env(f.bin + ":/usr/bin:/bin"));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("exited with status 201"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("*ERROR reading *NODE: a fake failure"), std::string::npos) << r.err;
  EXPECT_TRUE(ringtest::empty_dir(f.tmp)) << ringtest::shell("ls -A " + f.tmp);
}

TEST(CalculixCli, ACcxThatPrintsAnErrorButExitsZeroIsExit3) {
  Fixture f;
  f.fake_ccx("echo '*ERROR in calinput: at least one fatal error'\nexit 0");
  const auto r = ringvib("modes " + f.scene + " --solver calculix", f.env(f.bin + ":/usr/bin:/bin"));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("at least one fatal error"), std::string::npos) << r.err;
  EXPECT_TRUE(ringtest::empty_dir(f.tmp));
}

/// Runs `ringvib ARGS` (no shell) with `env`, output to /dev/null: its exit code and its
/// peak resident set in bytes (the kernel's ru_maxrss of the child).
std::pair<int, double> run_measured(const std::vector<std::string>& args,
                                    const std::vector<std::pair<std::string, std::string>>& env) {
  std::vector<std::string> all = {ringtest::ringvib_path()};
  all.insert(all.end(), args.begin(), args.end());
  const pid_t pid = ringtest::spawn(all, env);
  int status = 0;
  struct rusage ru {};
  if (pid < 0 || wait4(pid, &status, 0, &ru) != pid) return {-1, 0.0};
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1024.0 * double(ru.ru_maxrss)};  // Linux: KiB
}

// Found by a robustness probe: ccx's log was read whole: a ccx writing 200 MB and then failing made
// ringvib peak at 790 MB to print the last 12 lines. The log is read from its ends; its size
// must not show in ringvib's peak memory. Oracle: the kernel's peak RSS of the same failing
// run with a one-line log; 100 MB of log held whole, even once, would add 100 MB, so the
// 16 MiB allowance (ringvib holds 128 KiB of it) separates the two by a factor 6.
TEST(CalculixCli, ALongLogIsReadFromItsEndsInBoundedMemory) {
  Fixture f;
  const std::vector<std::pair<std::string, std::string>> env = {{"TMPDIR", f.tmp}, {"PATH", f.bin + ":/usr/bin:/bin"}};
  const std::vector<std::string> args = {"modes", f.scene, "--solver", "calculix"};
  f.fake_ccx("echo '*ERROR in e_c3d: a fake failure'\nexit 201");
  const auto [small_code, small_peak] = run_measured(args, env);
  ASSERT_EQ(small_code, 3);
  f.fake_ccx("echo ' number of equations'\necho ' 246'\nyes ' iteration 7, residual 1.0e-3' | head -c 100000000\n"
             "echo\necho '*ERROR in e_c3d: a fake failure after 100 MB'\nexit 201");
  const auto [big_code, big_peak] = run_measured(args, env);
  ASSERT_EQ(big_code, 3);
  EXPECT_LT(big_peak, small_peak + 16.0 * (1 << 20))
      << "peak " << big_peak / 1e6 << " MB with a 100 MB log, " << small_peak / 1e6 << " MB with one line";
  // The message still ends with ccx's last lines, and an *ERROR far from either end of a
  // log whose ccx exited 0 is still found.
  const auto r = ringvib("modes " + f.scene + " --solver calculix", f.env(f.bin + ":/usr/bin:/bin"));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("*ERROR in e_c3d: a fake failure after 100 MB"), std::string::npos) << r.err.substr(0, 2000);
  EXPECT_LT(r.err.size(), 4096u) << "the last 12 lines, not more";
  f.fake_ccx("yes ' iteration 7' | head -c 50000000\necho\necho '*ERROR in the middle'\n"
             "yes ' iteration 8' | head -c 50000000\nexit 0");
  const auto middle = ringvib("modes " + f.scene + " --solver calculix", f.env(f.bin + ":/usr/bin:/bin"));
  EXPECT_EQ(middle.code, 3) << middle.err.substr(0, 2000);
  EXPECT_NE(middle.err.find("ccx reported an error"), std::string::npos) << middle.err.substr(0, 2000);
  EXPECT_TRUE(ringtest::empty_dir(f.tmp)) << ringtest::shell("ls -A " + f.tmp);
}

TEST(CalculixCli, ACcxOutlastingItsTimeoutIsKilledAndExit3) {
  Fixture f;
  f.fake_ccx("echo 'still factoring'\nexec sleep 30");
  const auto r = ringvib("modes " + f.scene + " --solver calculix --set calculix.timeout=0.3",
                         f.env(f.bin + ":/usr/bin:/bin"));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("did not finish within calculix.timeout"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("still factoring"), std::string::npos) << r.err;
  EXPECT_TRUE(ringtest::empty_dir(f.tmp));
}

TEST(CalculixCli, ASignalKillsCcxAndRemovesItsFolder) {
  Fixture f;
  const std::string pidfile = f.dir + "/ccx.pid";
  f.fake_ccx("echo $$ > " + pidfile + "\nexec sleep 30");
  const pid_t pid = ringtest::spawn({ringtest::ringvib_path(), "modes", f.scene, "--solver", "calculix"},
                                    {{"TMPDIR", f.tmp}, {"PATH", f.bin + ":/usr/bin:/bin"}});
  // Wait until ccx runs in its folder.
  for (int i = 0; i < 500 && !ringtest::exists(pidfile); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(ringtest::exists(pidfile));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(ringtest::empty_dir(f.tmp));
  kill(pid, SIGTERM);
  const int status = ringtest::wait_bounded(pid, 10.0);
  ASSERT_NE(status, -1);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_TRUE(ringtest::empty_dir(f.tmp)) << ringtest::shell("ls -A " + f.tmp);
  std::ifstream p(pidfile);
  int child = 0;
  p >> child;
  ASSERT_GT(child, 0);
  EXPECT_NE(kill(child, 0), 0) << "ccx (pid " << child << ") still runs";
}

TEST(CalculixCli, ExportDeckRefusesWhatTheDeckCannotExpressAndWritesNothing) {
  Fixture f;
  ringtest::write(f.scene, std::string(kScene) + "");
  const std::string out = f.dir + "/deck";
  const auto r = ringvib("export-deck " + f.scene + " --solver calculix --out " + out +
                             " --set 'ring.section={area = 0.0113, inertia = 1.0e-5}' --set calculix.section=as-given",
                         f.env("/usr/bin:/bin"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("calculix.section"), std::string::npos) << r.err;
  EXPECT_FALSE(ringtest::exists(out));
}

/// Frequencies (rad/s) of the in-plane modes in a .dat file ccx wrote for a deck whose
/// nodes are 1..nodes: the eigenvalue table, without modes whose beam nodes do not move in
/// the plane (the section's twisting).
std::vector<double> dat_frequencies(const std::string& path) {
  std::ifstream in(path);
  std::vector<double> w;
  bool table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) table = true;
    if (line.find("P A R T I C I P A T I O N") != std::string::npos) break;
    std::istringstream s(line);
    int k;
    double eig, omega;
    if (table && (s >> k >> eig >> omega)) w.push_back(omega);
  }
  return w;
}

bool ccx_absent() { return ringtest::shell("command -v ccx").empty(); }

TEST(CalculixCli, TheExportedDeckRunByHandGivesTheColumnsFrequencies) {
  if (ccx_absent()) GTEST_SKIP() << "ccx is not on the PATH (Debian package calculix-ccx; scripts/install-deps.sh)";
  Fixture f;
  const std::string out = f.dir + "/deck";
  const auto e = ringvib("export-deck " + f.scene + " --solver calculix --out " + out);
  ASSERT_EQ(e.code, 0) << e.err;
  ASSERT_TRUE(ringtest::exists(out + "/ring.inp"));
  // Readable: a comment says what each block is.
  const std::string deck = ringtest::shell("cat " + out + "/ring.inp");
  EXPECT_EQ(deck.rfind("** CalculiX deck written by ringvib", 0), 0u);
  for (const char* block : {"*NODE", "*ELEMENT", "*MATERIAL", "*BEAM SECTION", "*BOUNDARY", "*STEP"}) {
    const auto at = deck.find(std::string("\n") + block);
    ASSERT_NE(at, std::string::npos) << block;
    EXPECT_NE(deck.rfind("\n** ", at), std::string::npos) << "no comment before " << block;
  }
  // Run by hand, as a user would, then the column through ringvib.
  ASSERT_EQ(std::system(("cd " + out + " && OMP_NUM_THREADS=1 ccx ring >ccx.log 2>&1").c_str()), 0);
  const std::vector<double> by_hand = dat_frequencies(out + "/ring.dat");
  const auto m = ringvib("modes " + f.scene + " --solver calculix --json");
  ASSERT_EQ(m.code, 0) << m.err;
  const auto j = nlohmann::json::parse(m.out);
  ASSERT_EQ(j["rigid_modes"], 1);
  const auto omega = j["omega"].get<std::vector<double>>();
  ASSERT_EQ(omega.size(), 8u);
  ASSERT_GE(by_hand.size(), 9u);
  // The same deck: the same printed digits (the pinned ring's rigid mode first; no
  // twisting mode below the 8th in-plane one at 40 elements).
  for (std::size_t i = 0; i < omega.size(); ++i) EXPECT_EQ(omega[i], by_hand[i + 1]) << "mode " << i + 1;
}

/// The paper ring pinned at 270 deg, its point at 90 deg driven down by 1e-4 m (1e-5 R), in
/// the calculix column at 40 B32R elements.
std::string driven_scene(const std::string& plastic = "") {
  return "title = \"driven pinch, calculix\"\n" + ringtest::paper_ring_toml() + plastic + R"([supports]
pin = 270.0
[calculix]
elements = 40
[static]
solvers = ["calculix"]
displacement = { at = 90.0, value = [0.0, -1e-4] }
record = [90.0]
steps = 2
)";
}

TEST(CalculixCli, ADrivenPinchPrintsTheReactionOfTheClosedForm) {
  if (ccx_absent()) GTEST_SKIP() << "ccx is not on the PATH (Debian package calculix-ccx; scripts/install-deps.sh)";
  Fixture f;
  ringtest::write(f.scene, driven_scene());
  const auto r = ringvib("static " + f.scene + " --solver calculix --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("reaction")) << r.out;
  // The thin ring's pinching force c / ((pi/4 - 2/pi) R^3 / EI) (Roark's ring case 1), EI of the
  // paper's circle d = 0.12 m: within 1e-3, the column's error at 40 elements (measured 6.7e-4,
  // calculix_driven_test: B32R's discretization and the bricks' shear and extension).
  const double d = 0.12, EI = 2.1e11 * M_PI * std::pow(d, 4) / 64.0, R = 10.0;
  const double P = 1e-4 / ((M_PI / 4.0 - 2.0 / M_PI) * R * R * R / EI);
  EXPECT_NEAR(j["reaction"][1].get<double>() / -P, 1.0, 1e-3) << r.out;
  EXPECT_NEAR(j["displacements"][0]["uy"].get<double>(), -1e-4, 1e-10) << r.out;
}

TEST(CalculixCli, ADrivenRingWithTheResultantLawIsExit2NamingTheKey) {
  Fixture f;
  // The resultant law (moment against curvature) has no place in ccx's bricks, driven or not.
  ringtest::write(f.scene, driven_scene("plastic = { moment = 1e3 }\n"));
  const auto r = ringvib("static " + f.scene + " --solver calculix --json");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("ring.plastic.moment"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

}  // namespace
