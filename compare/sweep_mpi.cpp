#include "compare/sweep_mpi.hpp"

#include <chrono>
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
