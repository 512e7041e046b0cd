// An independent reference for the nonlinear statics tests: the inextensible
// elastica of a thin ring squeezed by two equal and opposite forces P along a
// diameter, by shooting on the ODE of a quarter ring. Nothing here uses multibody/.
//
// Quarter ring, first quadrant, arc length s from the top point T (on the axis
// perpendicular to the load, tangent horizontal by symmetry) clockwise to the loaded
// point C (on the load axis, tangent vertical by symmetry), 0 <= s <= pi R / 2.
// psi = angle of the tangent with +x, eta = y_T - y(s). Cutting the quarter at s,
// the part [0, s] carries at T the force +P/2 x (from the other quarter; a symmetric
// section carries no shear) and the unknown moment M0, so the bending moment is
// M(s) = M0 + (P/2) eta(s) and, with the undeformed curvature -1/R (clockwise),
//     psi' = -1/R + M(s)/EI,   eta' = -sin psi,   x' = cos psi,
//     psi(0) = 0, eta(0) = 0, x(0) = 0;   M0 chosen so that psi(pi R/2) = -pi/2.
// Then x_C = x(pi R/2), y_T = eta(pi R/2), the loaded diameter shortens by
// 2 (R - x_C) and the perpendicular one lengthens by 2 (y_T - R).
// Integrated with classical RK4 on a fixed grid (error O(h^4), h = pi/2/steps in
// units of R), M0 by the secant method; linear limit checked in the tests against
// ring::closed_form::diametral_load (Roark, Table 9.2 case 1).
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>

namespace elastica {

struct DiametralResult {
  double along = 0.0;   ///< shortening of the loaded diameter, in units of R
  double across = 0.0;  ///< lengthening of the perpendicular diameter, in units of R
  double m0 = 0.0;      ///< moment at T, in units of EI/R
};

namespace detail {
/// State {psi, eta, x} at s = pi/2 for p = P R^2/EI and m = M0 R/EI (R = 1).
inline std::array<double, 3> shoot(double p, double m, int steps) {
  auto f = [&](const std::array<double, 3>& y) {
    return std::array<double, 3>{-1.0 + m + 0.5 * p * y[1], -std::sin(y[0]), std::cos(y[0])};
  };
  std::array<double, 3> y{0.0, 0.0, 0.0};
  const double h = 0.5 * M_PI / steps;
  for (int i = 0; i < steps; ++i) {
    auto k1 = f(y);
    std::array<double, 3> t;
    for (int j = 0; j < 3; ++j) t[j] = y[j] + 0.5 * h * k1[j];
    auto k2 = f(t);
    for (int j = 0; j < 3; ++j) t[j] = y[j] + 0.5 * h * k2[j];
    auto k3 = f(t);
    for (int j = 0; j < 3; ++j) t[j] = y[j] + h * k3[j];
    auto k4 = f(t);
    for (int j = 0; j < 3; ++j) y[j] += h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return y;
}
}  // namespace detail

/// Diametral compression of the inextensible elastica ring, p = P R^2 / EI >= 0.
/// M0 by the secant method, continued in p from the linear solution in increments of
/// at most 0.25 so that the shooting stays on the branch connected to the unloaded ring.
/// Cost: O(steps) per secant iteration.
inline DiametralResult diametral(double p, int steps = 20000) {
  const int increments = 1 + static_cast<int>(p / 0.25);
  double m = 0.0;
  for (int k = 1; k <= increments; ++k) {
    const double pk = p * k / increments;
    auto miss = [&](double mm) { return detail::shoot(pk, mm, steps)[0] + 0.5 * M_PI; };
    // First guess: the previous increment, or linear theory M0 = -P R (1/2 - 1/pi) (Roark).
    double m0 = k == 1 ? -pk * (0.5 - 1.0 / M_PI) : m, m1 = m0 + 1e-4 * (1.0 + pk);
    double f0 = miss(m0), f1 = miss(m1);
    for (int it = 0; it < 60 && std::abs(f1) > 1e-13 && f1 != f0; ++it) {
      const double m2 = m1 - f1 * (m1 - m0) / (f1 - f0);
      m0 = m1;
      f0 = f1;
      m1 = m2;
      f1 = miss(m1);
    }
    if (!(std::abs(f1) <= 1e-11)) throw std::runtime_error("elastica: shooting did not converge");
    m = m1;
  }
  const auto y = detail::shoot(p, m, steps);
  return {2.0 * (1.0 - y[2]), 2.0 * (y[1] - 1.0), m};
}

}  // namespace elastica
