// The one energy check of every forced-response integrator: multibody newmark,
// generalized-alpha and energy-momentum, the lumped chain's midpoint rule, the FE beam's
// newmark and generalized-alpha. Header-only, so that every solver includes it without
// depending on another solver.
//
// The rule. After every recorded step, with T, V and W the kinetic energy, the strain
// energy and the work of the load, e = T + V - W and e_0 its value at t = 0, a run has
// gained energy and failed when
//
//   e - e_0 > kTolerance * max |W| + r,
//
// max |W| the largest |work| so far and r the round-off resolution of e (below). The
// check is signed: a loss (e < e_0) is the integrator's numerical dissipation
// (generalized-alpha's by design) or the damping, never a failure; a gain means the
// history holds energy that no force put in, and is not a result.
//
// Damped runs: the same rule, on the same e = T + V - W, without the dissipated energy D.
// A damper only removes energy, so T + V <= W holds for every damped history, whatever
// the damping; D itself is each solver's quadrature of the damping power (the balance
// column T + V + D - W of a history), exact only for the trapezoidal and midpoint rules
// on a linear system. With D in the check, the quadrature's error failed valid runs: the
// FE beam's trapezoidal rule on v^T C v counts the first step's dissipation twice
// (Newmark, Rayleigh a = 5 1/s: +1.8 % of the work after one step; b = 0.05 s: +27 %),
// and the chain's generalized-alpha balance with a hinge damper reached +0.4 % of the
// work. The price: a damped run that gains less energy than its damping removes is not
// caught.
//
// Why a floor r, and what it is. Relative to the work alone the check failed valid runs
// whose work is zero or at round-off: a load the roller reacts (W ~ 1e-11 J, the rounding
// of the loaded point's position), a force of 1e-300 N (W underflows; T + V ~ 1e-22 J of
// rounding), ring.rho = 1e15 or response.dt = 1e-9 s (a step's change of position is at
// or below the rounding of the positions themselves). r bounds what the rounding of the
// state alone puts into e. The chains carry absolute coordinates (angles ~ pi, hinge
// positions ~ R), so every position is known only to dx = kResolution eps R. Every
// integrator here takes its acceleration from positions, a = (x_1 - x_hat) / (beta h^2),
// and its velocity from a, v_1 = v_hat + gamma h a (the midpoint rule: v_1 = 2 (x_1 - x_0)
// / h - v_0, the same with beta = 1/4, gamma = 1/2; generalized-alpha has beta >= 1/4,
// gamma / beta <= 2), so one step's rounding moves a by 4 dx / h^2 and v by dv = 2 dx / h,
// h the smallest step taken. With the ring's mass M = rho A 2 pi R and the stiffness of a
// position error dx at each of the n nodes (the turning angle at a node moves by at most
// 4 dx / l, l = 2 pi R / n: bending energy (EI / l) (4 dx / l)^2 / 2 per node), one
// step's rounding holds the energy
//
//   E_1 = M dv^2 / 2 + 8 n^4 EI dx^2 / (2 pi R)^3
//
// and changes T + V to first order by at most 2 sqrt((T + V) E_1) (Cauchy-Schwarz in the M
// and K inner products: |v^T M dv| <= sqrt(2 T) sqrt(dv^T M dv)), T + V the largest so far.
// Over k steps the first-order changes can add up coherently: a motion whose step changes
// position by little more than dx (ring.rho = 1e15, dt = 0.01 s: h^2 |a| ~ 50 eps R at the
// start) is computed with a biased acceleration in every step, and the multibody chain's
// balance is then off by +7 % of the work (n = 40, newmark and generalized-alpha; +6 %
// with energy-momentum). The second-order parts are taken to add up like a random walk,
// k E_1 (measured with a force of 1e-300 N, n = 40, newmark: T + V, rounding alone, grows
// about linearly in k, to 4e-19 J at k = 200 against k E_1 = 7e-17 J). The work
// W = sum f_k F . (x_{k+1} - x_k) telescopes (summation by parts) to a rounding of at most
// |F| dx (2 max |f| + sum |f_k - f_{k-1}|), f_k the load factor each step's work used. And
// the sums themselves: eps (k + 4) (T + V + |W|). So
//
//   r = |F| dx (2 max |f| + sum |f_k - f_{k-1}|) + k E_1 + 2 k sqrt((T + V) E_1)
//       + eps (k + 4) (T + V + |W|).
//
// r cannot be zero (M, R > 0), and it is far below any resolved response: on the 20 kN
// scene (n = 40, dt = 0.01 s, 500 steps) r = 1.5e-4 J against kTolerance max |W| = 630 J;
// at n = 10^4 and 1000 steps ~15 J (the n^4 of the strain term, a bound for hinge
// positions; for the multibody chain's angle coordinates it is loose by 10^7: the strain
// energy of rounding measured 1.4e-22 J at n = 400 against 8 n^4 EI dx^2 / (2 pi R)^3 =
// 2.2e-15 J). Where r is not small,
// the state cannot resolve the response and no energy balance can be judged
// (ring.rho = 1e15: E_1 = 1.8e-8 J and a first-order term of 1.4e-5 J at 0.35 s, against
// a work of 2.1e-6 J; dt = 1e-9 s: the motion of 1e-7 s is below eps R). Measured margins
// (the gain over the allowance, the worst step): 0.10 for the roller, 0.01 for
// ring.rho = 1e15, 0.005 for dt = 1e-9 s (tests/compare/test_energy_guard_cli.cpp).
// kResolution = 16: measured, rounding puts positions off by up to 11 eps R (the closure
// residual of the multibody chain, a sum of n segments, at n = 2000; 1-4 eps R at n = 40
// and 10^4; the roller's work 0.9 eps R |F|; the lumped chain's kinetic energy at
// dt = 1e-9 s, 1.3 M (eps R / h)^2 / 2). The FE beam's coordinates are displacements,
// whose rounding is relative to u, not R: for it r is an upper bound, as for the others.
//
// Cost: O(1) per step.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "ring/spec.hpp"

