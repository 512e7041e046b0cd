// The multibody arch suites' own oracle (until tests/support/arch.hpp): the natural
// frequencies of the inextensible circular arch (Euler-Bernoulli, no rotary inertia), the limit
// the rigid-segment chain converges to. Written from the beam equations, sharing no code
// with multibody/.
//
// ## Derivation
// Arch of radius R over the polar angles theta in [0, alpha]; tangential displacement w(theta),
// radial u (outward). Inextensible: w' + u = 0, so u = -w'. The change of curvature is
// (u'' + u) / R^2 = -(w''' + w') / R^2 and the tangent's rotation (w - u') / R = (w + w'') / R.
// Hamilton's principle with the kinetic energy rho A (u'^2 + w'^2) / 2 per length gives, for
// w = W(theta) sin(omega t) and Omega = rho A R^4 omega^2 / EI,
//   W^(6) + 2 W^(4) + W'' = Omega (W'' - W)
// (check: W = e^{i k theta} gives Omega = k^2 (k^2 - 1)^2 / (k^2 + 1), the inextensible ring).
// Ends: pinned u = w = 0 and no moment, so W = W' = W''' = 0; clamped u = w = 0 and no
// rotation, so W = W' = W'' = 0. With y = (W, ..., W^(5)), y' = A(Omega) y, and
// Y = exp(A alpha): three components of y(0) are free, three of y(alpha) vanish; the
// frequencies are the roots of the 3 x 3 determinant, found by a scan in log Omega and
// bisection.
#pragma once

#include <unsupported/Eigen/MatrixFunctions>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace mbtest::arch {

enum class End { pinned, clamped };

/// The 3 x 3 boundary determinant at Omega (file comment).
inline double boundary_determinant(double alpha, End from, End to, double Omega) {
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 5; ++i) A(i, i + 1) = 1.0;
  A(5, 0) = -Omega;
  A(5, 2) = Omega - 1.0;
  A(5, 4) = -2.0;
  const Eigen::Matrix<double, 6, 6> Y = (A * alpha).exp();
  // Free at theta = 0: the derivatives not held there; vanishing at alpha: those held.
  const std::array<int, 3> free = from == End::pinned ? std::array<int, 3>{2, 4, 5} : std::array<int, 3>{3, 4, 5};
  const std::array<int, 3> held = to == End::pinned ? std::array<int, 3>{0, 1, 3} : std::array<int, 3>{0, 1, 2};
  Eigen::Matrix3d D;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = Y(held[i], free[j]);
  return D.determinant();
}

/// The `count` lowest Omega = rho A R^4 omega^2 / EI of the arch of opening `alpha` (rad),
/// ascending, to ~1e-13 relative. Throws std::runtime_error if fewer are found below 1e5.
inline std::vector<double> frequencies_squared(double alpha, End from, End to, int count) {
  std::vector<double> roots;
  double a = 1e-3, fa = boundary_determinant(alpha, from, to, a);
  while (static_cast<int>(roots.size()) < count && a < 1e5) {
    const double b = a * 1.002, fb = boundary_determinant(alpha, from, to, b);
    if ((fa > 0.0) != (fb > 0.0)) {
      double lo = a, hi = b, flo = fa;
      for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        const double mid = 0.5 * (lo + hi), fm = boundary_determinant(alpha, from, to, mid);
        if ((fm > 0.0) == (flo > 0.0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      roots.push_back(0.5 * (lo + hi));
    }
    a = b;
    fa = fb;
  }
  if (static_cast<int>(roots.size()) < count) throw std::runtime_error("mbtest::arch: too few roots below 1e5");
  return roots;
}

}  // namespace mbtest::arch
