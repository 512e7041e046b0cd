// The chain's statics past the critical pressure end at the bifurcation (the continuation
// driver's test, paths/continuation.hpp, with the chain's count of unstable directions,
// lumped_mass/stability.hpp), as the multibody chain's do (tests/multibody/test_buckling.cpp).
//
// Oracles: the chain's own linear buckling (lumped::compute_buckling: on the perfect ring the
// pre-buckling path is circular, a uniform pressure does no work on the inextensible chain,
// so its equilibria turn unstable exactly at lambda_1, and the bracket must hold
// lambda_1 / 1.5 when the load is 1.5 lambda_1); the dense count (the eigenvalues of Z^T T Z)
// for the frontal count (Sylvester on the KKT matrix), which are two algorithms for one
// number.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "common.hpp"
#include "lumped_mass/buckling.hpp"
#include "lumped_mass/chain.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "lumped_mass/stability.hpp"
#include "ring/errors.hpp"
#include "support/bracket.hpp"
#include "support/paper.hpp"

namespace {

using Kind = ring::Pressure::Kind;
using lumped::InertiaRoute;

const char* name(Kind k) { return k == Kind::follower ? "follower" : k == Kind::central ? "central" : "dead"; }

double critical(const ring::RingSpec& spec, int n, Kind kind) {
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, kind};
  b.count = 1;
  return lumped::compute_buckling(spec, lumptest::options(n, lumptest::kChain), b).factors[0];
}

/// The bracket "between load factors A and B" of the statics' NumericalError at 1.5
/// lambda_1 holds 1 / 1.5 to `slack`.
void expect_bracket(const ring::RingSpec& spec, int n, Kind kind, InertiaRoute route, double slack) {
  ring::StaticOptions st;
  st.loads.pressure = {1.5 * critical(spec, n, kind), kind};
  SCOPED_TRACE(std::string(name(kind)) + (route == InertiaRoute::frontal ? ", frontal" : ", dense"));
  try {
    lumped::solve_static_detail(spec, lumptest::options(n, lumptest::kChain), st, route);
    ADD_FAILURE() << "no bifurcation reported";
  } catch (const ring::NumericalError& e) {
    const std::string m = e.what();
    const auto bracket = ringtest::bifurcation_bracket(m);
    ASSERT_TRUE(bracket) << m;
    const auto [low, high] = *bracket;
    EXPECT_LE(low, 1.0 / 1.5 + slack) << m;
    EXPECT_GE(high, 1.0 / 1.5 - slack) << m;
    EXPECT_LT(high - low, 1e-6) << m;
  }
}

// The paper's ring on a pin and a roller, n = 40 (the dense count), each kind of pressure:
// the path stops at the bifurcation, in a bracket under 1e-6 wide that holds 1 / 1.5 to
// 1e-9 (the multibody chain's test).
TEST(LumpedBifurcation, StaticsPastTheCriticalPressureEndAtTheBifurcation) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central})
    expect_bracket(spec, 40, kind, InertiaRoute::automatic, 1e-9);
}

// The same with the frontal count forced: its resolution near the critical load is coarser
// (stability.hpp: the follower pair's count flips within 3e-8 of lambda_1 at n = 40,
// measured), so 1 / 1.5 is held to 1e-7.
TEST(LumpedBifurcation, FrontalCountEndsTheStaticsAtTheBifurcationToo) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central})
    expect_bracket(spec, 40, kind, InertiaRoute::frontal, 1e-7);
}

// Above kMaxInertiaHinges the count is not given (rounding decides it: stability.hpp), so
// the statics do not stop at a bifurcation that may be noise.
TEST(LumpedBifurcation, NoCountAboveTheLimit) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  const int n = lumped::kMaxInertiaHinges + 2;
  const lumped::Chain c = lumped::make_chain(spec, lumptest::options(n, lumptest::kChain));
  ring::Loads loads;
  loads.pressure = {1.0, Kind::follower};
  const lumped::ChainLoads L(loads, c.rest, c.l, lumped::mass_matrix(c), {});
  EXPECT_FALSE(lumped::unstable_directions(c, L, c.rest, Eigen::VectorXd::Zero(c.rows()), 0.0, 1.0,
                                           InertiaRoute::automatic));
}

// Below the critical pressure the path reaches the full load (circular, no bifurcation).
TEST(LumpedBifurcation, BelowTheCriticalPressureThePathReachesTheFullLoad) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
    ring::StaticOptions st;
    st.loads.pressure = {0.9 * critical(spec, 40, kind), kind};
    st.record = {0.0};
    EXPECT_NO_THROW(lumped::solve_static(spec, lumptest::options(40, lumptest::kChain), st)) << name(kind);
  }
}

// The two counts on the circular equilibria of the polygon under each kind of pressure at
// s lambda_1 for s from 0 to 3.5 (lambda from G^T lambda = -s grad P, exact for the uniform
// pressure on the regular polygon), and on the same states with the hinges moved by up to
// 1e-3 l at random (fixed seed; not equilibria, but the count is defined for any state):
// equal, and the count rises past s = 1 (so that the comparison is not of zeros only).
TEST(LumpedBifurcation, FrontalCountAgreesWithTheDenseEigenvalues) {
  const ring::RingSpec spec = ringtest::pin_270_roller_90();
  std::srand(7);
  for (int n : {40, 300})
    for (Kind kind : {Kind::follower, Kind::dead, Kind::central}) {
      const ring::LumpedOptions o = lumptest::options(n, lumptest::kChain);
      const lumped::Chain c = lumped::make_chain(spec, o);
      ring::Loads loads;
      loads.pressure = {critical(spec, n, kind), kind};
      const lumped::ChainLoads L(loads, c.rest, c.l, lumped::mass_matrix(c), {});
      lumped::Triplets g;
      lumped::jacobian(c, c.rest, 0, 1.0, true, g);
      Eigen::SparseMatrix<double> GT(2 * n, c.rows());
      GT.setFromTriplets(g.begin(), g.end());
      const Eigen::MatrixXd GTd(GT);
      const Eigen::VectorXd unit = GTd.colPivHouseholderQr().solve(-L.gradient(c.rest));
      const double scale = spec.EI() / (c.l * c.l * c.l);
      int most = 0;
      for (double s : {0.0, 0.5, 0.9, 1.1, 2.0, 3.5})
        for (double jiggle : {0.0, 1e-3 * c.l}) {
          const Eigen::VectorXd x = c.rest + jiggle * Eigen::VectorXd::Random(2 * n);
          const auto dense = lumped::unstable_directions(c, L, x, s * unit, s, scale, InertiaRoute::dense);
          const auto frontal = lumped::unstable_directions(c, L, x, s * unit, s, scale, InertiaRoute::frontal);
          ASSERT_TRUE(dense && frontal);
          EXPECT_EQ(*frontal, *dense) << name(kind) << ", n = " << n << ", s = " << s << ", jiggle " << jiggle;
          if (s < 1.0 && jiggle == 0.0) {
            EXPECT_EQ(*dense, 0) << name(kind) << ", n = " << n << ", s = " << s;
          }
          most = std::max(most, *dense);
        }
      EXPECT_GE(most, 2) << name(kind) << ", n = " << n;
    }
}

}  // namespace
