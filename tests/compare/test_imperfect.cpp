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

namespace {

// ringvib trim: masses at 60 and 90 degrees cancel the k = 2 split of the 1 % defect at 30
// (to first order three equal masses 60 degrees apart: their 2k theta = 120, 240, 360
// degrees sum to zero, Fox 1990). Trimmed with the FE beam to the tolerance; the trimmed
// scene, measured again by the lumped chain (an independent model), keeps only the chain's
// discretization error of the trim's effect.
TEST(ImperfectRing, TrimmingCancelsTheSplitAndAnotherSolverConfirmsIt) {
  const std::string out = ringtest::temp_dir() + "/trimmed.toml";
  const auto r = ringvib("trim " + source("scenes/imperfect-ring.toml") +
                         " --mode 1 --at 60,90 --solver fem --json --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["wave"], 2);
  EXPECT_LT(double(j["split_after"]), 1e-6);
  // First order: 55.43 kg each; the second order moves them by O(m / M) = 1 % (measured
  // 2.4 % and 0.02 %), bound 5 %.
  for (const auto& m : j["masses"]) EXPECT_NEAR(double(m["mass"]), 55.43, 0.05 * 55.43) << m.dump();
  const auto check = ringvib("modes " + out + " --solver lumped --json");
  ASSERT_EQ(check.code, 0) << check.err;
  double after = 0.0;
  for (const auto& p : nlohmann::json::parse(check.out).value("pairs", nlohmann::json::array()))
    if (p["wave"] == 2) after = p["relative_split"];
  // The lumped chain's split errors are O((k/n)^2) of the masses' effect (1.2e-3 of a
  // split at n = 120 above): measured 1.8e-4 of the untrimmed split, bound 5e-3.
  std::printf("lumped chain on the FE's trim: relative split %.3g (untrimmed %.3g)\n", after, double(j["split_before"]));
  EXPECT_LT(after, 5e-3 * double(j["split_before"]));
}

TEST(ImperfectRing, TrimRefusesWhatCannotWork) {
  const std::string scene = source("scenes/imperfect-ring.toml");
  // Two angles 45 degrees apart act alike on k = 2.
  auto r = ringvib("trim " + scene + " --mode 1 --at 75,30 --solver fem");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--at"), std::string::npos) << r.err;
  // Not a node (every 3 degrees at n = 120).
  r = ringvib("trim " + scene + " --mode 1 --at 60,91 --solver fem");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--at"), std::string::npos) << r.err;
  // A perfect ring has no split pair.
  r = ringvib("trim " + scene + " --mode 1 --at 60,90 --solver fem --set masses=[]");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--mode"), std::string::npos) << r.err;
  // A removal would be needed (90 and 96 degrees: the mass at 90 must be negative).
  r = ringvib("trim " + scene + " --mode 1 --at 75,96 --solver fem");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("removal"), std::string::npos) << r.err;
}

}  // namespace
