// The FE beam's statics past the critical pressure end at the bifurcation (the continuation
// driver's test, paths/continuation.hpp, with the tangent's inertia on the free unknowns,
// fem_reference/static_path.cpp), as the multibody chain's do
// (tests/multibody/test_buckling.cpp).
//
// Oracle: the FE's own linear buckling (fem::compute_buckling) on the same discretization,
// the paper's ring on a pin at 270 deg and a roller at 90 deg under 1.5 lambda_1 of each
// kind of pressure: the bracket must hold 1 / 1.5. Linear buckling linearizes about rest,
// while the extensible beam's path compresses (hoop strain p R / EA) before it buckles; the
// critical factor of the path differs from lambda_1 by O(p R / EA) = O(I / (A R^2))
// relative (measured below; the same order as the extensible factors' distance from the
// inextensible closed forms, 9e-6, fem_reference/buckling.hpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "fem_reference/buckling.hpp"
#include "fem_reference/nonlinear.hpp"
#include "ring/errors.hpp"
#include "support/paper.hpp"
#include "support/bracket.hpp"

namespace {

using Kind = ring::Pressure::Kind;

const char* name(Kind k) { return k == Kind::follower ? "follower" : k == Kind::central ? "central" : "dead"; }

ring::FemOptions fem_options() {
  ring::FemOptions o;
  o.elements = 16;
  o.degree = 4;
  o.extensible = true;
  return o;
}

// Each kind at 1.5 lambda_1: a NumericalError whose bracket, under 1e-6 wide, holds 1 / 1.5
// to the pre-buckling compression's 1e-4 (measured offsets: docs/measured.md, "fem_reference:
// bifurcations and the path to contact").
TEST(FemBifurcation, StaticsPastTheCriticalPressureEndAtTheBifurcation) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::FemOptions o = fem_options();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    ring::BucklingOptions b;
    b.loads.pressure = {1.0, kind};
    b.count = 1;
    const double critical = fem::compute_buckling(spec, o, b).factors[0];
    ring::StaticOptions st;
    st.loads.pressure = {1.5 * critical, kind};
    SCOPED_TRACE(name(kind));
    try {
      fem::solve_static(spec, o, st);
      ADD_FAILURE() << "no bifurcation reported";
    } catch (const ring::NumericalError& e) {
      const std::string m = e.what();
      const auto bracket = ringtest::bifurcation_bracket(m);
      ASSERT_TRUE(bracket) << m;
      const auto [low, high] = *bracket;
      std::printf("%s: bracket [%.10f, %.10f], offset of 1/1.5 from its middle %.3e (relative)\n", name(kind), low,
                  high, (0.5 * (low + high) - 1.0 / 1.5) * 1.5);
      EXPECT_LE(low, 1.0 / 1.5 + 1e-4) << m;
      EXPECT_GE(high, 1.0 / 1.5 - 1e-4) << m;
      EXPECT_LT(high - low, 1e-6) << m;
    }
  }
}

// Below the critical pressure the path reaches the full load.
TEST(FemBifurcation, BelowTheCriticalPressureThePathReachesTheFullLoad) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const ring::FemOptions o = fem_options();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    ring::BucklingOptions b;
    b.loads.pressure = {1.0, kind};
    b.count = 1;
    ring::StaticOptions st;
    st.loads.pressure = {0.9 * fem::compute_buckling(spec, o, b).factors[0], kind};
    st.record = {0.0};
    EXPECT_NO_THROW(fem::solve_static(spec, o, st)) << name(kind);
  }
}

}  // namespace
