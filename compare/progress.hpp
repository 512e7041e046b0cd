// Progress of long work on a terminal: one line on stderr that updates in place,
//
//   ringvib: bench 3/12 runs, 4.1 s, about 12 s left
//
// drawn only where a person watches it. The rules, the same for every command:
// - the line goes to the stream progress_stream() gives: stderr when it is a terminal and
//   -q is not given, else null, and with a null stream nothing at all is written (CI logs
//   and pipes stay exactly as they were);
// - nothing is drawn before the work has run kDelay (2 s): short runs print nothing new;
// - at most one redraw every kInterval (0.1 s), whatever the rate of update();
// - a stage line (note()) clears the progress line, is printed on its own line as before,
//   and the progress line is drawn again under it;
// - finish() (or the destructor) draws the last state and ends the line with a newline,
//   if the line was ever drawn.
// The estimate is linear in the work done: elapsed / done * (total - done).
// Thread-safe (sweep's workers update one line). The clock is injectable for tests.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>

namespace cmp {

/// stderr when `terminal` and not `quiet`, null otherwise: where progress (the updating
/// line and the stage lines) goes.
std::ostream* progress_stream(bool quiet, bool terminal);
/// The same with terminal = isatty(STDERR_FILENO).
std::ostream* progress_stream(bool quiet);

/// The text of the line: "ringvib: <what> <count>, <elapsed> s, about <left> s left", where
/// count is "i/n <unit>" or "p %"; without an estimate (nothing done yet) the last part is left out.
std::string progress_text(const std::string& what, const std::string& count, double elapsed,
                          std::optional<double> left);

class ProgressLine {
 public:
  using Clock = std::function<double()>;  ///< seconds, monotonic
  static constexpr double kDelay = 2.0;      ///< s of work before the line first shows
  static constexpr double kInterval = 0.1;   ///< s between redraws, at least

  /// `what`: the work ("bench", "response multibody"); `unit`: what is counted ("runs"), or
  /// empty; `out`: from progress_stream() (null: the object does nothing); `clock`: default
  /// std::chrono::steady_clock. The elapsed time counts from construction.
  ProgressLine(std::string what, std::string unit, std::ostream* out, Clock clock = {});
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// `done` of `total` units finished; `extra` is appended to the count (", 1 failed").
  void update(long done, long total, const std::string& extra = "");
  /// A fraction in [0, 1] of the work finished, shown in percent. A fraction below the last
  /// one starts a new run of the work (the FE reference halving dt): shown as "p % of run k",
  /// with the estimate for that run alone.
  void fraction(double f);
  /// One stage line ("ringvib: " + line), as the commands printed before there was a
  /// progress line; nothing when the stream is null.
  void note(const std::string& line);
  /// Ends the line (a newline) if it was drawn; later calls print nothing.
  void finish();

 private:
  std::string text_locked(double now) const;
  void draw_locked(double now);
  void clear_locked();

  std::string what_, unit_;
  std::ostream* out_;
  Clock clock_;
  double start_;
  mutable std::mutex m_;
  // The last state reported: done of total (total < 0: a fraction in done_f).
  long done_ = 0, total_ = -1;
  double done_f_ = 0.0;
  int run_ = 1;             ///< the run of the work the fraction is of
  double run_start_ = 0.0;  ///< when that run started
  std::string extra_;
  bool have_state_ = false, drawn_ = false, finished_ = false;
  double last_draw_ = 0.0;
  std::size_t width_ = 0;  ///< characters of the line on screen, padded over on redraw
};

}  // namespace cmp
