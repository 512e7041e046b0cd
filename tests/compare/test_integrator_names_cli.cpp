// One meaning per integrator name, through the binary. "energy-momentum" names only a
// scheme that conserves the undamped energy balance (the multibody chain's discrete
// gradient); the lumped chain's implicit midpoint rule does not, so it is offered as
// "midpoint" and a request for "energy-momentum" is refused with exit 2, naming the
// scene file, the key and "midpoint". A solver without a midpoint rule refuses "midpoint".
// Oracles: the contract of docs/scenes.md (response.integrator) and docs/commands.md ("Exit codes") and the energy
// balance T + V - W of each history, which says whether a scheme conserves energy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"

using ringtest::ringvib;
using ringtest::source;

namespace {

const std::string kForced = "scenes/paper1990-forced.toml";

void expect_refusal(const ringtest::Run& r, const std::vector<std::string>& names) {
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;  // nothing computed, nothing written
  for (const auto& name : names) EXPECT_NE(r.err.find(name), std::string::npos) << "does not name " << name << ": " << r.err;
}

/// max |energy_error| / max |work| of the response CSV that `respond` prints.
double balance_error(const std::string& csv) {
  std::istringstream in(csv);
  std::string header;
  std::getline(in, header);
  std::vector<std::string> names;
  std::stringstream hs(header);
  for (std::string f; std::getline(hs, f, ',');) names.push_back(f);
  const auto column = [&](const std::string& n) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin());
  };
  const std::size_t ie = column("energy_error"), iw = column("work");
  EXPECT_LT(ie, names.size()) << header;
  EXPECT_LT(iw, names.size()) << header;
  double worst = 0.0, work = 0.0;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');) row.push_back(std::strtod(f.c_str(), nullptr));
    if (row.size() != names.size()) continue;
    worst = std::max(worst, std::abs(row[ie]));
    work = std::max(work, std::abs(row[iw]));
  }
  return work > 0 ? worst / work : HUGE_VAL;
}

TEST(IntegratorNames, LumpedChainRefusesEnergyMomentumAndNamesMidpoint) {
  const auto r = ringvib("respond " + source(kForced) + " --solver lumped --set response.integrator=energy-momentum");
  expect_refusal(r, {"paper1990-forced.toml", "response.integrator", "energy-momentum", "\"midpoint\""});
  // The same through `run`, which checks every solver the scene lists before any runs.
  const auto run = ringvib("run " + source(kForced) + " --set 'response.solvers=[\"lumped\"]' "
                           "--set response.integrator=energy-momentum");
  expect_refusal(run, {"response.integrator", "\"midpoint\""});
}

TEST(IntegratorNames, LumpedChainRunsMidpointAndItDoesNotConserveEnergy) {
  const std::string sets = " --solver lumped --set response.t_end=1.0 --set response.integrator=";
  const auto midpoint = ringvib("respond " + source(kForced) + sets + "midpoint");
  ASSERT_EQ(midpoint.code, 0) << midpoint.err;
  // "newmark" runs the same scheme on the chain (docs/scenes.md, response.integrator): the same
  // history, digit for digit.
  const auto newmark = ringvib("respond " + source(kForced) + sets + "newmark");
  ASSERT_EQ(newmark.code, 0) << newmark.err;
  EXPECT_EQ(midpoint.out, newmark.out);
  // Why it is not called energy-momentum: the midpoint rule's O(dt^2) error on the
  // non-quadratic springs leaves T + V - W off by ~1e-7 of the work at dt = 0.01 s
  // (lumped_mass/nonlinear.hpp); round-off alone would be ~1e-13.
  EXPECT_GT(balance_error(midpoint.out), 1e-10);
}

TEST(IntegratorNames, EnergyMomentumConservesWhereItIsOffered) {
  // The multibody chain's discrete gradient: the balance to the Newton tolerance for any
  // dt (docs/measured.md, "1000 steps, every integrator": 3.2e-13 of the work at n = 10^4);
  // 1e-9 leaves room for n = 40.
  const auto r = ringvib("respond " + source(kForced) +
                         " --solver multibody --set response.t_end=1.0 --set response.integrator=energy-momentum");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_LT(balance_error(r.out), 1e-9);
}

TEST(IntegratorNames, SolversWithoutAMidpointRuleRefuseIt) {
  expect_refusal(ringvib("respond " + source(kForced) + " --solver multibody --set response.integrator=midpoint"),
                 {"paper1990-forced.toml", "response.integrator", "\"midpoint\"", "energy-momentum"});
  expect_refusal(ringvib("respond " + source(kForced) + " --solver fem --set response.integrator=midpoint"),
                 {"paper1990-forced.toml", "response.integrator", "\"midpoint\"", "generalized-alpha"});
}

TEST(IntegratorNames, UnknownIntegratorListsMidpoint) {
  expect_refusal(ringvib("respond " + source(kForced) + " --solver lumped --set response.integrator=leapfrog"),
                 {"response.integrator", "\"midpoint\"", "leapfrog"});
}

}  // namespace
