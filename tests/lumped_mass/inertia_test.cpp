// A point mass's rotary inertia J in the lumped chain's forced response (nonlinear.cpp): J on
// the hinge's own rotation chi, with the hinge's split springs (terms.hpp, Terms::split), as
// the linear modes and the modes under load carry it. Oracles from outside the response:
//  - the response's own convergence in l, fitted from successive refinements (a Richardson
//    estimate of the error: the differences of a scheme of order p fall by 2^p);
//  - the chain's linear modes (lumped::compute_modes: model.cpp, the eigen layer), whose
//    frequencies the small-amplitude response must carry: the midpoint rule maps omega to
//    Omega = (2/dt) atan(omega dt/2) exactly on a linear system, so the free vibration is a
//    sum of cos and sin at those Omega and nothing else;
//  - the energy balance of the midpoint rule, exact for quadratic energies;
//  - the condensation identity: chi without inertia is the statics' condensed kr, so J -> 0
//    gives the response without chi (the one with J = 0).
// The ring: the paper's, pinned at 180 deg, a roller at 0 deg, a point inertia J = 5000 kg m^2
// (the study in docs/measured.md, "lumped_mass: terms beyond the paper": it moves mode 5 of
// the pinned ring by several per cent) with a
// rotational spring kr at 270 deg.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"

namespace {

constexpr double kJ = 5000.0;   // kg m^2
constexpr double kKr = 1e5;     // N m/rad, on the same hinge (in series with the split springs)

ring::LumpedOptions chain(int n) {
  ring::LumpedOptions o;
  o.n = n;
  return o;
}

ring::RingSpec ring_with_inertia(double J) {
  ring::RingSpec s = ringtest::pin_roller_ring();
  s.masses = {{270.0, 0.0, J}};
  s.supports.springs = {{270.0, 0.0, 0.0, kKr}};
  return s;
}

/// A half-sine pulse of a tangential force F at the inertia's hinge (and a radial one at
/// 90 deg), then free vibration to t_end; recorded at 270 and 90 deg.
ring::ResponseOptions pulse(double F, double dt, double t_end) {
  ring::ResponseOptions r;
  r.loads.points = {{270.0, {F, 0.0}}, {90.0, {0.0, -F}}};
  r.history.kind = ring::LoadHistory::Kind::half_sine;
  r.history.period = 0.2;
  r.dt = dt;
  r.t_end = t_end;
  r.integrator = ring::ResponseOptions::Integrator::midpoint;
  r.record = {270.0, 90.0};
  return r;
}

/// The recorded components (ux, uy at each point) as series.
std::vector<std::vector<double>> series(const ring::TimeHistory& h) {
  std::vector<std::vector<double>> s;
  for (std::size_t p = 0; p < h.ux.size(); ++p) {
    s.push_back(h.ux[p]);
    s.push_back(h.uy[p]);
  }
  return s;
}

double largest(const std::vector<std::vector<double>>& s) {
  double m = 0.0;
  for (const auto& c : s)
    for (double v : c) m = std::max(m, std::abs(v));
  return m;
}

/// max over components and grid points of |a - b|, over the largest |b|.
double difference(const ring::TimeHistory& a, const ring::TimeHistory& b) {
  const auto sa = series(a), sb = series(b);
  double d = 0.0;
  for (std::size_t c = 0; c < sa.size(); ++c)
    for (std::size_t k = 0; k < sa[c].size(); ++k) d = std::max(d, std::abs(sa[c][k] - sb[c][k]));
  return d / largest(sb);
}

std::string list(const std::vector<double>& v) {
  std::string s;
  char buf[32];
  for (double x : v) {
    std::snprintf(buf, sizeof buf, "%s%.3e", s.empty() ? "" : ", ", x);
    s += buf;
  }
  return s;
}

// Order in l. A pulse of 0.2 s (the modes up to ~60 rad/s, mode 5 among them, in which J
// matters) and free vibration to 1 s at n = 40, 80, 160, 320, dt = 2e-3 s for all (the time
// error then is the same to O(l^2) at every n and leaves the differences). e_n = the largest
// difference of the recorded histories between n and 2n over the largest displacement; a
// scheme of order p has e_n / e_2n -> 2^p. F = 2 N: u/R ~ 4e-6, nearly linear.
// Measured with J on the chord rotation (condensed, before): see docs/measured.md, "lumped_mass:
// a point inertia in the chain's response"; with chi: order
// 2. Bound: the fitted order within 0.25 of 2 (three differences; the next term of an order-2
// scheme is O(l^4), a quarter of the leading one at n = 40 at most), and an order 1 scheme
// would fail it.
TEST(LumpedInertia, PulseResponseConvergesAtOrderTwoInTheLinkLength) {
  const ring::RingSpec s = ring_with_inertia(kJ);
  const ring::ResponseOptions r = pulse(2.0, 2e-3, 1.0);
  std::vector<ring::TimeHistory> h;
  const std::vector<int> ns = {40, 80, 160, 320};
  for (int n : ns) h.push_back(lumped::respond(s, chain(n), r));
  std::vector<double> e;
  for (std::size_t i = 0; i + 1 < h.size(); ++i) e.push_back(difference(h[i], h[i + 1]));
  // Fitted over the three differences, each at its coarser n.
  const auto samples = ringtest::in_n(std::vector<int>(ns.begin(), ns.begin() + 3), e);
  const double order = ringtest::fit_order(samples).order;
  std::printf("[lumped inertia] pulse, J = %g kg m^2: differences n/2n (n = 40, 80, 160) %s, fitted order %.3f\n",
              kJ, list(e).c_str(), order);
  RecordProperty("differences", list(e));
  RecordProperty("order", std::to_string(order));
  EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.25, 1e-2));
}

