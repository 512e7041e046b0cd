// Oracles of the spinning ring (issue 49), in the frame that turns with it.
//
// ## The inextensible thin ring, closed form (derived here; Bryan 1890, Huang & Soedel 1987)
// A ring of radius R, bending stiffness EI, mass rho A per length, on a Winkler foundation
// (kr radial, kt tangential, N/m^2), spinning at Omega. Inextensible: the radial displacement
// u = -v' of the tangential v. For the wave number k, v = a cos k theta + b sin k theta; the
// kinetic energy in the turning frame, T = rho A/2 int ((u' - Omega v)^2 + (v' + Omega (R + u))^2)
// R dtheta (dots: time), gives per (a, b):
//   mass     m = pi rho A R (1 + k^2),
//   Coriolis g = 2 pi k rho A Omega R        (the term g (a b' - b a')),
//   stiffness K = pi EI k^2 (k^2 - 1)^2 / R^3               (bending)
//               + pi rho A Omega^2 R (k^2 - 1)^2            (the spin's hoop tension N0 = rho A Omega^2 R^2
//                                                           on the rotation (u' - v)/R; tension = "spin" only)
//               - pi rho A Omega^2 R (1 + k^2)              (centrifugal softening)
//               + pi R (kr k^2 + kt)                        (foundation),
// and m a'' - 2 g b' + K a = 0, m b'' + 2 g a' + K b = 0: with z = a + i b, m z'' + 2 i g z' + K z = 0,
// z = e^{i w t}:
//   w_forward = (sqrt(g^2 + m K) - g) / m,   w_backward = (sqrt(g^2 + m K) + g) / m   (turning frame).
// The forward wave travels with the spin. In the fixed frame the waves are w_forward + k Omega
// and w_backward - k Omega (the backward wave stands still where it crosses zero: the critical
// speed). The split is 2 g / m, whatever K: the pattern turns against the ring at
// (w_b - w_f) / (2 k) = 2 Omega / (k^2 + 1), so in space at Bryan's factor
//   (k^2 - 1) / (k^2 + 1) of the spin (0.6 for k = 2), exactly, for every foundation and tension.
// Check of the tension term: without bending and foundation (a spinning chain loop) the
// backward wave's w_b = k Omega: it stands still in space, the known shape-keeping loop.
#pragma once

#include <cmath>
#include <cstdlib>

namespace spintest {

struct Ring {
  double radius = 10.0;  ///< R, m
  double EI = 0.0;       ///< N m^2
  double rhoA = 0.0;     ///< kg/m
  double kr = 0.0, kt = 0.0;  ///< foundation, N/m^2
  double speed = 0.0;    ///< Omega, rad/s
  bool tension = true;   ///< rotation.tension = "spin"
};

struct WavePair {
  double forward = 0.0, backward = 0.0;              ///< turning frame, rad/s
  double forward_fixed = 0.0, backward_fixed = 0.0;  ///< fixed frame, signed (w + k Omega, w - k Omega)
};

/// The inextensible ring's wave pair k >= 1 (file comment).
inline WavePair inextensible(const Ring& r, int k) {
  const double pi = std::acos(-1.0), R = r.radius, W = std::abs(r.speed), k2 = double(k) * k;
  const double m = pi * r.rhoA * R * (1.0 + k2);
  const double g = 2.0 * pi * k * r.rhoA * W * R;
  const double K = pi * r.EI * k2 * (k2 - 1.0) * (k2 - 1.0) / (R * R * R) +
                   (r.tension ? pi * r.rhoA * W * W * R * (k2 - 1.0) * (k2 - 1.0) : 0.0) -
                   pi * r.rhoA * W * W * R * (1.0 + k2) + pi * R * (r.kr * k2 + r.kt);
  const double s = std::sqrt(g * g + m * K);
  WavePair p;
  p.forward = (s - g) / m;
  p.backward = (s + g) / m;
  p.forward_fixed = p.forward + k * W;
  p.backward_fixed = p.backward - k * W;
  return p;
}

/// Bryan's factor of the inextensible ring's wave k: (k^2 - 1) / (k^2 + 1).
inline double bryan_inextensible(int k) { return (double(k) * k - 1.0) / (double(k) * k + 1.0); }

}  // namespace spintest
