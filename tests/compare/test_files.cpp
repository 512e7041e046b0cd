// The file contract under hostile input, through the binary: ringvib touches
// only its own files, checks every destination before computing, publishes nothing of a
// failed or interrupted run, leaves no stage, and refuses what it cannot measure instead of
// printing NaN. The oracle is the contract of docs/commands.md ("Exit codes", "Files a run writes");
// each test names the probe finding it holds.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli.hpp"
#include "compare/files.hpp"
#include "support/paper.hpp"

using ringtest::exists;
using ringtest::leftovers;
using ringtest::ringvib;
using ringtest::shell;
using ringtest::source;

namespace {

std::string read(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void expect_input_error(const ringtest::Run& r, const std::string& names) {
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << "message does not name " << names << ": " << r.err;
}

const std::string kMultibody = "scenes/paper1990-multibody.toml";

// Security: a planted manifest line used to delete files outside --out ("../victim"),
// and a user's file and folder inside it ("sub/keep.txt", "sub").
TEST(Files, APlantedManifestRemovesNothingButRingvibsOwnFiles) {
  const std::string base = ringtest::temp_dir(), out = base + "/r";
  ASSERT_EQ(mkdir(out.c_str(), 0755), 0);
  ringtest::write(base + "/victim", "precious");
  ASSERT_EQ(mkdir((out + "/sub").c_str(), 0755), 0);
  ringtest::write(out + "/sub/keep.txt", "mine");
  ringtest::write(out + "/notes.txt", "mine");  // a name ringvib could write, but not listed
  ringtest::write(out + "/.ringvib-files", "../victim\n" + base + "/victim\nsub/keep.txt\nsub\n..\n.\n"
                                           "report.md/../../victim\n");
  const auto r = ringvib("run " + source(kMultibody) + " --out " + out + " -q");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read(base + "/victim"), "precious");
  EXPECT_EQ(read(out + "/sub/keep.txt"), "mine");
  EXPECT_EQ(read(out + "/notes.txt"), "mine");
  EXPECT_NE(r.err.find("ignored"), std::string::npos) << "the ignored lines are said: " << r.err;
  EXPECT_TRUE(exists(out + "/report.md"));
  // The new manifest lists only what this run wrote.
  const std::string manifest = read(out + "/.ringvib-files");
  EXPECT_EQ(manifest.find(".."), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find("sub"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("report.md"), std::string::npos) << manifest;
  EXPECT_EQ(leftovers(base), "");
}

// Security: an output path that is a device, FIFO or symlink was renamed over.
TEST(Files, OutputPathsThatAreNotRegularFilesAreRefusedUpFront) {
  const std::string dir = ringtest::temp_dir();
  const std::string forced = source("scenes/paper1990-forced.toml");
  ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0644), 0);
  ringtest::write(dir + "/target", "target");
  ASSERT_EQ(symlink((dir + "/target").c_str(), (dir + "/link").c_str()), 0);
  ASSERT_EQ(symlink((dir + "/nowhere").c_str(), (dir + "/dangling").c_str()), 0);
  // A character device where mknod is allowed (root, as in CI); /dev/null itself otherwise.
  const std::string device = mknod((dir + "/null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0 ? dir + "/null"
                                                                                                  : "/dev/null";
  for (const std::string& path : {dir + "/fifo", dir + "/link", dir + "/dangling", device}) {
    expect_input_error(ringvib("run " + source(kMultibody) + " --junit " + path), "--junit " + path);
    expect_input_error(ringvib("respond " + forced + " --csv " + path), "--csv " + path);
  }
  struct stat st;
  ASSERT_EQ(lstat((dir + "/fifo").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  ASSERT_EQ(lstat(device.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  ASSERT_EQ(lstat((dir + "/link").c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode));
  EXPECT_EQ(read(dir + "/target"), "target");
  // A stream is asked for with -, where it is offered (--junit goes to a file: exit 2).
  expect_input_error(ringvib("run " + source(kMultibody) + " --junit -"), "--junit -");
  const auto streamed = ringvib("respond " + forced + " --csv -");
  ASSERT_EQ(streamed.code, 0) << streamed.err;
  EXPECT_EQ(streamed.out.rfind("t,", 0), 0u) << streamed.out.substr(0, 80);
  // --out as a dangling symlink or a loop: refused before computing, nothing made.
  ASSERT_EQ(symlink((dir + "/loop").c_str(), (dir + "/loop").c_str()), 0);
  for (const std::string& out : {dir + "/dangling", dir + "/loop", dir + "/dangling/sub"})
    expect_input_error(ringvib("run " + source(kMultibody) + " --out " + out), "--out " + out);
  // --vtu as well (refused before the FE plug-in is loaded).
  expect_input_error(ringvib("modes " + source("scenes/paper1990.toml") + " --solver fem --vtu " + dir + "/dangling"),
                     "--vtu " + dir + "/dangling");
  EXPECT_FALSE(exists(dir + "/nowhere"));
  EXPECT_EQ(leftovers(dir), "");
}

// Found only after computing: a name ringvib writes taken by a folder; names at the file
// system's limit (the old ".tmp-PID" suffix passed NAME_MAX).
TEST(Files, DestinationsAreCheckedBeforeComputing) {
  const std::string dir = ringtest::temp_dir();
  ASSERT_EQ(system(("mkdir -p " + dir + "/s/sweep.md " + dir + "/r/report.md").c_str()), 0);
  expect_input_error(ringvib("sweep " + source(kMultibody) + " --vary 'multibody.n=[40, 80]' --out " + dir + "/s"),
                     "sweep.md");
  expect_input_error(ringvib("run " + source(kMultibody) + " --out " + dir + "/r"), "report.md");
  EXPECT_EQ(shell("LC_ALL=C ls -A " + dir + "/s"), "sweep.md\n");
  // 250 bytes: a valid name, written whole; 256 bytes: refused up front.
  const std::string long_name = dir + "/" + std::string(246, 'j') + ".xml";
  const auto ok = ringvib("run " + source(kMultibody) + " --junit " + long_name + " -q");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(read(long_name).find("<testsuite"), std::string::npos);
  const std::string too_long = dir + "/" + std::string(252, 'j') + ".xml";
  expect_input_error(ringvib("run " + source(kMultibody) + " --junit " + too_long), "longer than");
  expect_input_error(ringvib("run " + source(kMultibody) + " --out " + dir + "/" + std::string(256, 'd')),
                     "longer than");
  EXPECT_EQ(leftovers(dir), "");
}

// Published while failed: a failed response replaced a good run's response.csv with its
// one-row history.
TEST(Files, AFailedRunPublishesNothing) {
  const std::string dir = ringtest::temp_dir(), out = dir + "/f";
  const std::string forced = source("scenes/paper1990-forced.toml");
  ASSERT_EQ(ringvib("run " + forced + " --out " + out + " -q").code, 0);
  const std::string good = read(out + "/response.csv"), manifest = read(out + "/.ringvib-files");
  ASSERT_GT(std::count(good.begin(), good.end(), '\n'), 100);
  const auto failed = ringvib("run " + forced + " --set 'response.force=[-1e12, 0.0]' --out " + out + " -q");
  EXPECT_EQ(failed.code, 3) << failed.err;
  EXPECT_EQ(read(out + "/response.csv"), good);
  EXPECT_EQ(read(out + "/.ringvib-files"), manifest);
  // The same with --csv: the good file stays.
  ASSERT_EQ(ringvib("respond " + forced + " --csv " + dir + "/h.csv").code, 0);
  const std::string history = read(dir + "/h.csv");
  EXPECT_EQ(ringvib("respond " + forced + " --set 'response.force=[-1e12, 0.0]' --csv " + dir + "/h.csv").code, 3);
  EXPECT_EQ(read(dir + "/h.csv"), history);
  // A failing run into a new folder leaves no folder.
  EXPECT_EQ(ringvib("run " + forced + " --set 'response.force=[-1e12, 0.0]' --out " + dir + "/new/deeper -q").code, 3);
  EXPECT_FALSE(exists(dir + "/new"));
  EXPECT_EQ(leftovers(dir), "");
}

// Mixed or stale: a second sweep without a figure kept the first one's sweep.png; a sweep
// in which every case fails published its table and exited 3.
TEST(Files, ASweepFolderHoldsOneSweepsFiles) {
  const std::string out = ringtest::temp_dir() + "/s";
  ASSERT_EQ(ringvib("sweep " + source(kMultibody) + " --vary 'multibody.n=[40, 80]' --out " + out + " -q").code, 0);
  ASSERT_TRUE(exists(out + "/sweep.png"));
  // Values that are not numbers: no figure.
  const auto second = ringvib("sweep " + source(kMultibody) +
                              " --vary 'multibody.rotary_inertia=[true, false]' --out " + out + " -q");
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_FALSE(exists(out + "/sweep.png"));
  EXPECT_NE(read(out + "/sweep.csv").find("multibody.rotary_inertia"), std::string::npos);
  const std::string csv = read(out + "/sweep.csv");
  // Every case fails (the ring touches itself): exit 3, the folder as it was.
  const auto failing = ringvib("sweep " + source("scenes/paper1990-static.toml") +
                               " --vary 'static.force=[[-5e5, 0.0], [-6e5, 0.0]]' --out " + out + " -q");
  EXPECT_EQ(failing.code, 3) << failing.err;
  EXPECT_EQ(read(out + "/sweep.csv"), csv);
  EXPECT_EQ(leftovers(out), "");
}

// Two runs into one folder mixed their files: the second is refused while the first runs.
// The first run is stopped (SIGSTOP) once its stage exists, so it certainly still holds the
// folder when the second starts; it is continued afterwards and must end as usual. A first
// run that ended between the look and the stop is retried in a fresh folder.
TEST(Files, ASecondRunIntoTheSameFolderIsRefused) {
  const std::string base = ringtest::temp_dir();
  for (int attempt = 0; attempt < 5; ++attempt) {
    const std::string out = base + "/o" + std::to_string(attempt);
    const pid_t pid = ringtest::spawn({ringtest::ringvib_path(), "run", source("scenes/paper1990.toml"), "--out", out, "-q"});
    // The first run holds the folder from the moment its stage exists until it ends.
    bool held = false;
    const auto start = std::chrono::steady_clock::now();
    while (!held && std::chrono::steady_clock::now() - start < std::chrono::seconds(30)) {
      held = !shell("find " + out + " -maxdepth 1 -name '.ringvib-stage-*' 2>/dev/null").empty();
      if (!held) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (!held) {
      ringtest::wait_bounded(pid, 300.0);
      FAIL() << "the first run's stage never appeared";
    }
    ASSERT_EQ(kill(pid, SIGSTOP), 0);
    int stopped = 0;
    ASSERT_EQ(waitpid(pid, &stopped, WUNTRACED), pid);
    if (!WIFSTOPPED(stopped)) {  // it ended before the stop: its folder is free, try again
      EXPECT_TRUE(WIFEXITED(stopped) && WEXITSTATUS(stopped) == 0);
      continue;
    }
    const ringtest::Run second = ringvib("run " + source(kMultibody) + " --out " + out);
    kill(pid, SIGCONT);
    const int status = ringtest::wait_bounded(pid, 300.0);
    expect_input_error(second, "another ringvib run");
    ASSERT_TRUE(WIFEXITED(status)) << "the first run did not end after it was continued";
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(leftovers(out), "");
    return;
  }
  FAIL() << "in 5 attempts the first run always ended before it could be stopped holding the folder";
}

// Interrupted: SIGINT and SIGTERM at random points of a run with --out and of a sweep
// never leave a published file of the interrupted run, nor a stage. Each attempt writes
// into a fresh folder over an earlier complete run's files, which must survive intact.
TEST(Files, AnInterruptedRunPublishesNothing) {
  const std::string base = ringtest::temp_dir();
  std::mt19937 random(20261125);  // fixed seed: the same kill times every run
  int interrupted = 0;
  for (int attempt = 0; attempt < 10; ++attempt) {
    const bool sweep = attempt % 2 == 1;
    const int sig = attempt % 4 < 2 ? SIGINT : SIGTERM;
    const std::string out = base + "/run" + std::to_string(attempt);
    std::vector<std::string> args =
        sweep ? std::vector<std::string>{"sweep", source("scenes/paper1990.toml"), "--vary",
                                         "multibody.n=[40, 80, 160, 320]", "--out", out, "-q", "-j", "1"}
              : std::vector<std::string>{"run", source("scenes/paper1990.toml"), "--out", out, "-q"};
    // An earlier complete run: a marker file that the next run replaces only if it ends.
    ASSERT_EQ(mkdir(out.c_str(), 0755), 0);
    const std::string marker = sweep ? "sweep.md" : "report.md";
    ringtest::write(out + "/" + marker, "earlier run");
    ringtest::write(out + "/.ringvib-files", marker + "\n");
    args.insert(args.begin(), ringtest::ringvib_path());
    const pid_t pid = ringtest::spawn(args);
    // A run takes ~0.6 s and a sweep ~1.1 s here (README); kill within that span.
    std::uniform_int_distribution<int> ms(5, sweep ? 1100 : 600);
    std::this_thread::sleep_for(std::chrono::milliseconds(ms(random)));
    kill(pid, sig);
    const int status = ringtest::wait_bounded(pid, 60.0);
    ASSERT_NE(status, -1) << "attempt " << attempt << ": the run did not end after the signal";
    EXPECT_EQ(leftovers(base), "") << "attempt " << attempt;
    if (WIFSIGNALED(status)) {
      ++interrupted;
      EXPECT_EQ(WTERMSIG(status), sig);
      EXPECT_EQ(read(out + "/" + marker), "earlier run") << "attempt " << attempt;
      EXPECT_EQ(shell("LC_ALL=C ls -A " + out), ".ringvib-files\n" + marker + "\n") << "attempt " << attempt;
    } else {
      // Finished before the signal: the folder holds the new run, whole.
      EXPECT_EQ(WEXITSTATUS(status), 0) << "attempt " << attempt;
      EXPECT_NE(read(out + "/" + marker), "earlier run");
      EXPECT_TRUE(exists(out + (sweep ? "/sweep.csv" : "/table.csv")));
    }
  }
  EXPECT_GE(interrupted, 5) << "the signal should mostly arrive during the run";
}

// A signal that arrives after the results were published (the run has only its exit left)
// ends the run with its own code, the results in place, and a line that says so; the same
// signal just before publishing ends it by the signal with nothing published (above).
TEST(Files, ASignalAfterPublishingLeavesTheResultsAndTheExitCode) {
  const std::string out = ringtest::temp_dir() + "/published";
  int pipe_fd[2];
  ASSERT_EQ(pipe(pipe_fd), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(pipe_fd[1], STDERR_FILENO);
    cmp::install_signal_cleanup();
    cmp::Outputs files;
    files.folder(out, "--out", {"report"});
    files.open();
    std::ofstream(files.stage() + "/report.md") << "done\n";
    files.publish();
    raise(SIGTERM);
    _exit(7);  // the command's own code (a gate's, say)
  }
  close(pipe_fd[1]);
  std::string err;
  char buf[256];
  for (ssize_t n; (n = ::read(pipe_fd[0], buf, sizeof buf)) > 0;) err.append(buf, static_cast<std::size_t>(n));
  close(pipe_fd[0]);
  const int status = ringtest::wait_bounded(pid, 60.0);
  ASSERT_TRUE(WIFEXITED(status)) << "died of signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 7);
  EXPECT_EQ(read(out + "/report.md"), "done\n");
  EXPECT_NE(err.find("interrupted after the results were published"), std::string::npos) << err;
}

// Found only after computing: a solver's refusal came after other solvers had run (and in
// a sweep became input-error rows with exit 0).
TEST(Files, SolverRefusalsComeBeforeAnySolverRuns) {
  const std::string compare = source("scenes/paper1990-forced-compare.toml");
  const std::string dir = ringtest::temp_dir();
  expect_input_error(ringvib("respond " + compare + " --set response.integrator=energy-momentum"), "energy-momentum");
  expect_input_error(ringvib("respond " + compare + " --set response.integrator=generalized-alpha"),
                     "generalized-alpha");
  expect_input_error(ringvib("run " + compare + " --set fem.geometry=polygon --out " + dir + "/o"), "curved");
  EXPECT_FALSE(exists(dir + "/o"));
  expect_input_error(ringvib("run " + source("scenes/paper1990.toml") +
                             " --set multibody.method=sparse --set multibody.n=8 --set lumped.n=8 "
                             "--set fem.elements=8 --set modes.count=3"),
                     "n >= 10");
  const auto sweep = ringvib("sweep " + compare + " --vary 'response.integrator=[\"newmark\", \"energy-momentum\"]' "
                             "--out " + dir + "/s");
  expect_input_error(sweep, "energy-momentum");
  EXPECT_NE(sweep.err.find("case 1"), std::string::npos) << sweep.err;
  EXPECT_FALSE(exists(dir + "/s"));
}

// Wrong results with exit 0: bench printed every error as nan and "Verdict: holds" when
// the loaded point was not recorded.
TEST(Files, BenchRefusesWhatItCannotMeasure) {
  expect_input_error(ringvib("bench " + source("scenes/paper1990-static-compare.toml") + " --set 'static.record=[]'"),
                     "static.record");
  expect_input_error(ringvib("bench " + source("scenes/paper1990-forced-compare.toml") +
                             " --set 'response.record=[90.0, 180.0]'"),
                     "response.record");
}

// Guard: --max-memory nan switched the guard off.
TEST(Files, MaxMemoryMustBeAFinitePositiveNumber) {
  for (const char* v : {"nan", "inf", "-1", "0", "1e400", "x"})
    expect_input_error(ringvib("modes " + source(kMultibody) + " --solver multibody --max-memory " + v),
                       "--max-memory");
  expect_input_error(ringvib("modes " + source(kMultibody) + " --solver multibody --max-memory 1e-6"), "GiB");
}

// The scene is read once: a FIFO (or /dev/stdin) serves a whole sweep.
TEST(Files, ASweepReadsItsSceneOnce) {
  const std::string dir = ringtest::temp_dir();
  ASSERT_EQ(mkfifo((dir + "/scene").c_str(), 0644), 0);
  const std::string text = ringtest::source_text(kMultibody);
  std::thread writer([&] {
    std::ofstream f(dir + "/scene");
    f << text;
  });
  const auto r = ringvib("sweep " + dir + "/scene --vary 'multibody.n=[40, 80, 160]'");
  writer.join();
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find("input-error"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n2,160,"), std::string::npos) << r.out;
}

// --resume kept a case whose rows were cut short, copied old case ids, and a corrupt
// value gave "failure: stod" (exit 3) instead of naming sweep.csv and its line.
TEST(Files, ResumeKeepsOnlyCompleteCasesAndNamesACorruptLine) {
  const std::string out = ringtest::temp_dir() + "/s";
  const std::string scene = source(kMultibody);
  ASSERT_EQ(ringvib("sweep " + scene + " --vary 'multibody.n=[40, 80, 160]' --out " + out + " -q").code, 0);
  const std::string whole = read(out + "/sweep.csv");
  // Cut in the middle of case 1's rows (a crash, a full disk).
  std::size_t cut = 0;
  for (int line = 0; line < 1 + 23 + 11; ++line) cut = whole.find('\n', cut) + 1;
  ringtest::write(out + "/sweep.csv", whole.substr(0, cut + 7));
  const auto resumed = ringvib("sweep " + scene + " --vary 'multibody.n=[40, 80, 160]' --out " + out +
                               " --resume -q");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("3 cases, 2 run, 1 resumed"), std::string::npos) << resumed.err;
  const std::string again = read(out + "/sweep.csv");
  EXPECT_EQ(std::count(again.begin(), again.end(), '\n'), std::count(whole.begin(), whole.end(), '\n'));
  // Resuming a different list renumbers the kept cases.
  const auto other = ringvib("sweep " + scene + " --vary 'multibody.n=[60, 160]' --out " + out + " --resume -q");
  ASSERT_EQ(other.code, 0) << other.err;
  EXPECT_NE(other.err.find("2 cases, 1 run, 1 resumed"), std::string::npos) << other.err;
  EXPECT_NE(read(out + "/sweep.csv").find("\n1,160,"), std::string::npos);
  // A corrupt value: exit 2 naming the file and the line.
  std::string corrupt = read(out + "/sweep.csv");
  const auto third = corrupt.find('\n', corrupt.find('\n', corrupt.find('\n') + 1) + 1);
  const auto field = corrupt.find(",mode ", third);
  ASSERT_NE(field, std::string::npos);
  corrupt.replace(corrupt.find(',', field + 1) + 1, 3, "x!z");
  ringtest::write(out + "/sweep.csv", corrupt);
  const auto bad = ringvib("sweep " + scene + " --vary 'multibody.n=[60, 160]' --out " + out + " --resume -q");
  expect_input_error(bad, "sweep.csv");
  EXPECT_NE(bad.err.find("line 4"), std::string::npos) << bad.err;
}

}  // namespace

namespace {

// Guard: a sweep's own table was not estimated (10 keys x 100 values: bad_alloc). The
// case count is bounded before the list is built, the table and the cases at once after.
TEST(Files, ASweepsOwnMemoryIsInTheBudget) {
  std::string values;
  for (int i = 0; i < 100; ++i) values += (i ? ", " : "") + std::to_string(40 + 2 * i);
  std::string vary;
  for (const char* key : {"multibody.n", "lumped.n", "fem.elements", "modes.count", "ring.radius"})
    vary += std::string(" --vary '") + key + "=[" + values + "]'";
  expect_input_error(ringvib("sweep " + source(kMultibody) + vary), "--vary");  // 10^10 cases
  // Three cases are more than a budget of 1e-6 GiB (~1 KB) holds.
  expect_input_error(ringvib("sweep " + source(kMultibody) + " --vary 'multibody.n=[40, 80, 160]' --max-memory 1e-6"),
                     "memory budget");
  EXPECT_EQ(ringvib("sweep " + source(kMultibody) + " --vary 'multibody.n=[40, 80, 160]' --max-memory 1e-6 --force -q")
                .code,
            0);
}

}  // namespace

namespace {

/// `ringvib ARGS` (no shell) bounded to `seconds`: its exit code, or -1 when it had to be
/// killed (it blocked or read without end), so that a hang fails the test.
int bounded_code(const std::vector<std::string>& args, double seconds) {
  std::vector<std::string> all = {ringtest::ringvib_path()};
  all.insert(all.end(), args.begin(), args.end());
  const int status = ringtest::wait_bounded(ringtest::spawn(all), seconds);
  return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::string kImportRing = ringtest::paper_ring_toml() + R"([supports]
pin = 180.0
[multibody]
n = 40
[modes]
count = 5
solvers = ["multibody"]
)";

// Found by a robustness probe: an imported column was read without bound and unchecked: `file =
// "/dev/zero"` grew to 4.2 GB, a FIFO blocked open() forever. Every file a scene names
// (frequencies, shapes) must be a regular file within its cap (docs/commands.md, "Exit codes": 4 MiB
// and 64 MiB), checked before it is opened: exit 2 naming the file, at once. 5 s bounds a
// run that reads nothing (the refusals take milliseconds; the probe's hang never ends).
TEST(Files, ImportedFilesAreRegularFilesWithinTheirCapCheckedBeforeOpening) {
  const std::string dir = ringtest::temp_dir();
  ASSERT_EQ(mkfifo((dir + "/fifo.csv").c_str(), 0644), 0);
  ringtest::write(dir + "/modes.csv", "mode,omega\n1,2.48\n2,3.8\n3,11.3\n4,13.7\n5,27.4\n");
  // A file one byte over 4 MiB (sparse: no disk) and a shapes file one byte over 64 MiB.
  ringtest::write(dir + "/big.csv", "mode,omega\n");
  ringtest::write(dir + "/shapes.csv", "angle_deg");
  ASSERT_EQ(truncate((dir + "/big.csv").c_str(), (4 << 20) + 1), 0);
  ASSERT_EQ(truncate((dir + "/shapes.csv").c_str(), (64 << 20) + 1), 0);
  struct Case {
    std::string import, names;
  };
  for (const Case& c : std::vector<Case>{
           {"file = \"/dev/zero\"", "/dev/zero: is a character device"},
           {"file = \"fifo.csv\"", "fifo.csv: is a FIFO"},
           {"file = \"" + dir + "\"", "is a folder"},
           {"file = \"big.csv\"", "is 4194305 bytes, larger than the 4 MiB"},
           {"file = \"modes.csv\", shapes = \"fifo.csv\"", "fifo.csv: is a FIFO"},
           {"file = \"modes.csv\", shapes = \"/dev/zero\"", "/dev/zero: is a character device"},
           {"file = \"modes.csv\", shapes = \"shapes.csv\"", "is 67108865 bytes, larger than the 64 MiB"}}) {
    const std::string scene = dir + "/scene.toml";
    ringtest::write(scene, std::string(kImportRing) + "[table]\nimport = [{ label = \"ext\", " + c.import + " }]\n");
    ASSERT_EQ(bounded_code({"table", scene, "-q"}, 5.0), 2) << c.import;
    expect_input_error(ringvib("table " + scene + " -q"), c.names);
  }
  // The regular file within its cap is read.
  ringtest::write(dir + "/scene.toml", std::string(kImportRing) + "[table]\nimport = [{ label = \"ext\", file = \"modes.csv\" }]\n");
  EXPECT_EQ(ringvib("table " + dir + "/scene.toml -q").code, 0);
}

// Found by a robustness probe: a --resume table was read whole whatever its size. Over its cap
// (256 MiB; a sparse file, no disk) it is refused naming the cap, before it is read.
TEST(Files, AResumeTableOverItsCapIsRefusedUnread) {
  const std::string out = ringtest::temp_dir() + "/s";
  const std::string scene = source(kMultibody);
  ASSERT_EQ(ringvib("sweep " + scene + " --vary 'multibody.n=[40, 80]' --out " + out + " -q").code, 0);
  ASSERT_EQ(truncate((out + "/sweep.csv").c_str(), (256ll << 20) + 1), 0);
  const auto r = ringvib("sweep " + scene + " --vary 'multibody.n=[40, 80]' --out " + out + " --resume -q");
  expect_input_error(r, "sweep.csv: is 268435457 bytes, larger than the 256 MiB");
}

}  // namespace
