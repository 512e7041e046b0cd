#include "compare/progress.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iostream>

namespace cmp {

std::ostream* progress_stream(bool quiet, bool terminal) { return !quiet && terminal ? &std::cerr : nullptr; }

std::ostream* progress_stream(bool quiet) { return progress_stream(quiet, isatty(STDERR_FILENO) != 0); }

std::string progress_text(const std::string& what, const std::string& count, double elapsed,
                          std::optional<double> left) {
  std::string s = fmt::format("ringvib: {} {}, {:.1f} s", what, count, elapsed);
  if (left) s += fmt::format(", about {:.0f} s left", std::max(0.0, *left));
  return s;
}

ProgressLine::ProgressLine(std::string what, std::string unit, std::ostream* out, Clock clock)
    : what_(std::move(what)), unit_(std::move(unit)), out_(out), clock_(std::move(clock)) {
  if (!clock_)
    clock_ = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    };
  start_ = out_ ? clock_() : 0.0;
  run_start_ = start_;
}

ProgressLine::~ProgressLine() { finish(); }

std::string ProgressLine::text_locked(double now) const {
  const double elapsed = now - start_;
  std::string count;
  std::optional<double> left;
  if (total_ >= 0) {
    count = fmt::format("{}/{}", done_, total_);
    if (!unit_.empty()) count += " " + unit_;
    if (done_ > 0) left = elapsed / double(done_) * double(total_ - done_);
  } else {
    count = fmt::format("{:.0f} %", 100.0 * done_f_);
    if (run_ > 1) count += fmt::format(" of run {}", run_);
    if (done_f_ > 0.0) left = (now - run_start_) / done_f_ * (1.0 - done_f_);
  }
  return progress_text(what_, count + extra_, elapsed, left);
}

void ProgressLine::draw_locked(double now) {
  const std::string text = text_locked(now);
  // Spaces over what is left of a longer earlier line; no terminal escapes.
  *out_ << '\r' << text << std::string(width_ > text.size() ? width_ - text.size() : 0, ' ') << std::flush;
  width_ = text.size();
  drawn_ = true;
  last_draw_ = now;
}

void ProgressLine::clear_locked() {
  *out_ << '\r' << std::string(width_, ' ') << '\r';
  width_ = 0;
}

void ProgressLine::update(long done, long total, const std::string& extra) {
  if (!out_) return;
  const std::lock_guard<std::mutex> lock(m_);
  if (finished_) return;
  done_ = done;
  total_ = total;
  extra_ = extra.empty() ? "" : ", " + extra;
  have_state_ = true;
  const double now = clock_();
  if (now - start_ < kDelay || (drawn_ && now - last_draw_ < kInterval)) return;
  draw_locked(now);
}

void ProgressLine::fraction(double f) {
  if (!out_) return;
  const std::lock_guard<std::mutex> lock(m_);
  if (finished_) return;
  const double now = clock_();
  f = std::clamp(f, 0.0, 1.0);
  if (have_state_ && total_ < 0 && f < done_f_) {
    ++run_;
    run_start_ = now;
  }
  done_f_ = f;
  total_ = -1;
  have_state_ = true;
  if (now - start_ < kDelay || (drawn_ && now - last_draw_ < kInterval)) return;
  draw_locked(now);
}

void ProgressLine::note(const std::string& line) {
  if (!out_) return;
  const std::lock_guard<std::mutex> lock(m_);
  if (drawn_ && !finished_) clear_locked();
  *out_ << "ringvib: " << line << "\n";
  if (drawn_ && !finished_) draw_locked(clock_());
  else *out_ << std::flush;
}

void ProgressLine::finish() {
  if (!out_) return;
  const std::lock_guard<std::mutex> lock(m_);
  if (finished_) return;
  finished_ = true;
  if (!drawn_) return;
  if (have_state_) draw_locked(clock_());
  *out_ << "\n" << std::flush;
}

}  // namespace cmp
