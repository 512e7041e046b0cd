// Rigid plates ([plates], ring::PlatePair) in the lumped chain's nonlinear statics (and the
// frames', elastic): the paper ring (free, no supports) crushed between two frictionless plates
// normal to the diameter at 90 deg (lumped_mass/nonlinear.hpp, "Rigid plates"). Oracles from
// outside the code:
// - the inextensible ring's pinching force for a closing c, P = c / ((pi/4 - 2/pi) R^3 / EI)
//   (Roark's ring case 1; tests/support/plastic_ring.hpp, PinchedPlasticRing), at a fitted
//   order 2 in n, for the ring's own closing (the approach less the plates' sinking into the
//   wall; test 1 says why not a stiffer penalty);
// - the same chain's driven pinch (static.displacement at 90 deg, a pin at 270 deg): the same
//   equilibrium at the closing the plates leave after their sinking F / (k l) each;
// - DeRuntz & Hodge's rigid-plastic crushing (PinchedPlasticRing::plates_load,
//   plates_contact_length) for the resultant law (perfectly plastic, Mp R / EI = 1e-4) and the
//   fibre law (its Mp = sigma_y d^3 / 6), up to an approach of R;
// - the energy identity: the plates' work = stored (bending + penalty) + dissipated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <optional>
#include <vector>

#include "common.hpp"
#include "lumped_mass/checks.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "ring/analysis.hpp"
#include "ring/errors.hpp"
#include "tests/support/convergence.hpp"
#include "tests/support/paper.hpp"
#include "tests/support/plastic_ring.hpp"

