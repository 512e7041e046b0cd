// Independent oracles for the natural frequencies of the rigid-segment chain and of the
// continuous ring, written without multibody/ (different coordinates, different method).
//
// 1. Free chain, Fourier (Bloch) analysis. The free n-gon chain is invariant under
//    rotation by delta = 2 pi / n, so wave number k decouples. In hinge displacements
//    (radial w_j, tangential v_j at hinge j) with w_j = W z^j, v_j = V z^j, z = e^{i k delta},
//    inextensibility of segment j (t_j . (u_{j+1} - u_j) = 0) gives
//    V = i (s/c) cot(x) W, with c = cos(delta/2), s = sin(delta/2), x = k delta / 2.
//    Then, for W = 1 (derived by hand; product-form identities avoid cancellation):
//      segment rotation        |Theta|^2 = 4 sin^2((k-1)delta/2) sin^2((k+1)delta/2) / (l^2 c^2 sin^2 x)
//      midpoint displacement   P = |A|^2 + |B|^2 = cos^2 x / c^2 + s^2 / sin^2 x
//      spring rotation         |Theta (1 - z^{-1})|^2 = 4 sin^2 x |Theta|^2
//    and the Rayleigh quotient is exact (one unknown per k):
//      omega_k^2 = 4 K sin^2 x |Theta|^2 / (m P + Jr |Theta|^2),   2 <= k <= n/2,
//    a double eigenvalue for k < n/2 (cos and sin types). k = 0, 1: rigid modes.
//    As n -> infinity this tends to EI/(rho A R^4) k^2 (k^2-1)^2 / (k^2+1) (Love).
// 2. Ring pinned at one point, by receptance: the pinned frequencies are the roots of the
//    free system's 2x2 point receptance H(lambda) at the pin, which is diagonal in
//    (radial, tangential) by the reflection symmetry about the pin's diameter:
//      H_rr = -1/(M_t lambda) + sum_k psi_r^2 / (M_k (lambda_k - lambda))
//      H_tt = -1/(M_t lambda) - psi_rot^2 / (I_rot lambda) + sum_k psi_t^2 / (M_k (lambda_k - lambda))
//    (M_t total mass, I_rot inertia about the centre; the cos-type modes have psi = (1, 0)
//    at the pin, the sin-type psi = (0, tau_k)). Each is increasing between consecutive
//    poles, so every gap (pole_i, pole_{i+1}), pole_0 = 0, holds exactly one root,
//    found by bisection to rounding level. Used with the discrete chain's free modes
//    (item 1) and with the continuum ring's (w = cos k a, v = -sin(k a)/k, modal mass
//    pi R rho A (1 + 1/k^2), series truncated at k = 20000, remainder < 1e-13 relative).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace oracle {

struct ChainParams {
  int n;
  double R, EI, rhoA;
  bool rotary_inertia;
  double l() const { return 2 * M_PI * R / n; }
  double m() const { return rhoA * l(); }
  double Jr() const { return rotary_inertia ? m() * l() * l() / 12 : 0.0; }
  double K() const { return EI / l(); }
  double Rp() const { return l() / (2 * std::sin(M_PI / n)); }
};

struct FreeMode {
  int k;
  double lambda;   // omega^2
  double mass_c;   // modal mass of the cos-type real mode (W = 1)
  double mass_s;   // of the sin-type (0 if it vanishes, k = n/2)
  double tau;      // tangential amplitude of the sin-type at hinge 0
};

/// Free chain modes for k = 2 .. floor(n/2) (item 1). O(n).
inline std::vector<FreeMode> free_chain_modes(const ChainParams& p) {
  const double d = 2 * M_PI / p.n, c = std::cos(d / 2), s = std::sin(d / 2), l = p.l();
  std::vector<FreeMode> out;
  for (int k = 2; 2 * k <= p.n; ++k) {
    const double x = k * d / 2;
    const double th2 = 4 * std::pow(std::sin((k - 1) * d / 2) * std::sin((k + 1) * d / 2), 2) /
                       (l * l * c * c * std::pow(std::sin(x), 2));
    const double P = std::pow(std::cos(x) / c, 2) + std::pow(s / std::sin(x), 2);
    const double per = p.m() * P + p.Jr() * th2;
    FreeMode f;
    f.k = k;
    f.lambda = 4 * p.K() * std::pow(std::sin(x), 2) * th2 / per;
    const bool half = 2 * k == p.n;
    f.mass_c = half ? p.n * per : 0.5 * p.n * per;
    f.tau = (s / c) * std::cos(x) / std::sin(x);
    f.mass_s = half ? 0.0 : 0.5 * p.n * per;
    out.push_back(f);
  }
  return out;
}

