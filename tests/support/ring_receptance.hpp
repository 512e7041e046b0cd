// Independent oracles for the continuous ring with a point attachment at polar angle 0:
// receptances of the free, inextensible Euler-Bernoulli ring (no rotary inertia) built from
// its Fourier modes, written without any solver's code. Used by every solver's tests.
//
// Free modes (k >= 2, lambda_k = EI/(rho A R^4) k^2 (k^2 - 1)^2 / (k^2 + 1), Love sec. 294),
// each in two types, with radial w, tangential v (counter-clockwise) and the rotation of the
// tangent beta = (v - dw/dtheta) / R at theta = 0:
//   symmetric      w = cos k theta,  v = -sin(k theta)/k:  (w, v, beta)(0) = (1, 0, 0)
//   antisymmetric  w = sin k theta,  v =  cos(k theta)/k:  (w, v, beta)(0) = (0, 1/k, -(k^2 - 1)/(k R))
// both of modal mass pi R rho A (1 + 1/k^2). Rigid modes: the translations (k = 1, modal mass
// M_t = 2 pi R rho A: radial (1, 0, 0) and tangential (0, 1, 0) at 0) and the rotation about the
// centre (v = R alpha: (0, 1, 1/R) per unit R alpha, modal mass M_t).
// By the reflection symmetry about the diameter through 0 the point receptance splits into a
// radial part H_ww(lambda) and a 2 x 2 (v, beta) part, each = -rigid / lambda + sum_k
// phi_k phi_k^T / (M_k (lambda_k - lambda)); series to k = kmax, the beta-beta terms' 1/k^2 tail
// summed in closed form (h_vb).
//
// - A point mass m0 at 0 (no rotary inertia): roots of H_ww = 1/(m0 lambda) and of
//   H_vv = 1/(m0 lambda) with beta free, i.e. of the receptance h = -(r0 + 1/m0)/lambda +
//   sum r_k/(lambda_k - lambda), one root per gap between poles (bisection, as in
//   tests/multibody/ring_oracle.hpp). m0 -> infinity gives the ring pinned at 0.
// - A clamp at 0 (w = v = beta = 0): roots of H_ww(lambda) = 0 (the pinned ring's symmetric
//   family) and of det H_(v,beta)(lambda) = 0, found by sign changes on a fine grid inside
//   each gap between poles (continuous there) and bisection.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace receptance {

struct Ring {
  double R, EI, rhoA;
  int kmax = 20000;
  double lambda(int k) const {
    const double k2 = double(k) * k;
    return EI / (rhoA * R * R * R * R) * k2 * (k2 - 1) * (k2 - 1) / (k2 + 1);
  }
  double modal_mass(int k) const { return M_PI * R * rhoA * (1 + 1.0 / (double(k) * k)); }
  double total_mass() const { return 2 * M_PI * R * rhoA; }
};

/// Roots in each gap (0, lambda_2), (lambda_2, lambda_3), ... of a function continuous
/// inside the gaps, by sign changes on `samples` points per gap and bisection; at most
/// `count`, ascending.
template <class F>
std::vector<double> roots_in_gaps(const Ring& ring, F f, std::size_t count, int samples = 400) {
  std::vector<double> out;
  for (int k = 1; out.size() < count && k < ring.kmax; ++k) {
    const double a0 = k == 1 ? 0.0 : ring.lambda(k), b0 = ring.lambda(k + 1);
    // Sample away from the poles at the ends (relative 1e-12 of the gap).
    const double eps = 1e-12 * (b0 - a0);
    double xa = a0 + eps, fa = f(xa);
    for (int i = 1; i <= samples && out.size() < count; ++i) {
      const double t = double(i) / samples;
      const double xb = a0 + eps + (b0 - a0 - 2 * eps) * (0.5 - 0.5 * std::cos(M_PI * t));  // dense at the ends
      const double fb = f(xb);
      if ((fa < 0) != (fb < 0)) {
        double a = xa, b = xb, fl = fa;
        for (int it = 0; it < 200 && b - a > 4e-16 * b; ++it) {
          const double m = 0.5 * (a + b), fm = f(m);
          if ((fm < 0) == (fl < 0)) {
            a = m;
            fl = fm;
          } else {
            b = m;
          }
        }
        out.push_back(0.5 * (a + b));
      }
      xa = xb;
      fa = fb;
    }
  }
  return out;
}

/// H_ww(lambda): radial point receptance at 0.
inline double h_ww(const Ring& ring, double L) {
  double h = -1.0 / (ring.total_mass() * L);
  for (int k = 2; k <= ring.kmax; ++k) h += 1.0 / (ring.modal_mass(k) * (ring.lambda(k) - L));
  return h;
}

/// The (v, beta) point receptance at 0: {H_vv, H_vb, H_bb}.
inline std::array<double, 3> h_vb(const Ring& ring, double L) {
  const double Mt = ring.total_mass(), R = ring.R;
  // Rigid: the tangential translation (1, 0) and the rotation (1, 1/R), each of mass M_t.
  std::array<double, 3> h{-2.0 / (Mt * L), -1.0 / (R * Mt * L), -1.0 / (R * R * Mt * L)};
  for (int k = 2; k <= ring.kmax; ++k) {
    const double pv = 1.0 / k, pb = -(double(k) * k - 1) / (k * R);
    const double c = 1.0 / (ring.modal_mass(k) * (ring.lambda(k) - L));
    h[0] += c * pv * pv;
    h[1] += c * pv * pb;
    h[2] += c * pb * pb;
  }
  // pb^2 / (M_k lambda_k) = R / (pi EI k^2) exactly: the beta-beta terms decay only like 1/k^2
  // (the others like 1/k^4), and lambda / lambda_k < 1e-12 past kmax, so their tail is
  // R / (pi EI) sum_{k>K} 1/k^2 = R / (pi EI) (1/K - 1/(2K^2) + 1/(6K^3) - ...) (trigamma).
  const double K = ring.kmax;
  h[2] += R / (M_PI * ring.EI) * (1.0 / K - 0.5 / (K * K) + 1.0 / (6.0 * K * K * K));
  return h;
}

inline std::vector<double> sorted_omegas(std::vector<double> lambdas, std::size_t count) {
  std::sort(lambdas.begin(), lambdas.end());
  lambdas.resize(std::min(lambdas.size(), count));
  for (double& L : lambdas) L = std::sqrt(L);
  return lambdas;
}

/// The `count` lowest elastic frequencies (rad/s) of the free ring with a point mass m0 at 0.
inline std::vector<double> point_mass_omegas(const Ring& ring, double m0, std::size_t count) {
  std::vector<double> L = roots_in_gaps(ring, [&](double x) { return h_ww(ring, x) - 1.0 / (m0 * x); }, count);
  // beta is free at a point mass: the tangential receptance alone.
  const std::vector<double> t =
      roots_in_gaps(ring, [&](double x) { return h_vb(ring, x)[0] - 1.0 / (m0 * x); }, count);
  L.insert(L.end(), t.begin(), t.end());
  return sorted_omegas(L, count);
}

/// The `count` lowest frequencies (rad/s) of the ring clamped at 0.
inline std::vector<double> clamped_omegas(const Ring& ring, std::size_t count) {
  std::vector<double> L = roots_in_gaps(ring, [&](double x) { return h_ww(ring, x); }, count);
  const std::vector<double> a = roots_in_gaps(ring, [&](double x) {
    const auto h = h_vb(ring, x);
    return h[0] * h[2] - h[1] * h[1];
  }, count);
  L.insert(L.end(), a.begin(), a.end());
  return sorted_omegas(L, count);
}

}  // namespace receptance
