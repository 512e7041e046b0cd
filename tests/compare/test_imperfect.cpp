// An imperfect ring's split pairs (compare/pairs.hpp) in every solver against the exact
// split of the free inextensible ring with a point mass (the receptance oracle,
// tests/support/ring_receptance.hpp: the symmetric family about the mass's diameter from
// H_ww, the antisymmetric one from H_vv) and the orientation that symmetry fixes: the lower
// mode of each pair is symmetric about the mass, its radial antinode at the mass's angle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "support/ring_receptance.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

TEST(ImperfectRing, EverySolversSplitPairsMeetTheExactSplitAndTheMassesOrientation) {
  // scenes/imperfect-ring.toml: R = 10, E = 2.1e11, rho = 7.8e3, d = 0.12, m = 55.43 at 30.
  const double R = 10.0, A = M_PI * 0.06 * 0.06, I = M_PI * std::pow(0.06, 4) / 4.0;
  const receptance::Ring ring{R, 2.1e11 * I, 7.8e3 * A};
  const double m0 = 55.43;
  const auto sym = receptance::roots_in_gaps(ring, [&](double x) { return receptance::h_ww(ring, x) - 1.0 / (m0 * x); }, 3);
  const auto anti =
      receptance::roots_in_gaps(ring, [&](double x) { return receptance::h_vb(ring, x)[0] - 1.0 / (m0 * x); }, 3);
  for (const std::string solver : {"multibody", "lumped", "fem"}) {
    const auto r = ringvib("modes " + source("scenes/imperfect-ring.toml") + " --solver " + solver + " --json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j.contains("pairs")) << solver;
    const auto& pairs = j["pairs"];
    ASSERT_EQ(pairs.size(), 4u) << solver;  // k = 2 .. 5 among 8 modes
    for (int k = 2; k <= 4; ++k) {
      const auto& p = pairs[k - 2];
      EXPECT_EQ(p["wave"], k);
      const double lo = std::sqrt(sym[k - 2]), hi = std::sqrt(anti[k - 2]);
      const double exact = 2.0 * (hi - lo) / (hi + lo), got = p["relative_split"];
      std::printf("%-9s k = %d: relative split %.6e, exact %.6e (%+.2e of it), orientation %.9f\n", solver.c_str(), k,
                  got, exact, (got - exact) / exact, double(p["orientation_deg"]));
      // The chains converge to the inextensible ring at O((k / n)^2) (measured: up to 1.03e-2
      // of the split, the lumped chain at k = 4, n = 120; order 2 below), the FE beam to the
      // extensible one, (h / R)^2 = 1.4e-4 from it (measured 5e-5 of the split).
      EXPECT_NEAR(got, exact, (solver == "fem" ? 1e-3 : 3e-2) * exact) << solver << " k = " << k;
      // By symmetry about the mass's diameter, exact to the stations' round-off.
      EXPECT_NEAR(double(p["orientation_deg"]), 30.0, 1e-9) << solver << " k = " << k;
    }
  }
}

// The chain's split converges at order 2 in n to the exact one (k = 3, n = 60 and 120).
TEST(ImperfectRing, TheChainsSplitConvergesAtOrderTwo) {
  const double R = 10.0, A = M_PI * 0.06 * 0.06, I = M_PI * std::pow(0.06, 4) / 4.0;
  const receptance::Ring ring{R, 2.1e11 * I, 7.8e3 * A};
  const double m0 = 55.43;
  const double lo = std::sqrt(receptance::roots_in_gaps(ring, [&](double x) { return receptance::h_ww(ring, x) - 1.0 / (m0 * x); }, 2)[1]);
  const double hi =
      std::sqrt(receptance::roots_in_gaps(ring, [&](double x) { return receptance::h_vb(ring, x)[0] - 1.0 / (m0 * x); }, 2)[1]);
  const double exact = 2.0 * (hi - lo) / (hi + lo);
  std::vector<double> e;
  for (const int n : {60, 120}) {
    const auto r = ringvib("modes " + source("scenes/imperfect-ring.toml") + " --solver multibody --json --set multibody.n=" +
                           std::to_string(n));
    ASSERT_EQ(r.code, 0) << r.err;
    e.push_back(std::abs(double(nlohmann::json::parse(r.out)["pairs"][1]["relative_split"]) - exact));
  }
  const double order = std::log2(e[0] / e[1]);
  std::printf("multibody split error %.3e (n = 60), %.3e (n = 120): order %.3f\n", e[0], e[1], order);
  EXPECT_NEAR(order, 2.0, 0.2);  // the chain's O(1/n^2), its next term O(1/n^4) small at k / n <= 0.05
}

// A ring with no defect has no split pair: no "pairs" key, no section after the table.
TEST(ImperfectRing, APerfectRingReportsNoSplitPair) {
  const auto r = ringvib("modes " + source("scenes/imperfect-ring.toml") + " --solver fem --json --set masses=[]");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out).contains("pairs")) << r.out.substr(0, 400);
  const auto t = ringvib("table " + source("scenes/imperfect-ring.toml") + " --set masses=[]");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_EQ(t.out.find("Split pairs"), std::string::npos) << t.out;
}

}  // namespace
