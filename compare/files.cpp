#include "compare/files.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <set>
#include <stdexcept>

#include "ring/errors.hpp"

namespace cmp {
namespace {

constexpr const char* kManifest = ".ringvib-files";
constexpr const char* kStagePrefix = ".ringvib-stage-";
constexpr const char* kPrevious = ".previous";  ///< inside a stage: the earlier run's files during publish()

// ---------------------------------------------------------------------------------------
// What a signal must clean up: a fixed table (no allocation, so that the handler never
// sees a container in the middle of a reallocation), changed only with the signals blocked.

enum class Kind { none, file, stage, made };
struct Entry {
  Kind kind = Kind::none;
  char path[PATH_MAX] = {};
};
constexpr int kEntries = 32;
Entry g_cleanup[kEntries];
volatile sig_atomic_t g_child = 0;
constexpr int kChildren = 64;  ///< helper processes at once (a sweep's threads each run one)
volatile sig_atomic_t g_children[kChildren] = {};

const int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
/// Set when a run's files are all published and nothing is staged since: a signal then
/// finds the run finished, says so, and lets it end with its own exit code.
volatile sig_atomic_t g_finished = 0;

class SignalBlock {
 public:
  SignalBlock() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : kSignals) sigaddset(&set, s);
    sigprocmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalBlock() { sigprocmask(SIG_SETMASK, &old_, nullptr); }
  SignalBlock(const SignalBlock&) = delete;
  SignalBlock& operator=(const SignalBlock&) = delete;

 private:
  sigset_t old_;
};

bool signal_pending() {
  sigset_t pending;
  sigpending(&pending);
  for (int s : kSignals)
    if (sigismember(&pending, s)) return true;
  return false;
}

void add_cleanup(Kind kind, const std::string& path) {
  if (path.size() >= PATH_MAX) return;  // cannot happen: paths are checked up front
  SignalBlock block;
  g_finished = 0;  // something is staged again
  for (auto& e : g_cleanup)
    if (e.kind == Kind::none) {
      std::memcpy(e.path, path.c_str(), path.size() + 1);
      e.kind = kind;
      return;
    }
}

void drop_cleanup(const std::string& path) {
  SignalBlock block;
  for (auto& e : g_cleanup)
    if (e.kind != Kind::none && path == e.path) e.kind = Kind::none;
}

/// Removes the files of a flat folder and the folder, with async-signal-safe calls only
/// (open, getdents64, unlinkat, rmdir): the handler uses it. A sub-folder (.previous) is
/// emptied the same way, one level down.
void remove_flat(const char* dir, int depth = 0) {
  const int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC | O_NOFOLLOW);
  if (fd >= 0) {
    alignas(8) char buf[4096];
    for (long n; (n = syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0;) {
      for (long off = 0; off < n;) {
        struct Dirent64 {
          unsigned long long ino;
          long long off;
          unsigned short reclen;
          unsigned char type;
          char name[1];
        };
        const auto* d = reinterpret_cast<const Dirent64*>(buf + off);
        off += d->reclen;
        if (std::strcmp(d->name, ".") == 0 || std::strcmp(d->name, "..") == 0) continue;
        if (unlinkat(fd, d->name, 0) != 0 && errno == EISDIR && depth == 0) {
          char sub[PATH_MAX];
          const std::size_t a = std::strlen(dir), b = std::strlen(d->name);
          if (a + 1 + b < sizeof sub) {
            std::memcpy(sub, dir, a);
            sub[a] = '/';
            std::memcpy(sub + a + 1, d->name, b + 1);
            remove_flat(sub, 1);
          }
        }
      }
    }
    close(fd);
  }
  rmdir(dir);
}

void on_signal(int sig) {
  if (g_finished) {
    // The results stand, whole: the run has only its exit left (its code may still be a
    // gate's 1), which a death by the signal would hide.
    static const char kNote[] = "ringvib: interrupted after the results were published; they stand, whole\n";
    [[maybe_unused]] const auto written = write(2, kNote, sizeof kNote - 1);
    return;
  }
  if (g_child > 0) kill(g_child, SIGKILL);  // the running gnuplot
  for (const auto& c : g_children)          // helpers such as ccx, before their folders go
    if (c > 0) {
      kill(c, SIGKILL);
      waitpid(c, nullptr, 0);
    }
  for (const auto& e : g_cleanup)
    if (e.kind == Kind::file) unlink(e.path);
  for (const auto& e : g_cleanup)
    if (e.kind == Kind::stage) remove_flat(e.path);
  for (int i = kEntries - 1; i >= 0; --i)  // innermost first: made later
    if (g_cleanup[i].kind == Kind::made) rmdir(g_cleanup[i].path);
  signal(sig, SIG_DFL);
  raise(sig);
}

// ---------------------------------------------------------------------------------------

std::string trim_slashes(std::string p) {
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  return p;
}

std::string parent_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string real_path(const std::string& p) {
  char buf[PATH_MAX];
  return realpath(p.c_str(), buf) ? std::string(buf) : std::string();
}

bool writable_folder(const std::string& dir) {
  return access(dir.c_str(), W_OK | X_OK) == 0 && real_path(dir).rfind("/proc", 0) != 0;
}

/// What a non-regular directory entry is, for messages.
std::string kind_of(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISLNK(st.st_mode)) return "a symlink";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

/// Every name in the path must fit the file system's limit (NAME_MAX).
void check_lengths(const std::string& path, const std::string& what) {
  if (path.size() >= PATH_MAX - 64) throw ring::InputError("", what, "the path is longer than the system allows");
  std::size_t start = 0;
  while (start <= path.size()) {
    const auto slash = path.find('/', start);
    const std::size_t end = slash == std::string::npos ? path.size() : slash;
    if (end - start > NAME_MAX)
      throw ring::InputError("", what, "a name in the path is longer than " + std::to_string(NAME_MAX) + " bytes");
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> v;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name != "." && name != "..") v.push_back(name);
    }
    closedir(d);
  }
  std::sort(v.begin(), v.end());
  return v;
}

