// The implicit schemes' coefficients, written once for every solver's forced response:
// Newmark's average acceleration and the generalized-alpha method of Chung & Hulbert (1993).
// On a second-order model M a + f(q, v) = g(t) with the relations of Newmark,
//   q_1 = q_0 + h v_0 + h^2 ((1/2 - beta) a_0 + beta a_1),   v_1 = v_0 + h ((1 - gamma) a_0 + gamma a_1),
// generalized-alpha balances M a_{1-am} = f and g at t_{1-af}, x_{1-a} = (1 - a) x_1 + a x_0
// (a: am for the accelerations, af for the rest); Newmark is am = af = 0, beta = 1/4,
// gamma = 1/2. The step's unknown is q_1; its Newton matrix is
//   (1 - af) K_t + mass_rate(h) M + (1 - af) velocity_rate(h) C.
// The midpoint rule (paths/midpoint.hpp) and the chain's energy-momentum scheme are schemes of
// their own.
#pragma once

#include "ring/analysis.hpp"

namespace paths {

struct Scheme {
  double alpha_m = 0.0, alpha_f = 0.0, beta = 0.25, gamma = 0.5;

  /// Newmark's average acceleration: second order, unconditionally stable, no dissipation.
  static Scheme newmark() { return {}; }
  /// Chung & Hulbert (1993), eqs. (25) and (17): second order, unconditionally stable,
  /// high-frequency spectral radius rho_inf in [0, 1].
  static Scheme generalized_alpha(double rho_inf) {
    Scheme s;
    s.alpha_m = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
    s.alpha_f = rho_inf / (rho_inf + 1.0);
    s.gamma = 0.5 + s.alpha_f - s.alpha_m;
    s.beta = 0.25 * (s.gamma + 0.5) * (s.gamma + 0.5);
    return s;
  }
  /// The scheme of response.integrator: generalized-alpha with its rho_inf, Newmark otherwise
  /// (the energy-momentum and midpoint integrators do not use these coefficients).
  static Scheme of(const ring::ResponseOptions& r) {
    return r.integrator == ring::ResponseOptions::Integrator::generalized_alpha ? generalized_alpha(r.rho_inf)
                                                                                : newmark();
  }

  /// d a_1 / d q_1 = 1 / (beta h^2).
  double acceleration_rate(double h) const { return 1.0 / (beta * h * h); }
  /// d v_1 / d q_1 = gamma / (beta h).
  double velocity_rate(double h) const { return gamma / (beta * h); }
  /// d a_{1-am} / d q_1 = (1 - am) / (beta h^2): the mass's coefficient in the Newton matrix.
  double mass_rate(double h) const { return (1.0 - alpha_m) * acceleration_rate(h); }

  // Newmark's relations on vectors V with arithmetic expressions (Eigen's): the step's
  // prediction from the accepted (q, v, a), and the end state from its position q_1.
  /// q_hat = q + h v + h^2 (1/2 - beta) a: q_1 = q_hat + beta h^2 a_1.
  template <class V>
  V predicted_position(const V& q, const V& v, const V& a, double h) const {
    return q + h * v + h * h * (0.5 - beta) * a;
  }
  /// v_hat = v + h (1 - gamma) a: v_1 = v_hat + gamma h a_1.
  template <class V>
  V predicted_velocity(const V& v, const V& a, double h) const {
    return v + h * (1.0 - gamma) * a;
  }
  /// a_1 = (q_1 - q_hat) / (beta h^2).
  template <class V>
  V acceleration(const V& q1, const V& q_hat, double h) const {
    return (q1 - q_hat) * acceleration_rate(h);
  }
  /// v_1 = v_hat + gamma h a_1.
  template <class V>
  V velocity(const V& v_hat, const V& a1, double h) const {
    return v_hat + h * gamma * a1;
  }
  /// The true acceleration of generalized-alpha's pseudo-acceleration sequence (Arnold &
  /// Bruls 2007): qdd_1 = ((1 - am) a_1 + am a_0 - af qdd_0) / (1 - af); Newmark: a_1.
  template <class V>
  V true_acceleration(const V& a1, const V& a0, const V& qdd0) const {
    return ((1.0 - alpha_m) * a1 + alpha_m * a0 - alpha_f * qdd0) / (1.0 - alpha_f);
  }
};

}  // namespace paths
