// libFuzzer target for `ringvib sweep`'s own input; the first byte picks the kind:
// - even: --vary arguments (the rest of the input, one per NUL-separated part; bit 1 of
//   the first byte is --zip) through cmp::sweep_cases, and each accepted case's values as
//   overrides of a scene through the scene reader;
// - odd: a sweep.csv for --resume (the rest of the input) through cmp::done_cases, for a
//   sweep over multibody.n x static.force of 6 cases of 4 rows.
// Every outcome must be a result or a ring::InputError; any other exception, a crash, a
// leak, undefined behaviour or a broken promise (std::abort below) is a finding.
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "compare/registry.hpp"
#include "compare/sweep.hpp"
#include "ring/errors.hpp"
#include "ring/scene.hpp"

namespace {

const char* kScene = R"(title = "fuzz"
[ring]
radius = 10.0
E = 2.1e11
rho = 7.8e3
section = { shape = "circle", diameter = 0.12 }
[supports]
pin = 180.0
roller = 0.0
[multibody]
n = 40
[static]
at = 0.0
force = [-20e3, 0.0]
record = [0.0, 90.0]
)";

void check(bool promise) {
  if (!promise) std::abort();
}

void fuzz_vary(const std::string& text, bool zip) {
  std::vector<std::string> vary;
  for (std::size_t start = 0; start <= text.size() && vary.size() < 4;) {
    const auto end = text.find('\0', start);
    vary.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  // This harness's own limit: the product of the lists is built in memory (the sweep's
  // memory guard is check_sweep_cost's, after sweep_cases), so large products are skipped.
  double product = 1.0;
  for (const auto& v : vary) {
    const auto eq = v.find('=');
    try {
      if (eq != std::string::npos) product *= double(ring::toml_array_items(v.substr(eq + 1), "k").size());
    } catch (const ring::InputError&) {
    }
  }
  if (product > 4096) return;
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> cases;
  try {
    cases = cmp::sweep_cases(vary, zip, keys);
  } catch (const ring::InputError&) {
    return;
  }
  check(keys.size() == vary.size() && !cases.empty());
  for (std::size_t a = 0; a < keys.size(); ++a)
    for (std::size_t b = 0; b < keys.size(); ++b)
      check(a == b || (keys[a] != keys[b] && keys[b].rfind(keys[a] + ".", 0) != 0));
  for (const auto& c : cases) {
    check(c.size() == keys.size());
    for (const auto& v : c) {
      check(v.find_first_of("\n\r") == std::string::npos);
      check(ring::toml_array_items("[" + v + "]", "k") == std::vector<std::string>{v});  // a fixed point
    }
  }
  for (std::size_t i = 0; i < cases.size() && i < 2; ++i) {
    std::vector<std::string> overrides;
    for (std::size_t k = 0; k < keys.size(); ++k) overrides.push_back(keys[k] + "=" + cases[i][k]);
    try {
      const ring::Scene s = cmp::parse_scene(kScene, "fuzz.toml", overrides);
      check(s.ring.radius > 0 && s.ring.A() > 0 && s.ring.I() > 0 && s.modes.count >= 1);
    } catch (const ring::InputError&) {
    }
  }
}

void fuzz_resume(const std::string& text) {
  // The file lives in memory: /proc/self/fd/N of a memfd, rewritten for every input.
  static const int fd = memfd_create("sweep.csv", 0);
  static const std::string file = "/proc/self/fd/" + std::to_string(fd);
  static const std::vector<std::string> keys = {"multibody.n", "static.force"};
  static const std::vector<std::vector<std::string>> cases = {
      {"40", "[-10000.0, 0.0]"}, {"40", "[-30000.0, 0.0]"}, {"80", "[-10000.0, 0.0]"},
      {"80", "[-30000.0, 0.0]"}, {"160", "[-10000.0, 0.0]"}, {"160", "[-30000.0, 0.0]"}};
  check(fd >= 0 && ftruncate(fd, 0) == 0 &&
        pwrite(fd, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size()));
  try {
    const auto kept = cmp::done_cases(file, keys, cases, [](std::size_t) { return 4.0; });
    for (const auto& [values, rows] : kept) {
      bool known = false;
      for (const auto& c : cases) known |= c == values;
      check(known && rows.size() == 4);
      for (const auto& r : rows) check(r.status == "ok" && std::isfinite(r.value) && r.values == values);
    }
  } catch (const ring::InputError& e) {
    check(std::string(e.what()).rfind(file + ": ", 0) == 0);  // names the file
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 0) fuzz_vary(rest, (data[0] & 2) != 0);
  else fuzz_resume(rest);
  return 0;
}
