// The file contract of every command (docs/commands.md, "Files a run writes"):
//
// - own files only: ringvib writes, replaces and removes only files it writes itself. An
//   output folder's manifest (DIR/.ringvib-files) is read as a list of candidates, and a
//   line is honoured only if it names a file ringvib could have written there (own_name:
//   no separator, no "..", not hidden, one of ringvib's extensions) and that file is a
//   regular file; anything else in it is ignored, and said once.
// - checked before computing: every destination (an output file, an output folder and the
//   names a command writes into it) is checked when the command starts, and a problem is
//   ring::InputError (exit 2) naming the option and the path as the user gave it. An
//   output path must be absent or a regular file: a symlink, a FIFO or a device is refused
//   (`-` asks for standard output where a command offers it).
// - nothing half-done is published: writers write into a private stage (the folder
//   DIR/.ringvib-stage-PID; a single output file goes to a short hidden name beside it);
//   publish() moves everything into place by renames once the last file is complete.
//   publish() is a transaction: the earlier run's files are set aside first, and if a
//   rename fails or a signal arrives meanwhile, everything is put back as it was. A run
//   that fails, throws or is interrupted publishes nothing and leaves no stage (the
//   destructor and the signal handler remove it, and the folder itself if the run made it).
// - one run per folder: DIR is locked (flock) from open() to the end of the run, so a
//   second run into the same folder is refused (exit 2) instead of mixing its files in.
//
// Usage:
//   Outputs out;
//   out.folder(dir, "--out", {"report", "table"});   // checks, before computing
//   out.file(junit, "--junit", scene.file);
//   out.open();                                       // creates, locks, stages
//   ... compute ...
//   write_report(out.stage(), report);                // writers fill the stage
//   out.stage_file(junit, junit_xml(...));
//   out.publish();                                    // all at once
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace cmp {

/// Writes `content` to `path` (inside a stage: the stage is private, so no temporary is
/// needed). Throws std::runtime_error naming the path on failure (a full disk: exit 3).
void write_file(const std::string& path, const std::string& content);

/// True when `name` is a file name ringvib writes into an output folder: not empty, not
/// hidden, no '/', no "..", at most 255 bytes, and one of ringvib's extensions (md, txt,
/// csv, json, png, dat, gp, vtu, xml, inp).
bool own_name(const std::string& name);

/// Checks for an output file given as option `option` (e.g. "--csv"): absent or a
/// regular file (not a folder, symlink, FIFO or device), not the scene file itself, a
/// name the file system accepts, in an existing writable folder. Throws ring::InputError.
void check_output_file(const std::string& path, const std::string& option, const std::string& scene);

/// Every output of one command: folders and single files. Not copyable; the destructor
/// removes whatever was staged and not published.
class Outputs {
 public:
  Outputs() = default;
  Outputs(const Outputs&) = delete;
  Outputs& operator=(const Outputs&) = delete;
  ~Outputs();

  /// An output folder (option `option`, e.g. "--out"). `prefixes` are the beginnings of
  /// the names the command may write into it ("report", "table", ...): an existing entry
  /// with such a name that is not a regular file is refused now. The folder must be absent
  /// (it will be made, with its parents) or a folder, reachable and writable; a dangling
  /// symlink or a loop is refused. At most one folder. Throws ring::InputError.
  void folder(const std::string& dir, const std::string& option, const std::vector<std::string>& prefixes);
  /// A single output file (check_output_file); "-" is refused (a command that offers
  /// standard output handles it before calling this).
  void file(const std::string& path, const std::string& option, const std::string& scene);

  /// Makes the folder if it is missing, locks it against a second run (ring::InputError if
  /// another run holds it) and creates the stage; removes stages that crashed runs left.
  void open();
  /// The folder the writers write into (valid after open()).
  const std::string& stage() const { return stage_; }
  /// Stages the content of a single output file given to file().
  void stage_file(const std::string& path, const std::string& content);
  /// Moves every staged file into place (above). Throws std::runtime_error, with
  /// everything put back, when a rename fails.
  void publish();

 private:
  struct Single {
    std::string path, temp;
    bool staged = false;
  };
  /// publish() with the signals blocked; true when a signal arrived and all was undone.
  bool transaction();
  void discard() noexcept;

  std::string dir_, dir_option_;  ///< the output folder as given, or empty
  std::vector<std::string> made_; ///< folders open() created, outermost first
  std::string stage_;
  std::vector<Single> files_;
  int lock_fd_ = -1;
  bool published_ = false;
};

/// On SIGINT, SIGTERM and SIGHUP: stop the running gnuplot, remove every open stage and
/// staged file and the folders the run made, and die of the signal (exit status 128 +
/// signal in a shell). Call once, first thing in main().
void install_signal_cleanup();
/// The child process a signal must stop first (gnuplot), 0 for none.
void register_child(int pid);
/// A helper program's private folder (ccx's job folder, calculix/ccx.hpp) and the
/// process working in it, for the same cleanup: on a signal the process is killed and the
/// folder removed with its files (flat), like a stage. Several may be registered at once
/// (a sweep's threads); the caller unregisters them when it has removed them itself.
void register_temp_folder(const std::string& path);
void unregister_temp_folder(const std::string& path);
void add_child(int pid);
void remove_child(int pid);

/// The calling thread's check for an interruption, for a caller that must not die of a
/// signal (the Python module: Ctrl-C raises KeyboardInterrupt). Long work calls it where
/// it can stop, at least every 0.1 s: ccx's wait (calculix::Hooks::poll, which kills ccx
/// first) and the time-stepping driver (ResponseOptions::progress). It throws to stop;
/// whatever was staged is removed on the way out (Outputs' destructor). Empty (the
/// default, and the command's: its signal handler ends the process): never called.
void set_interrupt_check(std::function<void()> check);
const std::function<void()>& interrupt_check();

}  // namespace cmp
