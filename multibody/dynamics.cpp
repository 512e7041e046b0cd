#include "multibody/dynamics.hpp"

#include <Eigen/LU>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"

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

/// The whole problem, fixed for a run.
struct Problem {
  const Chain& chain;
  DeadLoad load;
  ring::LoadHistory history;
  Matrix K;  ///< spring stiffness (constant)
  Matrix C;  ///< damping (constant): a M(q0) + b K + hinge dampers
  bool damped = false;
};

/// Consistent initial accelerations and multipliers: the index-1 problem
/// [M G^T; G 0] [qdd; lambda] = [f Phi - xi - C v - K theta; -Jdot v]. O(n^3).
void initial_acceleration(const Problem& p, State& s) {
  const Chain& ch = p.chain;
  const int n = ch.dofs(), c = ch.constraint_count();
  const Kinematic k = detail::evaluate(ch, s.q);
  Vector phi, dphi;
  detail::load_forces(ch, p.load, s.q, phi, dphi);
  Matrix A = Matrix::Zero(n + c, n + c);
  A.topLeftCorner(n, n) = k.M;
  A.topRightCorner(n, c) = k.G.transpose();
  A.bottomLeftCorner(c, n) = k.G;
  Vector b(n + c);
  b.head(n) = p.history.factor(s.t) * phi - detail::quadratic_velocity(k, s.v) - p.C * s.v -
              ch.spring_forces(s.q);
  b.tail(c) = -ch.constraint_jdot_qdot(s.q, s.v);
  const Vector x = A.partialPivLu().solve(b);
  s.qdd = x.head(n);
  s.lambda = x.tail(c);
  s.a = s.qdd;
}

/// Result of one attempted step.
struct StepOutcome {
  bool converged = false;
  int iterations = 0;
};

