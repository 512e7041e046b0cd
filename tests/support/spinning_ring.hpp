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
//
// ## The Timoshenko ring (shear and rotary inertia), exact per wave number
// A TimoshenkoRing adds the cross-section's rotation psi (its own field), the shear stiffness
// kGA and the rotary inertia rho I, with ring::closed_form::free_ring_timoshenko's kinematics:
// shear strain gamma = psi - phi, change of curvature psi'/R (phi = (v - w')/R as above), energy
// per length EA/2 eps^2 + kGA/2 gamma^2 + EI/2 (psi'/R)^2 + N0 E + foundation. The section turns
// at Omega + psi_t in space: its kinetic energy rho I/2 (Omega + psi_t)^2 has no Coriolis term
// (rho I Omega psi_t is a total time derivative) and no centrifugal softening (as the shared
// vocabulary's K: the softening is of the translations' mass only). On q = (W, V, P) e^{i k theta},
// P = R psi, each energy term c (l q)^2 contributes c l^H l to K_k:
//   eps:    l = (1, ik, 0)/R,    c = EA + N0      (N0 E's eps^2/2 included, as above)
//   gamma:  l = (ik, -1, 1)/R,   c = kGA
//   psi'/R: l = (0, 0, ik)/R^2,  c = EI
//   phi:    l = (-ik, 1, 0)/R,   c = N0           (N0 E's phi^2/2)
// plus diag(kr - c, kt - c, 0); M = diag(m, m, rho I/R^2); G = 2 m Omega on (W, V) as above.
// (kGA -> infinity: P = V - ik W and the bending row is (k^2, ik, 0)/R^2: the Euler-Bernoulli
// K_k above.) The thin ring's stiff terms (EA, kGA: up to 1e16 above the flexural scale) are
// taken apart exactly: in y = (l_eps q, l_gamma q, V) R, q = T y with
//   T = [[1, 0, -ik], [0, 0, 1], [-ik, 1, 1 - k^2]]   (columns y1, y2, y3; det T = -1),
// the stiff terms are diag(alpha, beta, 0), alpha = (EA + N0)/R^2, beta = kGA/R^2, and the rest
// S(omega) = T^H (K_soft - omega^2 M + i omega G) T is of the flexural scale, so
//   f(omega) = det(diag(alpha, beta, 0) + S)/(alpha beta)
//            = S33 + det S[y2 y3]/beta + det S[y1 y3]/alpha + det S/(alpha beta)
// (real: the matrix is Hermitian) carries no cancellation, and takes EA or kGA = infinity
// (1/alpha or 1/beta = 0: y1 = 0 is inextensibility, y2 = 0 Euler-Bernoulli; y3 alone is
// spintest::inextensible's mode, w = -v', R psi = v - w'). Roots: first guesses from the
// Hermitian linearisation [[0, Kt^(1/2)], [Kt^(1/2), i Gt]] (Kt, Gt: K and G in coordinates
// where M = I, on the finite coordinates; a massless y2 (rho I = 0) condensed out first, exactly,
// as it has neither mass nor Coriolis term), whose eigenvalues are the roots to eps times the
// largest; the non-Hermitian companion when Kt is not positive definite. Then Newton on f
// (central-difference slope), and a close pair (the free ring's k = 1 translation) as the
// root of f'. Branches ascending: n finite coordinates give 2 n roots r_0 <= ... <= r_{2n-1},
// branch j forward -r_{n-1-j}, backward r_{n+j} (j = 0 flexural; then extensional and shear,
// ascending, as ring::closed_form::free_ring_timoshenko's).
#pragma once

#include "ring/spec.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <limits>
#include <vector>