// Small amplitude: the free vibration after the pulse (t >= 0.2 s to 4 s, dt = 2e-3 s, n = 40)
// is, for the linearized chain, sum_k (a_k cos Omega_k t + b_k sin Omega_k t) over its elastic
// modes, Omega_k = (2/dt) atan(omega_k dt / 2) with omega_k the chain's own linear modes with
// the inertia (all 38 of them: J on chi adds one to n - 3). The least-squares fit of each
// recorded component on those 76 functions leaves a residual from the nonlinear terms,
// O(u/l) ~ 2e-6 of the signal (u ~ 4e-6 m at F = 0.2 N, l = 1.57 m), and from the Newton
// tolerance, 1e-11 R = 1e-10 m against u: ~3e-5 at most (measured 2.7e-7); a frequency off by
// delta leaves ~delta t of the mode's share (the condensed inertia, docs/measured.md). Bound 1e-4.
TEST(LumpedInertia, SmallFreeVibrationCarriesTheLinearModesFrequencies) {
  const ring::RingSpec s = ring_with_inertia(kJ);
  const int n = 40;
  const double dt = 2e-3, t0 = 0.2;
  const ring::TimeHistory h = lumped::respond(s, chain(n), pulse(0.2, dt, 4.0));
  const int count = n - 3 + 1;
  const ring::ModalResult modes = lumped::compute_modes(s, chain(n), count);
  ASSERT_EQ(modes.omega.size(), std::size_t(count));
  std::vector<std::size_t> rows;
  for (std::size_t k = 0; k < h.t.size(); ++k)
    if (h.t[k] >= t0 + 1e-9) rows.push_back(k);
  Eigen::MatrixXd A(rows.size(), 2 * count);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int m = 0; m < count; ++m) {
      const double W = 2.0 / dt * std::atan(modes.omega[m] * dt / 2.0), t = h.t[rows[i]] - t0;
      A(i, 2 * m) = std::cos(W * t);
      A(i, 2 * m + 1) = std::sin(W * t);
    }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  double worst = 0.0;
  for (const auto& c : series(h)) {
    Eigen::VectorXd y(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) y[i] = c[rows[i]];
    if (y.norm() == 0.0) continue;
    const double residual = (A * qr.solve(y) - y).norm() / y.norm();
    worst = std::max(worst, residual);
  }
  std::printf("[lumped inertia] free vibration, n = %d: least-squares residual on the linear modes' %d "
              "frequencies %.3e of the signal\n",
              n, count, worst);
  RecordProperty("fit_residual", std::to_string(worst));
  EXPECT_LT(worst, 1e-4);
}

