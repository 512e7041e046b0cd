// The scene reference's solver sections in docs/scenes.md are `ringvib keys`'s output,
// generated from the solvers' option schemas: this test keeps the committed text equal to
// it, so a default, range or help text changed in a solver's schema cannot leave the docs
// behind (regenerate: see the note in docs/scenes.md).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cli.hpp"
#include "compare/registry.hpp"

namespace {

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
