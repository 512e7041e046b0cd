// Shared by the multibody response suites: the linear modal superposition of a chain's
// response from multibody::solve_modes (an independent linearization and eigensolver) and its
// deviation from a computed history.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "multibody/attachments.hpp"
#include "multibody/chain.hpp"
#include "multibody/linear_model.hpp"
#include "multibody/modes.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"

namespace mbtest {

using Integrator = ring::ResponseOptions::Integrator;

/// Response of one undamped mode x'' + w^2 x = f g(t) (g = the load history of `r`, from
/// rest) on the time grid t: exact for a step, (1 - cos w t) f / w^2, or (`discrete`, any
/// history) by the integrator of `r` applied to
/// this scalar equation, written here from Chung & Hulbert (1993) and Arnold & Bruls
/// (2007) independently of multibody/dynamics.cpp: equilibrium at t_{n+1},
/// (1-am) a_{n+1} + am a_n = (1-af) x''_{n+1} + af x''_n, Newmark updates with (beta,
/// gamma); Newmark is am = af = 0, beta = 1/4, gamma = 1/2. x''_0 is consistent; the
/// pseudo-acceleration starts (generalized-alpha, dynamics.hpp) from the Newton matrix of
/// the first step, (c + w^2) a_0 = c x''_0 with c = (1-am) / ((1-af) beta h^2). A linear
/// integrator commutes with the modal transformation, so applied mode by mode it gives
/// what it gives on the linearized chain.
inline std::vector<double> modal_response(double w, double f, const std::vector<double>& t,
                                   const ring::ResponseOptions& r, bool discrete) {
  std::vector<double> x(t.size());
  if (!discrete) {
    EXPECT_EQ(r.history.kind, ring::LoadHistory::Kind::step);
    for (size_t i = 0; i < t.size(); ++i) x[i] = f * (1.0 - std::cos(w * t[i])) / (w * w);
    return x;
  }
  double am = 0.0, af = 0.0, beta = 0.25, gamma = 0.5;
  if (r.integrator == Integrator::generalized_alpha) {
    am = (2.0 * r.rho_inf - 1.0) / (r.rho_inf + 1.0);
    af = r.rho_inf / (r.rho_inf + 1.0);
    gamma = 0.5 + af - am;
    beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
  }
  const ring::LoadHistory& g = r.history;
  double xn = 0.0, vn = 0.0, qdd = f * g.factor(0.0), a = qdd;
  if (t.size() > 1) {
    // Both integrators start from the acceleration filtered by the first step's Newton
    // matrix (multibody/dynamics.cpp): generalized-alpha's pseudo-acceleration, Newmark's
    // acceleration.
    const double h = t[1] - t[0], c = (1.0 - am) / ((1.0 - af) * beta * h * h);
    a = c * qdd / (c + w * w);
    if (r.integrator == Integrator::newmark) qdd = a;
  }
  x[0] = 0.0;
  for (size_t i = 1; i < t.size(); ++i) {
    const double h = t[i] - t[i - 1];
    // x1 = xhat + h^2 beta a1, x''1 = ((1-am) a1 + am a - af x'') / (1-af), x''1 + w^2 x1 = f.
    const double xhat = xn + h * vn + h * h * (0.5 - beta) * a;
    const double c1 = (1.0 - am) / (1.0 - af), c0 = (am * a - af * qdd) / (1.0 - af);
    const double a1 = (f * g.factor(t[i]) - c0 - w * w * xhat) / (c1 + w * w * h * h * beta);
    const double x1 = xhat + h * h * beta * a1;
    vn = vn + h * ((1.0 - gamma) * a + gamma * a1);
    qdd = c1 * a1 + c0;
    a = a1;
    xn = x1;
    x[i] = x1;
  }
  return x;
}

/// Linear modal superposition of a force F at hinge `load` of the chain about q0 (with the
/// spec's attachments), every elastic mode: u_p(t) = sum_k J_p dq_k x_k(t), x_k'' + w_k^2 x_k = dq_k . Phi,
/// with M0-orthonormal modes from solve_modes. Returns [point][step] for ux and uy.
struct Linear {
  std::vector<std::vector<double>> ux, uy;
};
inline Linear modal_superposition(const ring::RingSpec& spec, int n, const ring::ResponseOptions& r,
                           const std::vector<double>& t, bool discrete) {
  ring::MultibodyOptions o;
  o.n = n;
  const multibody::Chain chain(spec, o, r.loads.points.at(0).angle);
  // Every elastic mode: the unknowns (with the point inertias' hinge rotations and the
  // Timoshenko chain's shear angles, linear_model.hpp) less the constraint rows (with the
  // further pins'); the supports leave no rigid mode.
  const multibody::detail::LinearTerms terms = multibody::detail::linear_terms(chain, spec);
  const multibody::Shear shear = multibody::Shear::of(spec, chain.l());
  const bool timoshenko = spec.theory == ring::Theory::timoshenko;
  const int modes = multibody::linear_unknowns(chain, &terms, timoshenko ? &shear : nullptr) -
                    chain.constraint_count() - static_cast<int>(terms.J.rows());
  const multibody::ModalSolution sol = multibody::solve_modes(spec, o, modes);
  const multibody::Vector q0 = chain.q0();
  const multibody::Vector phi = chain.point_load_forces(
      q0, chain.hinge_at(r.loads.points.at(0).angle), Eigen::Vector2d(r.loads.points.at(0).force[0], r.loads.points.at(0).force[1]));
  Linear lin;
  for (double a : r.record) {
    const multibody::Matrix J = chain.hinge_jacobian(q0, chain.hinge_at(a));
    std::vector<double> ux(t.size(), 0.0), uy(t.size(), 0.0);
    for (int k = 0; k < modes; ++k) {
      const double w = sol.result.omega[k];
      const Eigen::Vector2d shape = J * sol.dq.col(k);
      const std::vector<double> eta = modal_response(w, sol.dq.col(k).dot(phi), t, r, discrete);
      for (size_t i = 0; i < t.size(); ++i) {
        ux[i] += shape.x() * eta[i];
        uy[i] += shape.y() * eta[i];
      }
    }
    lin.ux.push_back(ux);
    lin.uy.push_back(uy);
  }
  return lin;
}

inline double max_abs(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

/// Largest deviation between the response and a linear reference, relative to the
/// reference's peak, over the points that move.
inline double relative_deviation(const ring::TimeHistory& th, const Linear& lin, int p) {
  const double peak = std::max(max_abs(lin.ux[p]), max_abs(lin.uy[p]));
  double worst = 0.0;
  for (size_t i = 0; i < th.t.size(); ++i)
    worst = std::max({worst, std::abs(th.ux[p][i] - lin.ux[p][i]), std::abs(th.uy[p][i] - lin.uy[p][i])});
  return worst / peak;
}

}  // namespace mbtest