// The energy balance at the end of the free vibration (t = 2 s, n = 40): T + V - W, T with
// J w^2 / 2 of chi and V with the split springs. The midpoint rule conserves the quadratic
// energy of a linear system exactly; at F = 2 N (u/R ~ 4e-6) what is left is the floor of
// the Newton tolerance (1e-11 R on the positions), which falls against the work as 1/F
// (measured 1.2e-6, 5.2e-7, 1.8e-8, 2.5e-9 of the work at F = 0.02, 0.2, 2, 20 N): bound 1e-6.
// At F = 5e3 N (u/R ~ 1e-2) the balance is at the midpoint rule's O(dt^2) error on the
// non-quadratic energies (the turning angles' and m_h's atan2): order 2 in dt over dt = 16, 8,
// 4 ms within 0.3 (measured 8.2e-8, 1.9e-8, 4.5e-9, order 2.08; below 4 ms the floor above
// shows), bound 1e-6 on the finest. A chi energy left out of T or V would leave its share of
// the work, O(1), instead.
TEST(LumpedInertia, EnergyBalanceAtTheEndOfAFreeVibration) {
  const ring::RingSpec s = ring_with_inertia(kJ);
  auto balance = [&](double F, double dt) {
    const ring::TimeHistory h = lumped::respond(s, chain(40), pulse(F, dt, 2.0));
    double work = 0.0;
    for (double w : h.work) work = std::max(work, std::abs(w));
    EXPECT_GT(h.kinetic.back() + h.strain.back(), 0.5 * work) << "a free vibration keeps the pulse's work";
    return std::abs(h.energy_error.back()) / work;
  };
  const double small = balance(2.0, 2e-3);
  std::printf("[lumped inertia] energy balance at the end, F = 2 N: %.3e of the work\n", small);
  RecordProperty("small_amplitude_balance", std::to_string(small));
  EXPECT_LT(small, 1e-6);
  std::vector<double> dts = {16e-3, 8e-3, 4e-3}, err;
  for (double dt : dts) err.push_back(balance(5e3, dt));
  // The order in dt from the first and the last step (two points).
  const auto samples = ringtest::in_h({dts[0], dts[2]}, {err[0], err[2]});
  const double order = ringtest::fit_order(samples).order;
  std::printf("[lumped inertia] energy balance at the end, F = 5e3 N: %s of the work, order %.3f in dt\n",
              list(err).c_str(), order);
  RecordProperty("large_amplitude_balance", list(err));
  EXPECT_TRUE(ringtest::OrderNear(samples, 2.0, 0.3, 1e-6));
}

// J = 0: no hinge rotation (the unknowns are the 2n positions and the constraint rows, 2n + n
// + 3 on a pin and a roller), so the response is the one without chi. J -> 0: chi's equation
// becomes its split springs' equilibrium at the midpoint, whose minimum over chi is the
// condensed kr (terms.hpp), so the positions follow the J = 0 response; what J leaves is
// J (2/dt^2) / (4K + kr) ~ 4e-10 per unit of chi at J = 1e-9 kg m^2 (4K = 5.4e6 N m at n = 40),
// under the Newton tolerance's 1e-11 R / u ~ 3e-9 (u ~ 0.04 m at F = 2e3 N). Bound 1e-8 of the
// largest displacement.
TEST(LumpedInertia, VanishingInertiaIsTheResponseWithoutIt) {
  const ring::ResponseOptions r = pulse(2e3, 2e-3, 1.0);
  const ring::TimeHistory none = lumped::respond(ring_with_inertia(0.0), chain(40), r);
  const ring::TimeHistory tiny = lumped::respond(ring_with_inertia(1e-9), chain(40), r);
  EXPECT_EQ(none.unknowns, 2 * 40 + 40 + 3);
  EXPECT_EQ(tiny.unknowns, 2 * 40 + 1 + 40 + 3);
  const double d = difference(tiny, none);
  std::printf("[lumped inertia] J = 1e-9 against J = 0: %.3e of the largest displacement\n", d);
  RecordProperty("vanishing_inertia", std::to_string(d));
  EXPECT_LT(d, 1e-8);
}

}  // namespace