/// One step of size h from `s0`; on success writes `s1`. Newton on (q, lambda) with
/// the analytic tangent of dynamics_model.hpp. O(n^3) per iteration.
StepOutcome step(const Problem& p, const Coefficients& co, const State& s0, double h,
                 const IntegrationControls& ctl, State& s1) {
  const Chain& ch = p.chain;
  const int n = ch.dofs(), c = ch.constraint_count();
  const double t1 = s0.t + h;
  const double f1 = p.history.factor(t1);
  const double bh2 = co.beta * h * h;
  const double dqdd_dq = (1.0 - co.alpha_m) / ((1.0 - co.alpha_f) * bh2);
  const double dv_dq = co.gamma / (co.beta * h);
  // Predictor: unchanged true acceleration, previous multipliers.
  Vector a1 = (s0.qdd - co.alpha_m * s0.a) / (1.0 - co.alpha_m);
  const Vector q_hat = s0.q + h * s0.v + h * h * (0.5 - co.beta) * s0.a;
  const Vector v_hat = s0.v + h * (1.0 - co.gamma) * s0.a;
  Vector q = q_hat + bh2 * a1;
  Vector lambda = s0.lambda;
  Vector v, qdd;
  StepOutcome out;
  Matrix A(n + c, n + c);
  Vector rhs(n + c);
  Vector phi, dphi;
  Matrix dq, dv;
  for (int it = 1; it <= ctl.max_newton; ++it) {
    out.iterations = it;
    a1 = (q - q_hat) / bh2;
    v = v_hat + h * co.gamma * a1;
    qdd = ((1.0 - co.alpha_m) * a1 + co.alpha_m * s0.a - co.alpha_f * s0.qdd) / (1.0 - co.alpha_f);
    const Kinematic k = detail::evaluate(ch, q);
    detail::load_forces(ch, p.load, q, phi, dphi);
    detail::inertia_tangent(k, v, qdd, dq, dv);
    Vector r = k.M * qdd + detail::quadratic_velocity(k, v) + ch.spring_forces(q) +
               k.G.transpose() * lambda - f1 * phi;
    Matrix T = dqdd_dq * k.M + dv_dq * dv + dq + p.K;
    if (p.damped) {
      r += p.C * v;
      T += dv_dq * p.C;
    }
    T.diagonal() += k.hess_g.transpose() * lambda - f1 * dphi;
    // Scaled saddle-point system: rows of g and columns of lambda multiplied by
    // s = max|T_jj| / l so that both blocks have the size of T (Bottasso et al. 2007).
    const double sc = T.diagonal().cwiseAbs().maxCoeff() / ch.l();
    A.setZero();
    A.topLeftCorner(n, n) = T;
    A.topRightCorner(n, c) = sc * k.G.transpose();
    A.bottomLeftCorner(c, n) = sc * k.G;
    rhs.head(n) = -r;
    rhs.tail(c) = -sc * k.g;
    if (!rhs.allFinite()) return out;
    const Vector x = A.partialPivLu().solve(rhs);
    if (!x.allFinite()) return out;
    q += x.head(n);
    lambda += sc * x.tail(c);
    if (x.head(n).cwiseAbs().maxCoeff() <= ctl.tol_q) {
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

std::string describe(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t;
  return s.str();
}

}  // namespace

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

  const Chain chain(spec, options, response.load.angle);
  const int n = chain.dofs();
  Problem p{chain, {chain.hinge_at(response.load.angle),
                    {response.load.force[0], response.load.force[1]}},
            response.load.history, chain.stiffness_matrix(), Matrix::Zero(n, n), false};
  if (response.rayleigh_mass > 0 || response.rayleigh_stiffness > 0 || response.hinge_damping > 0) {
    p.damped = true;
    // Rayleigh damping about the undeformed chain; hinge dampers follow the springs'
    // pattern (cyclic 2, -1, -1), so they are the stiffness matrix times c / K.
    p.C = response.rayleigh_mass * chain.mass_matrix(chain.q0()) +
          (response.rayleigh_stiffness + response.hinge_damping / chain.K()) * p.K;
  }
  const Coefficients co = coefficients(response);

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
  initial_acceleration(p, s);
  const Eigen::Vector2d F = p.load.force;
  double work = 0.0, dissipated = 0.0;
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
    while (t_target - s.t > 1e-9 * response.dt) {
      const double remaining = t_target - s.t;
      const bool last = remaining <= h * (1.0 + 1e-9);
      const double hs = last ? remaining : h;
      State s1;
      const StepOutcome o = step(p, co, s, hs, controls, s1);
      iterations += o.iterations;
      if (!o.converged) {
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
      // energy dissipated by damping (trapezoidal).
      const Eigen::Vector2d x1 = chain.hinge_position(s1.q, p.load.hinge);
      work += 0.5 * (p.history.factor(s.t) + p.history.factor(s1.t)) * F.dot(x1 - x_load);
      x_load = x1;
      if (p.damped)
        dissipated += 0.5 * hs * (s.v.dot(p.C * s.v) + s1.v.dot(p.C * s1.v));
      s = std::move(s1);
      if (last) s.t = t_target;  // no round-off drift of the sub-steps
      if (!s.q.allFinite() || !s.v.allFinite())
        fail(IntegrationFailure::Reason::not_finite,
             "multibody::respond: non-finite state at t = " + describe(s.t) + " s");
      if (controls.check_contact) {
        const auto cp = detail::closest_nonadjacent(chain.hinge_positions(s.q), gap, depth);
        if (cp.distance < depth) {
          std::ostringstream m;
          m << "multibody::respond: the ring touches itself at t = " << describe(s.t)
            << " s: segments " << cp.i << " and " << cp.j << " are " << cp.distance
            << " m apart (section depth " << depth
            << " m); the chain model does not include contact";
          fail(IntegrationFailure::Reason::self_contact, m.str());
        }
      }
      if (h < response.dt && ++successes >= 2) {
        h = std::min(2.0 * h, response.dt);
        successes = 0;
      }
    }
    record(s, iterations, k);
  }
  return th;
}

}  // namespace multibody
