// The model theory of each solver against the ring's physics, through the ringvib command
// (docs/solvers.md, "Thick rings"): ring.theory is what the reference solves, fem.theory and
// lumped.variant the models the columns are. The oracle is outside the code: the closed forms
// of the free extensible Euler-Bernoulli ring and of the free Timoshenko ring
// (ring/closed_form.hpp), whose difference an Euler-Bernoulli FE column of a Timoshenko ring
// must show as its error against the Timoshenko reference.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ring/closed_form.hpp"
#include "ring/spec.hpp"
#include "tests/support/thick.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

/// The ring of scenes/thick-ring.toml (depth/R = 0.2, Timoshenko theory, Cowper's kappa).
ring::RingSpec thick_ring() { return ringtest::scene_thick_ring(); }

/// One elastic frequency of the free ring in both theories: the Euler-Bernoulli extensible
/// ring's and the Timoshenko ring's of the same wave number and branch.
struct Pair {
  int k;
  double euler, timoshenko;
};

/// The lower two branches of every wave number k = 0..kmax (the Timoshenko ring's lower two
/// tend to the extensible ring's two as kGA -> inf and rho I -> 0), without the rigid ones.
std::vector<Pair> closed_form_pairs(const ring::RingSpec& spec, int kmax) {
  ring::RingSpec euler = spec;
  euler.theory = ring::Theory::euler_bernoulli;
  std::vector<Pair> v;
  for (int k = 0; k <= kmax; ++k) {
    const auto e = ring::closed_form::free_ring_extensible(euler, k);
    const auto t = ring::closed_form::free_ring_timoshenko(spec, k);
    for (int b = 0; b < 2; ++b)
      if (e[b] > 1.0) v.push_back({k, e[b], t[b]});
  }
  return v;
}

nlohmann::json table(const std::string& sets) {
  const auto r = ringvib("table " + source("scenes/thick-ring.toml") + " --format json -q " + sets);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// fem.theory = "euler-bernoulli" on the Timoshenko ring: the FE column is the extensible
// Euler-Bernoulli ring, the reference the Timoshenko ring, and the column's error is the
// closed forms' difference. Tolerances: the Timoshenko reference meets its closed form to
// fem.tolerance = 1e-9 (relative; measured 1e-14); the column's own discretization (40
// cells of degree 4) meets free_ring_extensible to 2e-6 relative (measured 1.2e-6 at k = 5,
// 8e-9 at k = 2, round-off for the extensional k = 0, 1), which moves its error by at most
// 2e-6 x 100 x omega_EB / omega_T < 3e-4 % on differences of 0.3 to 15 %. The breathing
// mode (k = 0, w alone) is the same in both theories: a difference of 0.
TEST(ModelTheory, EulerFeColumnOfATimoshenkoRingDiffersByTheClosedForms) {
  const nlohmann::json t = table("--set 'fem.theory=\"euler-bernoulli\"' --set 'modes.solvers=[\"fem\"]' "
                                 "--set 'table.base=\"fem\"' --set 'table.against=[]'");
  ASSERT_TRUE(t.contains("rows"));
  const auto& rows = t["rows"];
  ASSERT_EQ(rows.size(), 11u);
  const std::vector<Pair> pairs = closed_form_pairs(thick_ring(), 12);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double fem = rows[i]["fem"].get<double>(), reference = rows[i]["reference"].get<double>();
    // The closed-form wave whose Euler-Bernoulli frequency the column's mode is (the
    // column's own error is below 2e-6, the nearest other wave 1e-2 or more away).
    const Pair* p = nullptr;
    for (const Pair& c : pairs)
      if (std::abs(fem - c.euler) <= 1e-5 * c.euler) p = &c;
    ASSERT_NE(p, nullptr) << "mode " << i + 1 << ": " << fem << " rad/s is no Euler-Bernoulli frequency of the ring";
    EXPECT_NEAR(fem, p->euler, 2e-6 * p->euler) << "mode " << i + 1 << ", k = " << p->k;
    EXPECT_NEAR(reference, p->timoshenko, 1e-8 * p->timoshenko) << "mode " << i + 1 << ", k = " << p->k;
    const double expected = (p->euler - p->timoshenko) / p->timoshenko * 100.0;
    if (p->k > 0) EXPECT_GT(expected, 0.0) << "k = " << p->k << ": the thin-ring model is the stiffer";
    EXPECT_NEAR(rows[i]["fem_error_pct"].get<double>(), expected, 3e-4) << "mode " << i + 1 << ", k = " << p->k;
  }
}

