#include "multibody/dynamics.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "multibody/energy_momentum.hpp"
#include "multibody/newton_backend.hpp"

namespace multibody {
namespace {

using detail::DeadLoad;
using detail::Kinematic;

/// Integrator coefficients in the Arnold-Bruls form; Newmark is alpha_m = alpha_f = 0.
struct Coefficients {
  double alpha_m = 0.0, alpha_f = 0.0, beta = 0.25, gamma = 0.5;
};

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

/// State at an accepted time: positions, velocities, accelerations, the
/// generalized-alpha pseudo-acceleration, multipliers.
struct State {
  double t = 0.0;
  Vector q, v, qdd, a, lambda;
};

/// The whole problem, fixed for a run; its linear algebra is the backend's.
struct Problem {
  const Chain& chain;
  DeadLoad load;
  ring::LoadHistory history;
  bool damped = false;
};

/// Starting value of generalized-alpha's pseudo-acceleration a_0 (the acceleration-like
/// sequence of Arnold & Bruls 2007; the true acceleration qdd_0 stays consistent):
///   [S G^T; G 0] [a_0; mu] = c [f Phi - xi - C v - K theta; -Gdot v],
/// S = c M + c' (C + dxi/dv) + tangent stiffness (springs, load, constraint curvature
/// with the consistent multipliers): the integrator's Newton matrix at t_0 for the step h
/// without the term d(M qdd)/dq,
/// c = (1 - alpha_m) / ((1 - alpha_f) beta h^2), c' = gamma / (beta h). In a linear mode
/// of frequency w this is a_0 = c qdd_0 / (c + w^2): qdd_0 (1 + O(w^2 h^2)) where the
/// step resolves the mode, so the accuracy of the consistent start is kept (second order
/// in q and v: tests/multibody/test_dynamics.cpp), and -> 0 where w h >> 1. Why not
/// a_0 = qdd_0: a mode with w h >> 1 started there leaves the first steps with the
/// velocity ~ h (1 - gamma) qdd_0 instead of ~ qdd_0 / w (the method's velocity
/// overshoot); a point step load gives every mode the acceleration F_k / m_k, the chain's
/// w_max grows like n^2, and the spurious velocity of the loaded hinge spins its segments
/// once h^2 |qdd_0| exceeds their length: +1.6 J at n = 640, +30 J at 1280, +1.3e3 J at
/// 2560 of T + V - W after the first step of the 20 kN scene (multibody/README.md,
/// "Energy growth is a failure"). With this start the balance stays <= 0. Cost: one
/// factorization of the Newton matrix (O(n) sparse, O(n^3) dense).
void starting_pseudo_acceleration(const Problem& p, const Coefficients& co, double h, detail::NewtonBackend& nb,
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

/// Result of one attempted step.
struct StepOutcome {
  bool converged = false;
  int iterations = 0;
  bool reused = false;  ///< began with a Newton matrix kept from an earlier step
};

/// One index-3 step of size h from `s0` (generalized-alpha, Arnold-Bruls form); on
/// success writes `s1`. Newton on (q, lambda) with the analytic tangent of
/// dynamics_model.hpp. O(n^3) per iteration.
StepOutcome step_index3(const Problem& p, const Coefficients& co, const State& s0, double h,
                        const IntegrationControls& ctl, detail::NewtonBackend& nb, State& s1) {
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
    if (!policy.accept(norm, 0.5)) {
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

/// One Newmark step in the paper's reduced form (its eqs. 18-20, coordinate
/// partitioning): the c dependent angles are the best-conditioned columns of G(q_n)
/// (column-pivoted QR), the Newmark formulas act on the n - c independent angles z, and
/// the dependent ones follow from g(q) = 0 at every iteration, their velocities and
/// accelerations from G v = 0 and G qdd + Gdot v = 0. The equations are D^T r = 0 with
/// D = [I; -G_y^{-1} G_z]; the Newton matrix is D^T T D with T the full tangent of
/// step_index3 and lambda = -G_y^{-T} r_y. The terms d D/dz of the dependent rates, of
/// order v and h, are left out (convergence fast-linear): added exactly (rank 2c,
/// Woodbury) they saved 17-25 % of the iterations but cost 30-40 % more wall time per
/// run on both paths (multibody/README.md, "Newton iterations per step"). Constraints hold to
/// round-off at the positions, velocities and accelerations; no multiplier oscillates,
/// which is what makes the trapezoidal rule stable here (applied to the index-3 form it
/// is not: Cardona & Geradin 1989). O(n^3) per iteration.
StepOutcome step_partitioned(const Problem& p, const Coefficients& co, const State& s0, double h,
                             const IntegrationControls& ctl, detail::NewtonBackend& nb, State& s1) {
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
    if (!policy.accept(norm, 0.5)) {  // more than 0.5 rad: left the basin
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

/// Segments from which the contact test uses the grid of closest_nonadjacent_grid:
/// below, the O(n^2) box loop is as fast (both well under the step's cost).
constexpr int kGridContact = 128;
/// An undamped run whose energy balance exceeds this fraction of the largest work has
/// gained energy and failed (the same bound as the other solvers' responses).
constexpr double kEnergyGrowth = 1e-2;

std::string describe(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t;
  return s.str();
}

}  // namespace

bool use_sparse_path(const ring::MultibodyOptions& options) {
  switch (options.method) {
    case ring::MultibodyOptions::Method::dense: return false;
    case ring::MultibodyOptions::Method::sparse: return true;
    default: return options.n >= kSparseDynamicsCrossover;
  }
}

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          const ring::ResponseOptions& response,
                          const IntegrationControls& controls) {
  if (!spec.supports.pin)
    throw std::invalid_argument("multibody::respond: the ring needs a pin (supports.pin)");
  if (!(response.dt > 0.0) || !std::isfinite(response.dt))
    throw std::invalid_argument("multibody::respond: dt must be > 0");
  if (!(response.t_end >= response.dt) || !std::isfinite(response.t_end))
    throw std::invalid_argument("multibody::respond: t_end must be >= dt");
  if (!(response.rho_inf >= 0.0 && response.rho_inf <= 1.0))
    throw std::invalid_argument("multibody::respond: rho_inf must lie in [0, 1]");
  if (response.rayleigh_mass < 0 || response.rayleigh_stiffness < 0 || response.hinge_damping < 0)
    throw std::invalid_argument("multibody::respond: damping coefficients must be >= 0");
  if (controls.max_newton < 1 || !(controls.min_dt_factor > 0 && controls.min_dt_factor <= 1))
    throw std::invalid_argument(
        "multibody::respond: controls need max_newton >= 1 and 0 < min_dt_factor <= 1");
  if (response.integrator == ring::ResponseOptions::Integrator::energy_momentum)
    return respond_energy_momentum(spec, options, response, controls);

  const Chain chain(spec, options, response.load.angle);
  const int n = chain.dofs();
  Problem p{chain, {chain.hinge_at(response.load.angle), {response.load.force[0], response.load.force[1]}},
            response.load.history};
  // Rayleigh damping about the undeformed chain; hinge dampers follow the springs'
  // pattern (cyclic 2, -1, -1), so they add c / K times the stiffness.
  const detail::Damping damping{response.rayleigh_mass,
                                (response.rayleigh_stiffness + response.hinge_damping / chain.K()) * chain.K()};
  p.damped = damping.any();
  const std::unique_ptr<detail::NewtonBackend> backend =
      detail::make_newton_backend(chain, p.load, damping, use_sparse_path(options));
  detail::NewtonBackend& nb = *backend;
  const Coefficients co = coefficients(response);
  const bool partitioned = response.integrator == ring::ResponseOptions::Integrator::newmark;

  std::vector<int> rec;
  for (double a : response.record) rec.push_back(chain.hinge_at(a));
  const int gap = detail::contact_gap(chain, spec.section.depth());
  const double depth = spec.section.depth();

  ring::TimeHistory th;
  th.record_angles = response.record;
  th.ux.assign(rec.size(), {});
  th.uy.assign(rec.size(), {});
  const long steps = std::lround(response.t_end / response.dt);
  std::vector<long> snap_steps;
  for (int i = 0; i < controls.snapshots; ++i)
    snap_steps.push_back(controls.snapshots == 1 ? steps
                                                 : std::lround(double(steps) * i / (controls.snapshots - 1)));

  State s;
  s.q = chain.q0();
  s.v = Vector::Zero(n);
  if (!nb.initial_acceleration(s.q, s.v, p.history.factor(s.t), s.qdd, s.lambda))
    throw std::runtime_error("multibody::respond: initial accelerations not computable");
  s.a = s.qdd;
  if (!partitioned) starting_pseudo_acceleration(p, co, response.dt, nb, s);
  const Eigen::Vector2d F = p.load.force;
  double work = 0.0, dissipated = 0.0, max_work = 0.0;
  Eigen::Vector2d x_load = chain.hinge_position(s.q, p.load.hinge);

  auto record = [&](const State& st, int iterations, long k) {
    th.t.push_back(st.t);
    const Eigen::Matrix2Xd hp = chain.hinge_positions(st.q);
    for (size_t i = 0; i < rec.size(); ++i) {
      const Eigen::Vector2d u = hp.col(rec[i]) - chain.hinge_rest(rec[i]);
      th.ux[i].push_back(u.x());
      th.uy[i].push_back(u.y());
    }
    const double T = chain.kinetic_energy(st.q, st.v), V = chain.spring_energy(st.q);
    th.kinetic.push_back(T);
    th.strain.push_back(V);
    th.work.push_back(work);
    th.energy_error.push_back(T + V + dissipated - work);
    th.constraint_residual.push_back(chain.constraints(st.q).cwiseAbs().maxCoeff());
    th.newton_iterations.push_back(iterations);
    for (long ks : snap_steps)
      if (ks == k) {
        th.snapshot_t.push_back(st.t);
        th.snapshot_x.emplace_back(hp.row(0).begin(), hp.row(0).end());
        th.snapshot_y.emplace_back(hp.row(1).begin(), hp.row(1).end());
        break;
      }
  };
  auto fail = [&](IntegrationFailure::Reason why, const std::string& msg) {
    throw IntegrationFailure(why, th.t.empty() ? 0.0 : th.t.back(), th, msg);
  };
  record(s, 0, 0);

  const double min_dt = controls.min_dt_factor * response.dt;
  double h = response.dt;
  int successes = 0;
  for (long k = 1; k <= steps; ++k) {
    const double t_target = response.dt * k;
    int iterations = 0;
    // Sub-steps (after halving) end exactly on the grid; a remainder below 1e-7 dt is
    // round-off and is snapped. Never leave a sliver: accelerations come from
    // (q - q_hat) / (beta h^2), so a step of 1e-9 dt would turn round-off into garbage;
    // a remainder between h and 2 h is split into two equal steps.
    while (t_target - s.t > 1e-7 * response.dt) {
      const double remaining = t_target - s.t;
      const bool last = remaining <= h * (1.0 + 1e-9);
      const double hs = last ? remaining : (remaining < 2.0 * h ? 0.5 * remaining : h);
      State s1;
      const StepOutcome o = partitioned ? step_partitioned(p, co, s, hs, controls, nb, s1)
                                        : step_index3(p, co, s, hs, controls, nb, s1);
      iterations += o.iterations;
      if (!o.converged) {
        nb.invalidate();
        if (o.reused) continue;  // first try again with a Newton matrix of this state
        h = 0.5 * hs;
        successes = 0;
        if (h < min_dt)
          fail(IntegrationFailure::Reason::step_too_small,
               "multibody::respond: Newton did not converge at t = " + describe(s.t) +
                   " s even with the step halved to " + describe(h) + " s (minimum " +
                   describe(min_dt) + " s)");
        continue;
      }
      // Work of the dead load (trapezoidal in time; exact for a constant force) and
      // energy dissipated by damping.
      const Eigen::Vector2d x1 = chain.hinge_position(s1.q, p.load.hinge);
      work += 0.5 * (p.history.factor(s.t) + p.history.factor(s1.t)) * F.dot(x1 - x_load);
      x_load = x1;
      if (p.damped) {
        // Midpoint form h (v_n + v_{n+1})^T C (v_n + v_{n+1}) / 4: for newmark on a linear
        // system this is exactly the energy the discrete damping force removes.
        const Vector vm = s.v + s1.v;
        dissipated += 0.25 * hs * vm.dot(nb.damping_times(vm));
      }
      s = std::move(s1);
      if (last) s.t = t_target;  // no round-off drift of the sub-steps
      if (!s.q.allFinite() || !s.v.allFinite())
        fail(IntegrationFailure::Reason::not_finite,
             "multibody::respond: non-finite state at t = " + describe(s.t) + " s");
      if (controls.check_contact) {
        // Above kGridContact segments the uniform grid (same pairs, same result, O(n)).
        const Eigen::Matrix2Xd hp = chain.hinge_positions(s.q);
        const auto cp = chain.n() >= kGridContact
                            ? detail::closest_nonadjacent_grid(hp, chain.l(), gap, depth)
                            : detail::closest_nonadjacent(hp, gap, depth);
        if (cp.distance < depth) {
          std::ostringstream m;
          m << "multibody::respond: the ring touches itself at t = " << describe(s.t)
            << " s: " << detail::describe_contact(cp) << " (section depth " << depth
            << " m); the chain model does not include contact";
          fail(IntegrationFailure::Reason::self_contact, m.str());
        }
      }
      if (h < response.dt && ++successes >= 2) {
        h = std::min(2.0 * h, response.dt);
        successes = 0;
      }
    }
    s.t = t_target;
    record(s, iterations, k);
    // An undamped run that gains energy has failed, whatever the integrator: its history
    // is not a result (generalized-alpha did on fine chains under a point step load when
    // it started from a_0 = qdd_0; see starting_pseudo_acceleration).
    max_work = std::max(max_work, std::abs(work));
    if (!p.damped && max_work > 0 && th.energy_error.back() > kEnergyGrowth * max_work)
      fail(IntegrationFailure::Reason::energy_growth,
           "multibody::respond: the energy balance T + V - W grew to " + describe(th.energy_error.back()) +
               " J, more than " + describe(100.0 * kEnergyGrowth) + " % of the work " + describe(max_work) +
               " J, at t = " + describe(s.t) + " s: the integration gains energy (try response.integrator = "
               "\"energy-momentum\" or \"newmark\")");
  }
  return th;
}

}  // namespace multibody