namespace {

using lumptest::kChain;

constexpr double kMp = 1e-4;  ///< Mp R / EI of the plastic tests (displacement_test.cpp's)

/// The paper ring without supports; the resultant law with Mp = mp EI / R (none: elastic).
ring::RingSpec free_ring(std::optional<double> mp) {
  ring::RingSpec s = ringtest::driven_plastic_ring(mp);
  s.supports.pin.reset();
  return s;
}

ringtest::PinchedPlasticRing oracle(double mp = kMp) {
  const ring::RingSpec s = free_ring(mp);
  return {s.radius, s.EI(), s.plastic->moment};
}

/// The default penalty, E A^2 / (12 I) (the scene reader's: the wall's stiffness through its depth).
double wall(const ring::RingSpec& s) { return s.E * s.A() * s.A() / (12.0 * s.I()); }

/// The plates at 90 deg approaching by `travel` (m) at load factor 1, penalty `k` (N/m^2).
ring::StaticOptions plates(double travel, double k, std::vector<double> history = {}, int steps = 20,
                           bool path = true) {
  ring::StaticOptions st;
  st.plates = ring::StaticOptions::Plates{90.0, travel, k};
  st.record = {90.0, 270.0};
  st.history = std::move(history);
  st.path = path;
  st.steps = steps;
  return st;
}

lumped::StaticDetail crush(const ring::RingSpec& spec, int n, const ring::StaticOptions& st) {
  return lumped::solve_static_detail(spec, lumptest::options(n, kChain), st);
}

// 1. Elastic, approach c = 1e-5 R: the force of the plate at 90 deg on the ring is (0, -P), P the
// closed form's for the ring's own closing u_y(270) - u_y(90) (the approach less the plates'
// sinking into the wall, 2 F / (k l), checked to 1e-9 of c), its error falling at the chain's
// order 2 in n = 32 .. 256 (as the driven pinch of displacement_test.cpp: the same chain). The
// approach is small because the geometric nonlinearity is O(c / R) of P: at c = 1e-3 R it
// shifted the errors by 8e-4 (1.25e-3 at n = 256 against 4.7e-4, the fit to order 1.55:
// measured). The penalty is 1e-2 x the default E A^2 / (12 I), not 1e3 x: the force is k l
// times the sinking, and a node's position is known to ulp(R) = 1.8e-15 m at R = 10 m, so the
// force only to k l ulp(R): 2.7e-4 of it at the default k (n = 64), 0.27 at 1e3 x (at c = 1e-6 R
// it left no force at all, measured), 2.7e-6 at 1e-2 x. The sinking, 1.3e-5 of c here, is what
// the ring's closing takes out. Tolerance 0.1 on the order; ceiling twice the finest error
// measured (4.7e-4). The two plates' forces are equal and opposite to 1e-9, the x force and the
// three rows' multipliers (no slide, centre) vanish by symmetry to 1e-9 of P.
TEST(PlatesChain, ElasticForceConvergesToThePinchingForce) {
  const ringtest::PinchedPlasticRing o = oracle();
  const double c = 1e-5 * o.R;
  const std::vector<int> ns{32, 64, 128, 256};
  std::vector<double> e;
  for (int n : ns) {
    const ring::RingSpec spec = free_ring(std::nullopt);
    const double k = 1e-2 * wall(spec), l = 2.0 * M_PI * o.R / n;
    const lumped::StaticDetail d = crush(spec, n, plates(c, k, {}, 2, false));
    const auto& r = d.result.reaction;
    const double closing = d.result.displacements[1].uy - d.result.displacements[0].uy, P = closing / o.elastic_closing(1.0);
    e.push_back(std::abs(-r[1] / P - 1.0));
    std::printf(
        "[ plates ] chain n = %4d: force (%.3e, %.12e) N, closed form (0, %.12e), error %.3e; plates %.12e %.12e N; "
        "sinking %.6e of c (2 F / (k l c) = %.6e); multipliers %.3e %.3e %.3e N\n",
        n, r[0], r[1], -P, e.back(), d.plate_loads[0], d.plate_loads[1], 1.0 - closing / c, -2.0 * r[1] / (k * l * c),
        d.no_slide[0], d.no_slide[1], d.centre);
    EXPECT_LT(std::abs(r[0]), 1e-9 * P) << "n = " << n;
    EXPECT_NEAR(d.plate_loads[1], d.plate_loads[0], 1e-9 * P) << "n = " << n;
    EXPECT_NEAR(d.plate_loads[0], -r[1], 1e-12 * P) << "n = " << n;
    EXPECT_NEAR(d.result.displacements[1].uy, -d.result.displacements[0].uy, 1e-9 * c) << "n = " << n;
    for (double m : {d.no_slide[0], d.no_slide[1], d.centre}) EXPECT_LT(std::abs(m), 1e-9 * P) << "n = " << n;
    EXPECT_NEAR(c - closing, -2.0 * r[1] / (k * l), 1e-9 * c) << "n = " << n << ": the sinking is F / (k l) each";
  }
  const ringtest::Samples s = ringtest::in_n(ns, e);
  const ringtest::Order f = ringtest::fit_order(s);
  std::printf("[ plates ] chain elastic force: fitted order %.3f +- %.3f, finest error %.3e\n", f.order,
              f.standard_error, f.finest_error);
  EXPECT_TRUE(ringtest::OrderNear(s, 2.0, 0.1, 1e-3));
}

// 2. Against the same chain's driven pinch (static.displacement at 90 deg, a pin at 270 deg;
// displacement_test.cpp's fixture), elastic, at the approach c = 1e-3 R (geometrically
// nonlinear by 8e-4 of P, above). While only the two nodes at 90 and 270 deg touch, the plates
// are that pinch: the contact nodes' rows along the plates (no slide) are the pin's and the
// drive's x rows, the plates' force along d_0 is the drive's y force, and the translation along
// d_0 is rigid. Only the closing differs: the plates' approach less their sinking into the wall,
// 2 F / (k l) (one node each). So the pinch driven to the ring's closing under the plates,
// u_y(270) - u_y(90), needs the plates' force, to the rounding of the penalty's force: its gap
// is known to eps R (R = 10 m: 2e-15 m), so the force to k l eps R = 4e-4 N, 3e-6 of F (1.1e-6
// measured): bound 1e-5. And the sinking is what the force says, F / (k l), to the closing's
// rounding, 2 eps R against a sinking of 6.6e-10 m, 6e-6 (1.2e-6 measured): bound 1e-5.
TEST(PlatesChain, AreTheDrivenPinchAtTheClosingTheyLeave) {
  const ringtest::PinchedPlasticRing o = oracle();
  const double c = 1e-3 * o.R;
  const int n = 64;
  const ring::RingSpec spec = free_ring(std::nullopt);
  const double k = wall(spec), l = 2.0 * M_PI * o.R / n;
  const lumped::StaticDetail d = crush(spec, n, plates(c, k, {}, 4, false));
  const double F = -d.result.reaction[1];
  const double closing = d.result.displacements[1].uy - d.result.displacements[0].uy;
  ring::StaticOptions st = ringtest::driven_pinch(closing, {}, 4);
  st.path = false;
  const lumped::StaticDetail pinch =
      lumped::solve_static_detail(ringtest::driven_plastic_ring(std::nullopt), lumptest::options(n, kChain), st);
  const double Fp = -pinch.result.reaction[1];
  std::printf("[ plates ] n = %d, approach %.6e m: plates %.12e N, ring closing %.12e m (sinking 2 x %.6e m, "
              "F / (k l) = %.6e m); the driven pinch to that closing %.12e N, ratio - 1 = %.3e\n",
              n, c, F, closing, 0.5 * (c - closing), F / (k * l), Fp, F / Fp - 1.0);
  EXPECT_NEAR(F / Fp, 1.0, 1e-5);
  EXPECT_NEAR(0.5 * (c - closing) / (F / (k * l)), 1.0, 1e-5);
  EXPECT_LT(std::abs(d.result.contact_length[0]), 1e-6 * l) << "one node in contact: no extent";
}

/// The paper ring with the fibre law whose fully plastic moment sigma_y d^3 / 6 (the circle) is
/// mp EI / R, perfectly plastic.
ring::RingSpec fibre_free_ring(double mp) {
  ring::RingSpec s = free_ring(std::nullopt);
  ring::Plastic p;
  p.law = ring::Plastic::Law::fibre;
  p.stress = mp * s.EI() / s.radius / (std::pow(s.section.diameter, 3) / 6.0);
  s.plastic = p;
  return s;
}

/// The plates' approach at a path point, m.
double approach(const ring::PathPoint& p, double travel) { return p.load_factor * travel; }

struct Worst {
  double force = 0.0, length = 0.0;
  int points = 0;
};
/// The largest |F / plates_load(c) - 1| and |L - plates_contact_length(c)| / l over the path
/// points with c in [from, R] (both plates' contact lengths), printing a few.
Worst against_deruntz_hodge(const lumped::StaticDetail& d, const ringtest::PinchedPlasticRing& o, double travel,
                            double from, int n, const char* what) {
  const double l = 2.0 * M_PI * o.R / n;
  Worst w;
  for (const ring::PathPoint& p : d.result.path) {
    const double c = approach(p, travel);
    if (c < from || c > o.R * (1 + 1e-12)) continue;
    ++w.points;
    const double F = -p.reaction[1], P = o.plates_load(c), L = o.plates_contact_length(c);
    w.force = std::max(w.force, std::abs(F / P - 1.0));
    for (double Lp : p.contact_length) w.length = std::max(w.length, std::abs(Lp - L) / l);
    EXPECT_LT(std::abs(p.reaction[0]), 1e-6 * P) << what << " n = " << n << ", c = " << c << ": symmetric";
    EXPECT_NEAR(p.contact_length[1], p.contact_length[0], 1e-6 * l) << what << " n = " << n << ", c = " << c;
  }
  std::printf("[ plates ] %s n = %3d: %d points with c in [%.2f R, R]: |F / P_DH - 1| <= %.4f (l / R = %.4f), "
              "|L - L_DH| <= %.3f l; at c = R: F = %.6f P_DH, L = %.6f m (L_DH %.6f m)\n",
              what, n, w.points, from / o.R, w.force, l / o.R, w.length,
              -d.result.reaction[1] / o.plates_load(travel), d.result.contact_length[0],
              o.plates_contact_length(travel));
  return w;
}

// 3a. Plastic (resultant law, perfectly plastic, Mp R / EI = 1e-4), the approach up to R:
// DeRuntz & Hodge's rigid-plastic crushing, P(c) = 4 Mp / (R sqrt(1 - (c / 2R)^2)) and the
// flat contact length L(c) = 2 R asin(c / 2R). Their mechanism has hinges that travel with the
// contact's edges; the chain's hinges are its nodes, so the contact grows a node at a time and
// the hinge waits at the last node touched: the contact length is within one link per side of
// L (2 l; measured 1.02 l at n = 64 and 128), and the force, whose lever is the distance from
// the contact's edge to the hinges at 0 and 180 deg, within O(l / R) of P (measured 0.57 l / R at
// n = 64, 0.59 l / R at n = 128 for c >= 0.05 R: bound l / R). The elastic–plastic ring lags the
// rigid-plastic one by its elastic closing, O(Mp R^2 / EI) = 1e-4 R, which moves P by 1e-4 of
// it at most: inside the bound. Both plates alike, and the x force 0, by symmetry.
TEST(PlatesPlasticChain, ForceAndContactLengthFollowDeRuntzHodge) {
  const ringtest::PinchedPlasticRing o = oracle();
  for (int n : {64, 128}) {
    const lumped::StaticDetail d = crush(free_ring(kMp), n, plates(o.R, wall(free_ring(kMp))));
    const Worst w = against_deruntz_hodge(d, o, o.R, 0.05 * o.R, n, "resultant");
    const double l = 2.0 * M_PI * o.R / n;
    EXPECT_GE(w.points, 20) << "n = " << n;
    EXPECT_LE(w.force, l / o.R) << "n = " << n;
    EXPECT_LE(w.length, 2.0) << "n = " << n;
    EXPECT_EQ(d.result.end, "full load");
    EXPECT_GT(d.result.dissipated, 0.0);
  }
}

// 3b. The fibre law (ring.plastic.stress, the circle, sigma_y d^3 / 6 = Mp of 3a): the same
// crushing, within the same bounds of DeRuntz & Hodge. Its moment tends to Mp as the hinge's
// curvature grows past first yield's (the elastic core's share falls as (kappa_y / kappa)^2),
// and at c = R the chain's hinges have turned by about a radian over l = 1 m against
// kappa_y = My / EI = 6e-6 / m: the force there is the resultant law's to (kappa_y / kappa)^2,
// 1e-10 (0 measured): bound 1e-6.
TEST(PlatesPlasticChain, TheFibreLawCrushesAsTheResultantLaw) {
  const ringtest::PinchedPlasticRing o = oracle();
  const int n = 64;
  const lumped::StaticDetail fibre = crush(fibre_free_ring(kMp), n, plates(o.R, wall(free_ring(kMp))));
  const lumped::StaticDetail resultant = crush(free_ring(kMp), n, plates(o.R, wall(free_ring(kMp))));
  const Worst w = against_deruntz_hodge(fibre, o, o.R, 0.05 * o.R, n, "fibre");
  const double l = 2.0 * M_PI * o.R / n;
  std::printf("[ plates ] at c = R: fibre %.9e N, resultant %.9e N, ratio - 1 = %.3e; dissipated %.6e / %.6e J\n",
              -fibre.result.reaction[1], -resultant.result.reaction[1],
              fibre.result.reaction[1] / resultant.result.reaction[1] - 1.0, fibre.result.dissipated,
              resultant.result.dissipated);
  EXPECT_GE(w.points, 20);
  EXPECT_LE(w.force, l / o.R);
  EXPECT_LE(w.length, 2.0);
  EXPECT_NEAR(fibre.result.reaction[1] / resultant.result.reaction[1], 1.0, 1e-6);
  EXPECT_EQ(fibre.result.end, "full load");
}

// 3c. The energy identity along the crushing of 3a (n = 64) to c = R: the plates' work,
// integrated here by the trapezoidal rule over the recorded path,
// W = sum (F_a + F_b) / 2 (c_b - c_a) (each plate does F dc / 2), equals the stored energy
// (bending and penalty) at the end plus the plastic work, to the rule's error. Within a step the
// force is monotone in c (it rises steeply where a node comes into contact and falls along the
// mechanism between), and the trapezoid of a monotone function over a step errs by at most
// |F_b - F_a| (c_b - c_a) / 2: bound the sum of that over the path, measured on the path itself
// (the defect measured 4.5e-5 of W). The solver's own sum (StaticDetail::work) is the same rule:
// equal to 1e-12 of W.
TEST(PlatesPlasticChain, WorkIsStoredPlusDissipated) {
  const ringtest::PinchedPlasticRing o = oracle();
  const int n = 64;
  const lumped::StaticDetail d = crush(free_ring(kMp), n, plates(o.R, wall(free_ring(kMp))));
  const std::vector<ring::PathPoint>& pts = d.result.path;
  double W = 0.0, bound = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double ca = approach(pts[k], o.R), cb = approach(pts[k + 1], o.R);
    const double Fa = -pts[k].reaction[1], Fb = -pts[k + 1].reaction[1];
    W += 0.5 * (Fa + Fb) * (cb - ca);
    bound += 0.5 * std::abs((Fb - Fa) * (cb - ca));
  }
  const double UD = d.stored + d.result.dissipated;
  std::printf("[ plates ] energy: W %.12e J (solver %.12e), U %.6e + D %.6e = %.12e, defect %.3e (%.3e of W, "
              "bound %.3e)\n",
              W, d.work, d.stored, d.result.dissipated, UD, W - UD, (W - UD) / W, bound);
  EXPECT_GT(d.stored, 0.0);
  EXPECT_LE(std::abs(W - UD), bound);
  EXPECT_NEAR(d.work, W, 1e-12 * W);
}

