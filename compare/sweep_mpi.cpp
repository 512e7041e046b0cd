#include "compare/sweep_mpi.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ring/errors.hpp"

#ifdef RINGVIB_WITH_MPI
#include <mpi.h>
#endif

namespace cmp::mpi {
namespace {

int env_int(std::initializer_list<const char*> names, int fallback) {
  for (const char* n : names)
    if (const char* v = std::getenv(n)) return std::atoi(v);
  return fallback;
}

}  // namespace

int launched_size() { return env_int({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "SLURM_NTASKS"}, 1); }
int launched_rank() { return env_int({"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID"}, 0); }

// ---- the launcher of `sweep --ranks N` ----

namespace {

/// The executable `name` on PATH, or "".
std::string on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string d; std::getline(dirs, d, ':');) {
    const std::string f = (d.empty() ? "." : d) + "/" + name;
    if (access(f.c_str(), X_OK) == 0) return f;
  }
  return "";
}

/// The processes whose parent is `parent` (from /proc): mpirun's ranks.
std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> v;
  if (DIR* d = opendir("/proc")) {
    while (const dirent* e = readdir(d)) {
      const pid_t pid = static_cast<pid_t>(std::atoi(e->d_name));
      if (pid <= 0) continue;
      std::ifstream f("/proc/" + std::string(e->d_name) + "/stat");
      std::string stat((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
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

}  // namespace

int launch(int ranks, int argc, char** argv) {
  const std::string mpirun = on_path("mpirun");
  if (mpirun.empty())
    throw ring::InputError("", "--ranks", "starts mpirun, and no mpirun is on PATH (install Open MPI, or run the sweep "
                                          "on this machine's cores without --ranks)");
  char self[4096];
  const ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
  if (len <= 0) throw std::runtime_error("--ranks: cannot find this program's path");
  self[len] = '\0';
  std::vector<std::string> args{mpirun, "-np", std::to_string(ranks), self};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--ranks") {
      ++i;  // and its value
      continue;
    }
    if (a.rfind("--ranks=", 0) == 0) continue;
    args.push_back(a);
  }
  std::vector<char*> cargs;
  for (auto& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);

  // The signals stay blocked in the launcher and are taken by sigtimedwait, SIGCHLD with
  // them (mpirun's end), so that none falls between a check and a wait.
  sigset_t wait_for, old;
  sigemptyset(&wait_for);
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGCHLD}) sigaddset(&wait_for, s);
  sigprocmask(SIG_BLOCK, &wait_for, &old);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("--ranks: cannot start mpirun: ") + std::strerror(errno));
  if (pid == 0) {
    // A process group of its own (a terminal's Ctrl-C reaches the launcher alone) and no
    // terminal input (mpirun would forward it to rank 0, and a background read stops it).
    setpgid(0, 0);
    const int null = open("/dev/null", O_RDONLY);
    if (null >= 0) dup2(null, 0);
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &dfl, nullptr);
    sigprocmask(SIG_SETMASK, &old, nullptr);
    execv(cargs[0], cargs.data());
    static const char kFail[] = "ringvib: --ranks: cannot run mpirun\n";
    [[maybe_unused]] const auto w = write(2, kFail, sizeof kFail - 1);
    _exit(127);
  }
  setpgid(pid, pid);  // also here: whichever runs first
  int status = 0, caught = 0;
  for (;;) {
    if (waitpid(pid, &status, WNOHANG) == pid) break;
    siginfo_t info;
    const timespec tick{0, 200'000'000};  // a bound only: SIGCHLD wakes the wait at mpirun's end
    const int sig = sigtimedwait(&wait_for, &info, &tick);
    if (sig == SIGINT || sig == SIGTERM || sig == SIGHUP) {
      caught = sig;
      // To the ranks (mpirun's children), each of which dies of it (rank 0 after removing
      // what it staged), so that mpirun reports 128 + signal; to mpirun itself only while
      // it has started no rank yet.
      const std::vector<pid_t> children = children_of(pid);
      if (children.empty()) kill(pid, sig);
      for (const pid_t c : children) kill(c, sig);
    }
  }
  // The signals stay blocked: the launcher only returns its code now, and a late signal
  // must not turn a finished sweep's 0 into a death.
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  // A sweep that published before the signal ended with 0: it finished.
  return caught && code != 0 ? 128 + caught : code;
}

#ifdef RINGVIB_WITH_MPI

bool built() { return true; }

