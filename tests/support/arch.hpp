// Independent oracles for circular arches (issue 48), written from the mechanics without any
// solver's code: the natural frequencies of a curved Euler-Bernoulli arch by its exact
// transfer matrix, DaDeppo & Schmidt's deep arch under an apex load by shooting on the
// inextensible elastica, and Timoshenko & Gere's buckling pressures of pinned and clamped
// arches under uniform follower pressure.
//
// Conventions (those of ring::closed_form and ring_receptance.hpp): polar angle theta
// counter-clockwise, radial displacement w (outward), tangential v (counter-clockwise),
// strain eps = (v' + w)/R, rotation of the tangent phi = (v - w')/R, change of curvature
// phi'/R (' = d/dtheta). An arch of opening alpha runs from theta = 0 to theta = alpha.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

namespace archtest {

// ---------------------------------------------------------------------------------------
// 1. Natural frequencies of a circular arch.
//
// Equations. Cut the arch at theta; the part beyond the cut acts on the part before it with
// the force N e_theta + Q e_r (N: hoop force, tension positive; Q: radial shear) and the
// moment M (counter-clockwise). Balance of an element R dtheta (e_r' = e_theta,
// e_theta' = -e_r), harmonic motion at omega, no distributed load:
//   N' = -Q - R rhoA omega^2 v,   Q' = N - R rhoA omega^2 w,   M' = R Q - R rhoI omega^2 phi,
// and the constitutive and kinematic relations
//   w' = v - R phi,   v' = R N / EA - w,   phi' = R M / EI.
// Optionally (kGA finite) Timoshenko's shear: phi is then the rotation of the cross-section,
// the centroid line's tangent turns by (v - w')/R = phi - gamma with the shear strain
// gamma = Q / kGA (the thin-ring kinematics of ring::closed_form::free_ring_timoshenko), so
//   w' = v - R phi + R Q / kGA;
// a clamp holds the cross-section's rotation.
// Optionally a Winkler foundation (kr radial, kt tangential, N/m per metre, on the displacements
// of the undeformed point) adds R kt v to N' and R kr w to Q' (the inertia terms' places).
// In units R = EI = rhoA = 1 (state y = (w/R, v/R, phi, M R/EI, N R^2/EI, Q R^2/EI),
// Omega^2 = rhoA omega^2 R^4 / EI, e = EI/(EA R^2), j = rhoI/(rhoA R^2), g = EI/(kGA R^2)):
//   y' = A(Omega) y,  A constant along the arch, so y(alpha) = exp(A alpha) y(0).
// e = 0 is the exact inextensible arch (v' = -w, N a reaction): the system stays regular.
//
// End conditions (three of the six components vanish at each end):
//   free    M = N = Q = 0,   pinned  w = v = M = 0,   clamped  w = v = phi = 0.
// With B0 (6 x 3) the components left free at theta = 0 and C1 (3 x 6) those fixed at
// theta = alpha, the frequencies are the roots of D(Omega) = det(C1 exp(A alpha) B0).
// D is an entire function of Omega^2 (exp(A alpha) is), so it has no poles: every simple
// root is a sign change. The exponential grows like exp(alpha sqrt(Omega)) along the
// arch, so D is formed stably: the state scaled by the bending wavenumber kappa =
// max(1, sqrt(Omega)) (y = diag(1, 1, kappa, kappa^2, kappa^3, kappa^3) y~, which only
// multiplies D by a positive factor), the arch cut into m pieces of growth <= e^3, the
// three columns carried through the pieces and re-orthonormalized (QR) after each,
// D = det(C1 Q_m) prod det(R_i) kept as a sign and a logarithm (continuous orthonormalization,
// Godunov / Conte 1966). Roots by sign changes on a grid in sqrt(Omega) (64 points per
// straight beam's mode spacing pi/alpha) and bisection to the last bits.
// Error: the matrix exponential's (Pade, scaling and squaring: ~1e-15 relative per piece)
// and the bisection's; ~1e-12 relative on the frequencies. Two roots closer than a grid
// step would be missed; the tests count modes against independent oracles.

enum class End { free, pinned, clamped };

/// A circular arch of radius R and opening alpha (radians, 0 < alpha <= 2 pi).
/// EA = infinity: the inextensible arch. rhoI: rotary inertia per length (0: none).
/// kGA = infinity: Euler-Bernoulli (no shear strain); finite: Timoshenko's shear.
struct Arch {
  double R = 1.0;
  double alpha = M_PI;
  double EI = 1.0;
  double EA = std::numeric_limits<double>::infinity();
  double rhoA = 1.0;
  double rhoI = 0.0;
  double kGA = std::numeric_limits<double>::infinity();
  double kr = 0.0, kt = 0.0;  ///< Winkler foundation, radial and tangential, N/m per metre (>= 0)
  End start = End::pinned;    ///< the end at theta = 0 (ring.arc's `from`)
  End end = End::pinned;      ///< the end at theta = alpha (ring.arc's `to`)
};

namespace detail {

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// The components of y = (w, v, phi, M, N, Q) that an end fixes.
inline std::array<int, 3> fixed_components(End e) {
  switch (e) {
    case End::free: return {3, 4, 5};
    case End::pinned: return {0, 1, 3};
    case End::clamped: return {0, 1, 2};
  }
  throw std::invalid_argument("archtest: unknown end condition");
}

/// The components an end leaves free (the complement of fixed_components).
inline std::array<int, 3> free_components(End e) {
  const auto f = fixed_components(e);
  std::array<int, 3> out{};
  int k = 0;
  for (int i = 0; i < 6; ++i)
    if (i != f[0] && i != f[1] && i != f[2]) out[k++] = i;
  return out;
}

/// A of y' = A y in units R = EI = rhoA = 1, for Omega^2 = W2, e = EI/(EA R^2), j = rhoI/(rhoA R^2),
/// g = EI/(kGA R^2).
/// Foundation: fr = kr R^4/EI, ft = kt R^4/EI.
inline Mat6 system_matrix(double W2, double e, double j, double g = 0.0, double fr = 0.0, double ft = 0.0) {
  Mat6 A = Mat6::Zero();
  A(0, 1) = 1.0;  // w'   = v - phi + g Q
  A(0, 2) = -1.0;
  A(0, 5) = g;
  A(1, 0) = -1.0;  // v'   = -w + e N
  A(1, 4) = e;
  A(2, 3) = 1.0;  // phi' = M
  A(3, 5) = 1.0;  // M'   = Q - j Omega^2 phi
  A(3, 2) = -j * W2;
  A(4, 5) = -1.0;  // N'   = -Q - (Omega^2 - ft) v
  A(4, 1) = -(W2 - ft);
  A(5, 4) = 1.0;  // Q'   = N - (Omega^2 - fr) w
  A(5, 0) = -(W2 - fr);
  return A;
}

struct SignedLog {
  int sign = 1;
  double log_abs = 0.0;
};

/// D(Omega) = det(C1 exp(A alpha) B0) up to a positive factor, as sign and log|.|.
/// Cost O(m) 6 x 3 QRs and one 6 x 6 exponential, m ~ alpha sqrt(Omega) / 3.
inline SignedLog boundary_determinant(const Arch& a, double Omega) {
  const double e = std::isinf(a.EA) ? 0.0 : a.EI / (a.EA * a.R * a.R);
  const double j = a.rhoI / (a.rhoA * a.R * a.R);
  const double g = std::isinf(a.kGA) ? 0.0 : a.EI / (a.kGA * a.R * a.R);
  const double W2 = Omega * Omega, kappa = std::max(1.0, std::sqrt(Omega));
  const double f = a.EI / (a.R * a.R * a.R * a.R);
  Mat6 A = system_matrix(W2, e, j, g, a.kr / f, a.kt / f);
  const Eigen::Matrix<double, 6, 1> d{1.0, 1.0, kappa, kappa * kappa, kappa * kappa * kappa, kappa * kappa * kappa};
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) A(r, c) *= d(c) / d(r);  // A~ = D^-1 A D
  const double norm = A.cwiseAbs().rowwise().sum().maxCoeff();
  const int m = 1 + static_cast<int>(a.alpha * norm / 3.0);
  const Mat6 T = (A * (a.alpha / m)).exp();
  Eigen::Matrix<double, 6, 3> Y = Eigen::Matrix<double, 6, 3>::Zero();
  const auto b0 = free_components(a.start);
  for (int k = 0; k < 3; ++k) Y(b0[k], k) = 1.0;
  SignedLog out;
  for (int p = 0; p < m; ++p) {
    Y = T * Y;
    Eigen::HouseholderQR<Eigen::Matrix<double, 6, 3>> qr(Y);
    const Eigen::Matrix<double, 6, 3> R6 = qr.matrixQR();
    for (int k = 0; k < 3; ++k) {
      const double r = R6(k, k);
      if (r < 0) out.sign = -out.sign;
      out.log_abs += std::log(std::abs(r));
    }
    Y = qr.householderQ() * Eigen::Matrix<double, 6, 3>::Identity();
  }
  const auto c1 = fixed_components(a.end);
  Eigen::Matrix3d C;
  for (int r = 0; r < 3; ++r) C.row(r) = Y.row(c1[r]);
  const double det = C.determinant();
  if (det < 0) out.sign = -out.sign;
  out.log_abs += std::log(std::abs(det));
  return out;
}

}  // namespace detail

