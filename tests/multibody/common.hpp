// Shared by the multibody suites: the section-5 load, the energy balance of a history and a
// number format for RecordProperty (fitted orders: tests/support/convergence.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "ring/analysis.hpp"
#include "ring/closed_form.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"
#include "support/paper.hpp"

namespace mbtest {

/// A number for RecordProperty, in scientific notation with 4 significant digits.
inline std::string sci(double x) {
  std::ostringstream s;
  s << std::setprecision(4) << std::scientific << x;
  return s.str();
}

/// A chain of n segments on the dense path (the paper's formulation, every analysis).
inline ring::MultibodyOptions dense_chain(int n) {
  ring::MultibodyOptions o;
  o.n = n;
  o.method = ring::MultibodyOptions::Method::dense;
  return o;
}

/// Options of an n-segment chain on the path `method`, every other option at its default.
inline ring::MultibodyOptions chain_options(int n, ring::MultibodyOptions::Method method) {
  ring::MultibodyOptions o;
  o.n = n;
  o.method = method;
  return o;
}

/// The free ring on a Winkler foundation where bending and the foundation both matter in the
/// lowest modes (k_r = 500 N/m^2, about 2.3 EI/R^4; k_t = 300 N/m^2).
inline ring::RingSpec on_foundation() {
  ring::RingSpec s = ringtest::free_ring();
  s.foundation.radial = 500.0;
  s.foundation.tangential = 300.0;
  return s;
}

/// Closed-form frequencies of the free inextensible ring on a foundation
/// (ring::closed_form::ring_on_foundation_inextensional), k = 0 once and each k >= 1 twice, ascending.
inline std::vector<double> foundation_spectrum(const ring::RingSpec& spec, int count) {
  std::vector<double> w{ring::closed_form::ring_on_foundation_inextensional(spec, 0)};
  for (int k = 1; static_cast<int>(w.size()) < count; ++k)
    w.insert(w.end(), 2, ring::closed_form::ring_on_foundation_inextensional(spec, k));
  w.resize(count);
  return w;
}

/// Options of an n-segment chain, every other option at its default.
inline ring::MultibodyOptions segments(int n) {
  ring::MultibodyOptions o;
  o.n = n;
  return o;
}

/// The paper's section-5 load as this project reconstructs it: a 20 kN step at C (0 deg) toward the pin,
/// dt = 0.01 s, recorded points 0, 90, 180, 270 deg.
inline ring::ResponseOptions forced_scene(ring::ResponseOptions::Integrator integrator, double t_end = 5.0) {
  ring::ResponseOptions r;
  r.loads.points = {{0.0, {0.0, 0.0}}};
  r.loads.points.at(0).force = {-20e3, 0.0};
  r.dt = 0.01;
  r.t_end = t_end;
  r.integrator = integrator;
  r.rho_inf = 0.8;
  r.record = {0.0, 90.0, 180.0, 270.0};
  return r;
}

/// The statics of a ring hanging under its own weight, g along -y scaled so that the thin
/// ring's sag is about `sag` R (ring::closed_form::hanging_ring_self_weight), one load step,
/// recorded at 0, 180 and 270 deg.
inline ring::StaticOptions hanging_statics(const ring::RingSpec& spec, double sag) {
  ring::StaticOptions st;
  st.loads.gravity = {0.0, -sag * spec.EI() / (spec.rhoA() * std::pow(spec.radius, 3))};
  st.steps = 1;
  st.record = {0.0, 180.0, 270.0};
  return st;
}

/// The radial displacement under a small radial point load F of the free inextensible ring
/// on a foundation, at the load: the inextensional Fourier modes a_k (w = a_k cos k theta,
/// v = -a_k sin(k theta)/k) decouple, with stiffness K_k = pi (EI (k^2 - 1)^2 / R^3 + R (k_r +
/// k_t / k^2)) and load F, so w(0) = sum_{k>=1} F / K_k (k = 0 has no inextensional radial
/// mode), summed to k = 10^5 (the tail ~ R^3 / (3 EI k^3) is below 1e-15 of it).
inline double foundation_point_load_series(const ring::RingSpec& spec, double F) {
  double w = 0.0;
  for (int k = 1; k <= 100000; ++k) {
    const double k2 = double(k) * k;
    w += F / (M_PI * (spec.EI() * (k2 - 1) * (k2 - 1) / std::pow(spec.radius, 3) +
                      spec.radius * (spec.foundation.radial + spec.foundation.tangential / k2)));
  }
  return w;
}

/// The worst |T + V - W|, the largest |work|, the largest constraint residual and the
/// mean Newton iterations per step of a history.
struct Balance {
  double worst = 0.0, work = 0.0, constraint = 0.0, iterations = 0.0;
};

inline Balance balance(const ring::TimeHistory& h) {
  Balance b;
  for (std::size_t k = 0; k < h.t.size(); ++k) {
    b.worst = std::max(b.worst, std::abs(h.energy_error[k]));
    b.work = std::max(b.work, std::abs(h.work[k]));
    b.constraint = std::max(b.constraint, h.constraint_residual[k]);
    b.iterations += h.newton_iterations[k];
  }
  b.iterations /= static_cast<double>(h.t.size() - 1);
  return b;
}

}  // namespace mbtest