// lumped.variant = "frame" (an Euler-Bernoulli model) is taken on a Timoshenko ring, and the
// table names each column's theory once the columns mix theories.
TEST(ModelTheory, EulerFrameOfATimoshenkoRingIsTakenAndNamed) {
  const auto r = ringvib("table " + source("scenes/thick-ring.toml") + " -q --set 'lumped.variant=\"frame\"'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lumped mass (euler-bernoulli)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FE (timoshenko)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reference (timoshenko)"), std::string::npos) << r.out;
  // The shipped scene, every column in the ring's theory: the headers stay the labels.
  const auto same = ringvib("table " + source("scenes/thick-ring.toml") + " -q");
  ASSERT_EQ(same.code, 0) << same.err;
  EXPECT_EQ(same.out.find("(timoshenko)"), std::string::npos) << same.out;
  // The model's description says its theory (modes --json, "model").
  const auto m = ringvib("modes " + source("scenes/thick-ring.toml") +
                         " --solver lumped --count 3 --json --set 'lumped.variant=\"frame\"'");
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(nlohmann::json::parse(m.out)["model"]["theory"], "euler-bernoulli") << m.out;
}

// Bad model theories: exit 2 naming the file and the key, nothing computed.
TEST(ModelTheory, BadModelTheoryExitsTwoNamingTheKey) {
  const auto r = ringvib("table " + source("scenes/thick-ring.toml") + " --set 'fem.theory=\"shear\"'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("thick-ring.toml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("fem.theory"), std::string::npos) << r.err;
  const auto g = ringvib("table " + source("scenes/thick-ring.toml") +
                         " --set 'ring.section={area = 2e-4, inertia = 6.7e-9}' --set 'ring.theory=\"euler-bernoulli\"' "
                         "--set 'fem.theory=\"timoshenko\"'");
  EXPECT_EQ(g.code, 2) << g.err;
  EXPECT_NE(g.err.find("fem.theory"), std::string::npos) << g.err;
  EXPECT_NE(g.err.find("ring.shear_coefficient"), std::string::npos) << g.err;
}

}  // namespace

namespace {

// A pinned thick ring (depth/R = 0.2, the shipped scene with a pin): the three solvers' Timoshenko
// models converge to the same frequencies, each to the reference of its own kinematics. The
// Timoshenko frame and FE are extensible: against the extensible reference the frame's error
// falls by 4 per halving of its elements (order 2), the FE column (40 cells of degree 4) is within
// its own 1e-6. The chain's rigid segments are inextensible: against the inextensible reference
// (fem.extensible = false) its error falls by 4 per halving too. MAC pairing throughout.
// Measured: frame ratios 3.93-4.32, FE column 6.4e-9, chain ratios 3.64-4.12 (7.1e-4 at n = 160).
TEST(ModelTheory, PinnedThickRingEverySolverConvergesToItsReference) {
  const std::string pin = "--set supports.pin=180 --set modes.count=10 ";
  auto errors = [&](const std::string& sets, const std::string& solver) {
    const nlohmann::json t = table(pin + sets);
    std::vector<double> e;
    for (const auto& row : t["rows"]) {
      EXPECT_GT(row[solver + "_mac"].get<double>(), 0.99) << solver << " " << sets;
      e.push_back(std::abs(row[solver + "_error_pct"].get<double>()) / 100.0);
    }
    return e;
  };
  const std::vector<double> frame80 = errors("--set lumped.n=80", "lumped");
  const std::vector<double> frame160 = errors("--set lumped.n=160", "lumped");
  const std::vector<double> fe = errors("--set lumped.n=80", "fem");
  const std::string chain = "--set 'modes.solvers=[\"multibody\"]' --set table.base='\"multibody\"' "
                            "--set 'table.against=[]' --set fem.extensible=false --set multibody.n=";
  const std::vector<double> chain80 = errors(chain + "80", "multibody");
  const std::vector<double> chain160 = errors(chain + "160", "multibody");
  ASSERT_EQ(frame80.size(), 10u);
  ASSERT_EQ(chain80.size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_NEAR(frame80[i] / frame160[i], 4.0, 0.8) << "frame, mode " << i + 1;
    EXPECT_LT(fe[i], 1e-6) << "FE, mode " << i + 1;
    EXPECT_NEAR(chain80[i] / chain160[i], 4.0, 0.8) << "chain, mode " << i + 1;
    EXPECT_LT(chain160[i], 2e-3) << "chain, mode " << i + 1;
  }
}

}  // namespace