namespace spintest {

struct Ring {
  double radius = 10.0;       ///< R, m
  double EI = 0.0;            ///< N m^2
  double rhoA = 0.0;          ///< kg/m
  double kr = 0.0, kt = 0.0;  ///< foundation, N/m^2
  double speed = 0.0;         ///< Omega, rad/s
  bool tension = true;        ///< rotation.tension = "spin"
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

/// The closed form's ring of a spec (radius, EI, rho A, foundation, speed, tension): the
/// solvers' tests state their ring once, as a RingSpec, and take the oracle's from it.
inline Ring from_spec(const ring::RingSpec& s) {
  Ring r;
  r.radius = s.radius;
  r.EI = s.EI();
  r.rhoA = s.rhoA();
  r.kr = s.foundation.radial;
  r.kt = s.foundation.tangential;
  r.speed = s.rotation.speed;
  r.tension = s.rotation.tension == ring::Rotation::Tension::spin;
  return r;
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
    // A pair closer than 1e-6 of the scale is taken for one double root when P at the root of
    // P' between them is at round-off (100 eps times the sum of P's terms' sizes); a distinct
    // pair there has P = -P'' (sep/2)^2/2, above that for sep > ~1e-7 of the root.
    for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
      const double sep = roots[i + 1] - roots[i];
      if (sep >= 1e-6 * scale) continue;
      double x = 0.5 * (roots[i] + roots[i + 1]);
      for (int it = 0; it < 60; ++it) {
        const double d = q.slope(x) / ((12.0 * x * x + 2.0 * q.c2));
        if (!std::isfinite(d) || d == 0.0) break;
        x -= d;
        if (std::abs(d) < 1e-16 * std::abs(x)) break;
      }
      const double size = x * x * x * x + std::abs(q.c2) * x * x + std::abs(q.c1 * x) + std::abs(q.c0);
      if (std::abs(q(x)) <= 100.0 * std::numeric_limits<double>::epsilon() * size) {
        roots[i] = roots[i + 1] = x;
        ++i;
      }
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

/// The ring of the Timoshenko oracle (file comment): an ExtensibleRing's data with the shear
/// stiffness and the rotary inertia. EA or kGA may be infinite (inextensible; Euler-Bernoulli).
struct TimoshenkoRing {
  Ring ring;
  double EA = std::numeric_limits<double>::infinity();   ///< N
  double kGA = std::numeric_limits<double>::infinity();  ///< N
  double rhoI = 0.0;                                     ///< kg m
};

/// The Timoshenko ring's wave number k: branches ascending (flexural first), each a WavePair,
/// and the real roots, ascending (file comment). Unstable: branches empty, roots listed.
struct TimoshenkoWaves {
  std::vector<WavePair> branches;
  std::vector<double> roots;
};

namespace detail {

struct TimoshenkoPencil {
  Eigen::Matrix3cd T, K, M, G;  ///< K = K_soft (without the EA and kGA terms), in q = (W, V, P)
  double inv_alpha = 0.0, inv_beta = 0.0, alpha = 0.0, beta = 0.0;

  /// f(omega) of the file comment.
  double f(double w) const { return eval(w, false); }
  /// The same sum with every product by its size: f's round-off is eps times this.
  double size(double w) const { return eval(w, true); }

  double eval(double w, bool sizes) const {
    const std::complex<double> I(0.0, 1.0);
    Eigen::Matrix3cd S;
    if (sizes)
      S = (T.cwiseAbs().transpose() * (K.cwiseAbs() + w * w * M.cwiseAbs() + std::abs(w) * G.cwiseAbs()) * T.cwiseAbs())
              .cast<std::complex<double>>();
    else
      S = T.adjoint() * (K - w * w * M + I * w * G) * T;
    auto minor = [&](int a, int b) {
      return sizes ? std::abs(S(a, a) * S(b, b)) + std::abs(S(a, b) * S(b, a))
                   : (S(a, a) * S(b, b) - S(a, b) * S(b, a)).real();
    };
    double v = sizes ? std::abs(S(2, 2)) : S(2, 2).real();
    if (inv_beta != 0.0) v += inv_beta * minor(1, 2);
    if (inv_alpha != 0.0) v += inv_alpha * minor(0, 2);
    if (inv_alpha != 0.0 && inv_beta != 0.0) {
      if (sizes) {  // the six products of the 3 x 3 determinant
        double d = 0.0;
        const int P[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        for (const auto& r : P) d += std::abs(S(0, r[0]) * S(1, r[1]) * S(2, r[2]));
        v += inv_alpha * inv_beta * d;
      } else {
        v += inv_alpha * inv_beta * S.determinant().real();
      }
    }
    return sizes ? std::abs(v) : v;
  }
};

inline TimoshenkoPencil timoshenko_pencil(const TimoshenkoRing& t, int k) {
  const Ring& r = t.ring;
  const std::complex<double> ik(0.0, double(k));
  const double R = r.radius, W = std::abs(r.speed), m = r.rhoA, kk = double(k) * k;
  const double N0 = r.tension ? m * W * W * R * R : 0.0, c = m * W * W;
  TimoshenkoPencil p;
  p.T << 1.0, 0.0, -ik, 0.0, 0.0, 1.0, -ik, 1.0, 1.0 - kk;
  Eigen::RowVector3cd phi(-ik, 1.0, 0.0);
  p.K = (N0 / (R * R)) * phi.adjoint() * phi;
  p.K(2, 2) += r.EI * kk / (R * R * R * R);
  p.K(0, 0) += r.kr - c;
  p.K(1, 1) += r.kt - c;
  p.M = Eigen::Matrix3cd::Zero();
  p.M(0, 0) = m;
  p.M(1, 1) = m;
  p.M(2, 2) = t.rhoI / (R * R);
  p.G = Eigen::Matrix3cd::Zero();
  p.G(0, 1) = -2.0 * m * W;
  p.G(1, 0) = 2.0 * m * W;
  p.alpha = (t.EA + N0) / (R * R);
  p.beta = t.kGA / (R * R);
  p.inv_alpha = std::isinf(t.EA) ? 0.0 : 1.0 / p.alpha;
  p.inv_beta = std::isinf(t.kGA) ? 0.0 : 1.0 / p.beta;
  return p;
}

}  // namespace detail

/// The Timoshenko ring's waves k >= 0 (file comment).
inline TimoshenkoWaves timoshenko(const TimoshenkoRing& t, int k) {
  using Mat = Eigen::MatrixXcd;
  const std::complex<double> I(0.0, 1.0);
  const detail::TimoshenkoPencil p = detail::timoshenko_pencil(t, k);
  // y-coordinates: the stiff terms on the diagonal; keep the finite ones (y3 always).
  const Eigen::Matrix3cd Ky0 = p.T.adjoint() * p.K * p.T, My0 = p.T.adjoint() * p.M * p.T,
                         Gy0 = p.T.adjoint() * p.G * p.T;
  std::vector<int> keep;
  if (p.inv_alpha != 0.0) keep.push_back(0);
  if (p.inv_beta != 0.0) keep.push_back(1);
  keep.push_back(2);
  const int n0 = int(keep.size());
  Mat K(n0, n0), Ms(n0, n0), G(n0, n0);
  for (int i = 0; i < n0; ++i)
    for (int j = 0; j < n0; ++j) {
      K(i, j) = Ky0(keep[i], keep[j]);
      Ms(i, j) = My0(keep[i], keep[j]);
      G(i, j) = Gy0(keep[i], keep[j]);
    }
  for (int i = 0; i < n0; ++i) {
    if (keep[i] == 0) K(i, i) += p.alpha;
    if (keep[i] == 1) K(i, i) += p.beta;
  }
  if (t.rhoI == 0.0 && p.inv_beta != 0.0) {      // y2 massless, no Coriolis: condense it exactly
    const int s = (p.inv_alpha != 0.0) ? 1 : 0;  // its position in keep
    std::vector<int> rest;
    for (int i = 0; i < n0; ++i)
      if (i != s) rest.push_back(i);
    const int n1 = int(rest.size());
    Mat K1(n1, n1), M1(n1, n1), G1(n1, n1);
    for (int i = 0; i < n1; ++i)
      for (int j = 0; j < n1; ++j) {
        K1(i, j) = K(rest[i], rest[j]) - K(rest[i], s) * K(s, rest[j]) / K(s, s);
        M1(i, j) = Ms(rest[i], rest[j]);
        G1(i, j) = G(rest[i], rest[j]);
      }
    K = K1;
    Ms = M1;
    G = G1;
  }
  const int n = int(K.rows());
  // M = L L^H: Kt = L^-1 K L^-H, Gt likewise.
  const Eigen::LLT<Mat> llt(Ms);
  Mat Kt = llt.matrixL().solve(K);
  Kt = llt.matrixL().solve(Kt.adjoint().eval()).adjoint().eval();
  Mat Gt = llt.matrixL().solve(G);
  Gt = llt.matrixL().solve(Gt.adjoint().eval()).adjoint().eval();
  Kt = (0.5 * (Kt + Kt.adjoint())).eval();
  Gt = (0.5 * (Gt - Gt.adjoint())).eval();
  std::vector<std::complex<double>> guesses;
  const Eigen::SelfAdjointEigenSolver<Mat> ke(Kt);
  if (ke.eigenvalues().minCoeff() > 0.0) {
    const Mat root = ke.eigenvectors() * ke.eigenvalues().cwiseSqrt().asDiagonal() * ke.eigenvectors().adjoint();
    Mat H = Mat::Zero(2 * n, 2 * n);
    H.topRightCorner(n, n) = root;
    H.bottomLeftCorner(n, n) = root;
    H.bottomRightCorner(n, n) = I * Gt;
    const Eigen::SelfAdjointEigenSolver<Mat> he(0.5 * (H + H.adjoint()));
    for (int i = 0; i < 2 * n; ++i) guesses.push_back(he.eigenvalues()[i]);
  } else {
    Mat Z = Mat::Zero(2 * n, 2 * n);
    Z.topRightCorner(n, n) = Mat::Identity(n, n);
    Z.bottomLeftCorner(n, n) = Kt;
    Z.bottomRightCorner(n, n) = I * Gt;
    const Eigen::ComplexEigenSolver<Mat> ce(Z);
    for (int i = 0; i < 2 * n; ++i) guesses.push_back(ce.eigenvalues()[i]);
  }
  double scale = 0.0;
  for (const auto& g : guesses) scale = std::max(scale, std::abs(g));
  auto slope = [&](double x) {
    const double h = 1e-6 * std::max(std::abs(x), 1e-3 * scale);
    return (p.f(x + h) - p.f(x - h)) / (2.0 * h);
  };
  std::vector<double> roots;
  for (const auto& g : guesses) {
    if (std::abs(g.imag()) > 1e-6 * scale) continue;  // flutter, divergence (as extensible)
    double x = g.real();
    for (int it = 0; it < 60; ++it) {
      const double fx = p.f(x), d = fx / slope(x);
      if (!std::isfinite(d) || !(std::abs(p.f(x - d)) < std::abs(fx))) break;
      x -= d;
    }
    roots.push_back(x);
  }
  std::sort(roots.begin(), roots.end());
  for (std::size_t i = 0; i + 1 < roots.size(); ++i) {  // a double root: the root of f' (as extensible)
    const double sep = roots[i + 1] - roots[i];
    if (sep < 1e-6 * scale) {
      double x = 0.5 * (roots[i] + roots[i + 1]);
      for (int it = 0; it < 60; ++it) {
        const double h = 1e-4 * std::max(std::abs(x), 1e-3 * scale);
        const double d1 = (p.f(x + h) - p.f(x - h)) / (2.0 * h);
        const double d2 = (p.f(x + h) - 2.0 * p.f(x) + p.f(x - h)) / (h * h);
        const double d = d1 / d2;
        if (!std::isfinite(d) || std::abs(d) < 1e-15 * std::abs(x)) break;
        x -= d;
      }
      if (std::abs(p.f(x)) <= 100.0 * std::numeric_limits<double>::epsilon() * p.size(x)) {
        roots[i] = roots[i + 1] = x;
        ++i;
      }
    }
  }
  TimoshenkoWaves out;
  out.roots = roots;
  if (int(roots.size()) == 2 * n) {
    const double W = std::abs(t.ring.speed);
    for (int j = 0; j < n; ++j) {
      WavePair w;
      w.forward = -roots[n - 1 - j];
      w.backward = roots[n + j];
      w.forward_fixed = w.forward + k * W;
      w.backward_fixed = w.backward - k * W;
      out.branches.push_back(w);
    }
  }
  return out;
}

}  // namespace spintest
