// The shipped imperfect ring (scenes/ring-thickness-variation.toml: the silicon ring, free,
// its depth varying by 1 % as cos(4 theta)) through the command, every solver on one scene.
// Oracle (tests/support/variations.hpp, none of the solvers' code): Hill's method for the ring
// whose section varies, inextensible for the chains (which converge to it at O(1/n^2)),
// extensible for the FE beam; the pair k = 2 splits, the lower mode's radial antinodes at the
// thin spots.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "support/variations.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

vartest::Ring scene_ring(bool extensible) {
  vartest::Ring r;
  r.R = 3.0e-3;
  r.E = 1.69e11;
  r.rho = 2330.0;
  r.A0 = 1.0e-4 * 1.2e-4;
  r.I0 = 1.0e-4 * std::pow(1.2e-4, 3) / 12.0;
  r.circle = false;
  vartest::Harm h;
  h.harmonic = 4;
  h.thickness = 0.01;
  r.harmonics = {h};
  r.extensible = extensible;
  return r;
}

// Bounds from the errors measured through this command (about twice them), against Hill: the
// chains (n = 80, O(1/n^2)) 5.7e-4 (multibody) and 1.1e-4 (lumped) on the pair's frequencies,
// 1.4e-3 and 1.8e-3 on its relative split; the FE beam (40 cells of degree 3, O(h^4)) 1.1e-5 and
// 5.4e-7. The orientation (45 degrees, the thin spots) is fixed by the single harmonic's
// symmetry: every model meets it to round-off.
TEST(ThicknessVariationCli, EverySolversSplitPairMeetsHillsMethod) {
  for (const std::string solver : {"multibody", "lumped", "fem"}) {
    const auto r = ringvib("modes " + source("scenes/ring-thickness-variation.toml") + " --solver " + solver + " --json");
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const bool fe = solver == "fem";
    const vartest::Split exact = vartest::pair_split(scene_ring(fe), 2);
    const nlohmann::json* pair = nullptr;
    for (const auto& p : j.at("pairs"))
      if (p.at("wave") == 2) pair = &p;
    ASSERT_NE(pair, nullptr) << solver << ": " << j.dump();
    const double lower = pair->at("omega")[0], upper = pair->at("omega")[1];
    const double split = (upper - lower) / (0.5 * (upper + lower));
    const double exact_split = (exact.upper - exact.lower) / (0.5 * (exact.upper + exact.lower));
    const double tol = fe ? 2.5e-5 : 1.2e-3, split_tol = fe ? 1.2e-6 : 4e-3;
    EXPECT_NEAR(lower, exact.lower, tol * exact.lower) << solver;
    EXPECT_NEAR(upper, exact.upper, tol * exact.upper) << solver;
    EXPECT_NEAR(split, exact_split, split_tol * exact_split) << solver;
    EXPECT_NEAR(pair->at("orientation_deg").get<double>(), exact.orientation_deg, 1e-6) << solver;
  }
}

}  // namespace