bool regular(const std::string& path) {
  struct stat st;
  return lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

bool exists(const std::string& path) {
  struct stat st;
  return lstat(path.c_str(), &st) == 0;
}

/// The manifest's names that ringvib could have written in `dir` and that are regular
/// files there; the rest is ignored and said once on stderr.
std::vector<std::string> manifest_names(const std::string& dir) {
  std::vector<std::string> names;
  const std::string manifest = dir + "/" + kManifest;
  if (!regular(manifest)) return names;
  std::ifstream f(manifest);
  std::set<std::string> seen;
  int ignored = 0;
  std::string first_ignored;
  for (std::string line; std::getline(f, line);) {
    if (line.empty()) continue;
    if (own_name(line) && regular(dir + "/" + line)) {
      if (seen.insert(line).second) names.push_back(line);
    } else if (own_name(line) && !exists(dir + "/" + line)) {
      // Listed and already gone (removed by the user): nothing to do.
    } else {
      if (ignored++ == 0) first_ignored = line.substr(0, 80);
    }
  }
  if (ignored > 0)
    std::cerr << "ringvib: warning: " << manifest << ": ignored " << ignored << " line" << (ignored > 1 ? "s" : "")
              << " that name no file ringvib writes there (first: '" << first_ignored << "'); nothing else is removed\n";
  return names;
}

}  // namespace

// ---------------------------------------------------------------------------------------

void install_signal_cleanup() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int s : kSignals) sigaddset(&sa.sa_mask, s);
  for (int s : kSignals) sigaction(s, &sa, nullptr);
}

void register_child(int pid) { g_child = pid; }

void register_temp_folder(const std::string& path) { add_cleanup(Kind::stage, path); }
void unregister_temp_folder(const std::string& path) { drop_cleanup(path); }

void add_child(int pid) {
  SignalBlock block;
  for (auto& c : g_children)
    if (c == 0) {
      c = pid;
      return;
    }
}

void remove_child(int pid) {
  SignalBlock block;
  for (auto& c : g_children)
    if (c == pid) c = 0;
}

bool own_name(const std::string& name) {
  static const char* kExtensions[] = {".md", ".txt", ".csv", ".json", ".png", ".dat", ".gp", ".vtu", ".xml", ".inp"};
  if (name.empty() || name.size() > NAME_MAX || name.front() == '.') return false;
  if (name.find('/') != std::string::npos || name.find('\0') != std::string::npos ||
      name.find("..") != std::string::npos)
    return false;
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f) return false;
  for (const char* ext : kExtensions) {
    const std::string e = ext;
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0) return true;
  }
  return false;
}

void write_file(const std::string& path, const std::string& content) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  f << content;
  f.flush();
  if (!f) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