// 3d. A history [1, 0.9] (approach R, then back by 0.1 R): unloading is elastic, and the ring
// springs back by its elastic closing, of order Mp R^2 / EI = 1e-3 m, far less than the plates'
// first step back (the leg's 20 steps: 0.1 R / 20 = 0.05 m each): so from the first unloading
// point on the plates are clear of the ring, the force and the contact lengths 0, and the plastic
// work is the peak's exactly.
TEST(PlatesPlasticChain, UnloadingIsElastic) {
  const ringtest::PinchedPlasticRing o = oracle();
  const int n = 64;
  const lumped::StaticDetail d = crush(free_ring(kMp), n, plates(o.R, wall(free_ring(kMp)), {1.0, 0.9}));
  const std::vector<ring::PathPoint>& pts = d.result.path;
  std::size_t peak = 0;
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (pts[k].load_factor > pts[peak].load_factor) peak = k;
  std::printf("[ plates ] unloading: peak s = %.12f, F = %.6e N, dissipated %.12e J; %zu points after it; end "
              "s = %.6f, F = %.3e N, L = %.3e m, dissipated %.12e J\n",
              pts[peak].load_factor, -pts[peak].reaction[1], pts[peak].dissipated, pts.size() - peak - 1,
              pts.back().load_factor, -pts.back().reaction[1], pts.back().contact_length[0], d.result.dissipated);
  ASSERT_NEAR(pts[peak].load_factor, 1.0, 1e-12);
  ASSERT_GT(pts.size(), peak + 1);
  for (std::size_t k = peak + 1; k < pts.size(); ++k) {
    EXPECT_EQ(pts[k].reaction[1], 0.0) << "s = " << pts[k].load_factor;
    EXPECT_EQ(pts[k].contact_length[0], 0.0) << "s = " << pts[k].load_factor;
    EXPECT_EQ(pts[k].dissipated, pts[peak].dissipated) << "s = " << pts[k].load_factor;
  }
  EXPECT_GT(d.result.dissipated, 0.0);
  EXPECT_EQ(d.result.dissipated, pts[peak].dissipated);
  EXPECT_NEAR(pts.back().load_factor, 0.9, 1e-12);
  EXPECT_EQ(d.result.end, "end of the history");
}

