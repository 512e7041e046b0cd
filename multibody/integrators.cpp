// The integrators' steps (integrators.hpp).
#include "multibody/integrators.hpp"

#include "paths/newton.hpp"
#include "paths/schemes.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <stdexcept>

namespace multibody::detail {
namespace {

/// The partitioned step refreshes its Newton matrix after a correction above this (rad):
/// its Jacobian changes fast with the iterate at large n (the dependent angles' rates sum
/// over the whole chain), so a kept matrix contracts poorly after a large correction
/// (iterations and time per step for 1e-2 .. 1e-4: docs/measured.md, "Newton iterations
/// per step").
constexpr double kRefreshPartitioned = 1e-3;

/// The one Newton's rule for both steps: the correction's largest angle below tol_q, a kept
/// Newton matrix reused while it contracts (paths/newton.hpp).
paths::Rule step_rule(const IntegrationControls& ctl, double refresh_above = HUGE_VAL) {
  paths::Rule rule;
  rule.tolerance = ctl.tol_q;
  rule.cap = ctl.max_newton;
  rule.reuse = true;
  rule.refresh_above = refresh_above;
  return rule;
}

/// The constraints at the state q, and Gdot v. O(n).
Vector constraints(const Problem& p, const Vector& q) {
  const int nc = p.chain.dofs();
  return constraint_values(p.chain, p.terms, q.head(nc));
}
Vector jdot_qdot(const Problem& p, const Vector& q, const Vector& v) {
  const int nc = p.chain.dofs();
  if (p.terms) return constraint_jdot_qdot(p.terms->constraints(q.head(nc)), v.head(nc));
  return p.chain.constraint_jdot_qdot(q.head(nc), v.head(nc));
}

/// Solves g(q) = 0 for the dependent angles `dep` with the others fixed: chord iterations
/// with the block G_y of `G` (the Jacobian at a nearby configuration: the caller's last
/// one, which saves evaluating it here). O(n) per iteration. False if it fails.
bool solve_dependent(const Problem& p, const std::vector<int>& dep, const Matrix& G, Vector& q) {
  const Chain& ch = p.chain;  // the dependent angles are among the chain's coordinates, q's head
  const int c = static_cast<int>(dep.size());
  // |g| is in metres; 1e-15 R sqrt(n) is the round-off of the closure sum of n terms.
  const double tol = 1e-15 * ch.circumradius() * std::sqrt(double(ch.n()));
  Matrix Gy(c, c);
  for (int i = 0; i < c; ++i) Gy.col(i) = G.col(dep[i]);
  const Eigen::PartialPivLU<Matrix> lu(Gy);
  for (int it = 0; it < 30; ++it) {
    const Vector g = constraints(p, q);
    if (!g.allFinite()) return false;
    if (g.cwiseAbs().maxCoeff() <= tol) return true;
    const Vector dy = -lu.solve(g);
    if (!dy.allFinite()) return false;
    for (int i = 0; i < c; ++i) q[dep[i]] += dy[i];
    if (dy.cwiseAbs().maxCoeff() <= 1e-15) return true;
  }
  return constraints(p, q).cwiseAbs().maxCoeff() <= 1e3 * tol;
}

/// M(q) E for the columns of E (Problem::size rows): the chain's mass, the point masses', and
/// the sections' or the hinge rotations'. O(n k), O(n^2 k) with point masses.
Matrix mass_times_columns(const Problem& p, const Vector& q, const Matrix& E) {
  const int nc = p.chain.dofs();
  Matrix out = Matrix::Zero(E.rows(), E.cols());
  out.topRows(nc) = p.chain.mass_times_columns(q.head(nc), E.topRows(nc));
  if (p.terms && p.terms->has_mass()) {
    Matrix Mt = Matrix::Zero(nc, nc);
    p.terms->add_mass(q.head(nc), Mt);
    out.topRows(nc) += Mt * E.topRows(nc);
  }
  if (p.sections) p.sections->add_mass_times(E, out);
  if (p.hinges) p.hinges->add_mass_times(E, out);
  return out;
}

}  // namespace

Kinematic kinematics(const Problem& p, const Vector& q, bool values, bool hessian) {
  const int nc = p.chain.dofs();
  Kinematic k;
  if (p.terms && p.terms->pin_rows() > 0) {
    Chain::ConstraintKinematics ck = p.terms->constraints(q.head(nc));
    k = {std::move(ck.G), std::move(ck.g), std::move(ck.hess)};
  } else {
    k = detail::evaluate(p.chain, q.head(nc), values, hessian);
  }
  if (q.size() == nc) return k;
  auto widen = [&](Matrix& m) {
    if (m.size() == 0) return;
    Matrix w = Matrix::Zero(m.rows(), q.size());
    w.leftCols(nc) = m;
    m = std::move(w);
  };
  widen(k.G);
  widen(k.hess_g);
  return k;
}

Coefficients coefficients(const ring::ResponseOptions& r) { return paths::Scheme::of(r); }

void starting_pseudo_acceleration(const Problem& p, const Coefficients& co, double h, NewtonBackend& nb,
                                  State& s) {
  const double c = co.mass_rate(h) / (1.0 - co.alpha_f);
  const double cv = co.velocity_rate(h);
  Vector r;
  nb.residual(s.q, s.v, Vector::Zero(s.q.size()), p.history.factor(s.t), c, cv, r, true);
  const Kinematic k = kinematics(p, s.q, false, true);
  nb.add_to_tangent_diagonal(k.hess_g.transpose() * s.lambda);
  Vector a, mu;
  const bool ok = nb.factor(k.G, p.chain.l(), h) && nb.solve(c * r, c * jdot_qdot(p, s.q, s.v), a, mu);
  nb.invalidate();  // the first step factors its own matrix
  if (!ok) throw std::runtime_error("multibody::respond: starting accelerations not computable");
  s.a = a;
}

StepOutcome step_index3(const Problem& p, const Coefficients& co, const State& s0, double h,
                        const IntegrationControls& ctl, NewtonBackend& nb, State& s1) {
  const double t1 = s0.t + h;
  const double f1 = p.history.factor(t1);
  const double dqdd_dq = co.mass_rate(h) / (1.0 - co.alpha_f);
  const double dv_dq = co.velocity_rate(h);
  // Predictor: constant velocity, previous multipliers. Extrapolating the acceleration
  // as well is worse after a step load, whose initial accelerations are local and huge
  // at large n (at n = 640 it overshoots by radians and forces step halving).
  const Vector q_hat = co.predicted_position(s0.q, s0.v, s0.a, h);
  const Vector v_hat = co.predicted_velocity(s0.v, s0.a, h);
  Vector q = s0.q + h * s0.v;
  Vector lambda = s0.lambda;
  Vector a1, v, qdd, r, dqv, dl;
  Kinematic k;
  // Newton on (q, lambda) with the index-3 saddle-point matrix of the backend, through the
  // one Newton (paths/newton.hpp).
  paths::NewtonFunctions system;
  system.kept = [&] { return nb.usable(h); };
  system.linearize_at = [&](bool fresh) {
    a1 = co.acceleration(q, q_hat, h);
    v = co.velocity(v_hat, a1, h);
    qdd = co.true_acceleration(a1, s0.a, s0.qdd);
    k = kinematics(p, q, true, fresh);
    nb.residual(q, v, qdd, f1, dqdd_dq, dv_dq, r, fresh);
    if (fresh) {
      nb.add_to_tangent_diagonal(k.hess_g.transpose() * lambda);  // the constraint curvature
      if (!nb.factor(k.G, p.chain.l(), h)) return false;
    }
    r += k.G.transpose() * lambda;
    return true;
  };
  system.solve_for = [&](paths::Correction& c) {
    if (!nb.solve(r, k.g, dqv, dl)) return false;
    c.size = dqv.cwiseAbs().maxCoeff();
    c.move = c.size / kBasin;  // a correction turning a segment by more than 0.5 rad has left the basin
    return true;
  };
  system.apply_correction = [&] {
    q += dqv;
    lambda += dl;
  };
  // Converged when the correction is below tol_q and the constraints hold to 1e-12 R
  // (a kept Newton matrix contracts g only linearly, so check it explicitly).
  system.settle_at = [&](bool small, const paths::Correction&) {
    return small && constraints(p, q).cwiseAbs().maxCoeff() <= 1e-12 * p.chain.circumradius()
               ? paths::Verdict::converged
               : paths::Verdict::iterate;
  };
  const paths::NewtonResult nr = paths::newton(system, step_rule(ctl));
  const StepOutcome out{nr.converged, nr.iterations, nr.reused};
  if (!out.converged) return out;
  a1 = co.acceleration(q, q_hat, h);
  s1.t = t1;
  s1.q = q;
  s1.v = co.velocity(v_hat, a1, h);
  s1.qdd = co.true_acceleration(a1, s0.a, s0.qdd);
  s1.a = a1;
  s1.lambda = lambda;
  return out;
}

StepOutcome step_partitioned(const Problem& p, const Coefficients& co, const State& s0, double h,
                             const IntegrationControls& ctl, NewtonBackend& nb, State& s1) {
  const Chain& ch = p.chain;
  const int n = p.size(), c = p.constraint_count(), nz = n - c;
  std::vector<int> dep(c), ind;
  {
    // The shear angles' columns are zero: the pivoting takes the dependent ones among phi.
    const Eigen::ColPivHouseholderQR<Matrix> qr(kinematics(p, s0.q, false, false).G);
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
  const double cm = co.acceleration_rate(h), cv = co.velocity_rate(h);
  const Vector q_hat = co.predicted_position(s0.q, s0.v, s0.qdd, h);
  const Vector v_hat = co.predicted_velocity(s0.v, s0.qdd, h);
  const Vector z_hat = take(q_hat, ind), zd_hat = take(v_hat, ind);
  const double t1 = s0.t + h;
  const double f1 = p.history.factor(t1);
  // Predictor: constant velocity (see step_index3).
  Vector q = s0.q + h * s0.v;
  Vector v(n), qdd(n), lambda = s0.lambda, r, dq, dl;
  Matrix Gy(c, c), Gz(c, nz);
  Eigen::PartialPivLU<Matrix> gy;
  Kinematic k;
  // The first iteration treats every angle alike, as the index-3 form does (Newmark's
  // formulas on all of them); the others solve the partitioned equations.
  bool partitioned = false;
  // Velocities and accelerations of all angles at the current q (on g = 0 or not) and the
  // constraint kinematics there. Partitioned: Newmark on z, the dependent ones from
  // G v = 0 and G qdd + Gdot v = 0.
  auto rates = [&] {
    k = kinematics(p, q, true, true);
    for (int i = 0; i < c; ++i) Gy.col(i) = k.G.col(dep[i]);
    for (int i = 0; i < nz; ++i) Gz.col(i) = k.G.col(ind[i]);
    gy.compute(Gy);
    if (!partitioned) {
      qdd = co.acceleration(q, q_hat, h);
      v = co.velocity(v_hat, qdd, h);
      return;
    }
    const Vector zdd = co.acceleration(Vector(take(q, ind)), z_hat, h);
    const Vector zd = co.velocity(zd_hat, zdd, h);
    for (int i = 0; i < nz; ++i) v[ind[i]] = zd[i];
    const Vector vy = -gy.solve(Gz * zd);
    for (int i = 0; i < c; ++i) v[dep[i]] = vy[i];
    const Vector ay = -gy.solve(Gz * zdd + jdot_qdot(p, q, v));
    for (int i = 0; i < nz; ++i) qdd[ind[i]] = zdd[i];
    for (int i = 0; i < c; ++i) qdd[dep[i]] = ay[i];
  };
  // The part U V^T of the partitioned Newton matrix that T leaves out (header): U =
  // M(q) E_dep and Y = A^-1 [U; 0] are kept with the factorization A of this step, V^T
  // is evaluated at every iterate and the correction applied by Woodbury's formula.
  Matrix Yq(n, c), Yl(c, c);
  bool have_y = false;
  auto prepare_correction = [&] {
    Matrix E = Matrix::Zero(n, c);
    for (int i = 0; i < c; ++i) E(dep[i], i) = 1.0;
    if (!nb.solve_columns(mass_times_columns(p, q, E), Yq, Yl)) return false;
    Yq = -Yq;
    Yl = -Yl;
    have_y = true;
    return true;
  };
  auto correct = [&] {
    const Matrix Hv = k.hess_g * v.asDiagonal();  // d(G v)/dq at fixed v
    Matrix HvE(c, c);
    for (int i = 0; i < c; ++i) HvE.col(i) = Hv.col(dep[i]);
    const Matrix Vv = -gy.solve(cv * k.G + Hv);
    const Matrix Vt = -gy.solve(cm * k.G + k.hess_g * qdd.asDiagonal() - k.G * v.cwiseAbs2().asDiagonal() +
                                2.0 * cv * Hv + 2.0 * HvE * Vv);
    const Matrix S = Matrix::Identity(c, c) + Vt * Yq;
    const Vector w = S.partialPivLu().solve(Vt * dq);
    dq -= Yq * w;
    dl -= Yl * w;
    return dq.allFinite() && dl.allFinite();
  };
  // Newton on (q, lambda) through the one Newton (paths/newton.hpp), the partitioned
  // equations' matrix made exact by the rank-c correction above.
  paths::NewtonFunctions system;
  bool this_partitioned = false;  // the current iteration solves the partitioned equations
  system.kept = [&] { return nb.usable(h) && !(partitioned && !have_y); };
  system.linearize_at = [&](bool fresh) {
    this_partitioned = partitioned;
    rates();
    nb.residual(q, v, qdd, f1, cm, cv, r, fresh);
    // Partitioned: the multipliers that make the dependent rows of r + G^T lambda vanish.
    if (partitioned) lambda = -Gy.transpose().partialPivLu().solve(take(r, dep));
    if (fresh) {
      nb.add_to_tangent_diagonal(k.hess_g.transpose() * lambda);  // the constraint curvature
      if (!nb.factor(k.G, ch.l(), h) || !prepare_correction()) return false;
    }
    r += k.G.transpose() * lambda;
    return true;
  };
  system.solve_for = [&](paths::Correction& c) {
    if (!nb.solve(r, k.g, dq, dl) || (partitioned && !correct())) return false;
    c.size = dq.cwiseAbs().maxCoeff();
    c.move = c.size / kBasin;
    return true;
  };
  system.apply_correction = [&] {
    q += dq;
    if (!partitioned) {
      lambda += dl;
      partitioned = true;
    }
  };
  system.settle_at = [&](bool small, const paths::Correction&) {
    if (!this_partitioned) return paths::Verdict::iterate;
    if (!small || constraints(p, q).cwiseAbs().maxCoeff() > 1e-12 * ch.circumradius())
      return paths::Verdict::iterate;
    // The dependent angles to round-off, and the rates there.
    if (!solve_dependent(p, dep, k.G, q)) return paths::Verdict::failed;
    rates();
    return paths::Verdict::converged;
  };
  const paths::NewtonResult nr = paths::newton(system, step_rule(ctl, kRefreshPartitioned));
  const StepOutcome out{nr.converged, nr.iterations, nr.reused};
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
