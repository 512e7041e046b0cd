// The FE beam crushed between rigid plates ([plates]: fem_reference/beam_potential.cpp's penalty
// on the deformed centroid line, static_path.cpp's two no-slide rows) against oracles outside it:
//  - the elastic pinch's closed form P = c / ((pi/4 - 2/pi) R^3 / EI) (Roark's ring case 1,
//    tests/support/plastic_ring.hpp), with the fitted order of the force under mesh refinement;
//  - the same beam's driven pinch (static.displacement at 90 deg on a pin at 270 deg,
//    fem_driven_test's fixture): another formulation of the same squeeze;
//  - DeRuntz & Hodge's rigid–plastic crushing (PinchedPlasticRing::plates_load and
//    plates_contact_length) for the elastic–perfectly plastic ring, the energy identity and
//    elastic unloading.
// The ring: the paper's (R = 10 m, d = 0.12 m, E = 2.1e11 Pa) without supports, the plates
// normal to the vertical diameter (axis 90 deg).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem_reference/nonlinear.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/fibre_ring.hpp"
#include "support/plastic_ring.hpp"
#include "support/refusal.hpp"

namespace {

ring::FemOptions fem_options(int elements, int degree = 3) {
  ring::FemOptions o;
  o.elements = elements;
  o.degree = degree;
  return o;
}

/// The paper's ring without supports, with the resultant law's Mp = mp EI / R (none: elastic).
ring::RingSpec free_plastic_ring(std::optional<double> mp) {
  ring::RingSpec s = ringtest::driven_plastic_ring(mp);
  s.supports = ring::Supports{};
  return s;
}

/// The scene reader's default penalty E A^2 / (12 I) (ring::PlatePair), times `factor`.
double default_stiffness(const ring::RingSpec& s, double factor = 1.0) {
  return factor * s.E * s.A() * s.A() / (12.0 * s.I());
}

/// The plates at 90 and 270 deg approaching by `approach` (m), 90 deg recorded.
ring::StaticOptions crush(const ring::RingSpec& s, double approach, double stiffness_factor, std::vector<double> history = {},
                          int steps = 20) {
  ring::StaticOptions st;
  st.plates = ring::StaticOptions::Plates{90.0, approach, default_stiffness(s, stiffness_factor)};
  st.record = {90.0, 0.0};
  st.history = std::move(history);
  st.steps = steps;
  return st;
}

ringtest::PinchedPlasticRing oracle(const ring::RingSpec& s) {
  return {s.radius, s.EI(), s.plastic ? s.plastic->moment : 0.0};
}

/// The force of the upper plate (at 90 deg, pushing down): minus the reaction's y.
double crushing(const std::array<double, 2>& reaction) { return -reaction[1]; }

fem::StaticPath traced(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::StaticOptions& st) {
  fem::StaticPath p = fem::trace_static(spec, o, st);
  if (!p.reached) throw std::runtime_error("the plates' path did not reach its end: " + p.failure);
  return p;
}

/// The plates' work along a traced path: both plates push with |F| and each moves travel / 2
/// per unit s, so the work is the trapezoid of |F| d(s travel).
double plates_work(const fem::StaticPath& p, double travel) {
  double w = 0.0;
  for (std::size_t k = 1; k < p.points.size(); ++k) {
    const auto &a = p.points[k - 1], &b = p.points[k];
    const double fa = std::hypot(a.reaction[0], a.reaction[1]), fb = std::hypot(b.reaction[0], b.reaction[1]);
    w += 0.5 * (fa + fb) * (b.load_factor - a.load_factor) * travel;
  }
  return w;
}

}  // namespace

// Elastic, c = 1e-3 R, the penalty 1e3 x the default: the upper plate's force converges under
// mesh refinement at the beam's order for a point force's work (2 (p - 1) = 4 at p = 3, as
// FemDriven.ElasticReactionConvergesToTheClosedForm), measured against its own n = 128; that
// limit meets the closed form within the extensible beam's membrane share and c / R.
TEST(FemPlates, ElasticForceConvergesToThePinchClosedForm) {
  const ring::RingSpec spec = free_plastic_ring(std::nullopt);
  const ringtest::PinchedPlasticRing o = oracle(spec);
  const double R = spec.radius, c = 1e-3 * R;
  const double exact = c / o.elastic_closing(1.0);
  auto run = [&](int n) { return traced(spec, fem_options(n), crush(spec, c, 1e3, {}, 4)); };
  const fem::StaticPath finest = run(128);
  const auto& end = finest.points.back();
  const double P = crushing(end.reaction);
  const std::vector<int> ns = {8, 12, 16, 24, 32};
  std::vector<double> errors;
  for (int n : ns) {
    const fem::StaticPath p = run(n);
    errors.push_back(ringtest::rel(crushing(p.points.back().reaction), P));
    std::printf("n = %3d: P = %.12e N, against n = 128: %.3e\n", n, crushing(p.points.back().reaction), errors.back());
  }
  const ringtest::Order fit = ringtest::fit_order(ringtest::in_n(ns, errors));
  // The plates' sinking: the plate's travel c / 2 less the vertex's displacement at 90 deg.
  const double sinking = 0.5 * c + end.displacement[1];
  std::printf("fitted order %.3f +- %.3f, finest %.3e; n = 128: P = %.12e N against the closed form %.12e: %.3e; "
              "sinking %.3e of c; x force %.3e N; no-slide multipliers %.3e %.3e N; contact lengths %.3e %.3e m\n",
              fit.order, fit.standard_error, fit.finest_error, P, exact, ringtest::rel(P, exact), sinking / c,
              end.reaction[0], end.no_slide[0], end.no_slide[1], end.contact_length[0], end.contact_length[1]);
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, errors), 4.0, 0.2, 1e-4));
  EXPECT_TRUE(ringtest::IsClose(P, exact, 2e-3));
  EXPECT_LT(std::abs(sinking), 1e-6 * c);
  EXPECT_NEAR(end.reaction[0], 0.0, 1e-9 * P);
  EXPECT_NEAR(end.no_slide[0], 0.0, 1e-9 * P);
  EXPECT_NEAR(end.no_slide[1], 0.0, 1e-9 * P);
  EXPECT_NEAR(end.opposite[0], -end.reaction[0], 1e-9 * P);
  EXPECT_NEAR(end.opposite[1], -end.reaction[1], 1e-9 * P);
}
