// ring.variations on the chain's dense linear modes at rest (multibody/linear_model.hpp,
// LocalChain: segment masses rho A at the midpoints, hinge springs EI at the hinges). Oracles:
// the uniform chain itself (a variation of zero amplitude is the same discrete model, to
// round-off); a first-order split derived here; the inextensible Hill oracle of
// tests/support/variations.hpp (the chain is inextensible: it converges to that ring at order 2
// in 1/n), its first- and second-order splits; the refusals by key of what does not take it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "multibody/backend.hpp"
#include "multibody/modes.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "support/variations.hpp"
#include "tests/multibody/common.hpp"

namespace {

using Method = ring::MultibodyOptions::Method;

/// `spec` with one harmonic of the given amplitudes.
ring::RingSpec varied(ring::RingSpec spec, int harmonic, double thickness, double density, double phase = 0.0) {
  spec.variations.push_back({harmonic, thickness, density, phase});
  return spec;
}

/// Throws std::invalid_argument whose message names ring.variations.
template <class F>
void expect_refused(F&& f, const std::string& what) {
  try {
    f();
    ADD_FAILURE() << what << ": not refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ring.variations"), std::string::npos) << what << ": " << e.what();
  }
}

// A variation of zero amplitude makes every local mass and spring the uniform one, so the
// local assembly (LocalChain::rest_mass_matrix, the per-hinge springs, split_hinges with
// K(hinge)) must reproduce the chain's own to round-off: 1e-12 relative is ~100 eps on
// frequencies whose eigensolver is accurate to ~1e-14 (modes.hpp). Every support kind the
// dense path takes, with the point inertia (split hinge) and a rotational spring (condensed).
TEST(MultibodyVariations, ZeroAmplitudeIsTheUniformChain) {
  std::vector<std::pair<std::string, ring::RingSpec>> rings;
  rings.emplace_back("free", ringtest::free_ring());
  rings.emplace_back("pinned", ringtest::pinned_ring(180.0));
  rings.emplace_back("pin and roller", ringtest::pin_roller_ring());
  rings.emplace_back("foundation", mbtest::on_foundation());
  {
    ring::RingSpec s = ringtest::pinned_ring(180.0);
    s.masses = {{90.0, 50.0, 2.0}};
    s.supports.springs = {{0.0, 1e5, 0.0, 3e5}};
    rings.emplace_back("masses and springs", s);
  }
  for (const auto& [name, spec] : rings)
    for (bool rotary : {true, false})
      for (auto dependent : {ring::MultibodyOptions::Dependent::robust, ring::MultibodyOptions::Dependent::paper}) {
        if (dependent == ring::MultibodyOptions::Dependent::paper && !spec.supports.paper_only()) continue;
        ring::MultibodyOptions o = mbtest::dense_chain(40);
        o.rotary_inertia = rotary;
        o.dependent = dependent;
        const ring::ModalResult a = multibody::compute_modes(spec, o, 10);
        const ring::ModalResult b = multibody::compute_modes(varied(spec, 3, 0.0, 0.0, 17.0), o, 10);
        ASSERT_EQ(a.omega.size(), b.omega.size());
        for (std::size_t k = 0; k < a.omega.size(); ++k)
          EXPECT_NEAR(b.omega[k], a.omega[k], 1e-12 * a.omega[k]) << name << " rotary " << rotary << " mode " << k;
      }
}

// A uniform scaling is a variation too: the density scaled by 1 + d everywhere is not a
// harmonic, but the chain is linear in its masses, so two harmonics K and the same K with
// phase 180/K (cos(K(t - 180/K)) = -cos(K t)) of equal density amplitude cancel exactly and
// give the uniform chain (same tolerance as above).
TEST(MultibodyVariations, OpposedHarmonicsCancel) {
  ring::RingSpec spec = varied(ringtest::free_ring(), 4, 0.0, 0.3);
  spec.variations.push_back({4, 0.0, -0.3, 0.0});
  const ring::MultibodyOptions o = mbtest::dense_chain(40);
  const ring::ModalResult a = multibody::compute_modes(ringtest::free_ring(), o, 8);
  const ring::ModalResult b = multibody::compute_modes(spec, o, 8);
  for (std::size_t k = 0; k < a.omega.size(); ++k) EXPECT_NEAR(b.omega[k], a.omega[k], 1e-12 * a.omega[k]);
}

