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
//
// ## The extensible thin ring, exact per wave number (derived here from the Lagrangian)
// Same ring with a finite EA (an ExtensibleRing). Conventions of tests/support/arch.hpp and
// ring_receptance.hpp: w radial (outward), v tangential (counter-clockwise), ' = d/dtheta,
// strain eps = (v' + w)/R, rotation of the tangent phi = (v - w')/R, change of curvature phi'/R.
// Turning frame (Omega counter-clockwise; the basis (e_r, e_theta) turns with the ring, so the
// absolute velocity is (w_t - Omega v) e_r + (v_t + Omega (R + w)) e_theta):
//   T = rho A/2 int ((w_t - Omega v)^2 + (v_t + Omega (R + w))^2) R dtheta
//     = rho A R/2 int (w_t^2 + v_t^2) + rho A R Omega int (v_t w - v w_t)       (Coriolis)
//       + rho A R Omega^2/2 int (v^2 + w^2) + rho A R^2 Omega^2 int w           (centrifugal)
//       (+ a total time derivative rho A R^2 Omega d/dt int v, dropped).
//   U = int [EA/2 eps^2 + EI/2 (phi'/R)^2 + N0 E + (kr w^2 + kt v^2)/2] R dtheta, with the
//       centroid line's Green-Lagrange strain E = eps + (eps^2 + phi^2)/2 (|dr/dtheta|^2/R^2 =
//       1 + 2 eps + eps^2 + phi^2 exactly, for r = (R + w) e_r + v e_theta).
// The terms linear in w balance when N0 = rho A Omega^2 R^2 (tension = spin; N0 = 0 for none,
// whose unbalanced centrifugal load is ignored by definition). The Euler-Lagrange equations,
// divided by R, with m = rho A, a = (EA + N0)/R^2, b = EI/R^4, n = N0/R^2, c = m Omega^2:
//   m w_tt - 2 m Omega v_t + b (w'''' - v''') + a (w + v') + n (v' - w'') + (kr - c) w = 0,
//   m v_tt + 2 m Omega w_t - a (v'' + w') - b (v'' - w''') + n (v - w') + (kt - c) v = 0.
// On (w, v) = (W, V) e^{i (k theta + omega t)} (x(t) = Re(x e^{i omega t}), as
// modal/gyroscopic.hpp): (K_k - omega^2 M + i omega G) (W, V) = 0 with M = m I,
//   K_k = [[a + b k^4 + n k^2 + kr - c,   i kappa],
//          [-i kappa,   (a + b) k^2 + n + kt - c]],   kappa = k (a + b k^2 + n),
//   G = 2 m Omega [[0, -1], [1, 0]]  (the point mass's block of modal/gyroscopic.hpp).
// K_k is Hermitian and i omega G too, and the determinant is the REAL quartic
//   P(omega) = (K11 - m omega^2)(K22 - m omega^2) - (kappa - 2 m Omega omega)^2
//            = m^2 omega^4 - (m (K11 + K22) + 4 m^2 Omega^2) omega^2 + 4 m Omega kappa omega + det K_k,
//   det K_k = a (k^2 - 1)^2 (b k^2 + n) + f1 K22' + f2 K11' + f1 f2  (f1 = kr - c, f2 = kt - c,
//             K11' = K11 - f1, K22' = K22 - f2: written so, without cancellation, for a thin ring).
// Its four real roots (when stable): a root omega > 0 is the wave e^{i(k theta + omega t)},
// travelling clockwise (against the spin: backward); omega < 0 travels with it (forward).
// In the fixed frame (theta_fixed = theta + Omega t) the phase is k theta_fixed + (omega - k Omega) t:
// backward omega - k Omega (signed), forward |omega| + k Omega, as for the inextensible ring.
// The lower root of each sign is the flexural wave, the upper the extensional.
// A clockwise spin (Omega < 0) is the mirror image: the oracle uses |Omega|, and "forward" is
// always "with the spin".
// Exact checks in the derivation itself (tests/ring/test_spinning_oracle.cpp checks them
// numerically): P(k Omega) = 0 when b = kr = kt = 0, tension = spin, any EA (the spinning chain
// loop's backward wave stands still in space); P(Omega) = 0 at k = 1 without a foundation, either
// tension, any EA, EI (the rigid translation, at rest in space); Omega = 0 gives
// ring::closed_form::free_ring_extensible; k = 0 (kappa = 0): omega^2 roots of
// (K11 - m x)(K22 - m x) - 4 m^2 Omega^2 x, the free ring's breathing omega^2 = EA/(rho A R^2) +
// 4 Omega^2 under tension = spin (angular momentum r^2 theta_t kept, N = (N0 + EA w/R)(1 + w/R)).
// The N0 eps^2/2 part of N0 E adds N0/R^2 to a: relative N0/EA = rho Omega^2 R^2/E to the
// membrane stiffness, the order of the prestressed circle's expansion, which is left out (the
// linearisation is about the radius R); test rings keep it below 1e-6.
// Solve: the 4 x 4 companion matrix of P/m^2 (Eigen), each root then polished by Newton on P
// (the coefficients carry no cancellation, so the flexural roots keep their relative accuracy
// although they lie sqrt(A R^2/I) below the extensional ones).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

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

