// Without a terminal (CI, pipes, files) the progress line is never drawn: what `respond`
// and `bench` write is what they wrote before there was one (compare/progress.hpp). Here
// stderr is a file, as in CI; each run lasts longer than the line's 2-second delay.
#include <gtest/gtest.h>

#include "cli.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

void expect_no_progress(const ringtest::Run& r) {
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("ringvib: integrating"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("ringvib: bench"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("ringvib: response"), std::string::npos) << r.err;
}

TEST(ProgressCli, RespondWithoutATerminalPrintsWhatItPrintedBefore) {
  // Every solver and the FE reference, each taking its progress callback through its time loop.
  const std::string args =
      "respond " + source("scenes/paper1990-forced-compare.toml") + " --format csv --set response.t_end=1.0";
  const auto r = ringvib(args);
  ASSERT_EQ(r.code, 0) << r.err;
  expect_no_progress(r);
  const auto quiet = ringvib(args + " -q");
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(r.err, quiet.err);
  // One solver's history, through the CSV writer: the same bytes with and without -q.
  const std::string one = "respond " + source("scenes/paper1990-forced.toml") + " --solver multibody";
  const auto a = ringvib(one), b = ringvib(one + " -q");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(a.err, b.err);
  expect_no_progress(a);
}

TEST(ProgressCli, BenchWithoutATerminalPrintsNoProgress) {
  const std::string dir = ringtest::temp_dir();
  const auto r = ringvib("bench " + source("scenes/paper1990-forced-compare.toml") +
                         " --set 'response.solvers=[\"multibody\"]' --set response.t_end=0.5 --out " + dir + "/out");
  ASSERT_EQ(r.code, 0) << r.err;
  expect_no_progress(r);
}

}  // namespace