namespace ring {

/// Usage, once per run and once per step:
/// \code
///   ring::EnergyGuard guard(spec, n, ring::load_scale(spec, response.loads));
///   guard.start(T0, V0, W0);
///   // each accepted (sub-)step of length h whose work used the load factor f:
///   guard.step(h, f);
///   // each recorded step:
///   const auto v = guard.check(T, V, W);
///   if (v.gained) fail(energy_growth, "solver: " + describe(v, t));
/// \endcode
class EnergyGuard {
 public:
  /// A gain above this fraction of the largest work fails the run.
  static constexpr double kTolerance = 1e-2;
  /// Position resolution of a solver's state in units of eps R (measured <= 11, file comment).
  static constexpr double kResolution = 16.0;

  struct Verdict {
    bool gained = false;
    double gain = 0.0;     ///< e - e_0 (e = T + V - W), J
    double work = 0.0;     ///< largest |W| so far, J
    double roundoff = 0.0; ///< r, J
    double allowed() const { return kTolerance * work + roundoff; }
  };

  /// \param pieces nodes around the ring (segments, links, elements x degree), >= 1
  /// \param force the loads' force scale at load factor 1 (ring::load_scale), N
  EnergyGuard(const RingSpec& spec, int pieces, double force)
      : force_(force),
        dx_(kResolution * std::numeric_limits<double>::epsilon() * spec.radius),
        mass_(spec.rhoA() * 2.0 * M_PI * spec.radius) {
    const double n = std::max(pieces, 1), L = 2.0 * M_PI * spec.radius;
    strain_roundoff_ = 8.0 * std::pow(n, 4) * spec.EI() * dx_ * dx_ / (L * L * L);
  }

  /// The energies at t = 0 (the rest state's own rounding is not a gain).
  void start(double kinetic, double strain, double work) { balance0_ = kinetic + strain - work; }

  /// One accepted step (sub-steps included) of length h whose work used load factor f.
  void step(double h, double f) {
    if (h > 0) h_min_ = std::min(h_min_, h);
    if (steps_ > 0) variation_ += std::abs(f - f_last_);
    f_last_ = f;
    f_max_ = std::max(f_max_, std::abs(f));
    ++steps_;
  }

  /// After a recorded step: its kinetic and strain energy and the work so far, J.
  Verdict check(double kinetic, double strain, double work) {
    work_ = std::max(work_, std::abs(work));
    stored_ = std::max(stored_, std::abs(kinetic) + std::abs(strain));
    const double eps = std::numeric_limits<double>::epsilon();
    const double dv = 2.0 * dx_ / h_min_, k = double(steps_);
    const double E1 = 0.5 * mass_ * dv * dv + strain_roundoff_;
    Verdict v;
    v.gain = kinetic + strain - work - balance0_;
    v.work = work_;
    v.roundoff = force_ * dx_ * (2.0 * f_max_ + variation_) + k * E1 + 2.0 * k * std::sqrt(stored_ * E1) +
                 eps * (k + 4.0) * (stored_ + work_);
    // A non-finite energy fails too (it would make the bound infinite).
    v.gained = !(std::isfinite(v.gain) && std::isfinite(v.roundoff) && v.gain <= v.allowed());
    return v;
  }

 private:
  double force_, dx_, mass_, strain_roundoff_ = 0.0;
  double balance0_ = 0.0, work_ = 0.0, stored_ = 0.0;
  double h_min_ = std::numeric_limits<double>::infinity();
  double f_last_ = 0.0, f_max_ = 0.0, variation_ = 0.0;
  long steps_ = 0;
};

/// The failure message every solver gives (after its own prefix), t the time reached.
inline std::string describe(const EnergyGuard::Verdict& v, double t) {
  std::ostringstream s;
  s.precision(4);
  s << "T + V - W (kinetic and strain energy less the work of the load) grew by " << v.gain << " J since t = 0, more than "
    << 100.0 * EnergyGuard::kTolerance << " % of the largest work " << v.work << " J plus the round-off bound "
    << v.roundoff << " J, at t = " << t << " s: the integration gains energy";
  return s.str();
}

}  // namespace ring
