#include "ring/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>

#include "ring/errors.hpp"

namespace ring {
namespace {

/// What a file that is not a regular file is, for messages.
const char* kind_name(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

bool accepted(mode_t mode, InputKind kind) {
  return S_ISREG(mode) || (kind == InputKind::stream && (S_ISFIFO(mode) || S_ISCHR(mode)));
}

/// Closes a descriptor on every way out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

}  // namespace

std::string size_text(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 4) {
    bytes /= 1024.0;
    ++u;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, bytes == std::floor(bytes) ? "%.0f %s" : "%.1f %s", bytes, units[u]);
  return buf;
}

std::string read_input_file(const std::string& path, std::size_t cap, const std::string& what, InputKind kind) {
  const std::string expected = kind == InputKind::regular ? "a regular file" : "a file, a FIFO or standard input";
  struct stat st;
  if (stat(path.c_str(), &st) != 0) throw InputError(path, "", "cannot read " + what + " (missing or unreadable)");
  if (!accepted(st.st_mode, kind))
    throw InputError(path, "", std::string("is ") + kind_name(st.st_mode) + "; " + what + " must be " + expected +
                                   (S_ISDIR(st.st_mode) ? "" : " (a FIFO or device may block or never end)"));
  auto too_large = [&](const std::string& size) {
    return InputError(path, "",
                      "is " + (size.empty() ? "" : size + ", ") + "larger than the " + size_text(double(cap)) +
                          " that " + what + " may be (docs/commands.md, \"Exit codes\")");
  };
  if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > cap)
    throw too_large(std::to_string(st.st_size) + " bytes");
  // A regular file opens without blocking whatever replaced it since stat(); fstat() then
  // says what was opened. A stream (the command line's own pipe) waits for its writer.
  const int flags = O_RDONLY | O_CLOEXEC | (kind == InputKind::regular ? O_NONBLOCK : 0);
  const Fd f{open(path.c_str(), flags)};
  if (f.fd < 0) throw InputError(path, "", "cannot read " + what + " (missing or unreadable)");
  if (fstat(f.fd, &st) != 0 || !accepted(st.st_mode, kind))
    throw InputError(path, "", "changed while it was opened; " + what + " must be " + expected);
  // Read in chunks, at most one chunk past the cap: a larger stream (or a file that grew)
  // is refused, and memory follows what was read, not the cap.
  std::string text;
  if (S_ISREG(st.st_mode)) text.reserve(std::min(static_cast<std::size_t>(st.st_size), cap) + 1);
  char chunk[65536];
  for (;;) {
    const ssize_t n = read(f.fd, chunk, sizeof chunk);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path, "", "cannot read " + what);
    }
    text.append(chunk, static_cast<std::size_t>(n));
    if (text.size() > cap) throw too_large("");
  }
  return text;
}

}  // namespace ring