/// Elastic free-chain frequencies omega (rad/s), ascending, each double root listed twice.
inline std::vector<double> free_chain_omegas(const ChainParams& p) {
  std::vector<double> w;
  for (const auto& f : free_chain_modes(p)) {
    w.push_back(std::sqrt(f.lambda));
    if (f.mass_s > 0) w.push_back(std::sqrt(f.lambda));
  }
  std::sort(w.begin(), w.end());
  return w;
}

/// A family of poles and residues (lambda_i > 0, r_i > 0) plus a rigid term -r0 / lambda:
/// h(lambda) = -r0 / lambda + sum r_i / (lambda_i - lambda).
struct Receptance {
  double r0 = 0.0;
  std::vector<double> lambda, r;
  double operator()(double L) const {
    double h = -r0 / L;
    for (std::size_t i = 0; i < lambda.size(); ++i) h += r[i] / (lambda[i] - L);
    return h;
  }
  /// The roots below the `limit`-th pole, ascending (one per gap, by bisection).
  std::vector<double> roots(std::size_t limit) const {
    std::vector<double> poles = lambda;
    std::sort(poles.begin(), poles.end());
    poles.insert(poles.begin(), 0.0);
    std::vector<double> out;
    for (std::size_t i = 0; i + 1 < poles.size() && out.size() < limit; ++i) {
      double a = poles[i], b = poles[i + 1];
      for (int it = 0; it < 200 && b - a > 4e-16 * b; ++it) {
        const double mid = 0.5 * (a + b);
        ((*this)(mid) < 0 ? a : b) = mid;
      }
      out.push_back(0.5 * (a + b));
    }
    return out;
  }
};

/// The `count` lowest elastic frequencies (rad/s) of the chain pinned at one hinge (item 2).
inline std::vector<double> pinned_chain_omegas(const ChainParams& p, std::size_t count) {
  Receptance hr, ht;
  const double Mt = p.n * p.m();
  const double rho_mid = p.Rp() * std::cos(M_PI / p.n);
  const double Irot = p.n * (p.m() * rho_mid * rho_mid + p.Jr());
  hr.r0 = 1.0 / Mt;
  ht.r0 = 1.0 / Mt + p.Rp() * p.Rp() / Irot;
  for (const auto& f : free_chain_modes(p)) {
    hr.lambda.push_back(f.lambda);
    hr.r.push_back(1.0 / f.mass_c);
    if (f.mass_s > 0) {
      ht.lambda.push_back(f.lambda);
      ht.r.push_back(f.tau * f.tau / f.mass_s);
    }
  }
  std::vector<double> w;
  for (double L : hr.roots(count)) w.push_back(std::sqrt(L));
  for (double L : ht.roots(count)) w.push_back(std::sqrt(L));
  std::sort(w.begin(), w.end());
  w.resize(std::min(w.size(), count));
  return w;
}

/// The `count` lowest frequencies (rad/s) of the continuous inextensible Euler-Bernoulli
/// ring pinned at one point (item 2 with the continuum's free modes).
inline std::vector<double> pinned_ring_omegas(double R, double EI, double rhoA, std::size_t count,
                                              int kmax = 20000) {
  const double s = EI / (rhoA * R * R * R * R);
  Receptance hr, ht;
  const double Mt = 2 * M_PI * R * rhoA, Irot = 2 * M_PI * rhoA * R * R * R;
  hr.r0 = 1.0 / Mt;
  ht.r0 = 1.0 / Mt + R * R / Irot;
  for (int k = 2; k <= kmax; ++k) {
    const double k2 = double(k) * k;
    const double L = s * k2 * (k2 - 1) * (k2 - 1) / (k2 + 1);
    const double M = M_PI * R * rhoA * (1 + 1 / k2);
    hr.lambda.push_back(L);
    hr.r.push_back(1.0 / M);
    ht.lambda.push_back(L);
    ht.r.push_back(1.0 / (k2 * M));
  }
  std::vector<double> w;
  for (double L : hr.roots(count)) w.push_back(std::sqrt(L));
  for (double L : ht.roots(count)) w.push_back(std::sqrt(L));
  std::sort(w.begin(), w.end());
  w.resize(std::min(w.size(), count));
  return w;
}

}  // namespace oracle
