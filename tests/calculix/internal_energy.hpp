// ccx's own energy balance for the CalculiX suites that check the work of a drive against it:
// the deck run with the ring's total internal energy printed at every increment.
#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "calculix/ccx.hpp"
#include "calculix/dat.hpp"
#include "calculix/deck.hpp"

namespace ccxtest {

struct EnergyRun {
  calculix::DatStatic dat;
  std::vector<double> energy;  ///< J, ccx's total internal energy of the ring, one per increment
};

/// Runs `deck` (a static deck of the ring of `nodes` nodes) with "*EL PRINT, TOTALS=ONLY ELSE"
/// on the ring's elements added to its last step, and reads back the increments and energies.
inline EnergyRun run_with_internal_energy(std::string deck, const ring::CalculixOptions& o, int nodes) {
  const auto end = deck.rfind("*END STEP");
  EXPECT_NE(end, std::string::npos);
  deck.insert(end, "*EL PRINT, ELSET=ERING, TOTALS=ONLY\nELSE\n");
  const calculix::RunOutput out = calculix::run(deck, {o.timeout, o.threads});
  EnergyRun r{calculix::read_static_dat(out.dat, nodes), {}};
  std::istringstream in(out.dat);
  for (std::string line; std::getline(in, line);)
    if (line.find("total internal energy") != std::string::npos) {
      double e = NAN;
      in >> e;
      r.energy.push_back(e);
    }
  return r;
}

}  // namespace ccxtest