// dependent = "paper" is another basis of the same null space: on a varying pinned ring (pin
// and roller, the paper's supports) it gives the robust basis's frequencies. Tolerance 1e-9
// relative: the paper's block J_2 has condition cot(pi/n) ~ 13 at n = 40 (linear_model.hpp), so
// its rounding is a few hundred eps of the robust path's.
TEST(MultibodyVariations, PaperDependentAnglesAgree) {
  const ring::RingSpec spec = varied(ringtest::pin_roller_ring(), 4, 0.1, 0.05, 30.0);
  ring::MultibodyOptions paper = mbtest::dense_chain(40);
  paper.dependent = ring::MultibodyOptions::Dependent::paper;
  const ring::ModalResult a = multibody::compute_modes(spec, mbtest::dense_chain(40), 8);
  const ring::ModalResult b = multibody::compute_modes(spec, paper, 8);
  for (std::size_t k = 0; k < a.omega.size(); ++k) EXPECT_NEAR(b.omega[k], a.omega[k], 1e-9 * a.omega[k]) << k;
}

// What does not take ring.variations refuses by its key: the O(n) modes (method = sparse),
// the spinning modes, the Timoshenko chain; "auto" stays dense where it would go sparse.
TEST(MultibodyVariations, RefusedByKey) {
  const ring::RingSpec spec = varied(ringtest::free_ring(), 2, 0.05, 0.02);
  expect_refused([&] { multibody::compute_modes(spec, mbtest::chain_options(40, Method::sparse), 4); }, "sparse");
  {
    ring::RingSpec s = spec;
    s.rotation.speed = 1.0;
    expect_refused([&] { multibody::compute_modes(s, mbtest::dense_chain(40), 4); }, "spin");
  }
  {
    ring::RingSpec s = spec;
    s.theory = ring::Theory::timoshenko;
    expect_refused([&] { multibody::compute_modes(s, mbtest::dense_chain(40), 4); }, "timoshenko");
  }
  // "auto" at n = 300 (the sparse crossover is 257, backend.hpp) stays dense and answers.
  const ring::MultibodyOptions automatic = mbtest::chain_options(300, Method::automatic);
  EXPECT_EQ(multibody::backend(automatic, spec, 4), multibody::Backend::dense);
  EXPECT_EQ(multibody::backend(automatic, ringtest::free_ring(), 4), multibody::Backend::banded);
}

/// The orientation of a mode of wave number k: its radial shape ~ A cos(k (theta - psi)),
/// psi in [0, 180/k) degrees (the sign of a mode is arbitrary), from the k-th harmonic of the
/// radial shape at the common stations (ring/results.hpp). The same rule as compare/pairs.hpp.
double orientation(const ring::ModeShape& shape, int k) {
  double a = 0.0, b = 0.0;
  for (int s = 0; s < ring::kStations; ++s) {
    const double t = k * ring::station_angle(s) * M_PI / 180.0;
    a += shape.radial[s] * std::cos(t);
    b += shape.radial[s] * std::sin(t);
  }
  const double period = 180.0 / k;
  double psi = std::atan2(b, a) * 180.0 / M_PI / k;
  psi = std::fmod(psi, period);
  if (psi < 0.0) psi += period;
  return psi;
}

/// The circular distance of two orientations of period 180/k, degrees.
double orientation_distance(double a, double b, int k) {
  const double period = 180.0 / k, d = std::fmod(std::abs(a - b), period);
  return std::min(d, period - d);
}

