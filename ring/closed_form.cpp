#include "ring/closed_form.hpp"

#include <cmath>
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

double ring_on_foundation_inextensional(const RingSpec& spec, int k) {
  const double k2 = static_cast<double>(k) * k;
  const double bending = spec.EI() * k2 * (k2 - 1.0) * (k2 - 1.0) / std::pow(spec.radius, 4);
  return std::sqrt((bending + spec.foundation.radial * k2 + spec.foundation.tangential) / (spec.rhoA() * (k2 + 1.0)));
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

}  // namespace ring::closed_form
