// compare/spin.hpp on a spinning ring's result built from the inextensible closed form
// (tests/support/spinning_ring.hpp): the wave pairs, Bryan's factor and the fixed frame.
#include <gtest/gtest.h>

#include "compare/spin.hpp"
#include "support/spinning_ring.hpp"

namespace {

// The paper's ring on a foundation, spinning at `speed`: waves k = 2, 3 in the turning frame.
ring::ModalResult turning(const spintest::Ring& ring) {
  ring::ModalResult r;
  r.solver = "oracle";
  r.frame = "rotating";
  for (int k : {2, 3}) {
    const spintest::WavePair p = spintest::inextensible(ring, k);
    r.omega.push_back(p.forward), r.waves.push_back({k, 1});
    r.omega.push_back(p.backward), r.waves.push_back({k, -1});
  }
  r.shapes.resize(r.omega.size());
  return r;
}

spintest::Ring tyre(double speed) {
  spintest::Ring r;
  r.radius = 0.3;
  r.EI = 2.0e10 * 0.15 * 0.008 * 0.008 * 0.008 / 12.0;
  r.rhoA = 1600.0 * 0.15 * 0.008;
  r.kr = 1.0e6, r.kt = 3.0e5;
  r.speed = speed;
  r.tension = false;
  return r;
}

TEST(SpinPairs, BryansFactorOfTheInextensibleRing) {
  const spintest::Ring ring = tyre(50.0);
  const auto pairs = cmp::spin_pairs(turning(ring), ring.speed);
  ASSERT_EQ(pairs.size(), 2u);
  for (const auto& p : pairs)  // exact in the closed form: round-off of its square root only
    EXPECT_NEAR(p.bryan, spintest::bryan_inextensible(p.wave), 1e-12) << p.wave;
  EXPECT_NEAR(pairs[0].forward_fixed, spintest::inextensible(ring, 2).forward_fixed, 1e-12);
}

TEST(SpinPairs, TheFixedFrameResortsAndFlipsABackwardWavePastItsCriticalSpeed) {
  // Without the spin's tension the tyre's backward k = 3 wave stands still in space near
  // 390 rad/s (closed form); at 450 rad/s the spin carries it forward.
  const spintest::Ring ring = tyre(450.0);
  ASSERT_LT(spintest::inextensible(ring, 3).backward_fixed, 0.0);
  ring::ModalResult r = turning(ring);
  cmp::finish_spin(r, ring.speed, true);
  EXPECT_EQ(r.frame, "fixed");
  ASSERT_EQ(r.spin_pairs.size(), 2u);
  for (std::size_t i = 1; i < r.omega.size(); ++i) EXPECT_LE(r.omega[i - 1], r.omega[i]);
  bool flipped = false;
  for (std::size_t i = 0; i < r.omega.size(); ++i)
    if (r.waves[i].number == 3 && std::abs(r.omega[i] + spintest::inextensible(ring, 3).backward_fixed) < 1e-9) {
      EXPECT_EQ(r.waves[i].direction, 1);  // travels with the spin in space
      flipped = true;
    }
  EXPECT_TRUE(flipped);
}

TEST(SpinPairs, AResultWithoutWavesCannotBeShownInTheFixedFrame) {
  ring::ModalResult r;
  r.solver = "calculix";
  r.omega = {1.0, 2.0};
  EXPECT_THROW(cmp::finish_spin(r, 10.0, true), std::invalid_argument);
  cmp::finish_spin(r, 10.0, false);
  EXPECT_EQ(r.frame, "rotating");
  EXPECT_TRUE(r.spin_pairs.empty());
}

}  // namespace