// 4. The frames (elastic, the end of the path only): 1 (penalty 1e-2 x the default, the ring's
// own closing; 1 says why) and 2 for each. The frames are extensible
// (the Timoshenko frame shear flexible too), which moves their limit off the inextensible closed
// form by O(I / (A R^2)) and O(EI / (kGA R^2)), 1e-5 .. 1e-4 (displacement_test.cpp's driven
// frames measured the same order and offsets): order 2 over n = 16 .. 64 within 0.15, ceiling
// 1.5e-3 (that test's). Against each frame's own driven pinch at the closing the plates leave
// (c = 1e-3 R, n = 32): the plates' force to 1e-5, the penalty's rounding as for the chain.
TEST(PlatesFrames, ElasticForceConvergesAndIsTheirDrivenPinch) {
  const ringtest::PinchedPlasticRing o = oracle();
  const ring::RingSpec spec = free_ring(std::nullopt);
  const double k = wall(spec);
  using Variant = ring::LumpedOptions::Variant;
  for (Variant v : {Variant::frame, Variant::frame_consistent, Variant::timoshenko_frame}) {
    const double c = 1e-5 * o.R;
    const std::vector<int> ns{16, 32, 64};
    std::vector<double> e;
    for (int n : ns) {
      const lumped::StaticDetail d =
          lumped::solve_static_detail(spec, lumptest::options(n, v), plates(c, 1e-2 * k, {}, 2, false));
      const double closing = d.result.displacements[1].uy - d.result.displacements[0].uy;
      const double P = closing / o.elastic_closing(1.0);
      e.push_back(std::abs(-d.result.reaction[1] / P - 1.0));
      EXPECT_LT(std::abs(d.result.reaction[0]), 1e-9 * P) << ring::to_string(v) << " n = " << n;
      EXPECT_NEAR(d.plate_loads[1], d.plate_loads[0], 1e-9 * P) << ring::to_string(v) << " n = " << n;
      for (double m : {d.no_slide[0], d.no_slide[1], d.centre})
        EXPECT_LT(std::abs(m), 1e-9 * P) << ring::to_string(v) << " n = " << n;
    }
    const ringtest::Samples s = ringtest::in_n(ns, e);
    const ringtest::Order f = ringtest::fit_order(s);
    std::printf("[ plates ] %s elastic force: errors %.3e %.3e %.3e, fitted order %.3f +- %.3f\n",
                ring::to_string(v).c_str(), e[0], e[1], e[2], f.order, f.standard_error);
    EXPECT_TRUE(ringtest::OrderNear(s, 2.0, 0.15, 1.5e-3)) << ring::to_string(v);

    const double cl = 1e-3 * o.R;
    const lumped::StaticDetail d = lumped::solve_static_detail(spec, lumptest::options(32, v), plates(cl, k, {}, 4, false));
    const double F = -d.result.reaction[1];
    const double closing = d.result.displacements[1].uy - d.result.displacements[0].uy;
    ring::StaticOptions st = ringtest::driven_pinch(closing, {}, 4);
    st.path = false;
    const double Fp = -lumped::solve_static(ringtest::driven_plastic_ring(std::nullopt), lumptest::options(32, v), st)
                          .reaction[1];
    std::printf("[ plates ] %s n = 32, approach %.3e m: plates %.12e N, the driven pinch to their closing %.12e N, "
                "ratio - 1 = %.3e\n",
                ring::to_string(v).c_str(), cl, F, Fp, F / Fp - 1.0);
    EXPECT_NEAR(F / Fp, 1.0, 1e-5) << ring::to_string(v);
  }
}

