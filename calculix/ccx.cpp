#include "calculix/ccx.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "ring/errors.hpp"

namespace calculix {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// ccx's output as RunOutput::log keeps it (ccx.hpp), and whether "*ERROR" occurs anywhere
/// in it. A ccx that wrote 200 MB before failing made ringvib hold the whole log (790 MB
/// peak) to print its last 12 lines (issue 46): the head is read from the start, the tail
/// at the end (pread at size - kLogKeep / 2), and the search for "*ERROR" goes through the
/// rest in chunks.
/// Memory O(kLogKeep) whatever ccx wrote; time O(the log's size) for the search.
struct Log {
  std::string text;
  bool error = false;
};

Log read_log(const std::string& path) {
  Log log;
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return log;
  struct stat st;
  const off_t size = fstat(fd, &st) == 0 ? st.st_size : 0;
  const std::string marker = "*ERROR";
  // Reads [from, to) in chunks; each chunk keeps the last marker.size() - 1 bytes of the one
  // before it, so that a marker across two chunks is found.
  auto scan = [&](off_t from, off_t to, std::string* keep) {
    std::string carry;
    std::vector<char> chunk(kLogKeep / 2);
    for (off_t at = from; at < to;) {
      const ssize_t n = pread(fd, chunk.data(), static_cast<std::size_t>(std::min<off_t>(to - at, chunk.size())), at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      carry.append(chunk.data(), static_cast<std::size_t>(n));
      if (keep) keep->append(chunk.data(), static_cast<std::size_t>(n));
      log.error |= carry.find(marker) != std::string::npos;
      carry.erase(0, carry.size() - std::min(carry.size(), marker.size() - 1));
      at += n;
    }
  };
  if (size <= static_cast<off_t>(kLogKeep)) {
    scan(0, size, &log.text);
  } else {
    const off_t half = static_cast<off_t>(kLogKeep / 2);
    std::string head, tail;
    scan(0, half, &head);
    scan(half - static_cast<off_t>(marker.size()) + 1, size - half, nullptr);
    scan(size - half - static_cast<off_t>(marker.size()) + 1, size, &tail);
    tail.erase(0, marker.size() - 1);
    log.text = head + "\n[... " + std::to_string(size - 2 * half) + " bytes of ccx's output not kept ...]\n" + tail;
  }
  close(fd);
  return log;
}

/// Removes the job folder: ccx writes only plain files into it.
void remove_folder(const std::string& dir) {
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name != "." && name != "..") unlink((dir + "/" + name).c_str());
    }
    closedir(d);
  }
  rmdir(dir.c_str());
}

/// The job folder for the length of one run; removed on every way out.
class JobFolder {
 public:
  explicit JobFolder(const Hooks& hooks) : hooks_(hooks) {
    std::string tmpl = temp_root() + "/ringvib-ccx-XXXXXX";
    std::vector<char> buf(tmpl.begin(), tmpl.end());
    buf.push_back('\0');
    if (!mkdtemp(buf.data()))
      throw ring::NumericalError("calculix: cannot create a temporary folder " + tmpl + ": " + std::strerror(errno));
    path_ = buf.data();
    if (hooks_.folder_made) hooks_.folder_made(path_);
  }
  ~JobFolder() {
    remove_folder(path_);
    if (hooks_.folder_removed) hooks_.folder_removed(path_);
  }
  JobFolder(const JobFolder&) = delete;
  JobFolder& operator=(const JobFolder&) = delete;
  const std::string& path() const { return path_; }

 private:
  const Hooks& hooks_;
  std::string path_;
};

}  // namespace

std::string temp_root() {
  const char* tmp = std::getenv("TMPDIR");
  return tmp && *tmp ? tmp : "/tmp";
}

void require_environment(const std::string& solver) {
  require_ccx(solver);
  const char* tmp = std::getenv("TMPDIR");
  const std::string key = tmp && *tmp ? "TMPDIR" : "/tmp";
  const std::string root = temp_root();
  struct stat st;
  std::string why;
  if (stat(root.c_str(), &st) != 0) why = std::strerror(errno);
  else if (!S_ISDIR(st.st_mode)) why = "not a folder";
  else if (access(root.c_str(), W_OK | X_OK) != 0) why = "not writable: " + std::string(std::strerror(errno));
  if (!why.empty())
    throw ring::InputError("", key,
                           "the " + solver + " solver runs ccx in a temporary folder under " + root + " (" + why +
                               "); expected an existing writable folder: set TMPDIR to one, or unset it for /tmp");
}

