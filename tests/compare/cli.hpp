// Runs the ringvib executable as a user would and captures what it prints.
#pragma once

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

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

inline bool empty_dir(const std::string& dir) {
  return std::system(("test -z \"$(ls -A " + dir + ")\"").c_str()) == 0;
}

}  // namespace ringtest