void check_output_file(const std::string& path, const std::string& option, const std::string& scene) {
  const std::string what = option + " " + path;
  if (path.empty() || path.back() == '/') throw ring::InputError("", what, "expected a file name");
  check_lengths(path, what);
  struct stat st;
  if (lstat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw ring::InputError("", what, "is a folder; expected a file name");
    if (!S_ISREG(st.st_mode))
      throw ring::InputError("", what, "is " + kind_of(st) +
                                           "; ringvib replaces only regular files (give the real path, or - for "
                                           "standard output where the option offers it)");
    if (!scene.empty() && real_path(path) == real_path(scene))
      throw ring::InputError("", what, "is the scene file itself; it would be overwritten");
  }
  const std::string parent = parent_of(path);
  if (stat(parent.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw ring::InputError("", what, "its folder " + parent + " does not exist");
  if (!writable_folder(parent)) throw ring::InputError("", what, "its folder " + parent + " is not writable");
}

// ---------------------------------------------------------------------------------------

Outputs::~Outputs() { discard(); }

void Outputs::folder(const std::string& dir_given, const std::string& option,
                     const std::vector<std::string>& prefixes) {
  const std::string what = option + " " + dir_given;
  if (dir_given.empty()) throw ring::InputError("", option, "expected a folder");
  const std::string dir = trim_slashes(dir_given);
  check_lengths(dir, what);
  struct stat st;
  if (lstat(dir.c_str(), &st) == 0) {
    if (stat(dir.c_str(), &st) != 0)
      throw ring::InputError("", what, "is a symlink that leads nowhere (dangling, or a loop)");
    if (!S_ISDIR(st.st_mode)) throw ring::InputError("", what, "exists and is not a folder");
    if (!writable_folder(dir)) throw ring::InputError("", what, "the folder is not writable");
    struct stat m;
    if (lstat((dir + "/" + kManifest).c_str(), &m) == 0 && !S_ISREG(m.st_mode))
      throw ring::InputError("", what, dir + "/" + kManifest + " (ringvib's list of its files there) is " +
                                           kind_of(m) + "; remove it");
    for (const auto& name : entries(dir)) {
      if (!own_name(name)) continue;
      const bool ours = std::any_of(prefixes.begin(), prefixes.end(),
                                    [&](const std::string& p) { return name.rfind(p, 0) == 0; });
      struct stat e;
      if (ours && lstat((dir + "/" + name).c_str(), &e) == 0 && !S_ISREG(e.st_mode))
        throw ring::InputError("", what, dir + "/" + name + " is " + kind_of(e) +
                                             " where this command writes a file of that name; move it away or "
                                             "choose another folder");
    }
  } else {
    // The nearest existing ancestor must be a writable folder (following symlinks).
    std::string up = dir;
    while (lstat(up.c_str(), &st) != 0) {
      const std::string next = parent_of(up);
      if (next == up) break;
      up = next;
    }
    if (stat(up.c_str(), &st) != 0)
      throw ring::InputError("", what, up + " is a symlink that leads nowhere (dangling, or a loop)");
    if (!S_ISDIR(st.st_mode))
      throw ring::InputError("", what, up + " is a file, so the folder cannot be created");
    if (!writable_folder(up))
      throw ring::InputError("", what, "cannot create the folder: " + up + " is not writable");
  }
  dir_ = dir;
  dir_option_ = option;
}

void Outputs::file(const std::string& path, const std::string& option, const std::string& scene) {
  // A command that offers standard output (respond --csv -) prints instead of calling this.
  if (path == "-")
    throw ring::InputError("", option + " -", "standard output is not offered for this option; give a file name");
  check_output_file(path, option, scene);
  files_.push_back({path, "", false});
}

void Outputs::open() {
  const std::string pid = std::to_string(getpid());
  if (!dir_.empty()) {
    // Make the folder and its missing parents, each remembered so that a run that does
    // not publish removes what it made.
    std::vector<std::string> missing;
    for (std::string up = dir_; !exists(up);) {
      missing.push_back(up);
      const std::string next = parent_of(up);
      if (next == up) break;
      up = next;
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      if (mkdir(it->c_str(), 0755) != 0 && errno != EEXIST)
        throw ring::InputError("", dir_option_ + " " + dir_, std::string("cannot create the folder: ") +
                                                                 std::strerror(errno));
      made_.push_back(*it);
      add_cleanup(Kind::made, *it);
    }
    lock_fd_ = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (lock_fd_ < 0)
      throw ring::InputError("", dir_option_ + " " + dir_, std::string("cannot open the folder: ") + std::strerror(errno));
    if (flock(lock_fd_, LOCK_EX | LOCK_NB) != 0)
      throw ring::InputError("", dir_option_ + " " + dir_,
                             "another ringvib run is writing into this folder; wait for it to end or choose another "
                             "folder");
    // Under the lock, any other stage is a crashed run's: its owner would hold the lock.
    for (const auto& name : entries(dir_))
      if (name.rfind(kStagePrefix, 0) == 0) remove_flat((dir_ + "/" + name).c_str());
    stage_ = dir_ + "/" + kStagePrefix + pid;
    add_cleanup(Kind::stage, stage_);
    if (mkdir(stage_.c_str(), 0700) != 0)
      throw std::runtime_error("cannot create the staging folder " + stage_ + ": " + std::strerror(errno));
  }
  for (std::size_t i = 0; i < files_.size(); ++i)
    files_[i].temp = parent_of(files_[i].path) + "/.ringvib-" + pid + "-" + std::to_string(i) + ".tmp";
}

void Outputs::stage_file(const std::string& path, const std::string& content) {
  for (auto& f : files_)
    if (f.path == path) {
      add_cleanup(Kind::file, f.temp);
      write_file(f.temp, content);
      f.staged = true;
      return;
    }
  throw std::logic_error("Outputs::stage_file: " + path + " was not declared with file()");
}

void Outputs::publish() {
  if (transaction()) {
    // Reached only if no handler ended the run when the pending signal arrived.
    throw std::runtime_error("interrupted while publishing; nothing was published");
  }
}

bool Outputs::transaction() {
  SignalBlock block;  // a signal now waits for the end of the transaction
  std::vector<std::pair<std::string, std::string>> done;  // renames made, to undo on failure
  std::vector<std::string> old;                            // the replaced files, removed on success
  auto move = [&](const std::string& from, const std::string& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0)
      throw std::runtime_error("cannot move " + from + " to " + to + ": " + std::strerror(errno));
    done.emplace_back(from, to);
  };
  bool interrupted = false;
  try {
    if (!dir_.empty()) {
      const std::string previous = stage_ + "/" + kPrevious;
      if (mkdir(previous.c_str(), 0700) != 0)
        throw std::runtime_error("cannot create " + previous + ": " + std::strerror(errno));
      std::vector<std::string> fresh;
      for (const auto& name : entries(stage_))
        if (name != kPrevious) fresh.push_back(name);
      std::set<std::string> aside;
      for (const auto& name : manifest_names(dir_)) aside.insert(name);
      for (const auto& name : fresh)
        if (regular(dir_ + "/" + name)) aside.insert(name);
      for (const auto& name : aside) {
        move(dir_ + "/" + name, previous + "/" + name);
        old.push_back(previous + "/" + name);
      }
      std::string list;
      for (const auto& name : fresh) {
        move(stage_ + "/" + name, dir_ + "/" + name);
        list += name + "\n";
      }
      const std::string manifest = dir_ + "/" + kManifest, next = previous + "/" + kManifest + ".new";
      write_file(next, list);
      if (regular(manifest)) {
        move(manifest, previous + "/" + kManifest);
        old.push_back(previous + "/" + kManifest);
      }
      move(next, manifest);
    }
    for (std::size_t i = 0; i < files_.size(); ++i) {
      const Single& f = files_[i];
      if (!f.staged) continue;
      if (regular(f.path)) {
        const std::string was = f.temp + ".old";
        move(f.path, was);
        old.push_back(was);
      }
      move(f.temp, f.path);
    }
    interrupted = signal_pending();
  } catch (...) {
    for (auto it = done.rbegin(); it != done.rend(); ++it) std::rename(it->second.c_str(), it->first.c_str());
    throw;
  }
  if (interrupted) {
    // The user asked to stop before the run was complete on disk: put everything back;
    // when the block ends the signal arrives and the handler removes the stage.
    for (auto it = done.rbegin(); it != done.rend(); ++it) std::rename(it->second.c_str(), it->first.c_str());
    return true;
  }
  for (const auto& p : old) std::remove(p.c_str());
  published_ = true;
  discard();
  g_finished = 1;  // still under the block: a signal from now on finds the run finished
  return false;
}

void Outputs::discard() noexcept {
  for (const auto& f : files_) {
    if (!f.temp.empty()) {
      if (!published_) unlink(f.temp.c_str());
      drop_cleanup(f.temp);
    }
  }
  if (!stage_.empty()) {
    remove_flat(stage_.c_str());
    drop_cleanup(stage_);
    stage_.clear();
  }
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) {
    if (!published_) rmdir(it->c_str());  // only if empty: nothing of the user's goes
    drop_cleanup(*it);
  }
  made_.clear();
  if (lock_fd_ >= 0) {
    close(lock_fd_);  // releases the lock
    lock_fd_ = -1;
  }
}

namespace {
thread_local std::function<void()> g_interrupt_check;
}  // namespace

void set_interrupt_check(std::function<void()> check) { g_interrupt_check = std::move(check); }
const std::function<void()>& interrupt_check() { return g_interrupt_check; }

}  // namespace cmp
