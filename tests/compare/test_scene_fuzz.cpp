// Randomized scene parsing (stress): mutated scenes are either accepted as a valid scene
// or rejected with an InputError naming the file; never a crash, a hang, another
// exception type, or garbage accepted silently. Fixed seeds: failures reproduce.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "ring/errors.hpp"
#include "compare/registry.hpp"

namespace {

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The invariants every accepted scene must satisfy (the ranges of the README's scene reference).
void expect_valid(const ring::Scene& s, const std::string& text) {
  EXPECT_GT(s.ring.radius, 0.0) << text;
  EXPECT_GT(s.ring.E, 0.0) << text;
  EXPECT_GT(s.ring.rho, 0.0) << text;
  EXPECT_GT(s.ring.A(), 0.0) << text;
  EXPECT_GT(s.ring.I(), 0.0) << text;
  EXPECT_LT(s.ring.section.depth(), s.ring.radius) << text;
  EXPECT_GE(s.multibody.n, 4) << text;
  EXPECT_GE(s.lumped.n, 4) << text;
  EXPECT_GE(s.fem.elements, 4) << text;
  EXPECT_GE(s.fem.degree, 2) << text;
  EXPECT_GE(s.modes.count, 1) << text;
  if (s.ring.supports.roller) {
    EXPECT_TRUE(s.ring.supports.pin.has_value()) << text;
  }
  for (const auto* w : {&s.ring.radius, &s.ring.E, &s.ring.rho}) EXPECT_TRUE(std::isfinite(*w)) << text;
}

std::string mutate(std::string t, std::mt19937& rng) {
  static const std::vector<std::string> tokens = {
      "=", "[", "]", "{", "}", "\"", ",", "#", "\n", "-1", "0", "1e400", "nan", "inf", "-inf", "true", "\"x\"",
      "[1,2]", "3.5", "4", "1000000000000", "n", "pin", "roller", "count", "[modes]", "[ring]", "section", "E",
      "\xff\xfe", "\t", "=="};
  const int edits = 1 + rng() % 4;
  for (int e = 0; e < edits && !t.empty(); ++e) {
    const std::size_t pos = rng() % t.size();
    switch (rng() % 4) {
      case 0: t.erase(pos, 1 + rng() % 8); break;                          // delete a run
      case 1: t.insert(pos, tokens[rng() % tokens.size()]); break;         // insert a token
      case 2: t[pos] = static_cast<char>(32 + rng() % 95); break;          // replace a byte
      case 3: {                                                            // swap two lines
        std::vector<std::string> lines;
        std::stringstream ss(t);
        for (std::string l; std::getline(ss, l);) lines.push_back(l);
        if (lines.size() > 2) std::swap(lines[rng() % lines.size()], lines[rng() % lines.size()]);
        t.clear();
        for (const auto& l : lines) t += l + "\n";
      }
    }
  }
  return t;
}

TEST(SceneFuzz, MutatedScenesAreAcceptedValidOrRejectedClearly) {
  const std::vector<std::string> seeds = {
      read(std::string(RINGVIB_SOURCE_DIR) + "/scenes/paper1990.toml"),
      read(std::string(RINGVIB_SOURCE_DIR) + "/scenes/paper1990-forced.toml"),
      read(std::string(RINGVIB_SOURCE_DIR) + "/scenes/free-ring.toml")};
  std::mt19937 rng(20261121);
  int accepted = 0, rejected = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 5000; ++i) {
    const std::string text = mutate(seeds[i % seeds.size()], rng);
    try {
      const ring::Scene s = cmp::parse_scene(text, "fuzz.toml");
      expect_valid(s, text);
      ++accepted;
    } catch (const ring::InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("fuzz.toml: ", 0), 0u) << e.what();
      ++rejected;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception " << e.what() << " for\n" << text;
    }
  }
  std::cout << "[ fuzz ] " << accepted << " accepted, " << rejected << " rejected in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
  EXPECT_GT(rejected, 1000);  // the mutations do reach the validation
}

// Random --set overrides: the same contract.
TEST(SceneFuzz, RandomOverrides) {
  const std::string base = read(std::string(RINGVIB_SOURCE_DIR) + "/scenes/paper1990.toml");
  const std::vector<std::string> keys = {"ring.radius", "ring.E", "multibody.n", "fem.degree", "lumped.variant",
                                         "modes.count", "supports.pin", "supports.roller", "table.base", "x.y",
                                         "ring", "ring.section.diameter", "modes.solvers", ".", "a..b"};
  const std::vector<std::string> values = {"1", "-1", "0", "1e9", "\"frame\"", "frame", "[1,2]", "true", "nan",
                                           "{a=1}", "\"", "", "[\"fem\"]", "180.0", "41"};
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const std::string o = keys[rng() % keys.size()] + "=" + values[rng() % values.size()];
    try {
      expect_valid(cmp::parse_scene(base, "p.toml", {o}), o);
    } catch (const ring::InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception " << e.what() << " for --set " << o;
    }
  }
}

}  // namespace
