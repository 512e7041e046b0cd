#include "compare/sweep_mpi.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <mutex>
#include <thread>

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