/// The ring of the extensible oracle: a Ring with its axial stiffness.
struct ExtensibleRing {
  Ring ring;
  double EA = 0.0;  ///< N
};

/// The extensible ring's wave number k: the flexural and the extensional wave pairs (turning and
/// fixed frame, WavePair's conventions: forward = travelling with the spin), and the quartic's
/// roots, ascending, signed (omega > 0: backward; file comment). The roots r0 <= r1 <= r2 <= r3
/// give extensional.forward = -r0, flexural.forward = -r1, flexural.backward = r2,
/// extensional.backward = r3: a forward frequency may come out negative (a wave that the spin
/// carries backward: the free ring's k = 1, whose forward and backward roots are both the
/// translation at rest in space, +Omega, as spintest::inextensible's forward = -Omega there; or
/// past a critical speed). k = 0 has no direction: both members of a pair are the same standing
/// frequency (the lower pair: the rotation held by kt, 0 without it; the upper: breathing).
/// Unstable (complex roots: flutter, divergence): every field is NaN, the real roots listed.
/// The quartic has no cubic term, so the roots sum to 0: the extensional pair is split the
/// other way by the same amount (its forward wave is the upper one, w_b - w_f equal and
/// opposite to the flexural pair's).
struct ExtensibleWaves {
  WavePair flexural, extensional;
  std::vector<double> roots;  ///< the real roots of P, ascending (4 when stable)
};

namespace detail {

/// P(omega) / m^2 of the file comment: omega^4 + c2 omega^2 + c1 omega + c0.
struct Quartic {
  double c2 = 0.0, c1 = 0.0, c0 = 0.0;
  double operator()(double x) const { return ((x * x + c2) * x + c1) * x + c0; }
  double slope(double x) const { return (4.0 * x * x + 2.0 * c2) * x + c1; }
};

inline Quartic extensible_quartic(const ExtensibleRing& e, int k) {
  const Ring& r = e.ring;
  const double R = r.radius, W = std::abs(r.speed), kk = double(k) * k, m = r.rhoA;
  const double N0 = r.tension ? m * W * W * R * R : 0.0;
  const double a = (e.EA + N0) / (R * R), b = r.EI / (R * R * R * R), n = N0 / (R * R), c = m * W * W;
  const double f1 = r.kr - c, f2 = r.kt - c;
  const double K11p = a + b * kk * kk + n * kk, K22p = (a + b) * kk + n;
  const double kappa = k * (a + b * kk + n);
  const double det = a * (kk - 1.0) * (kk - 1.0) * (b * kk + n) + f1 * K22p + f2 * K11p + f1 * f2;
  Quartic q;
  q.c2 = -((K11p + f1 + K22p + f2) / m + 4.0 * W * W);
  q.c1 = 4.0 * W * kappa / m;
  q.c0 = det / (m * m);
  return q;
}

}  // namespace detail

