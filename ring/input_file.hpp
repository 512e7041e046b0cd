// Files a user names for ringvib to read: scenes, imported columns and their shapes, a
// sweep's --resume table. Each is checked before it is opened for reading and read with a
// cap, so that no path makes ringvib read without bound (/dev/zero), block in open() (a
// FIFO named in a scene) or hold a file larger than its purpose needs (issue 46). The caps
// are documented in docs/commands.md ("Exit codes").
#pragma once

#include <cstddef>
#include <string>

namespace ring {

/// Caps, bytes. A scene is a short TOML file; a column of frequencies holds modes.count's
/// largest 100,000 modes at 40 characters a line; a shapes file 3,000 modes at 360 stations
/// and 25 characters a value; a --resume table a sweep of 10^6 rows.
constexpr std::size_t kMaxSceneBytes = std::size_t(1) << 20;      // 1 MiB
constexpr std::size_t kMaxImportBytes = std::size_t(4) << 20;     // 4 MiB
constexpr std::size_t kMaxShapesBytes = std::size_t(64) << 20;    // 64 MiB
constexpr std::size_t kMaxResumeBytes = std::size_t(256) << 20;   // 256 MiB

/// What a path may be besides a regular file.
enum class InputKind {
  regular,  ///< a regular file only: a FIFO, device, socket or folder is refused unopened
  stream,   ///< also a FIFO or a character device, read once up to the cap: a scene given
            ///< as /dev/stdin or a pipe on the command line (docs/commands.md, "ringvib sweep")
};

/// The text of the file at `path` (symlinks followed), at most `cap` bytes. Before the file
/// is opened for reading, stat() says what it is, and the path is refused with
/// ring::InputError (exit 2; file = path, no key; `what` names its role, "the imported
/// file") when it is missing or unreadable, a folder, anything but a regular file (for
/// InputKind::regular; a FIFO, socket or block device for stream), or a regular file larger
/// than `cap`. A regular file is opened with O_NONBLOCK and checked again by fstat(), so a
/// FIFO swapped in after the check neither blocks nor is read. A stream is read up to
/// cap + 1 bytes and refused beyond the cap. O(size read).
std::string read_input_file(const std::string& path, std::size_t cap, const std::string& what,
                            InputKind kind = InputKind::regular);

/// A size in bytes as text: "1 MiB", "64 MiB", "4.2 GiB", "512 bytes".
std::string size_text(double bytes);

}  // namespace ring