namespace {
constexpr int kRequest = 1, kAssign = 2;

// Signals under mpirun (measured with Open MPI 4.1.4, Debian 12; docs/commands.md, "ringvib sweep").
// The run's files are rank 0's alone: it stages them and, on SIGINT, SIGTERM or SIGHUP,
// its handler (install_signal_cleanup) removes the stage and the folders the run made,
// then dies of the signal.
// - A signal to mpirun itself (Ctrl-C in a terminal reaches only mpirun: each rank runs in
//   a process group of its own): mpirun sends every rank SIGCONT, after
//   odls_base_sigkill_timeout (1 s) SIGTERM, after 1 s more SIGKILL, and exits 1 whatever
//   the ranks do: its abort path sets its default error code first and stops waiting for
//   the ranks' statuses. No program under mpirun can change that code.
// - A signal to the ranks (kill, pkill, a batch system signalling its tasks): mpirun exits
//   128 + signal, the code of the first rank that died ("so that prog and orterun prog
//   yield the same exit code", orte/mca/odls/base).
// When a worker rank died of mpirun's SIGTERM at once, rank 0 was killed in the middle of
// its cleanup (the output folder left behind, empty) in 3 of 6 shell runs and in 5 of 5
// runs of SweepMpi.ASignalPublishesNothing...; with the workers outliving rank 0, in none
// of 12 and none of 10. So a worker defers these signals by
// kWorkerGraceSeconds: under mpirun, the SIGKILL 1 s after SIGTERM ends it first; a signal
// sent to a worker directly still ends it, as that signal, within the grace time.
// A worker defers only once MPI has started (this function); a signal that reaches the
// ranks while they start MPI ends them at once, and then mpirun 4.1.4 sometimes hangs in
// PMIx_server_finalize after both ranks are gone (6 of about 50 tries that signalled the
// ranks right after rank 0 opened its outputs; rank 0's cleanup had run; kill mpirun).
constexpr unsigned kWorkerGraceSeconds = 2;
volatile std::sig_atomic_t g_deferred = 0;

void worker_signal(int sig) {
  if (g_deferred) return;
  g_deferred = sig;
  alarm(kWorkerGraceSeconds);
}

void worker_alarm(int) {
  const int sig = g_deferred;
  signal(sig, SIG_DFL);
  raise(sig);
}

void defer_signals_on_worker() {
  struct sigaction sa {};
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sa.sa_handler = worker_signal;
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &sa, nullptr);
  sa.sa_handler = worker_alarm;
  sigaction(SIGALRM, &sa, nullptr);
}

void send_text(const std::string& s, int to, int tag) {
  MPI_Send(s.data(), static_cast<int>(s.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::string receive_text(MPI_Status& st) {
  int len = 0;
  MPI_Get_count(&st, MPI_CHAR, &len);
  std::string s(static_cast<std::size_t>(len), '\0');
  MPI_Recv(s.data(), len, MPI_CHAR, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return s;
}
}  // namespace

bool distribute(int argc, char** argv, int n, const std::function<std::string(int)>& run,
                std::vector<std::string>& results) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank != 0) {
    defer_signals_on_worker();
    // Request: "<index>\n<result>" for the last case run, or "-1\n" at first.
    std::string message = "-1\n";
    for (;;) {
      send_text(message, 0, kRequest);
      int next = -1;
      MPI_Recv(&next, 1, MPI_INT, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (next < 0) break;
      message = std::to_string(next) + "\n" + run(next);
    }
    MPI_Finalize();
    return false;
  }
  results.assign(static_cast<std::size_t>(n), std::string());
  std::mutex m;
  int counter = 0;
  auto take = [&] {
    std::lock_guard<std::mutex> lock(m);
    return counter < n ? counter++ : -1;
  };
  // Rank 0's own worker (no MPI calls: MPI_THREAD_FUNNELED).
  std::thread local([&] {
    // Named, so that a user (top -H) or a test sees that the cases run.
    pthread_setname_np(pthread_self(), "ringvib-cases");
    for (int i; (i = take()) >= 0;) {
      std::string r = run(i);
      std::lock_guard<std::mutex> lock(m);
      results[static_cast<std::size_t>(i)] = std::move(r);
    }
  });
  int active = size - 1;
  while (active > 0) {
    // Poll rather than block: Open MPI's blocking probe spins a core, which the local
    // worker thread needs.
    MPI_Status st;
    for (int flag = 0;;) {
      MPI_Iprobe(MPI_ANY_SOURCE, kRequest, MPI_COMM_WORLD, &flag, &st);
      if (flag) break;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    const std::string msg = receive_text(st);
    const auto nl = msg.find('\n');
    const int done = std::atoi(msg.substr(0, nl).c_str());
    if (done >= 0) {
      std::lock_guard<std::mutex> lock(m);
      results[static_cast<std::size_t>(done)] = msg.substr(nl + 1);
    }
    const int next = take();
    MPI_Send(&next, 1, MPI_INT, st.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
    if (next < 0) --active;
  }
  local.join();
  MPI_Finalize();
  return true;
}

#else

bool built() { return false; }

bool distribute(int, char**, int, const std::function<std::string(int)>&, std::vector<std::string>&) { return true; }

#endif

}  // namespace cmp::mpi
