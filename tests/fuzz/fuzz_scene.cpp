// libFuzzer target: any bytes as a scene, with lines "#set key=value" (TOML comments,
// so the scene still reads) also applied as --set overrides. Every outcome must be a
// scene or a ring::InputError; any other exception, crash, leak or undefined behaviour
// is a finding (libFuzzer stops and writes the input to crash-*).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "fem_reference/checks.hpp"
#include "ring/errors.hpp"
#include "ring/scene.hpp"

namespace {

/// The solvers as the driver's registry describes them to the reader (compare/registry.cpp).
const ring::SceneSchema& schema() {
  static const ring::SceneSchema s = [] {
    ring::SceneSchema x;
    x.solvers.push_back({"multibody", "multibody.n", [](const ring::Scene& c) { return c.multibody.n; },
                         [](const ring::Scene& c) -> long long { return c.multibody.n - 3; }, true, true, true, {}});
    x.solvers.push_back({"lumped", "lumped.n", [](const ring::Scene& c) { return c.lumped.n; },
                         [](const ring::Scene& c) -> long long { return 3LL * c.lumped.n - 3; }, true, true, true, {}});
    x.solvers.push_back({"fem", "fem.elements", [](const ring::Scene& c) { return c.fem.elements; },
                         [](const ring::Scene& c) -> long long { return 2LL * c.fem.elements * c.fem.degree - 3; },
                         false, false, true, {{"degree", {fem::kMinDegree, fem::kMaxDegree}}}});
    x.default_solver = "multibody";
    x.reference_solver = "fem";
    return x;
  }();
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("#set ", 0) == 0) overrides.push_back(line.substr(5));
  try {
    const ring::Scene s = ring::parse_scene(text, "fuzz.toml", overrides, schema());
    // A valid scene satisfies what the reader promises.
    if (s.modes.count < 1 || s.ring.radius <= 0 || (s.response && !(s.response->dt > 0))) std::abort();
  } catch (const ring::InputError&) {
  }
  return 0;
}
