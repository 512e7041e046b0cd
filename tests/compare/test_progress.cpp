// The progress line (compare/progress.hpp) with an injected clock and a string stream in
// place of a terminal: its text, the 2-second rule, the throttle, stage lines under it,
// and nothing at all without a terminal or with -q.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <sstream>

#include "compare/progress.hpp"

namespace {

using cmp::ProgressLine;

std::size_t count(const std::string& s, char c) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), c)); }

struct Fixture {
  double now = 100.0;  ///< an arbitrary origin: the line counts from its construction
  std::ostringstream out;
  ProgressLine::Clock clock() {
    return [this] { return now; };
  }
};

TEST(Progress, TextNamesTheWorkTheCountTheElapsedTimeAndTheEstimate) {
  EXPECT_EQ(cmp::progress_text("bench", "3/12 runs", 4.14, 12.4), "ringvib: bench 3/12 runs, 4.1 s, about 12 s left");
  EXPECT_EQ(cmp::progress_text("sweep", "0/5 cases done", 2.0, std::nullopt), "ringvib: sweep 0/5 cases done, 2.0 s");
  EXPECT_EQ(cmp::progress_text("x", "1/2", 3.0, -1e-12), "ringvib: x 1/2, 3.0 s, about 0 s left");
}

TEST(Progress, OnlyOnATerminalAndWithoutQuiet) {
  EXPECT_EQ(cmp::progress_stream(false, true), &std::cerr);
  EXPECT_EQ(cmp::progress_stream(false, false), nullptr);
  EXPECT_EQ(cmp::progress_stream(true, true), nullptr);
  EXPECT_EQ(cmp::progress_stream(true, false), nullptr);
  // A null stream: every call is a no-op (and the clock is never read).
  ProgressLine line("bench", "runs", nullptr, [] {
    ADD_FAILURE() << "the clock was read without a terminal";
    return 0.0;
  });
  line.update(1, 2);
  line.fraction(0.5);
  line.note("stage");
  line.finish();
}

TEST(Progress, NothingNewBeforeTwoSeconds) {
  Fixture f;
  {
    ProgressLine line("bench", "runs", &f.out, f.clock());
    f.now += 1.0;
    line.update(1, 10);
    f.now += 0.99;
    line.update(5, 10);
    line.note("bench multibody at 40");  // a stage line prints as before
    line.finish();
  }
  EXPECT_EQ(f.out.str(), "ringvib: bench multibody at 40\n");
}

TEST(Progress, DrawsAfterTwoSecondsAtMostTenTimesASecondAndEndsWithANewline) {
  Fixture f;
  ProgressLine line("bench", "runs", &f.out, f.clock());
  f.now += 2.5;
  line.update(2, 10);
  EXPECT_EQ(f.out.str(), "\rringvib: bench 2/10 runs, 2.5 s, about 10 s left");
  // 90 updates within the next 0.09 s: throttled away.
  for (int i = 0; i < 90; ++i) {
    f.now += 0.001;
    line.update(3, 10);
  }
  EXPECT_EQ(count(f.out.str(), '\r'), 1u);
  f.now += 0.02;  // 0.11 s after the first draw
  line.update(4, 10);
  EXPECT_EQ(count(f.out.str(), '\r'), 2u);
  EXPECT_NE(f.out.str().find("\rringvib: bench 4/10 runs, 2.6 s, about 4 s left"), std::string::npos) << f.out.str();
  f.now += 0.01;
  line.update(10, 10);  // throttled, but finish() draws the last state
  line.finish();
  const std::string s = f.out.str();
  EXPECT_EQ(s.substr(s.rfind('\r')), "\rringvib: bench 10/10 runs, 2.6 s, about 0 s left\n");
  line.update(1, 10);
  line.finish();
  EXPECT_EQ(f.out.str(), s) << "nothing after finish";
}

TEST(Progress, AStageLineClearsTheLineAndTheLineComesBackUnderIt) {
  Fixture f;
  ProgressLine line("converge", "sizes", &f.out, f.clock());
  f.now += 3.0;
  line.update(1, 3);
  const std::string drawn = "\rringvib: converge 1/3 sizes, 3.0 s, about 6 s left";
  ASSERT_EQ(f.out.str(), drawn);
  line.note("multibody at n = 80");
  EXPECT_EQ(f.out.str(), drawn + "\r" + std::string(drawn.size() - 1, ' ') + "\r" + "ringvib: multibody at n = 80\n" + drawn);
}

TEST(Progress, AShorterLinePadsOverTheLongerOne) {
  Fixture f;
  ProgressLine line("sweep", "cases done", &f.out, f.clock());
  f.now += 2.0;
  line.update(1, 1000, "10 failed");
  const std::size_t first = f.out.str().size() - 1;
  f.now += 1.0;
  line.update(999, 1000, "0 failed");  // a shorter text
  const std::string s = f.out.str();
  const std::string second = s.substr(first + 1);
  EXPECT_EQ(second.size(), first + 1) << "padded to the first line's width: '" << second << "'";
  EXPECT_EQ(second.back(), ' ');
}

TEST(Progress, AFractionIsShownInPercent) {
  Fixture f;
  ProgressLine line("response multibody", "", &f.out, f.clock());
  f.now += 4.0;
  line.fraction(0.25);
  EXPECT_EQ(f.out.str(), "\rringvib: response multibody 25 %, 4.0 s, about 12 s left");
}

// The FE reference integrates again with dt halved: the fraction starts over, the estimate
// is for that run alone, and the elapsed time is the whole.
TEST(Progress, AFractionThatStartsOverIsTheNextRun) {
  Fixture f;
  ProgressLine line("response reference", "", &f.out, f.clock());
  f.now += 3.0;
  line.fraction(1.0);
  f.now += 1.0;
  line.fraction(0.0);
  f.now += 1.0;
  line.fraction(0.5);
  const std::string s = f.out.str();
  EXPECT_EQ(s.substr(s.rfind('\r')), "\rringvib: response reference 50 % of run 2, 5.0 s, about 1 s left");
}

}  // namespace
