// Every numeric key of a scene at the extremes a careless or hostile input gives it (1e300,
// 1e-300, NaN, infinity), through the binary as a user runs it (`ringvib run --out`): the
// run is refused (exit 2, nothing written), fails as numerics (exit 3), or succeeds; and
// whatever it prints or writes holds no non-finite number. A NaN that passed a check as a
// result (a backward error of NaN compared with "> 1e-2") was the first finding of a
// hostile-input probe; this sweeps every key for its like.
#include <gtest/gtest.h>

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "support/paper.hpp"

using ringtest::ringvib;

namespace {

/// A small scene that asks for every analysis of the chains and the FE modes: the paper's
/// ring on a pin and a roller, 12 segments, a 0.05 s response.
std::string scene() {
  return "title = \"extremes\"\n" + ringtest::paper_ring_toml() +
         "[supports]\npin = 180.0\nroller = 0.0\n"
         "[multibody]\nn = 12\n[lumped]\nn = 12\n[fem]\nelements = 8\ndegree = 2\n"
         "[modes]\ncount = 4\nsolvers = [\"multibody\", \"lumped\", \"fem\"]\n"
         "[static]\nsolvers = [\"multibody\", \"lumped\"]\nat = 90.0\nforce = [0.0, -1000.0]\nsteps = 2\n"
         "record = [90.0]\n"
         "[response]\nsolvers = [\"multibody\", \"lumped\"]\nat = 90.0\nforce = [0.0, -1000.0]\ndt = 0.01\n"
         "t_end = 0.05\nrecord = [90.0]\n";
}

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// Every regular file under `dir` (recursively), with its contents.
void files(const std::string& dir, std::vector<std::pair<std::string, std::string>>& out) {
  DIR* d = opendir(dir.c_str());
  if (!d) return;
  while (const dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    if (name == "." || name == "..") continue;
    const std::string path = dir + "/" + name;
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) continue;
    if (S_ISDIR(st.st_mode))
      files(path, out);
    else if (name.size() < 4 || name.substr(name.size() - 4) != ".png")
      out.emplace_back(path, read(path));
  }
  closedir(d);
}

/// A non-finite number as C++, Python or JSON writers print one.
bool non_finite(const std::string& text) {
  static const std::regex word(R"((^|[^A-Za-z_])(-?nan|-?inf(inity)?|NaN|-?Infinity)([^A-Za-z_]|$))",
                               std::regex::icase);
  return std::regex_search(text, word);
}

struct Key {
  std::string name;      ///< for messages
  std::string set;       ///< the --set argument with V for the value
};

/// The sweep of `keys` x `values` on `scene_text` through `ringvib run --out`: each run exits
/// 0, 2 or 3, prints and writes no non-finite number, and a refusal writes nothing and names
/// the key's section. Returns how many runs were refused.
int sweep(const std::string& scene_text, const std::vector<Key>& keys, const std::vector<std::string>& values);

}  // namespace

TEST(ExtremeValues, NoKeyMakesANonFiniteResultOrAPassedCheck) {
  const std::vector<Key> keys = {
      {"ring.radius", "ring.radius=V"},
      {"ring.E", "ring.E=V"},
      {"ring.rho", "ring.rho=V"},
      {"ring.section.diameter", "ring.section={shape=\"circle\", diameter=V}"},
      {"supports.pin", "supports.pin=V"},
      {"supports.roller", "supports.roller=V"},
      {"supports.springs.kx", "supports.springs=[{at=90.0, kx=V, ky=0.0, kr=0.0}]"},
      {"supports.springs.kr", "supports.springs=[{at=90.0, kx=0.0, ky=0.0, kr=V}]"},
      {"masses.mass", "masses=[{at=90.0, mass=V}]"},
      {"masses.inertia", "masses=[{at=90.0, mass=10.0, inertia=V}]"},
      {"foundation.radial", "foundation.radial=V"},
      {"foundation.tangential", "foundation.tangential=V"},
      {"multibody.n", "multibody.n=V"},
      {"lumped.n", "lumped.n=V"},
      {"fem.elements", "fem.elements=V"},
      {"fem.degree", "fem.degree=V"},
      {"fem.tolerance", "fem.tolerance=V"},
      {"modes.count", "modes.count=V"},
      {"static.at", "static.at=V"},
      {"static.force", "static.force=[0.0, V]"},
      {"static.steps", "static.steps=V"},
      {"static.pressure", "static.pressure={value=V, kind=\"follower\"}"},
      {"static.gravity", "static.gravity=[0.0, V]"},
      {"response.at", "response.at=V"},
      {"response.force", "response.force=[0.0, V]"},
      {"response.dt", "response.dt=V"},
      {"response.t_end", "response.t_end=V"},
      {"response.rho_inf", "response.rho_inf=V"},
      {"response.rayleigh_mass", "response.rayleigh_mass=V"},
      {"response.rayleigh_stiffness", "response.rayleigh_stiffness=V"},
      {"response.hinge_damping", "response.hinge_damping=V"},
  };
  const std::vector<std::string> values = {"1e300", "-1e300", "1e-300", "nan", "inf"};
  const int runs = static_cast<int>(keys.size() * values.size());
  EXPECT_GT(sweep(scene(), keys, values), runs / 2);  // NaN and infinity are refused everywhere
}

