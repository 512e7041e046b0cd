#include "multibody/dynamics.hpp"

#include "multibody/checks.hpp"

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "multibody/energy_momentum.hpp"
#include "multibody/integrators.hpp"
#include "multibody/newton_backend.hpp"
#include "ring/energy_guard.hpp"

namespace multibody {
namespace {

using detail::Coefficients;
using detail::Problem;
using detail::State;
using detail::StepOutcome;

/// Segments from which the contact test uses the grid of closest_nonadjacent_grid:
/// below, the O(n^2) box loop is as fast (both well under the step's cost).
constexpr int kGridContact = 128;

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
  check_response(spec, options, response);
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
  const bool damped = damping.any();
  const std::unique_ptr<detail::NewtonBackend> backend =
      detail::make_newton_backend(chain, p.load, damping, use_sparse_path(options));
  detail::NewtonBackend& nb = *backend;
  const Coefficients co = detail::coefficients(response);
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
  // Both integrators start from the accelerations that the first step's Newton matrix
  // filters (starting_pseudo_acceleration): generalized-alpha's pseudo-acceleration a_0,
  // Newmark's qdd_0 (its partitioned step reads only the independent angles' qdd_0).
  detail::starting_pseudo_acceleration(p, co, response.dt, nb, s);
  if (partitioned) s.qdd = s.a;
  const Eigen::Vector2d F = p.load.force;
  double work = 0.0, dissipated = 0.0;
  ring::EnergyGuard guard(spec, chain.n(), response.load.force);
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
  guard.start(th.kinetic.back(), th.strain.back(), th.work.back());

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
      const StepOutcome o = partitioned ? detail::step_partitioned(p, co, s, hs, controls, nb, s1)
                                        : detail::step_index3(p, co, s, hs, controls, nb, s1);
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
      const double f_mean = 0.5 * (p.history.factor(s.t) + p.history.factor(s1.t));
      work += f_mean * F.dot(x1 - x_load);
      guard.step(hs, f_mean);
      x_load = x1;
      if (damped) {
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
    // A run that gains energy has failed, whatever the integrator: its history is not a
    // result (generalized-alpha did on fine chains under a point step load when it
    // started from a_0 = qdd_0; see starting_pseudo_acceleration). The rule: energy_guard.hpp.
    const ring::EnergyGuard::Verdict verdict =
        guard.check(th.kinetic.back(), th.strain.back(), work);
    if (verdict.gained)
      fail(IntegrationFailure::Reason::energy_growth,
           "multibody::respond: " + ring::describe(verdict, s.t) +
               " (try response.integrator = \"energy-momentum\" or \"newmark\")");
  }
  return th;
}

}  // namespace multibody