std::string tail(const std::string& text, int lines) {
  std::size_t pos = text.size();
  while (pos > 0 && (text[pos - 1] == '\n' || text[pos - 1] == ' ')) --pos;
  const std::size_t end = pos;
  for (int n = 0; n < lines && pos > 0; ++n) {
    const std::size_t nl = text.rfind('\n', pos - 1);
    pos = nl == std::string::npos ? 0 : nl;
    if (nl == std::string::npos) break;
  }
  std::string out = text.substr(pos, end - pos);
  while (!out.empty() && out.front() == '\n') out.erase(out.begin());
  return out;
}

std::string find_ccx() {
  const char* path = std::getenv("PATH");
  if (!path) return "";
  std::stringstream s(path);
  for (std::string dir; std::getline(s, dir, ':');) {
    if (dir.empty()) dir = ".";
    const std::string p = dir + "/ccx";
    struct stat st;
    if (stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(p.c_str(), X_OK) == 0) return p;
  }
  return "";
}

void require_ccx(const std::string& solver) {
  if (find_ccx().empty())
    throw ring::InputError("", solver,
                           "the " + solver + " solver runs the program ccx, which is not on the PATH; install the "
                           "Debian package calculix-ccx (apt-get install calculix-ccx, or scripts/install-deps.sh)");
}

RunOutput run(const std::string& deck, const RunOptions& options, const Hooks& hooks) {
  const std::string ccx = find_ccx();
  if (ccx.empty()) require_ccx();
  JobFolder job(hooks);
  {
    std::ofstream f(job.path() + "/ring.inp", std::ios::binary);
    f << deck;
    f.flush();
    if (!f) throw ring::NumericalError("calculix: cannot write the deck into " + job.path());
  }
  const std::string log_path = job.path() + "/ccx.log";
  const std::string threads = std::to_string(options.threads);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) throw ring::NumericalError(std::string("calculix: cannot start ccx: ") + std::strerror(errno));
  if (pid == 0) {
    // The child: its own folder, output to the log, the thread counts, then ccx.
    if (chdir(job.path().c_str()) != 0) _exit(126);
    const int out = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int in = open("/dev/null", O_RDONLY);
    if (out < 0 || in < 0) _exit(126);
    dup2(in, STDIN_FILENO);
    dup2(out, STDOUT_FILENO);
    dup2(out, STDERR_FILENO);
    for (const char* v : {"OMP_NUM_THREADS", "CCX_NPROC_EQUATION_SOLVER", "CCX_NPROC_STIFFNESS", "CCX_NPROC_RESULTS",
                          "NUMBER_OF_CPUS"})
      setenv(v, threads.c_str(), 1);
    // Signals ringvib blocks (during a publish) must not stay blocked in ccx.
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    execl(ccx.c_str(), "ccx", "-i", "ring", static_cast<char*>(nullptr));
    _exit(127);
  }
  if (hooks.child) hooks.child(pid);
  int status = 0;
  bool timed_out = false;
  struct rusage usage {};
  for (;;) {
    const pid_t r = wait4(pid, &status, WNOHANG, &usage);
    if (r == pid) break;
    if (hooks.poll) {
      try {
        hooks.poll();
      } catch (...) {  // interrupted: ccx first, then the folder (JobFolder), then the caller
        kill(pid, SIGKILL);
        while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
        }
        if (hooks.child) hooks.child(0);
        throw;
      }
    }
    if (r < 0 && errno != EINTR) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > options.timeout) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &usage);
      timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (hooks.child) hooks.child(0);
  RunOutput o;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.cpu_seconds = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  const Log log = read_log(log_path);
  o.log = log.text;
  auto fail = [&](const std::string& why) {
    throw ring::NumericalError("calculix: " + why + "; the last lines of its output:\n" + tail(o.log, 12));
  };
  if (timed_out) fail("ccx did not finish within calculix.timeout = " + std::to_string(options.timeout) + " s");
  if (WIFSIGNALED(status)) fail("ccx died of signal " + std::to_string(WTERMSIG(status)));
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127 && o.log.empty()) fail("ccx could not be started (" + ccx + ")");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail("ccx exited with status " + std::to_string(WEXITSTATUS(status)));
  if (log.error) fail("ccx reported an error");
  o.dat = read_all(job.path() + "/ring.dat");
  o.sta = read_all(job.path() + "/ring.sta");
  if (o.dat.empty()) fail("ccx wrote no ring.dat");
  return o;
}

}  // namespace calculix
