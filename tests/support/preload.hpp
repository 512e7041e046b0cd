// Frequencies under load against a closed form, for the tests of every solver: the free
// thin ring on a Winkler foundation (k_r = 4, k_t = 1 EI/R^4: it holds every rigid motion)
// under a uniform follower pressure, whose circle stays the equilibrium and whose omega_k^2
// falls linearly in p (ring::closed_form::ring_on_foundation_inextensional).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ring/analysis.hpp"
#include "ring/closed_form.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"
#include "support/paper.hpp"

namespace ringtest {

/// The paper's ring, free, on the foundation above.
inline ring::RingSpec ring_on_foundation() {
  ring::RingSpec s = free_ring();
  const double unit = s.EI() / std::pow(s.radius, 4);
  s.foundation.radial = 4.0 * unit;
  s.foundation.tangential = 1.0 * unit;
  return s;
}

/// `modes(spec, statics, count)` (a solver's compute_modes_under_load) at 1/4 and 1/2 of the
/// n = 2 pair's critical pressure: the five lowest omega (the rotation k = 0, the
/// translations k = 1, the ovals k = 2, ascending while p < 0.6 of it) within `rel` of the
/// closed form, the k = 0 and 1 untouched by the pressure, and the k = 2 pair's omega^2 falling
/// with the closed form's slope -k^2 (k^2 - 1) / (R rho A (k^2 + 1)) within `slope_rel`.
template <class Modes>
void expect_the_closed_form_under_pressure(Modes modes, double rel, double slope_rel) {
  const ring::RingSpec spec = ring_on_foundation();
  const double critical = (36.0 + 16.0 + 1.0) / 12.0 * spec.EI() / std::pow(spec.radius, 3);  // k = 2
  ASSERT_NEAR(ring::closed_form::ring_on_foundation_inextensional(spec, 2, 0.999 * critical) /
                  ring::closed_form::ring_on_foundation_inextensional(spec, 2),
              std::sqrt(1e-3), 1e-9);  // the closed form's own zero
  double w2[2] = {0.0, 0.0};
  for (int i = 0; i < 2; ++i) {
    const double p = (i + 1) * 0.25 * critical;
    ring::StaticOptions st;
    st.loads.pressure = {p, ring::Pressure::Kind::follower};
    const ring::ModalResult r = modes(spec, st, 5);
    ASSERT_EQ(r.omega.size(), 5u);
    const int wave[5] = {0, 1, 1, 2, 2};
    for (int m = 0; m < 5; ++m) {
      const double exact = ring::closed_form::ring_on_foundation_inextensional(spec, wave[m], p);
      std::printf("p = %.2f p_cr: mode %d (k = %d) omega %.9g, closed form %.9g, %.2e\n", (i + 1) * 0.25, m + 1,
                  wave[m], r.omega[m], exact, r.omega[m] / exact - 1.0);
      EXPECT_NEAR(r.omega[m] / exact, 1.0, rel) << "mode " << m + 1 << " at " << (i + 1) * 0.25 << " p_cr";
    }
    w2[i] = r.omega[3] * r.omega[3];
  }
  const double slope = (w2[1] - w2[0]) / (0.25 * critical);
  const double exact = -4.0 * 3.0 / (spec.radius * spec.rhoA() * 5.0);
  std::printf("slope of omega_2^2 against p: %.9g, closed form %.9g, %.2e\n", slope, exact, slope / exact - 1.0);
  EXPECT_NEAR(slope / exact, 1.0, slope_rel);
}

}  // namespace ringtest
