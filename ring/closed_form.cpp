#include "ring/closed_form.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <stdexcept>
#include <string>

namespace ring::closed_form {

double free_ring_inextensional(const RingSpec& spec, int k) {
  if (k < 2) throw std::invalid_argument("free_ring_inextensional: k must be >= 2, got " + std::to_string(k));
  const double kk = k;
  return spec.bending_frequency_scale() * kk * (kk * kk - 1.0) / std::sqrt(kk * kk + 1.0);
}

std::array<double, 2> free_ring_extensible(const RingSpec& spec, int k) {
  if (k < 0) throw std::invalid_argument("free_ring_extensible: k must be >= 0, got " + std::to_string(k));
  const double R = spec.radius, kk = k;
  const double a = spec.EA() / (R * R), b = spec.EI() / (R * R * R * R);
  const double kr = spec.foundation.radial, kt = spec.foundation.tangential;
  const double k11 = a + b * kk * kk * kk * kk + kr;
  const double k22 = (a + b) * kk * kk + kt;
  // det K = a b k^2 (k^2 - 1)^2 without the foundation, written so that the k = 1 zero is
  // exact; the foundation adds kr k22' + kt k11' + kr kt (k11', k22' without it).
  const double det = a * b * kk * kk * (kk * kk - 1.0) * (kk * kk - 1.0) + kr * (k22 - kt) + kt * (k11 - kr) + kr * kt;
  const double tr = k11 + k22;
  const double disc = std::sqrt(std::max(tr * tr - 4.0 * det, 0.0));
  const double upper = 0.5 * (tr + disc);
  const double lower = upper > 0.0 ? det / upper : 0.0;  // avoids cancellation in (tr - disc)/2
  return {std::sqrt(lower / spec.rhoA()), std::sqrt(upper / spec.rhoA())};
}

namespace {

/// The roots, ascending, of det(K - x M) for K = sum_p d_p v_p v_p^T (d_p >= 0) and a positive
/// diagonal M, 3 x 3. The shear branch of a thin Timoshenko ring lies 1e16 above the lowest
/// (kGA / rho I against EI / rho A R^4), where an eigen-solver's lowest value is pure
/// round-off; so the characteristic polynomial c0 - c1 x + c2 x^2 - c3 x^3 is formed from
/// principal minors by Cauchy-Binet (sums of squares times positive weights: no
/// cancellation), and each root is found in a bracket that the coefficients give
/// (x1 in [c0/c1, 3 c0/c1] from c1/c0 = sum 1/x_i; x3 in [c2/(3 c3), c2/c3]; x2 from the
/// product c0/c3), by bisection to the last bit.
std::array<double, 3> rank_one_pencil_roots(const std::vector<std::pair<double, Eigen::Vector3d>>& terms,
                                            const Eigen::Vector3d& M) {
  auto minor2 = [&](int r, int c) {  // principal 2x2 minor on rows/columns {r, c}
    double m = 0.0;
    for (std::size_t p = 0; p < terms.size(); ++p)
      for (std::size_t q = p + 1; q < terms.size(); ++q) {
        const Eigen::Vector3d &a = terms[p].second, &b = terms[q].second;
        const double d = a[r] * b[c] - a[c] * b[r];
        m += terms[p].first * terms[q].first * d * d;
      }
    return m;
  };
  double c0 = 0.0;
  for (std::size_t p = 0; p < terms.size(); ++p)
    for (std::size_t q = p + 1; q < terms.size(); ++q)
      for (std::size_t r = q + 1; r < terms.size(); ++r) {
        Eigen::Matrix3d V;
        V << terms[p].second, terms[q].second, terms[r].second;
        const double d = V.determinant();
        c0 += terms[p].first * terms[q].first * terms[r].first * d * d;
      }
  Eigen::Vector3d diag = Eigen::Vector3d::Zero();
  for (const auto& [d, v] : terms) diag += d * v.cwiseProduct(v);
  const double c1 = M[0] * minor2(1, 2) + M[1] * minor2(0, 2) + M[2] * minor2(0, 1);
  const double c2 = diag[0] * M[1] * M[2] + diag[1] * M[0] * M[2] + diag[2] * M[0] * M[1];
  const double c3 = M[0] * M[1] * M[2];
  auto P = [&](double x) { return c0 - x * (c1 - x * (c2 - x * c3)); };
  auto bisect = [&](double lo, double hi) {
    const bool rising = P(lo) < P(hi);
    for (int it = 0; it < 2000 && lo < hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      ((P(mid) < 0.0) == rising ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  if (c0 <= 0.0) {  // a zero root: the quadratic c1 - c2 x + c3 x^2, its roots stably
    const double disc = std::sqrt(std::max(c2 * c2 - 4.0 * c1 * c3, 0.0));
    return {0.0, 2.0 * c1 / (c2 + disc), (c2 + disc) / (2.0 * c3)};
  }
  const double x1 = bisect(c0 / c1, 3.0 * c0 / c1);
  const double x3 = bisect(c2 / (3.0 * c3), c2 / c3);
  return {x1, c0 / (c3 * x1 * x3), x3};
}

}  // namespace

std::array<double, 3> free_ring_timoshenko(const RingSpec& spec, int k) {
  if (k < 0) throw std::invalid_argument("free_ring_timoshenko: k must be >= 0, got " + std::to_string(k));
  if (!(spec.kappa() > 0.0)) throw std::invalid_argument("free_ring_timoshenko: the shear coefficient must be > 0");
  const double R = spec.radius, kk = k;
  const std::vector<std::pair<double, Eigen::Vector3d>> K{
      {spec.EA() / (R * R), Eigen::Vector3d(kk, 1.0, 0.0)},
      {spec.kGA() / (R * R), Eigen::Vector3d(-1.0, -kk, 1.0)},
      {spec.EI() * kk * kk / (R * R * R * R), Eigen::Vector3d::UnitZ()},
      {spec.foundation.tangential, Eigen::Vector3d::UnitX()},
      {spec.foundation.radial, Eigen::Vector3d::UnitY()}};
  const auto x = rank_one_pencil_roots(K, Eigen::Vector3d(spec.rhoA(), spec.rhoA(), spec.rhoI() / (R * R)));
  return {std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2])};
}

std::array<double, 2> free_ring_timoshenko_inextensional(const RingSpec& spec, int k) {
  if (k < 2) throw std::invalid_argument("free_ring_timoshenko_inextensional: k must be >= 2, got " + std::to_string(k));
  if (!(spec.kappa() > 0.0))
    throw std::invalid_argument("free_ring_timoshenko_inextensional: the shear coefficient must be > 0");
  const double R = spec.radius, k2 = static_cast<double>(k) * k, c = k2 - 1.0;
  const double s = spec.kGA() / (R * R), bend = spec.EI() * k2 / (R * R * R * R);
  const double f = spec.foundation.tangential + k2 * spec.foundation.radial;
  const double k11 = s * c * c + f, k12 = s * c, k22 = s + bend;
  const double det = s * c * c * bend + f * k22;  // k11 k22 - k12^2 without the s^2 cancellation
  const double m1 = spec.rhoA() * (1.0 + k2), m2 = spec.rhoI() / (R * R);
  // m1 m2 x^2 - (k11 m2 + k22 m1) x + det = 0, its discriminant written as a sum of squares
  // and the lower root as 2 det / (b + sqrt(disc)): no cancellation in either.
  const double b = k11 * m2 + k22 * m1, a = m1 * m2;
  const double disc = std::sqrt(std::pow(k11 * m2 - k22 * m1, 2) + 4.0 * a * k12 * k12);
  return {std::sqrt(2.0 * det / (b + disc)), std::sqrt((b + disc) / (2.0 * a))};
}

double ring_on_foundation_inextensional(const RingSpec& spec, int k, double follower_pressure) {
  const double k2 = static_cast<double>(k) * k;
  const double bending = spec.EI() * k2 * (k2 - 1.0) * (k2 - 1.0) / std::pow(spec.radius, 4);
  const double pressure = -follower_pressure * k2 * (k2 - 1.0) / spec.radius;
  const double w2 =
      (bending + spec.foundation.radial * k2 + spec.foundation.tangential + pressure) / (spec.rhoA() * (k2 + 1.0));
  return w2 > 0.0 ? std::sqrt(w2) : std::nan("");
}

std::array<double, 2> point_mass_shift(const RingSpec& spec, double m0, int k) {
  const double k2 = static_cast<double>(k) * k;
  const double base = -m0 / (M_PI * spec.radius * spec.rhoA() * (k2 + 1.0));
  return {base, base * k2};
}

DiametralDeflection diametral_load(const RingSpec& spec, double P) {
  const double c = P * std::pow(spec.radius, 3) / spec.EI();
  return {(M_PI / 4.0 - 2.0 / M_PI) * c, (2.0 / M_PI - 0.5) * c};
}

double pressure_stiffness_factor(Pressure::Kind kind, int n) {
  if (n < 2) throw std::invalid_argument("pressure_stiffness_factor: n must be >= 2, got " + std::to_string(n));
  const double m = static_cast<double>(n) * n - 1.0, n2 = static_cast<double>(n) * n;
  switch (kind) {
    case Pressure::Kind::follower: return m;
    case Pressure::Kind::dead: return m * m / n2;
    case Pressure::Kind::central: return (m * m - 1.0) / n2;
  }
  return 0.0;
}

double critical_pressure(const RingSpec& spec, Pressure::Kind kind, int n) {
  const double m = static_cast<double>(n) * n - 1.0;
  return spec.EI() * m * m / (std::pow(spec.radius, 3) * pressure_stiffness_factor(kind, n));
}

double pinned_ring_critical_pressure(const RingSpec& spec, Pressure::Kind kind) {
  const double unit = spec.EI() / std::pow(spec.radius, 3);
  if (kind == Pressure::Kind::follower) return 3.0 * unit;
  if (kind == Pressure::Kind::central) return 4.5 * unit;
  // The secular function of the out-of-phase even harmonics, increasing on (0, 4) from -1.
  auto f = [](double P) {
    double sum = 0.0;
    for (int n = 20000; n >= 2; n -= 2) {  // smallest terms first
      const double m = static_cast<double>(n) * n;
      sum += 1.0 / ((m - 1.0) * (m - 1.0) * (m - P));
    }
    return 2.0 * P * sum - 1.0;
  };
  double lo = 0.0, hi = 4.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) (f(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi) * unit;
}

DiametralDeflection diametral_load_under_pressure(const RingSpec& spec, double P, const Pressure& pressure) {
  constexpr int kLast = 40000;
  const double R3 = std::pow(spec.radius, 3);
  std::vector<double> flex(kLast + 1, 0.0);  // 1 / (pi K_n), n >= 1
  for (int n = 1; n <= kLast; ++n) {
    const double m = static_cast<double>(n) * n - 1.0;
    double k = 0.0;
    if (n == 1) k = pressure.kind == Pressure::Kind::central ? pressure.value : 0.0;
    else k = spec.EI() * m * m / R3 - pressure.value * pressure_stiffness_factor(pressure.kind, n);
    if (n > 1 && !(k > 0.0))
      throw std::invalid_argument("diametral_load_under_pressure: the pressure is not below critical");
    flex[n] = k > 0.0 ? 1.0 / (M_PI * k) : 0.0;
  }
  const bool held = flex[1] > 0.0;  // else the translation is free and the pin takes nothing
  // Radial displacement at theta of radial forces F_i at theta_i, every harmonic n >= 1.
  auto w = [&](double theta, const std::vector<std::pair<double, double>>& forces) {
    double sum = 0.0;
    for (int n = kLast; n >= 1; --n)  // smallest terms first
      for (const auto& [at, F] : forces) sum += F * flex[n] * std::cos(n * (theta - at));
    return sum;
  };
  const std::vector<std::pair<double, double>> squeeze{{0.0, -P}, {M_PI, -P}};
  const double pin = -0.5 * M_PI;
  const std::vector<std::pair<double, double>> unit_reaction{{pin, 1.0}};
  const double at_pin = w(pin, unit_reaction);
  const double V = held ? -w(pin, squeeze) / at_pin : 0.0;
  std::vector<std::pair<double, double>> all = squeeze;
  all.emplace_back(pin, V);
  return {-(w(0.0, all) + w(M_PI, all)), w(0.5 * M_PI, all) + w(-0.5 * M_PI, all)};
}

HangingDeflection hanging_ring_self_weight(const RingSpec& spec, double g) {
  const double c = spec.rhoA() * std::abs(g) * std::pow(spec.radius, 4) / spec.EI();
  return {(M_PI * M_PI - 8.0) / 4.0 * c, (2.0 - M_PI / 2.0) * c};
}

}  // namespace ring::closed_form
