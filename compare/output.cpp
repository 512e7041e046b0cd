#include "compare/output.hpp"

#include <dirent.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <vector>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>

#include "ring/errors.hpp"

namespace cmp {

namespace {

// What a signal must clean up. Modified only with the signals blocked, so that the
// handler never sees a vector in the middle of a reallocation.
std::vector<std::string>* g_temporaries = nullptr;
std::string g_staging;  ///< the folder a run writes into before publish_folder, or empty
volatile sig_atomic_t g_child = 0;

class SignalBlock {
 public:
  SignalBlock() {
    sigset_t all;
    sigemptyset(&all);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&all, s);
    sigprocmask(SIG_BLOCK, &all, &old_);
  }
  ~SignalBlock() { sigprocmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

void on_signal(int sig) {
  if (g_child > 0) kill(g_child, SIGKILL);  // the running gnuplot
  if (g_temporaries)
    for (const auto& p : *g_temporaries) {  // files first, then the (emptied) folders
      if (unlink(p.c_str()) != 0) rmdir(p.c_str());
    }
  if (g_temporaries)
    for (auto it = g_temporaries->rbegin(); it != g_temporaries->rend(); ++it) rmdir(it->c_str());
  signal(sig, SIG_DFL);
  raise(sig);
}

std::string real_path(const std::string& p) {
  char buf[PATH_MAX];
  return realpath(p.c_str(), buf) ? std::string(buf) : std::string();
}

std::string parent_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::vector<std::string> read_lines(const std::string& file) {
  std::vector<std::string> v;
  std::ifstream f(file);
  for (std::string line; std::getline(f, line);)
    if (!line.empty()) v.push_back(line);
  return v;
}

}  // namespace

void install_signal_cleanup() {
  if (!g_temporaries) g_temporaries = new std::vector<std::string>();
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, s);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &sa, nullptr);
}

void register_temporary(const std::string& path) {
  if (!g_temporaries) return;
  SignalBlock block;
  g_temporaries->push_back(path);
}

void release_temporary(const std::string& path) {
  if (!g_temporaries) return;
  SignalBlock block;
  auto& v = *g_temporaries;
  v.erase(std::remove(v.begin(), v.end(), path), v.end());
}

void begin_staging(const std::string& dir) {
  g_staging = dir;
  register_temporary(dir);
}

void finished_file(const std::string& path) {
  // A finished file in the staging folder is still a temporary until it is published.
  if (!g_staging.empty() && path.rfind(g_staging + "/", 0) == 0) register_temporary(path);
}

void register_child(int pid) { g_child = pid; }

void check_output_file(const std::string& path, const std::string& option, const std::string& scene) {
  struct stat st;
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw ring::InputError("", option + " " + path, "is a folder; expected a file name");
    if (!scene.empty() && real_path(path) == real_path(scene))
      throw ring::InputError("", option + " " + path, "is the scene file itself; it would be overwritten");
  }
  const std::string parent = parent_of(path);
  if (stat(parent.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw ring::InputError("", option + " " + path, "its folder " + parent + " does not exist");
  if (access(parent.c_str(), W_OK) != 0 || real_path(parent).rfind("/proc", 0) == 0)
    throw ring::InputError("", option + " " + path, "its folder " + parent + " is not writable");
}

void check_output_dir(const std::string& dir, const std::string& option) {
  struct stat st;
  if (stat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) throw ring::InputError("", option + " " + dir, "exists and is not a folder");
    if (access(dir.c_str(), W_OK) != 0 || real_path(dir).rfind("/proc", 0) == 0)
      throw ring::InputError("", option + " " + dir, "the folder is not writable");
    return;
  }
  std::string up = dir;
  while (stat(up.c_str(), &st) != 0) {
    const std::string next = parent_of(up);
    if (next == up) break;
    up = next;
  }
  if (!S_ISDIR(st.st_mode))
    throw ring::InputError("", option + " " + dir, up + " is a file, so the folder cannot be created");
  if (access(up.c_str(), W_OK) != 0 || real_path(up).rfind("/proc", 0) == 0)
    throw ring::InputError("", option + " " + dir, "cannot create the folder: " + up + " is not writable");
}

void publish_folder(const std::string& staging, const std::string& dir) {
  make_dirs(dir);
  const std::string manifest = dir + "/.ringvib-files";
  for (const auto& f : read_lines(manifest)) std::remove((dir + "/" + f).c_str());
  std::vector<std::string> files;
  if (DIR* d = opendir(staging.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name != "." && name != "..") files.push_back(name);
    }
    closedir(d);
  }
  std::sort(files.begin(), files.end());
  std::string list;
  for (const auto& f : files) {
    const std::string from = staging + "/" + f, to = dir + "/" + f;
    if (std::rename(from.c_str(), to.c_str()) != 0)
      throw std::runtime_error("cannot move " + from + " to " + to + ": " + std::strerror(errno));
    list += f + "\n";
  }
  rmdir(staging.c_str());
  if (g_temporaries) {
    SignalBlock block;
    auto& v = *g_temporaries;
    v.erase(std::remove_if(v.begin(), v.end(),
                           [&](const std::string& p) { return p == staging || p.rfind(staging + "/", 0) == 0; }),
            v.end());
  }
  g_staging.clear();
  write_file(manifest, list);
}

void write_file(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp-" + std::to_string(getpid());
  register_temporary(tmp);
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) {
      release_temporary(tmp);
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    }
    f << content;
    f.flush();
    if (!f) {
      std::remove(tmp.c_str());
      release_temporary(tmp);
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    release_temporary(tmp);
    throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + std::strerror(errno));
  }
  finished_file(path);
  release_temporary(tmp);
}

void make_dirs(const std::string& dir) {
  std::string partial;
  std::size_t pos = 0;
  while (pos != std::string::npos) {
    pos = dir.find('/', pos + 1);
    partial = dir.substr(0, pos);
    if (partial.empty()) continue;
    if (mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST)
      throw ring::InputError("", "--out " + dir, std::string("cannot create the folder: ") + std::strerror(errno));
  }
  struct stat st;
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw ring::InputError("", "--out " + dir, "exists and is not a folder");
}

std::string sig4(double v) {
  if (!std::isfinite(v)) return "nan";
  if (v == 0.0) return "0.000";
  const int mag = static_cast<int>(std::floor(std::log10(std::abs(v))));
  int decimals = std::max(0, 3 - mag);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  // Rounding can carry into a new digit (9.9996 -> 10.000): recompute once.
  const double r = std::atof(buf);
  if (r != 0.0 && static_cast<int>(std::floor(std::log10(std::abs(r)))) != mag) {
    decimals = std::max(0, decimals - 1);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  return buf;
}

std::string model_value(const ring::ModelValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  if (const std::string* s = std::get_if<std::string>(&v)) return *s;
  if (const long long* i = std::get_if<long long>(&v)) return std::to_string(*i);
  std::ostringstream s;
  s << std::get<double>(v);
  return s.str();
}

std::string pct2(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return std::string(buf) == "-0.00" ? "0.00" : buf;
}

}  // namespace cmp
