// The integrators' steps (integrators.hpp).
#include "multibody/integrators.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <stdexcept>

namespace multibody::detail {
namespace {

/// Decides, iteration by iteration, whether the kept Newton matrix is still good enough.
struct RefreshPolicy {
  bool refresh = false;   ///< factor again at the next iteration
  bool fresh = false;     ///< the matrix was factored at the current iteration
  double previous = 0.0;  ///< size of the previous correction
  /// After a correction of size `norm` (not yet applied): true to apply it, false to
  /// discard it and retry with a fresh matrix (only when the matrix was old).
  bool accept(double norm, double limit) {
    if (!(norm <= limit)) {
      if (fresh) return false;
      refresh = true;
      return false;
    }
    // A matrix kept from an earlier step serves one iteration (a cheap first correction,
    // 10-1000 times smaller than the predictor's error) and is then refreshed, so that
    // the step finishes in Newton's quadratic range; one kept within the step is refreshed
    // when it shrinks the correction by less than 8.
    if (!fresh && previous == 0.0) refresh = true;
    if (!fresh && previous > 0.0 && norm > 0.125 * previous) refresh = true;
    previous = norm;
    return true;
  }
};

/// Solves g(q) = 0 for the dependent angles `dep` with the others fixed: chord iterations
/// with the block G_y of `G` (the Jacobian at a nearby configuration: the caller's last
/// one, which saves evaluating it here). O(n) per iteration. False if it fails.
bool solve_dependent(const Chain& ch, const std::vector<int>& dep, const Matrix& G, Vector& q) {
  const int c = static_cast<int>(dep.size());
  // |g| is in metres; 1e-15 R sqrt(n) is the round-off of the closure sum of n terms.
  const double tol = 1e-15 * ch.circumradius() * std::sqrt(double(ch.n()));
  Matrix Gy(c, c);
  for (int i = 0; i < c; ++i) Gy.col(i) = G.col(dep[i]);
  const Eigen::PartialPivLU<Matrix> lu(Gy);
  for (int it = 0; it < 30; ++it) {
    const Vector g = ch.constraints(q);
    if (!g.allFinite()) return false;
    if (g.cwiseAbs().maxCoeff() <= tol) return true;
    const Vector dy = -lu.solve(g);
    if (!dy.allFinite()) return false;
    for (int i = 0; i < c; ++i) q[dep[i]] += dy[i];
    if (dy.cwiseAbs().maxCoeff() <= 1e-15) return true;
  }
  return ch.constraints(q).cwiseAbs().maxCoeff() <= 1e3 * tol;
}

}  // namespace

Coefficients coefficients(const ring::ResponseOptions& r) {
  Coefficients c;
  if (r.integrator == ring::ResponseOptions::Integrator::generalized_alpha) {
    // Chung & Hulbert (1993), eq. (25) and (17): second order, unconditionally stable,
    // high-frequency spectral radius rho_inf.
    const double rho = r.rho_inf;
    c.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
    c.alpha_f = rho / (rho + 1.0);
    c.gamma = 0.5 + c.alpha_f - c.alpha_m;
    c.beta = 0.25 * (c.gamma + 0.5) * (c.gamma + 0.5);
  }
  return c;
}

void starting_pseudo_acceleration(const Problem& p, const Coefficients& co, double h, NewtonBackend& nb,
                                  State& s) {
  const double c = (1.0 - co.alpha_m) / ((1.0 - co.alpha_f) * co.beta * h * h);
  const double cv = co.gamma / (co.beta * h);
  Vector r;
  nb.residual(s.q, s.v, Vector::Zero(s.q.size()), p.history.factor(s.t), c, cv, r, true);
  const Kinematic k = detail::evaluate(p.chain, s.q, false, true);
  nb.add_to_tangent_diagonal(k.hess_g.transpose() * s.lambda);
  Vector a, mu;
  const bool ok = nb.factor(k.G, p.chain.l(), h) && nb.solve(c * r, c * p.chain.constraint_jdot_qdot(s.q, s.v), a, mu);
  nb.invalidate();  // the first step factors its own matrix
  if (!ok) throw std::runtime_error("multibody::respond: starting accelerations not computable");
  s.a = a;
}

StepOutcome step_index3(const Problem& p, const Coefficients& co, const State& s0, double h,
                        const IntegrationControls& ctl, NewtonBackend& nb, State& s1) {
  const Chain& ch = p.chain;
  const double t1 = s0.t + h;
  const double f1 = p.history.factor(t1);
  const double bh2 = co.beta * h * h;
  const double dqdd_dq = (1.0 - co.alpha_m) / ((1.0 - co.alpha_f) * bh2);
  const double dv_dq = co.gamma / (co.beta * h);
  // Predictor: constant velocity, previous multipliers. Extrapolating the acceleration
  // as well is worse after a step load, whose initial accelerations are local and huge
  // at large n (at n = 640 it overshoots by radians and forces step halving).
  Vector a1;
  const Vector q_hat = s0.q + h * s0.v + h * h * (0.5 - co.beta) * s0.a;
  const Vector v_hat = s0.v + h * (1.0 - co.gamma) * s0.a;
  Vector q = s0.q + h * s0.v;
  Vector lambda = s0.lambda;
  Vector v, qdd;
  StepOutcome out;
  Vector r, dqv, dl;
  RefreshPolicy policy;
  for (int it = 1; it <= ctl.max_newton; ++it) {
    out.iterations = it;
    a1 = (q - q_hat) / bh2;
    v = v_hat + h * co.gamma * a1;
    qdd = ((1.0 - co.alpha_m) * a1 + co.alpha_m * s0.a - co.alpha_f * s0.qdd) / (1.0 - co.alpha_f);
    policy.fresh = policy.refresh || !nb.usable(h);
    const Kinematic k = detail::evaluate(ch, q, true, policy.fresh);
    if (it == 1) out.reused = !policy.fresh;
    nb.residual(q, v, qdd, f1, dqdd_dq, dv_dq, r, policy.fresh);
    if (policy.fresh) {
      nb.add_to_tangent_diagonal(k.hess_g.transpose() * lambda);  // the constraint curvature
      if (!nb.factor(k.G, ch.l(), h)) return out;
      policy.refresh = false;
    }
    r += k.G.transpose() * lambda;
    if (!nb.solve(r, k.g, dqv, dl)) return out;
    const double norm = dqv.cwiseAbs().maxCoeff();
    // A correction turning a segment by more than 0.5 rad has left the basin.
    if (!policy.accept(norm, kBasin)) {
      if (policy.refresh) continue;
      return out;
    }
    q += dqv;
    lambda += dl;
    // Converged when the correction is below tol_q and the constraints hold to 1e-12 R
    // (a kept Newton matrix contracts g only linearly, so check it explicitly).
    if (norm <= ctl.tol_q &&
        ch.constraints(q).cwiseAbs().maxCoeff() <= 1e-12 * ch.circumradius()) {
      out.converged = true;
      break;
    }
  }
  if (!out.converged) return out;
  a1 = (q - q_hat) / bh2;
  s1.t = t1;
  s1.q = q;
  s1.v = v_hat + h * co.gamma * a1;
  s1.qdd = ((1.0 - co.alpha_m) * a1 + co.alpha_m * s0.a - co.alpha_f * s0.qdd) / (1.0 - co.alpha_f);
  s1.a = a1;
  s1.lambda = lambda;
  return out;
}

StepOutcome step_partitioned(const Problem& p, const Coefficients& co, const State& s0, double h,
                             const IntegrationControls& ctl, NewtonBackend& nb, State& s1) {
  const Chain& ch = p.chain;
  const int n = ch.dofs(), c = ch.constraint_count(), nz = n - c;
  std::vector<int> dep(c), ind;
  Matrix G0;
  {
    G0 = ch.constraint_jacobian(s0.q);
    const Eigen::ColPivHouseholderQR<Matrix> qr(G0);
    const auto& perm = qr.colsPermutation().indices();
    std::vector<bool> is_dep(n, false);
    for (int i = 0; i < c; ++i) {
      dep[i] = perm[i];
      is_dep[perm[i]] = true;
    }
    for (int j = 0; j < n; ++j)
      if (!is_dep[j]) ind.push_back(j);
  }
  auto take = [&](const Vector& x, const std::vector<int>& idx) {
    Vector y(idx.size());
    for (size_t i = 0; i < idx.size(); ++i) y[i] = x[idx[i]];
    return y;
  };
  const double bh2 = co.beta * h * h;
  const double dv_dq = co.gamma / (co.beta * h);
  const Vector z0 = take(s0.q, ind), zd0 = take(s0.v, ind), zdd0 = take(s0.qdd, ind);
  const Vector z_hat = z0 + h * zd0 + h * h * (0.5 - co.beta) * zdd0;
  const Vector zd_hat = zd0 + h * (1.0 - co.gamma) * zdd0;
  const double t1 = s0.t + h;
  const double f1 = p.history.factor(t1);
  // Predictor: constant velocity (see step_index3).
  Vector q = s0.q + h * s0.v;
  Vector z = take(q, ind);
  Vector v(n), qdd(n), lambda(c), r, dqv, dl;
  Matrix Gy(c, c), Gz(c, nz);
  StepOutcome out;
  // Positions, velocities and accelerations of all angles from z (and the constraint
  // kinematics there); false if the dependent angles cannot be found.
  auto complete = [&](Kinematic& k) {
    for (int i = 0; i < nz; ++i) q[ind[i]] = z[i];
    if (!solve_dependent(ch, dep, k.G.size() ? k.G : G0, q)) return false;
    k = detail::evaluate(ch, q, false, false);
    for (int i = 0; i < c; ++i) Gy.col(i) = k.G.col(dep[i]);
    for (int i = 0; i < nz; ++i) Gz.col(i) = k.G.col(ind[i]);
    const Eigen::PartialPivLU<Matrix> lu(Gy);
    const Vector zdd = (z - z_hat) / bh2;
    const Vector zd = zd_hat + h * co.gamma * zdd;
    for (int i = 0; i < nz; ++i) v[ind[i]] = zd[i];
    const Vector vy = -lu.solve(Gz * zd);
    for (int i = 0; i < c; ++i) v[dep[i]] = vy[i];
    const Vector ay = -lu.solve(Gz * zdd + ch.constraint_jdot_qdot(q, v));
    for (int i = 0; i < nz; ++i) qdd[ind[i]] = zdd[i];
    for (int i = 0; i < c; ++i) qdd[dep[i]] = ay[i];
    return true;
  };
  Kinematic k;
  RefreshPolicy policy;
  for (int it = 1; it <= ctl.max_newton; ++it) {
    out.iterations = it;
    if (!complete(k)) return out;
    // Multipliers that make the dependent rows of r + G^T lambda vanish; the rest is the
    // reduced residual D^T r. The Newton correction restricted to G dq = 0 solves
    // D^T T D dz = -D^T r, which is the saddle-point system with the full T.
    policy.fresh = policy.refresh || !nb.usable(h);
    if (it == 1) out.reused = !policy.fresh;
    nb.residual(q, v, qdd, f1, 1.0 / bh2, dv_dq, r, policy.fresh);
    lambda = -Gy.transpose().partialPivLu().solve(take(r, dep));
    if (policy.fresh) {
      k.hess_g = ch.constraint_jacobian((q.array() + 0.5 * M_PI).matrix());  // see evaluate
      nb.add_to_tangent_diagonal(k.hess_g.transpose() * lambda);  // the constraint curvature
      if (!nb.factor(k.G, ch.l(), h)) return out;
      policy.refresh = false;
    }
    r += k.G.transpose() * lambda;
    if (!nb.solve(r, Vector::Zero(c), dqv, dl)) return out;
    const Vector dz = take(dqv, ind);
    const double norm = dz.cwiseAbs().maxCoeff();
    if (!policy.accept(norm, kBasin)) {  // left the basin
      if (policy.refresh) continue;
      return out;
    }
    z += dz;
    // The dependent rows of the correction keep G dq = 0 to first order: a predictor
    // for solve_dependent, which then needs fewer evaluations of g.
    for (int i = 0; i < c; ++i) q[dep[i]] += dqv[dep[i]];
    if (norm <= ctl.tol_q) {
      out.converged = complete(k);
      break;
    }
  }
  if (!out.converged) return out;
  s1.t = t1;
  s1.q = q;
  s1.v = v;
  s1.qdd = qdd;
  s1.a = qdd;
  s1.lambda = lambda;
  return out;
}

}  // namespace multibody::detail
