// Randomized scene parsing (stress): mutated scenes are either accepted as a valid scene
// or rejected with an InputError naming the file; never a crash, a hang, another
// exception type, or garbage accepted silently. The same for random --vary lists
// (sweep_cases) and mutated sweep.csv files read by --resume (done_cases). Fixed seeds:
// failures reproduce.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "ring/errors.hpp"
#include "compare/registry.hpp"
#include "compare/sweep.hpp"

namespace {

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The invariants every accepted scene must satisfy (the ranges of the scene reference, docs/scenes.md).
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

// ---- --vary lists and --resume rows: the same contract ----

/// Random --vary arguments: keys (good, bad, overlapping), TOML values of every kind and
/// broken ones, comments and newlines, then byte mutations.
std::string random_vary(std::mt19937& rng) {
  static const std::vector<std::string> keys = {
      "multibody.n", "ring.section", "ring.section.diameter", "title", "lumped.variant", "static.force", " multibody . n ",
      "", ".", "a..b", "ring", "x.y", "modes.count", "ring.E"};
  // The first kValid are TOML values; the rest break the list or are not TOML.
  static const std::vector<std::string> values = {
      "40", "80", "3", "-1", "0.1", "1e-300", "5e-324", "-0.0", "0x10", "1_000", "1e4", "nan", "-inf", "true",
      "\"a\\\"b\"", "'lit\\'", "\"\"\"two\nlines\"\"\"", "\"\\u00e9\"", "\"frame\"", "{diameter = 0.01}",
      "{ width = 0.1, height = 0.2 }", "{a.b.c = 1}", "[-1e4, 0.0]", "[[1], [2, [3]]]", "[]", "{}", "1979-05-27",
      "07:32:00", "1e400", "007", "\"\\uD800\"", "chain", "# c\n", "\n", ",", "]", "[", "{", "\"", "=", "\\"};
  constexpr std::size_t kValid = 28, kGoodKeys = 7;
  // Half the lists are well-formed, of the first keys; the rest may break anywhere.
  const bool clean = rng() % 2 == 0;
  const std::size_t kinds = clean ? kValid : values.size();
  std::string v = keys[rng() % (clean ? kGoodKeys : keys.size())];
  if (clean || rng() % 10) v += "=";
  std::string list = "[";
  const int n = static_cast<int>(rng() % 5);
  for (int i = 0; i < n; ++i) list += (i ? (rng() % 4 ? ", " : ",\n  ") : "") + values[rng() % kinds];
  if (rng() % 5 == 0) list += ",";
  if (clean || rng() % 8) list += "]";
  if (rng() % 6 == 0) list += rng() % 2 ? "  # end" : "\nw = 1";
  v += list;
  for (int e = clean ? 0 : static_cast<int>(rng() % 3); e > 0 && !v.empty(); --e) {
    const std::size_t pos = rng() % v.size();
    switch (rng() % 3) {
      case 0: v.erase(pos, 1 + rng() % 4); break;
      case 1: v.insert(pos, values[rng() % values.size()]); break;
      case 2: v[pos] = static_cast<char>(1 + rng() % 127); break;
    }
  }
  return v;
}

TEST(SweepFuzz, RandomVaryListsGiveCasesOrAnInputError) {
  const std::string base = read(std::string(RINGVIB_SOURCE_DIR) + "/scenes/paper1990-static.toml");
  std::mt19937 rng(2311);
  int accepted = 0, rejected = 0;
  for (int i = 0; i < 3000; ++i) {
    std::vector<std::string> vary;
    for (int k = 1 + static_cast<int>(rng() % 3); k > 0; --k) vary.push_back(random_vary(rng));
    const bool zip = rng() % 4 == 0;
    std::string shown;
    for (const auto& v : vary) shown += "--vary '" + v + "' ";
    try {
      std::vector<std::string> keys;
      const auto cases = cmp::sweep_cases(vary, zip, keys);
      ++accepted;
      ASSERT_EQ(keys.size(), vary.size()) << shown;
      for (std::size_t a = 0; a < keys.size(); ++a)
        for (std::size_t b = 0; b < keys.size(); ++b)
          if (a != b) {
            EXPECT_NE(keys[a], keys[b]) << shown;
            EXPECT_NE(keys[b].rfind(keys[a] + ".", 0), 0u) << shown;
          }
      ASSERT_FALSE(cases.empty()) << shown;
      for (const auto& c : cases) {
        ASSERT_EQ(c.size(), keys.size()) << shown;
        for (const auto& v : c) {
          EXPECT_EQ(v.find_first_of("\n\r"), std::string::npos) << shown;
          // The canonical text is a fixed point: read as a list, it comes back as itself.
          EXPECT_EQ(ring::toml_array_items("[" + v + "]", "k"), std::vector<std::string>{v}) << shown;
        }
      }
      // The scene reader takes every case as overrides: a scene or an InputError.
      for (std::size_t c = 0; c < std::min<std::size_t>(cases.size(), 3); ++c) {
        std::vector<std::string> overrides;
        for (std::size_t k = 0; k < keys.size(); ++k) overrides.push_back(keys[k] + "=" + cases[c][k]);
        try {
          expect_valid(cmp::parse_scene(base, "p.toml", overrides), shown);
        } catch (const ring::InputError&) {
        }
      }
    } catch (const ring::InputError& e) {
      ++rejected;
      EXPECT_EQ(std::string(e.what()).rfind("--", 0), 0u) << "names the option: " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception " << e.what() << " for " << shown;
    }
  }
  std::cout << "[ fuzz ] --vary: " << accepted << " accepted, " << rejected << " rejected\n";
  EXPECT_GT(accepted, 300);  // both outcomes are reached
  EXPECT_GT(rejected, 300);
}

// Found by fuzz_sweep: an unknowns value beyond long long was cast (undefined behaviour).
TEST(SweepFuzz, ResumeUnknownsBeyondACountAreAnInputError) {
  const std::string file = std::string("/tmp/ringvib-fuzz-") + std::to_string(getpid()) + "-unknowns.csv";
  {
    std::ofstream f(file);
    f << "case,multibody.n,solver,analysis,quantity,value,error_pct,unknowns,seconds,status,message\n"
         "0,40,multibody,static,u at 0.000 deg,0.5,,5.5e46,0.01,ok,\n";
  }
  try {
    cmp::done_cases(file, {"multibody.n"}, {{"40"}}, [](std::size_t) { return 1.0; });
    ADD_FAILURE() << "accepted unknowns = 5.5e46";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file + ": line 2: ", 0), 0u) << e.what();
  }
  std::remove(file.c_str());
}

