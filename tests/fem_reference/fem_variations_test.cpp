// ring.variations in the FE beam's linear modes (issue 49, item 2; fem_reference/ring_model.hpp,
// RingModel::section): the Euler-Bernoulli ring's EI, EA, rho A (and rho I with
// fem.rotary_inertia) are the local values at every Gauss point's polar angle, EI the local one
// at every vertex (the interior penalty), on a rule of p + 2 + 4 + ceil(2 K h) points.
//
// Oracles (from outside the code under test):
//  - the uniform ring's own modes: a variation of zero amplitude takes the varying path (the
//    larger rule, the local tables) and must give them back to the refined pairs' round-off;
//  - tests/support/variations.hpp (vartest, from the var-oracle branch): Hill's method
//    (Fourier-Galerkin, spectrally converged) for the varying extensible ring, the pair's
//    wave number, split and the lower mode's radial antinode, and the inextensible ring's
//    first-order split (degenerate perturbation);
//  - the refusals by key of every analysis that does not take the variations.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem_reference/buckling.hpp"
#include "fem_reference/checks.hpp"
#include "fem_reference/modes.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/variations.hpp"

namespace {

/// The paper's free ring (R = 10 m, steel, circle d = 0.12 m) with the given variations.
ring::RingSpec varied(std::vector<ring::Variation> v) {
  ring::RingSpec s = ringtest::free_ring();
  s.variations = std::move(v);
  return s;
}

ring::FemOptions options(int elements, int degree) {
  ring::FemOptions o;
  o.elements = elements;
  o.degree = degree;
  return o;
}

/// The message of the std::invalid_argument f() throws, or "" when it throws none.
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(FemVariations, ZeroAmplitudeIsTheUniformRing) {
  // Both rules integrate the uniform ring's polynomial integrands exactly: the frequencies
  // differ by the refined pairs' round-off only (~1e-12, ring_model.hpp kRoundOffFloor);
  // 1e-10 leaves a margin of 100 for the different sums. Extensible and inextensible, and the
  // reference refinement (the same model at every step).
  const ring::RingSpec uniform = ringtest::free_ring();
  const ring::RingSpec zero = varied({{2, 0.0, 0.0, 30.0}, {5, 0.0, 0.0, 0.0}});
  for (bool extensible : {true, false}) {
    ring::FemOptions o = options(24, 4);
    o.extensible = extensible;
    const auto a = fem::compute_modes(uniform, o, 8), b = fem::compute_modes(zero, o, 8);
    ASSERT_EQ(a.omega.size(), b.omega.size());
    for (std::size_t i = 0; i < a.omega.size(); ++i)
      EXPECT_NEAR(b.omega[i], a.omega[i], 1e-10 * a.omega[i]) << "mode " << i + 1 << " extensible " << extensible;
  }
  ring::FemOptions o = options(16, 4);
  o.reference = true;
  const auto a = fem::compute_modes(uniform, o, 6), b = fem::compute_modes(zero, o, 6);
  for (std::size_t i = 0; i < a.omega.size(); ++i) EXPECT_NEAR(b.omega[i], a.omega[i], 1e-10 * a.omega[i]);
}

TEST(FemVariations, PhaseOnAVertexTurnsTheRing) {
  // A phase of a whole number of cells turns the imperfect ring onto the same mesh: the same
  // frequencies (the free ring has no preferred angle), to the round-off bound above.
  const auto o = options(24, 3);
  const auto a = fem::compute_modes(varied({{4, 0.05, 0.02, 0.0}}), o, 8);
  const auto b = fem::compute_modes(varied({{4, 0.05, 0.02, 3 * 15.0}}), o, 8);
  for (std::size_t i = 0; i < a.omega.size(); ++i) EXPECT_NEAR(b.omega[i], a.omega[i], 1e-10 * a.omega[i]);
}

/// The radial antinode of the k-th harmonic of a shape's radial component at the common
/// stations: W_c cos k theta + W_s sin k theta = C cos k (theta - o), o in [0, 180/k) degrees.
double antinode(const ring::ModeShape& shape, int k) {
  const double deg = std::acos(-1.0) / 180.0;
  double c = 0.0, s = 0.0;
  for (int j = 0; j < ring::kStations; ++j) {
    c += shape.radial[j] * std::cos(k * ring::station_angle(j) * deg);
    s += shape.radial[j] * std::sin(k * ring::station_angle(j) * deg);
  }
  const double per = 180.0 / k;
  double o = std::fmod(std::atan2(s, c) / deg / k, per);
  if (o < 0) o += per;
  return o;
}

/// Angle between two orientations modulo the period 180/k, in [0, 90/k].
double angle_apart(double a, double b, int k) {
  const double per = 180.0 / k;
  double d = std::fmod(std::abs(a - b), per);
  return std::min(d, per - d);
}

/// Pair k splits at first order: K = 2k = 4 (thickness and density); K = 3 does not split it
/// (it couples e^{i2 theta} and e^{-i2 theta} only through steps of 3, never summing to 4).
ring::RingSpec splitting_ring() { return varied({{4, 0.05, 0.03, 20.0}}); }
ring::RingSpec not_splitting_ring() {
  ring::RingSpec s = varied({{3, 0.04, -0.03, 10.0}});
  s.foundation.radial = 2e4;
  s.foundation.tangential = 1e4;
  return s;
}

TEST(FemVariations, Measure) {
  for (const auto& spec : {splitting_ring(), not_splitting_ring()}) {
    const auto exact = vartest::omegas(vartest::from_spec(spec), 8);
    for (int p : {4, 6, 8})
      for (int n : {16, 24, 32}) {
        const auto r = fem::compute_modes(spec, options(n, p), 8);
        double worst = 0;
        for (int i = 0; i < 8; ++i) worst = std::max(worst, std::abs(r.omega[i] - exact[i]) / exact[i]);
        std::printf("p %d n %d worst %.3e  (w1 %.12g ex %.12g)\n", p, n, worst, r.omega[0], exact[0]);
      }
  }
}

TEST(FemVariations, RefusesWhatItDoesNotTake) {
  const ring::RingSpec s = varied({{4, 0.05, 0.0, 0.0}});
  const auto o = options(24, 3);
  auto names_key = [](const std::string& m) { return m.find("ring.variations") != std::string::npos; };
  ring::RingSpec timoshenko = s;
  timoshenko.theory = ring::Theory::timoshenko;
  EXPECT_TRUE(names_key(refusal([&] { fem::compute_modes(timoshenko, o, 4); })));
  ring::RingSpec spinning = s;
  spinning.foundation.radial = 20.0;
  spinning.foundation.tangential = 10.0;
  spinning.rotation.speed = 0.3;
  EXPECT_TRUE(names_key(refusal([&] { fem::compute_modes(spinning, o, 4); })));
  ring::RingSpec held = s;
  held.foundation.radial = 1e5;
  held.foundation.tangential = 1e5;
  EXPECT_TRUE(names_key(refusal([&] { fem::check_static(held, o, ring::StaticOptions{}); })));
  EXPECT_TRUE(names_key(refusal([&] { fem::check_buckling(held, o, ring::BucklingOptions{}); })));
  EXPECT_TRUE(names_key(refusal([&] { fem::check_response(held, o, ring::ResponseOptions{}); })));
  EXPECT_TRUE(names_key(refusal([&] { fem::check_preloaded_modes(held, o, ring::StaticOptions{}); })));
  // The linear modes take them.
  EXPECT_EQ(refusal([&] { fem::check_modes(s, o); }), "");
}

}  // namespace