// What the lumped models do not take with plates is refused by key for the library's callers
// (the scene reader refuses most of it first): the frames along static.path or plastic, supports, loads, a drive beside them,
// first-contact points off the nodes, a travel outside (0, 2 R), a stiffness not > 0, and the
// modes under load about a crushed state.
TEST(PlatesRefusals, NameTheKey) {
  auto refused = [](const std::function<void()>& run, const std::string& what, const std::string& key) {
    try {
      run();
      ADD_FAILURE() << what << " was not refused";
    } catch (const ring::InputError& e) {
      EXPECT_EQ(e.key(), key) << what << ": " << e.what();
    }
  };
  const ring::RingSpec spec = free_ring(std::nullopt);
  const double k = wall(spec);
  const ring::LumpedOptions o = lumptest::options(32, kChain);
  refused([&] { lumped::solve_static(spec, lumptest::options(32, ring::LumpedOptions::Variant::frame), plates(1.0, k)); },
          "plates on the frame along static.path", "static.path");
  refused([&] { lumped::solve_static(free_ring(kMp), lumptest::options(32, ring::LumpedOptions::Variant::timoshenko_frame),
                                     plates(1.0, k, {}, 20, false)); },
          "plates on a plastic Timoshenko frame", "ring.plastic");
  refused([&] { lumped::solve_static(ringtest::driven_plastic_ring(std::nullopt), o, plates(1.0, k)); },
          "plates on a pinned ring", "plates");
  ring::StaticOptions loaded = plates(1.0, k);
  loaded.loads.points = {{0.0, {1.0, 0.0}}};
  refused([&] { lumped::solve_static(spec, o, loaded); }, "plates beside a load", "plates");
  ring::StaticOptions driven = plates(1.0, k);
  driven.displacement = ring::StaticOptions::Displacement{0.0, {1e-3, 0.0}};
  refused([&] { lumped::solve_static(spec, o, driven); }, "plates beside a drive", "plates");
  ring::StaticOptions off = plates(1.0, k);
  off.plates->axis = 5.0;
  refused([&] { lumped::solve_static(spec, o, off); }, "first contact off the nodes", "plates.axis");
  for (double t : {0.0, -1.0, 2.0 * spec.radius, std::nan("")}) {
    ring::StaticOptions bad = plates(t, k);
    refused([&] { lumped::solve_static(spec, o, bad); }, "travel " + std::to_string(t), "plates.travel");
  }
  refused([&] { lumped::check_preloaded_modes(spec, o, plates(1.0, k)); }, "modes under a crushing", "plates");
  for (double kk : {0.0, -1.0, HUGE_VAL}) {
    ring::StaticOptions bad = plates(1.0, kk);
    refused([&] { lumped::solve_static(spec, o, bad); }, "stiffness " + std::to_string(kk), "plates.stiffness");
  }
}

}  // namespace