TEST(SweepFuzz, MutatedResumeFilesGiveKeptCasesOrAnInputError) {
  // A sweep.csv of 6 cases x 4 rows, as a sweep writes it; then mutated lines and bytes.
  const std::vector<std::string> keys = {"multibody.n", "static.force"};
  std::vector<std::vector<std::string>> cases;
  for (const char* n : {"40", "80", "160"})
    for (const char* f : {"[-10000.0, 0.0]", "[-30000.0, 0.0]"}) cases.push_back({n, f});
  std::vector<cmp::SweepRow> rows;
  for (std::size_t c = 0; c < cases.size(); ++c)
    for (int p = 0; p < 4; ++p) {
      cmp::SweepRow r;
      r.index = static_cast<int>(c);
      r.values = cases[c];
      r.solver = "multibody";
      r.analysis = "static";
      r.quantity = "u at " + std::to_string(90 * p) + " deg";
      r.value = 0.1 * (p + 1);
      r.error_pct = NAN;
      r.unknowns = 37;
      r.seconds = 0.01;
      rows.push_back(r);
    }
  const std::string csv = cmp::sweep_csv(keys, rows);
  const auto expected_rows = [](std::size_t) { return 4.0; };
  const std::string file = std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") + "/ringvib-fuzz-" +
                           std::to_string(getpid()) + "-sweep.csv";
  auto write = [&](const std::string& text) {
    std::ofstream f(file, std::ios::binary);
    f << text;
  };
  write(csv);
  EXPECT_EQ(cmp::done_cases(file, keys, cases, expected_rows).size(), cases.size()) << "the file as written";

  static const std::vector<std::string> tokens = {",", "\"", "\"\"", "\n", "\r", "nan", "inf", "-inf", "1e999", "0x1p3",
                                                  "ok", "input-error", "numerical-failure", "OK", " ", "-", "1e-320",
                                                  "[-10000.0, 0.0]", "40", "\xff", ""};
  std::mt19937 rng(1123);
  int kept_some = 0, rejected = 0;
  for (int i = 0; i < 2000; ++i) {
    std::string t = csv;
    for (int e = 1 + static_cast<int>(rng() % 4); e > 0 && !t.empty(); --e) {
      const std::size_t pos = rng() % t.size();
      switch (rng() % 6) {
        case 0: t.erase(pos, 1 + rng() % 12); break;
        case 1: t.insert(pos, tokens[rng() % tokens.size()]); break;
        case 2: t[pos] = static_cast<char>(rng() % 256); break;
        case 3: t.resize(pos); break;  // cut short, as by a crash
        case 4: {                      // a line repeated
          const auto a = t.rfind('\n', pos), b = t.find('\n', pos);
          if (a != std::string::npos && b != std::string::npos) t.insert(b + 1, t.substr(a + 1, b - a));
          break;
        }
        case 5: {  // one field replaced
          const auto a = t.rfind(',', pos);
          if (a != std::string::npos) t.insert(a + 1, tokens[rng() % tokens.size()] + ",");
          break;
        }
      }
    }
    write(t);
    try {
      const auto kept = cmp::done_cases(file, keys, cases, expected_rows);
      kept_some += !kept.empty();
      for (const auto& [values, rs] : kept) {
        EXPECT_NE(std::find(cases.begin(), cases.end(), values), cases.end()) << t;
        EXPECT_EQ(rs.size(), 4u) << t;
        for (const auto& r : rs) {
          EXPECT_EQ(r.status, "ok") << t;
          EXPECT_TRUE(std::isfinite(r.value)) << t;
          EXPECT_EQ(r.values, values) << t;
        }
      }
    } catch (const ring::InputError& e) {
      ++rejected;
      EXPECT_EQ(std::string(e.what()).rfind(file + ": ", 0), 0u) << "names the file: " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception " << e.what() << " for\n" << t;
    }
  }
  std::remove(file.c_str());
  std::cout << "[ fuzz ] --resume: " << kept_some << " kept some case, " << rejected << " rejected\n";
  EXPECT_GT(kept_some, 300);
  EXPECT_GT(rejected, 300);
}

}  // namespace