/// The extensible thin ring's waves k >= 0 (file comment).
inline ExtensibleWaves extensible(const ExtensibleRing& e, int k) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const detail::Quartic q = detail::extensible_quartic(e, k);
  std::vector<double> roots;
  if (q.c1 == 0.0) {  // k = 0 or no spin: biquadratic in x = omega^2, x^2 + c2 x + c0 = 0
    const double disc = q.c2 * q.c2 - 4.0 * q.c0;
    if (disc >= 0.0) {
      const double upper = 0.5 * (-q.c2 + std::sqrt(disc));
      const double lower = upper > 0.0 ? q.c0 / upper : 0.0;  // no cancellation
      for (double x : {lower, upper}) {
        if (x < 0.0 && x > -1e-13 * upper) x = 0.0;  // an exact 0 (the spin's change at k = 0) as round-off
        if (x >= 0.0) {
          roots.push_back(std::sqrt(x));
          roots.push_back(-std::sqrt(x));
        }
      }
    }
  } else {
    // Companion of the quartic in x = omega / s, s = sqrt(|c2|) (the extensional scale), so that
    // its coefficients are O(1) and the eigenvalues' round-off is eps s.
    const double sc = std::sqrt(std::abs(q.c2)) + std::abs(q.c1) / (std::abs(q.c2) + 1e-300) + 1e-300;
    Eigen::Matrix4d C = Eigen::Matrix4d::Zero();
    C(0, 1) = 1.0;
    C(1, 2) = 1.0;
    C(2, 3) = 1.0;
    C(3, 0) = -q.c0 / (sc * sc * sc * sc);
    C(3, 1) = -q.c1 / (sc * sc * sc);
    C(3, 2) = -q.c2 / (sc * sc);
    const Eigen::Vector4cd ev = sc * C.eigenvalues().array();
    const double scale = ev.cwiseAbs().maxCoeff();
    for (int i = 0; i < 4; ++i) {
      // Complex pairs (flutter, divergence) are not waves; a real root's imaginary part is the
      // companion's round-off, ~1e-16 of the largest root, ~1e-8 at a double root (1e-6: above
      // both; a flutter that weak is taken for a double root).
      if (std::abs(ev[i].imag()) > 1e-6 * scale) continue;
      double x = ev[i].real();
      for (int it = 0; it < 60; ++it) {  // Newton, kept only while |P| falls
        const double d = q(x) / q.slope(x);
        if (!std::isfinite(d) || !(std::abs(q(x - d)) < std::abs(q(x)))) break;
        x -= d;
      }
      roots.push_back(x);
    }
    std::sort(roots.begin(), roots.end());
    // A double root (k = 1 of a free ring: the translation at rest in space, with its secular
    // companion) comes out of the companion and Newton only to sqrt(eps); it is the root of P'
    // there, which Newton finds quadratically.
    for (std::size_t i = 0; i + 1 < roots.size(); ++i)
      if (roots[i + 1] - roots[i] < 1e-6 * scale) {
        double x = 0.5 * (roots[i] + roots[i + 1]);
        for (int it = 0; it < 60; ++it) {
          const double d = q.slope(x) / ((12.0 * x * x + 2.0 * q.c2));
          if (!std::isfinite(d) || d == 0.0) break;
          x -= d;
          if (std::abs(d) < 1e-16 * std::abs(x)) break;
        }
        roots[i] = roots[i + 1] = x;
        ++i;
      }
  }
  std::sort(roots.begin(), roots.end());
  ExtensibleWaves out;
  out.roots = roots;
  const double W = std::abs(e.ring.speed);
  auto fill = [&](WavePair& p, double forward, double backward) {
    p.forward = forward;
    p.backward = backward;
    p.forward_fixed = forward + k * W;
    p.backward_fixed = backward - k * W;
  };
  fill(out.flexural, nan, nan);
  fill(out.extensional, nan, nan);
  if (roots.size() == 4) {
    fill(out.flexural, -roots[1], roots[2]);
    fill(out.extensional, -roots[0], roots[3]);
  }
  return out;
}

}  // namespace spintest