/// The `count` lowest elastic natural frequencies (rad/s, ascending) of the arch; the zero
/// frequencies of rigid motions (free-free: 3, free-pinned: 1) are not listed.
/// Cost: ~64 determinant evaluations per mode plus ~50 per root.
inline std::vector<double> arch_omegas(const Arch& a, std::size_t count) {
  if (!(a.alpha > 0.0 && a.alpha <= 2.0 * M_PI + 1e-12) || !(a.R > 0) || !(a.EI > 0) || !(a.EA > 0) || !(a.rhoA > 0) ||
      !(a.rhoI >= 0) || !(a.kGA > 0) || !(a.kr >= 0) || !(a.kt >= 0))
    throw std::invalid_argument("archtest::arch_omegas: need 0 < alpha <= 2 pi and positive R, EI, EA, kGA, rhoA");
  auto sign_at = [&](double t) { return detail::boundary_determinant(a, t * t).sign; };
  const double dt = M_PI / a.alpha / 64.0;
  std::vector<double> out;
  // Start a fraction of a step above 0: at Omega = 0 the rigid motions make D vanish.
  double ta = 0.25 * dt;
  int sa = sign_at(ta);
  for (int i = 1; out.size() < count; ++i) {
    if (i > 200000) throw std::runtime_error("archtest::arch_omegas: too few roots found");
    const double tb = 0.25 * dt + i * dt;
    const int sb = sign_at(tb);
    if (sb != sa) {
      double lo = ta, hi = tb;
      for (int it = 0; it < 200 && hi - lo > 2e-16 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (sign_at(mid) == sa ? lo : hi) = mid;
      }
      const double t = 0.5 * (lo + hi);
      out.push_back(t * t * std::sqrt(a.EI / (a.rhoA * a.R * a.R * a.R * a.R)));
    }
    ta = tb;
    sa = sb;
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// 2. DaDeppo & Schmidt's deep arch (D. A. DaDeppo and R. Schmidt, "Instability of clamped-
// hinged circular arches subjected to a point load", J. Appl. Mech. 42, 1975, 894-896:
// P R^2/EI = 8.97 at the limit; Simo & Vu-Quoc 1986 and others reproduce ~9.0-9.1 with
// extensible, shear-flexible elements).
//
// Geometry: radius R = 1, opening 215 degrees symmetric about the vertical through the apex
// (0, 1): the centroid line runs counter-clockwise from the clamped end at -17.5 degrees
// (the arc's `from`, right) to the pinned end at 197.5 degrees (`to`, left). A downward
// dead load P at the apex (arc length L/2). The mirror problem (clamp on the left) has the
// same load and vertical displacement and the opposite horizontal one.
//
// Inextensible, unshearable elastica in the arc length s from the clamp, tangent angle psi,
// units R = EI = 1 (loads in EI/R^2, lengths in R):
//   x' = cos psi,  y' = sin psi,  psi' = 1 + M,  M' = n_x sin psi - n_y cos psi,
// with (n_x, n_y) the force that the part beyond s exerts on [0, s]: the pin's reaction
// (h_x, h_y) for s > L/2 and (h_x, h_y - P) for s < L/2 (moment balance of an element:
// dM/ds + t x n = 0). At the clamp x, y, psi are the undeformed values; unknowns M(0), h_x,
// h_y and P; conditions x(L), y(L) at the pin, M(L) = 0, and the prescribed apex descent
// 1 - y(L/2) = d (the path parameter: it passes the limit point in P). Shooting with classical
// RK4 on `steps` equal steps (the apex on a node), Newton with the exact Jacobian of the
// discrete map (RK4 applied to the variational equations), continuation in d from the
// unloaded arch (secant predictor). Error O(h^4) (the tests fit it); the limit is the root
// of dP/dd = 0 (implicit differentiation of the converged system), by the secant method.
// Measured (steps 250 .. 2000, differences falling 16-fold per halving; Richardson-extrapolated):
// P R^2/EI = 8.97308997, apex dx = -0.61141466 R (towards the pin), dy = -1.13732063 R at the
// limit; steps = 2000 is within 2e-10 of the extrapolated load.

struct DeepArchPoint {
  double load = 0.0;     ///< P R^2 / EI
  double apex_dx = 0.0;  ///< horizontal displacement of the apex / R (clamp on the right)
  double apex_dy = 0.0;  ///< vertical displacement of the apex / R (negative: down)
};

namespace detail {

struct DeepArch {
  int steps;
  double half = 107.5 * M_PI / 180.0;
  double L = 2.0 * half;
  double theta_c = 0.5 * M_PI - half, theta_p = 0.5 * M_PI + half;

  struct Shot {
    Eigen::Vector4d F;  // x(L) - x_p, y(L) - y_p, M(L), y_apex
    Eigen::Matrix4d J;  // dF / d(m0, hx, hy, P)
    double apex_x = 0.0;
  };

  /// One RK4 shot from the clamp with unknowns u = (M(0), h_x, h_y, P), and its Jacobian.
  Shot shoot(const Eigen::Vector4d& u) const {
    // z = (x, y, psi, M) and their derivatives with respect to u (4 x 4, column k: d/du_k).
    using Z = Eigen::Matrix<double, 4, 5>;
    auto f = [&](const Z& z, bool before_apex) {
      const double s = std::sin(z(2, 0)), c = std::cos(z(2, 0));
      const double nx = u(1), ny = u(2) - (before_apex ? u(3) : 0.0);
      Z r;
      r(0, 0) = c;
      r(1, 0) = s;
      r(2, 0) = 1.0 + z(3, 0);
      r(3, 0) = nx * s - ny * c;
      for (int k = 0; k < 4; ++k) {
        const double dpsi = z(2, k + 1);
        const double dnx = k == 1 ? 1.0 : 0.0, dny = k == 2 ? 1.0 : (k == 3 && before_apex ? -1.0 : 0.0);
        r(0, k + 1) = -s * dpsi;
        r(1, k + 1) = c * dpsi;
        r(2, k + 1) = z(3, k + 1);
        r(3, k + 1) = (nx * c + ny * s) * dpsi + dnx * s - dny * c;
      }
      return r;
    };
    Z z = Z::Zero();
    z(0, 0) = std::cos(theta_c);
    z(1, 0) = std::sin(theta_c);
    z(2, 0) = theta_c + 0.5 * M_PI;
    z(3, 0) = u(0);
    z(3, 1) = 1.0;
    const double h = L / steps;
    Shot out;
    for (int i = 0; i < steps; ++i) {
      if (i == steps / 2) {
        out.F(3) = z(1, 0);
        out.J.row(3) = z.block<1, 4>(1, 1);
        out.apex_x = z(0, 0);
      }
      const bool before = i < steps / 2;
      const Z k1 = f(z, before), k2 = f(z + 0.5 * h * k1, before), k3 = f(z + 0.5 * h * k2, before),
              k4 = f(z + h * k3, before);
      z += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    out.F(0) = z(0, 0) - std::cos(theta_p);
    out.F(1) = z(1, 0) - std::sin(theta_p);
    out.F(2) = z(3, 0);
    out.J.row(0) = z.block<1, 4>(0, 1);
    out.J.row(1) = z.block<1, 4>(1, 1);
    out.J.row(2) = z.block<1, 4>(3, 1);
    return out;
  }

  /// Newton on (pin, M(L) = 0, 1 - y_apex = d) from the guess u; returns the converged shot.
  Shot solve(Eigen::Vector4d& u, double d) const {
    for (int it = 0; it < 50; ++it) {
      Shot s = shoot(u);
      s.F(3) = 1.0 - s.F(3) - d;
      s.J.row(3) = -s.J.row(3);
      const Eigen::Vector4d du = s.J.partialPivLu().solve(-s.F);
      u += du;
      if (du.norm() <= 1e-13 * (1.0 + u.norm())) {
        s = shoot(u);
        s.F(3) = 1.0 - s.F(3) - d;
        s.J.row(3) = -s.J.row(3);
        return s;
      }
    }
    throw std::runtime_error("archtest: the deep arch's Newton did not converge at d = " + std::to_string(d));
  }

  /// dP/dd on the solved path: J du/dd = -dF/dd = (0, 0, 0, 1).
  static double slope(const Shot& s) { return s.J.partialPivLu().solve(Eigen::Vector4d(0, 0, 0, 1))(3); }
};

}  // namespace detail

/// The elastica's equilibrium with the apex lowered by `apex_down` (in R, >= 0), followed
/// from the unloaded arch in steps of at most 0.02 R. Cost O(steps) per Newton iteration,
/// ~3 iterations per continuation step. `steps` must be even.
inline DeepArchPoint deep_arch_at(double apex_down, int steps = 2000) {
  if (steps < 4 || steps % 2 != 0) throw std::invalid_argument("archtest::deep_arch_at: steps must be even and >= 4");
  if (!(apex_down >= 0.0)) throw std::invalid_argument("archtest::deep_arch_at: apex_down must be >= 0");
  const detail::DeepArch arch{steps};
  const int n = 1 + static_cast<int>(apex_down / 0.02);
  Eigen::Vector4d u = Eigen::Vector4d::Zero(), prev = u;
  detail::DeepArch::Shot s{};
  for (int k = 1; k <= n; ++k) {
    Eigen::Vector4d v = k > 1 ? Eigen::Vector4d(2.0 * u - prev) : u;  // secant predictor (equal steps)
    s = arch.solve(v, apex_down * k / n);
    prev = u;
    u = v;
  }
  return {u(3), s.apex_x, -apex_down};
}

/// The equilibrium on the rising branch (from the unloaded arch to the limit) under the apex
/// load `load` (P R^2/EI, 0 <= load < the limit load): continuation in d by 0.02 R until the
/// load is passed, then Newton on P(d) = load with dP/dd, safeguarded by bisection in that
/// bracket. Throws std::invalid_argument past the limit. For a solver's load-controlled path.
inline DeepArchPoint deep_arch_under(double load, int steps = 2000) {
  if (steps < 4 || steps % 2 != 0)
    throw std::invalid_argument("archtest::deep_arch_under: steps must be even and >= 4");
  if (!(load >= 0.0)) throw std::invalid_argument("archtest::deep_arch_under: load must be >= 0");
  if (load == 0.0) return {};
  const detail::DeepArch arch{steps};
  const double dd = 0.02;
  Eigen::Vector4d u = Eigen::Vector4d::Zero(), prev = u;
  double d = 0.0;
  for (int k = 1; k <= 200; ++k) {
    Eigen::Vector4d v = k > 1 ? Eigen::Vector4d(2.0 * u - prev) : u;
    detail::DeepArch::Shot s = arch.solve(v, d + dd);
    if (v(3) >= load) {
      double a = d, b = d + dd, c = b;
      Eigen::Vector4d uc = v;
      for (int it = 0; it < 100; ++it) {
        const double r = uc(3) - load;
        if (std::abs(r) <= 1e-13 * load) return {uc(3), s.apex_x, -c};
        (r < 0 ? a : b) = c;
        const double g = detail::DeepArch::slope(s);
        double next = g > 0 ? c - r / g : 0.5 * (a + b);
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        c = next;
        s = arch.solve(uc, c);
      }
      throw std::runtime_error("archtest::deep_arch_under: no convergence at load " + std::to_string(load));
    }
    if (detail::DeepArch::slope(s) <= 0.0)
      throw std::invalid_argument("archtest::deep_arch_under: load " + std::to_string(load) +
                                  " is above the limit load " + std::to_string(v(3)));
    prev = u;
    u = v;
    d += dd;
  }
  throw std::invalid_argument("archtest::deep_arch_under: load above the limit");
}

/// The limit point (maximum load) of the deep arch's equilibrium path from the unloaded arch:
/// {P R^2/EI, apex dx / R, apex dy / R}. Cost: ~60 continuation steps and ~10 secant steps.
inline DeepArchPoint deep_arch_limit(int steps = 2000) {
  if (steps < 4 || steps % 2 != 0)
    throw std::invalid_argument("archtest::deep_arch_limit: steps must be even and >= 4");
  const detail::DeepArch arch{steps};
  const double dd = 0.02;
  Eigen::Vector4d u = Eigen::Vector4d::Zero(), prev = u;
  double d = 0.0, g = 1.0;
  detail::DeepArch::Shot s{};
  for (int k = 1;; ++k) {
    if (k > 200) throw std::runtime_error("archtest::deep_arch_limit: no limit point up to d = 4 R");
    Eigen::Vector4d v = k > 1 ? Eigen::Vector4d(2.0 * u - prev) : u;
    s = arch.solve(v, d + dd);
    const double gv = detail::DeepArch::slope(s);
    if (gv <= 0.0) {
      // The root of dP/dd in (d, d + dd): secant (regula falsi, Illinois) on the slope.
      double a = d, b = d + dd, ga = g, gb = gv;
      Eigen::Vector4d ua = u, ub = v;
      int side = 0;
      for (int it = 0; it < 100 && b - a > 1e-13; ++it) {
        const double c = (a * gb - b * ga) / (gb - ga);
        Eigen::Vector4d uc = ua + (ub - ua) * ((c - a) / (b - a));
        s = arch.solve(uc, c);
        const double gc = detail::DeepArch::slope(s);
        if (std::abs(gc) < 1e-14) {
          a = b = c;
          ua = uc;
          break;
        }
        if ((gc > 0) == (ga > 0)) {
          a = c, ga = gc, ua = uc;
          if (side == -1) gb *= 0.5;
          side = -1;
        } else {
          b = c, gb = gc, ub = uc;
          if (side == 1) ga *= 0.5;
          side = 1;
        }
      }
      const double c = 0.5 * (a + b);
      Eigen::Vector4d uc = ua;
      s = arch.solve(uc, c);
      return {uc(3), s.apex_x, -c};
    }
    prev = u;
    u = v;
    d += dd;
    g = gv;
  }
}

// ---------------------------------------------------------------------------------------
// 3. Buckling of a circular arch under uniform follower (hydrostatic) pressure q (force per
// length, inward), inextensible, antisymmetric mode (S. P. Timoshenko & J. M. Gere, "Theory
// of Elastic Stability", 2nd ed., 1961, sec. 7.5), alpha = HALF the opening angle:
//   pinned ends:   q R^3 / EI = pi^2 / alpha^2 - 1,
//   clamped ends:  k tan(alpha) cot(k alpha) = 1,  q R^3 / EI = k^2 - 1.
// The clamped equation is tan(k alpha) = k tan(alpha); k = 1 always solves it (q = 0), the
// buckling root is x = k alpha in (pi, 2 pi): x in (pi, 3 pi/2) for alpha < pi/2, x = 3 pi/2
// at alpha = pi/2 (q R^3/EI = 8), x in (3 pi/2, 2 pi) beyond. Written without poles as
// h(x) = alpha cos(alpha) sin(x) - x sin(alpha) cos(x) = 0 (the equation times
// alpha cos(alpha) cos(x)), h(pi) = pi sin(alpha) > 0 > h(2 pi) = -2 pi sin(alpha), one root
// between; bisection to the last bit. Valid for 0 < alpha < pi.

inline double pinned_follower_pressure(double half_angle) {
  if (!(half_angle > 0.0 && half_angle < M_PI))
    throw std::invalid_argument("archtest::pinned_follower_pressure: need 0 < half angle < pi");
  return M_PI * M_PI / (half_angle * half_angle) - 1.0;
}

inline double clamped_follower_pressure(double half_angle) {
  const double a = half_angle;
  if (!(a > 0.0 && a < M_PI))
    throw std::invalid_argument("archtest::clamped_follower_pressure: need 0 < half angle < pi");
  auto h = [&](double x) { return a * std::cos(a) * std::sin(x) - x * std::sin(a) * std::cos(x); };
  double lo = M_PI, hi = 2.0 * M_PI;
  for (int it = 0; it < 200 && hi - lo > 4e-16 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (h(mid) > 0.0 ? lo : hi) = mid;
  }
  const double k = 0.5 * (lo + hi) / a;
  return k * k - 1.0;
}

}  // namespace archtest