// The first-order split of the free inextensible ring (derived here, Rayleigh quotient with
// the unperturbed pair as trial functions, which the K = 2k harmonic diagonalizes): with the
// pair v = cos k(theta - phi), sin k(theta - phi), w = -v' and rho A = rho A0 (1 + d cos 2k(theta
// - phi)), EI = EI0 (1 + e cos 2k(theta - phi)), the two Rayleigh quotients are
//   omega^2 / omega0^2 = 1 -+ (e + d (1 - k^2) / (1 + k^2)) / 2   (cos mode: -, sin mode: +),
// so the relative split is |e + d (1 - k^2) / (1 + k^2)| / 2 + O(amplitude^2), and the lower
// mode is the cos mode (radial antinode at phi + 90/k) when e + d (1 - k^2)/(1 + k^2) > 0, the
// sin mode (antinode at phi) otherwise. The circle section scales its diameter by the depth
// factor 1 + t cos: A ~ 1 + 2t, I ~ 1 + 4t to first order, so e = 4t, d = 2t + density.
// Tolerance: amplitude 1e-3, so the neglected O(amplitude^2) is ~1e-3 of the split; the chain's
// O(1/n^2) error at n = 160 is ~1e-4 relative of the frequencies (README: 1.5e-5 .. 2e-4 on
// pair 2 at n = 160) and the split's own discretization error the same fraction of the split:
// 1 % of the split holds both with margin; the orientation to 0.5 deg.
TEST(MultibodyVariations, FirstOrderSplitOfTheFreeRing) {
  struct Case {
    int k;
    double thickness, density, phase;
  };
  for (const Case& c : {Case{2, 0.0, 1e-3, 20.0}, Case{2, 1e-3, 0.0, 10.0}, Case{3, 1e-3, 0.0, 0.0},
                        Case{3, 0.0, -1e-3, 50.0}}) {
    const ring::RingSpec spec = varied(ringtest::free_ring(), 2 * c.k, c.thickness, c.density, c.phase);
    const double e = 4.0 * c.thickness, d = 2.0 * c.thickness + c.density;
    const double g = e + d * (1.0 - c.k * c.k) / (1.0 + c.k * c.k);
    const double split = std::abs(g) / 2.0;
    const double antinode = g > 0.0 ? c.phase + 90.0 / c.k : c.phase;
    const ring::ModalResult r = multibody::compute_modes(spec, mbtest::dense_chain(160), 2 * c.k - 1);
    // Free ring: the elastic modes are pairs k = 2, 3, ...: pair k at indices 2 (k - 2), +1.
    const int lower = 2 * (c.k - 2), upper = lower + 1;
    const double w0 = r.omega[lower], w1 = r.omega[upper];
    const double measured = 2.0 * (w1 - w0) / (w1 + w0);
    EXPECT_NEAR(measured, split, 0.01 * split) << "k " << c.k << " t " << c.thickness << " d " << c.density;
    EXPECT_LT(orientation_distance(orientation(r.shapes[lower], c.k), antinode, c.k), 0.5)
        << "k " << c.k << " orientation " << orientation(r.shapes[lower], c.k) << " expected " << antinode;
    RecordProperty("split_k" + std::to_string(c.k) + "_t" + mbtest::sci(c.thickness) + "_d" + mbtest::sci(c.density),
                   mbtest::sci(measured) + " vs " + mbtest::sci(split));
  }
}

/// The chain's modes and the inextensible Hill oracle's, by index: the oracle's wave numbers
/// name the chain's modes in the same ascending order.
struct Pair {
  double lower = 0.0, upper = 0.0, orientation = 0.0;
  double relative() const { return 2.0 * (upper - lower) / (upper + lower); }
};

/// Pair k of the chain's result r: the two modes at the indices where the oracle's modes
/// `oracle` (ascending) have wave number k.
Pair chain_pair(const ring::ModalResult& r, const std::vector<vartest::Mode>& oracle, int k) {
  std::vector<int> at;
  for (int i = 0; i < static_cast<int>(oracle.size()) && at.size() < 2; ++i)
    if (oracle[i].wave == k) at.push_back(i);
  if (at.size() < 2) throw std::runtime_error("pair " + std::to_string(k) + " not among the oracle's modes");
  return {r.omega.at(at[0]), r.omega.at(at[1]), orientation(r.shapes.at(at[0]), k)};
}

struct OracleScene {
  std::string name;
  ring::RingSpec spec;
  int k;  ///< the pair the K = 2k harmonic splits
};

/// A thickness and a density harmonic K = 2k together (different phases, so the orientation
/// is neither's alone), plus a harmonic that does not split pair k at first order, on the free
/// ring and on a foundation.
std::vector<OracleScene> oracle_scenes() {
  std::vector<OracleScene> out;
  {
    ring::RingSpec s = ringtest::free_ring();
    s.variations = {{4, 0.1, 0.0, 10.0}, {4, 0.0, 0.15, 35.0}, {3, 0.05, 0.05, 0.0}};
    out.push_back({"free, K = 4 splits k = 2", s, 2});
  }
  {
    ring::RingSpec s = mbtest::on_foundation();
    s.variations = {{6, 0.08, 0.0, 5.0}, {6, 0.0, -0.1, 40.0}};
    out.push_back({"foundation, K = 6 splits k = 3", s, 3});
  }
  {
    ring::RingSpec s = mbtest::on_foundation();
    s.section.shape = ring::Section::Shape::rectangle;
    s.section.width = 0.12;
    s.section.height = 0.12;
    s.variations = {{4, 0.1, 0.05, 20.0}};
    out.push_back({"foundation, rectangle, K = 4 splits k = 2", s, 2});
  }
  return out;
}