// The plastic law's keys and the load history on the pinched plastic ring (statics only: the
// plastic law refuses a response): 1e300 as a plastic moment is the elastic ring, 1e-300 a
// ring with no strength, whose path ends in exit 3.
TEST(ExtremeValues, ThePlasticKeysAndTheHistoryMakeNoNonFiniteResult) {
  const std::string plastic =
      "title = \"extremes\"\n" + ringtest::paper_ring_toml() + "plastic = { moment = 7.2e4, hardening = 0.0 }\n" +
      "[supports]\npin = 180.0\nroller = 0.0\n[multibody]\nn = 12\n[lumped]\nn = 12\n[fem]\nelements = 12\n"
      "[static]\nsolvers = [\"multibody\", \"lumped\", \"fem\"]\nat = 0.0\nforce = [-2e4, 0.0]\n"
      "history = [1.0, 0.0]\nsteps = 4\nrecord = [0.0, 90.0]\n";
  const std::vector<Key> keys = {
      {"ring.plastic.moment", "ring.plastic={moment=V}"},
      {"ring.plastic.hardening", "ring.plastic={moment=7.2e4, hardening=V}"},
      {"static.history", "static.history=[1.0, V]"},
  };
  sweep(plastic, keys, {"1e300", "-1e300", "1e-300", "nan", "inf", "0.999999"});
}

// The driven point (static.displacement) on the plastic pinch: its angle and its value at the
// extremes, and at 4 radii (the reader's bound: accepted, and far past anything a ring can do,
// so the path ends in exit 3 or at contact).
TEST(ExtremeValues, TheDrivenPointsKeysMakeNoNonFiniteResult) {
  const std::string driven =
      "title = \"extremes\"\n" + ringtest::paper_ring_toml() + "plastic = { moment = 7.2e4, hardening = 0.0 }\n" +
      "[supports]\npin = 270.0\n[multibody]\nn = 12\n[lumped]\nn = 12\n[fem]\nelements = 12\n"
      "[static]\nsolvers = [\"multibody\", \"lumped\", \"fem\"]\n"
      "displacement = { at = 90.0, value = [0.0, -0.5] }\nsteps = 4\nrecord = [90.0, 0.0]\n";
  const std::vector<Key> keys = {
      {"static.displacement.value", "static.displacement={at=90.0, value=[0.0, V]}"},
      {"static.displacement.at", "static.displacement={at=V, value=[0.0, -0.5]}"},
  };
  sweep(driven, keys, {"1e300", "-1e300", "1e-300", "nan", "inf", "-40.0"});
}

namespace {

int sweep(const std::string& scene_text, const std::vector<Key>& keys, const std::vector<std::string>& values) {
  const std::string dir = ringtest::temp_dir();
  const std::string path = dir + "/scene.toml";
  std::ofstream(path) << scene_text;
  // The scene as it is runs and writes finite numbers (else the sweep would prove nothing).
  {
    const auto r = ringvib("run " + path + " -q --out " + dir + "/plain");
    EXPECT_EQ(r.code, 0) << r.err;
    std::vector<std::pair<std::string, std::string>> written;
    files(dir + "/plain", written);
    EXPECT_FALSE(written.empty());
    if (r.code != 0 || written.empty()) return 0;
  }
  int runs = 0, refused = 0, failed = 0, succeeded = 0;
  for (const Key& k : keys)
    for (const std::string& v : values) {
      std::string set = k.set;
      set.replace(set.find('V'), 1, v);
      const std::string out = dir + "/out" + std::to_string(runs++);
      const auto r = ringvib("run " + path + " -q --out " + out + " --set '" + set + "'");
      SCOPED_TRACE(set);
      EXPECT_TRUE(r.code == 0 || r.code == 2 || r.code == 3) << "exit " << r.code << "\n" << r.err;
      EXPECT_FALSE(non_finite(r.out)) << r.out;
      std::vector<std::pair<std::string, std::string>> written;
      files(out, written);
      if (r.code == 2) {
        ++refused;
        EXPECT_TRUE(written.empty()) << "a refused run wrote " << written.front().first;
        EXPECT_NE(r.err.find(k.name.substr(0, k.name.find('.'))), std::string::npos)
            << "the refusal does not name the key's section: " << r.err;
        continue;
      }
      r.code == 0 ? ++succeeded : ++failed;
      for (const auto& [file, text] : written) EXPECT_FALSE(non_finite(text)) << file;
    }
  std::printf("[ extremes ] %d runs: %d refused, %d numerical failures, %d succeeded\n", runs, refused, failed,
              succeeded);
  return refused;
}

}  // namespace
