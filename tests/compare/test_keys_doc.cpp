// The scene reference's solver sections in docs/scenes.md are `ringvib keys`'s output,
// generated from the solvers' option schemas: this test keeps the committed text equal to
// it, so a default, range or help text changed in a solver's schema cannot leave the docs
// behind (regenerate: see the note in docs/scenes.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "compare/registry.hpp"

namespace {

std::string read_source(const std::string& path) {
  std::ifstream f(ringtest::source(path));
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// What a newcomer reads first stays short (the README's promise of five minutes): at most 200
// lines, none longer than 120 characters outside tables and code blocks, and every page of
// docs/ linked from it, so that nothing there is unreachable from the front page.
TEST(Readme, IsShortWithLinesAFewWideAndLinksEveryPageOfDocs) {
  const std::string readme = read_source("README.md");
  ASSERT_FALSE(readme.empty());
  std::istringstream lines(readme);
  std::string line;
  int count = 0;
  bool code = false;
  while (std::getline(lines, line)) {
    ++count;
    if (line.rfind("```", 0) == 0) code = !code;
    if (!code && line.rfind("|", 0) != 0)
      EXPECT_LE(line.size(), 120u) << "README.md line " << count << ": " << line;
  }
  EXPECT_LE(count, 200) << "README.md has " << count << " lines";
  int pages = 0;
  for (const auto& entry : std::filesystem::directory_iterator(ringtest::source("docs"))) {
    if (entry.path().extension() != ".md") continue;
    ++pages;
    const std::string link = "(docs/" + entry.path().filename().string();
    EXPECT_NE(readme.find(link), std::string::npos) << "README.md does not link " << link.substr(1);
  }
  EXPECT_GE(pages, 8);
}

TEST(SceneReference, DocsSolverSectionsAreWhatRingvibKeysPrints) {
  const ringtest::Run r = ringtest::ringvib("keys");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("### `[multibody]`"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| `fem.degree` | | 3 | [2, 16] |"), std::string::npos) << r.out;

  std::ifstream f(ringtest::source("docs/scenes.md"));
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string doc = ss.str();
  const auto begin = doc.find(cmp::kKeysBegin);
  const auto end = doc.find(cmp::kKeysEnd);
  ASSERT_NE(begin, std::string::npos) << "docs/scenes.md has no marker " << cmp::kKeysBegin;
  ASSERT_NE(end, std::string::npos) << "docs/scenes.md has no marker " << cmp::kKeysEnd;
  const auto from = begin + std::string(cmp::kKeysBegin).size();
  ASSERT_LT(from, end);
  EXPECT_EQ(doc.substr(from, end - from), "\n\n" + r.out + "\n")
      << "docs/scenes.md's solver sections differ from `ringvib keys`: regenerate them (the note above the marker)";
}

}  // namespace