// The chain converges to the inextensible Hill ring (N = 64: converged to 1e-14, the oracle's
// header) at order 2 in 1/n: both frequencies of pair k, and the relative split itself.
// Tolerances: order 2 +- 0.15 (the chain's uniform modes fit 2.0 +- 0.02, README; the variations'
// own O(1/n^2) terms add a little curvature at n = 40); the finest error (n = 160) below 5e-4
// relative for the frequencies (the uniform chain's pair 3 error at n = 160 is ~1e-4, README's
// table) and 2e-2 relative for the split (a difference of two such frequencies over a split of a
// few per cent). The orientation of the lower mode at n = 160 within 0.5 deg of Hill's (its
// discretization error is O(1/n^2) of 180/k degrees: ~0.01 deg; the shape's sampling at the
// common stations between hinges interpolates linearly, O(1/n^2) too).
TEST(MultibodyVariations, ConvergesToHillAtOrderTwo) {
  const std::vector<int> ns{40, 80, 160};
  for (const OracleScene& sc : oracle_scenes()) {
    const vartest::Ring hill = vartest::from_spec(sc.spec, false);
    const std::vector<vartest::Mode> oracle = vartest::modes(hill, 2 * sc.k + 3);
    const vartest::Split ref = vartest::pair_split(hill, sc.k);
    const double ref_split = 2.0 * (ref.upper - ref.lower) / (ref.upper + ref.lower);
    std::vector<double> lower, upper, split, orient;
    for (int n : ns) {
      const ring::ModalResult r = multibody::compute_modes(sc.spec, mbtest::dense_chain(n), 2 * sc.k + 3);
      const Pair p = chain_pair(r, oracle, sc.k);
      lower.push_back(std::abs(p.lower - ref.lower) / ref.lower);
      upper.push_back(std::abs(p.upper - ref.upper) / ref.upper);
      split.push_back(std::abs(p.relative() - ref_split) / ref_split);
      orient.push_back(orientation_distance(p.orientation, ref.orientation_deg, sc.k));
      RecordProperty(sc.name + " n=" + std::to_string(n),
                     "lower " + mbtest::sci(lower.back()) + " upper " + mbtest::sci(upper.back()) + " split " +
                         mbtest::sci(split.back()) + " (" + mbtest::sci(p.relative()) + " vs " + mbtest::sci(ref_split) +
                         ") orientation " + mbtest::sci(p.orientation) + " vs " + mbtest::sci(ref.orientation_deg));
    }
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, lower), 2.0, 0.15, 5e-4)) << sc.name << " lower";
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, upper), 2.0, 0.15, 5e-4)) << sc.name << " upper";
    EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(ns, split), 2.0, 0.15, 2e-2)) << sc.name << " split";
    EXPECT_LT(orient.back(), 0.5) << sc.name << " orientation";
    // The first-order split of the header, to O(amplitude^2) of it (amplitudes ~0.1 here).
    const vartest::FirstOrder f = vartest::first_order_inextensible(hill, sc.k);
    RecordProperty(sc.name + " first order", mbtest::sci(f.relative) + " vs Hill " + mbtest::sci(ref_split));
  }
}

// A harmonic that does not split pair k at first order: a density harmonic K = k splits the
// free ring's pair k at second order, d^2 / (4 (k^2 + 1)) (the oracle's
// second_order_density_inextensible). The chain's split at d and d/2: ratio 4 (order 2 in the
// amplitude, fitted: 2 +- 0.05: the next term is O(d^4) relative d^2, 1e-3 at d = 0.05), and
// within 2 % of the formula at n = 160 (the chain's O(1/n^2) ~1e-3 of the split and O(d^2) ~1 %).
TEST(MultibodyVariations, NonSplittingHarmonicSplitsAtSecondOrder) {
  const int k = 2;
  std::vector<double> amplitudes{0.1, 0.05}, splits;
  for (double d : amplitudes) {
    const ring::RingSpec spec = varied(ringtest::free_ring(), k, 0.0, d, 25.0);
    const ring::ModalResult r = multibody::compute_modes(spec, mbtest::dense_chain(160), 2);
    const double measured = 2.0 * (r.omega[1] - r.omega[0]) / (r.omega[1] + r.omega[0]);
    const double formula = vartest::second_order_density_inextensible(vartest::from_spec(spec, false), k).relative;
    splits.push_back(measured);
    EXPECT_NEAR(measured, formula, 0.02 * formula) << "d " << d;
    RecordProperty("second order d=" + mbtest::sci(d), mbtest::sci(measured) + " vs " + mbtest::sci(formula));
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(amplitudes, splits), 2.0, 0.05)) << "split against amplitude";
  // K = 3 does not divide 2k = 4: pair 2 stays double (the chain's own symmetry with n = 40 would
  // couple k and -k only through the aliasing 4 = 3 a + 40 b, a = -12: order 12): round-off
  // of the dense eigensolver, 1e-12 relative (modes.hpp: ~1e-14).
  const ring::ModalResult r = multibody::compute_modes(varied(ringtest::free_ring(), 3, 0.1, 0.1), mbtest::dense_chain(40), 2);
  EXPECT_LT(2.0 * (r.omega[1] - r.omega[0]) / (r.omega[1] + r.omega[0]), 1e-12);
}

}  // namespace
