// Runs the ringvib executable as a user would and captures what it prints.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ringtest {

struct Run {
  int code = -1;
  std::string out, err;
};

inline std::string ringvib_path() { return std::string(RINGVIB_BINARY_DIR) + "/bin/ringvib"; }
inline std::string source(const std::string& rel) { return std::string(RINGVIB_SOURCE_DIR) + "/" + rel; }

/// Runs `ringvib ARGS` (a shell fragment) with `env` prepended; stdout and stderr apart.
inline Run ringvib(const std::string& args, const std::string& env = "") {
  char tmpl[] = "/tmp/ringvib-cli-XXXXXX";
  const int fd = mkstemp(tmpl);
  close(fd);
  const std::string errfile = tmpl;
  const std::string cmd = env + " " + ringvib_path() + " " + args + " 2>" + errfile + " </dev/null";
  Run r;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(errfile);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  std::remove(errfile.c_str());
  return r;
}

/// A fresh empty folder under /tmp.
inline std::string temp_dir() {
  char tmpl[] = "/tmp/ringvib-test-XXXXXX";
  return mkdtemp(tmpl);
}

inline void write(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
}

/// True when something (a file, a folder, a link) is at `path`.
inline bool exists(const std::string& path) {
  struct stat st;
  return lstat(path.c_str(), &st) == 0;
}

/// What a shell command prints on stdout.
inline std::string shell(const std::string& cmd) {
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  return out;
}

/// Anything a run stages below `dir`: its stage folder, a staged single file, or an older
/// writer's temporary. Empty when nothing is left.
inline std::string leftovers(const std::string& dir) {
  return shell("find " + dir + " \\( -name '.ringvib-stage-*' -o -name '.ringvib-*.tmp*' -o -name '*.tmp-*' \\) "
               "2>/dev/null");
}

/// Starts `program ARGS` (no shell) with standard input, output and error on /dev/null
/// and `env` set in the child; returns its pid.
inline pid_t spawn(const std::vector<std::string>& command,
                   const std::vector<std::pair<std::string, std::string>>& env = {}) {
  std::vector<std::string> all = command;
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_RDWR);
    dup2(null, STDIN_FILENO);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

/// Waits at most `seconds` for `pid` to end and returns its wait status; a child still
/// running then is killed (SIGKILL, with its process group's other members it started)
/// and -1 is returned, so that a hang fails a test instead of stalling the suite.
inline int wait_bounded(pid_t pid, double seconds) {
  int status = 0;
  for (double waited = 0.0; waited < seconds; waited += 0.01) {
    if (waitpid(pid, &status, WNOHANG) == pid) return status;
    usleep(10000);
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return -1;
}

inline bool empty_dir(const std::string& dir) {
  return std::system(("test -z \"$(ls -A " + dir + ")\"").c_str()) == 0;
}

}  // namespace ringtest
