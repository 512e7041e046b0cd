// The energy-momentum integrator in natural coordinates (energy_momentum.hpp).
#include "multibody/energy_momentum.hpp"

#include "multibody/checks.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "multibody/natural.hpp"
#include "ring/energy_guard.hpp"

namespace multibody {
namespace {

using namespace natural;
/// A spring's discrete-gradient correction is applied where it exceeds this many times
/// its round-off (see step()).
constexpr double kResolved = 1e3;
constexpr double kEps = 2.220446049250313e-16;
constexpr int kMaxNewton = 15;
// Newton's stopping rule: natural::NewtonStop (bounds relative to R = n l / 2 pi: the
// round-off of positions is ~eps R, so a bound in l could not be met at large n).

struct Step {
  bool converged = false;
  int iterations = 0;
};

/// The vectors of a Newton iteration, sized once for the chain: allocated per iteration,
/// the allocator returned them to the system and faulted them back in (~5% of an
/// iteration at n = 10^4).
struct Work {
  explicit Work(const Natural& c)
      : V0(c.n), xm(2 * c.n), w(2 * c.n), rx(2 * c.n), g(c.rows()), z(c.size()), scratch(c.size()) {}
  Vec V0, xm, w, rx, g, z, scratch;
};

/// One step of the scheme from (x0, v0) over h with load factor f at the midpoint;
/// x1 and lambda are the starting guess and the result.
Step step(const Natural& c, const Vec& x0, const Vec& v0, double h, double f, Vec& x1, Vec& lambda,
          BandedKkt& kkt, Work& work) {
  const int N = 2 * c.n;
  const double cm = 2.0 / (h * h);
  const double s = 0.25 * c.m, r = c.Jr / (c.l * c.l);
  const double kappa = cm * (s + r);
  Step out;
  NewtonStop stop(c.radius());
  // The springs' energies at x0 (constant over the iterations).
  Vec& V0 = work.V0;
  for (int k = 0; k < c.n; ++k) {
    const double d0 = turn_angle(local(c, x0, k)) - c.theta0;
    V0[k] = 0.5 * c.K * d0 * d0;
  }
  Vec &xm = work.xm, &rx = work.rx, &dz = work.z;
  for (int it = 1; it <= kMaxNewton; ++it) {
    kkt.clear();
    xm = 0.5 * (x0 + x1);
    // Inertia: (2/h^2) M (x1 - x0 - h v0).
    work.w = x1 - x0 - h * v0;
    mass_times(c, work.w, rx);
    rx *= cm;
    rx.segment<2>(2 * c.load) -= f * c.F;
    for (int i = 0; i < c.n; ++i) {
      const int j = (i + 1) % c.n;
      for (int a = 0; a < 2; ++a) {
        kkt.add(2 * i + a, 2 * i + a, cm * (s + r));
        kkt.add(2 * j + a, 2 * j + a, cm * (s + r));
        kkt.add(2 * i + a, 2 * j + a, cm * (s - r));
        kkt.add(2 * j + a, 2 * i + a, cm * (s - r));
      }
    }
    // Constraint forces at the midpoint: d/dx1 of G(xm)^T lambda = 1/2 sum lambda_i Hess c_i.
    add_constraint_curvature(c, lambda, 0.5, kkt);
    // Springs: each one's discrete gradient and its exact Jacobian in y1.
    for (int k = 0; k < c.n; ++k) {
      const Vec6 y0 = local(c, x0, k), y1 = local(c, x1, k), dy = y1 - y0;
      const Turn tm = turn(0.5 * (y0 + y1));
      const double dm = tm.theta - c.theta0;
      const Vec6 gm = c.K * dm * tm.d;
      const Mat6 Hm = c.K * (tm.d * tm.d.transpose() + dm * tm.dd);
      Vec6 g = gm;
      Mat6 J = 0.5 * Hm;
      const double ss = dy.squaredNorm();
      const Turn t1 = turn(y1, false);
      const double V1 = 0.5 * c.K * (t1.theta - c.theta0) * (t1.theta - c.theta0);
      const double e = V1 - V0[k] - gm.dot(dy);
      // The correction only where e is resolved above its round-off; elsewhere it would
      // be noise (and its Jacobian noise / |dy|^2), and leaving it out costs an energy
      // error below kResolved eps V per spring and step.
      if (ss > 0 && std::abs(e) > kResolved * kEps * (std::abs(V0[k]) + std::abs(V1) + std::abs(gm.dot(dy)))) {
        g += e / ss * dy;
        const Vec6 de = c.K * (t1.theta - c.theta0) * t1.d - 0.5 * Hm * dy - gm;
        J += dy * de.transpose() / ss + e / ss * (Mat6::Identity() - 2.0 * dy * dy.transpose() / ss);
      }
      add_spring(c, k, g, J, rx, kkt);
    }
    // Constraint rows and multiplier columns scaled by the inertia's diagonal so that the
    // KKT matrix is balanced (unscaled, its solve loses ~8 digits to the 1e8 ratio).
    add_constraint_jacobian(c, xm, N, true, kappa, kkt, &lambda, &rx);  // G(xm)^T as columns
    add_constraint_jacobian(c, x1, N, false, kappa, kkt, nullptr, nullptr);  // G(x1) as rows
    constraints(c, x1, work.g);
    dz << -rx, -kappa * work.g;
    if (!kkt.factor()) return out;
    kkt.solve(dz, work.scratch);
    if (!dz.allFinite()) return out;
    x1 += dz.head(N);
    lambda += kappa * dz.tail(c.rows());
    out.iterations = it;
    if (turns_a_link_by(c, dz.head(N)) > detail::kBasin) return out;  // left the basin
    constraints(c, x1, work.g);
    if (stop.converged(dz.head(N).cwiseAbs().maxCoeff(), work.g.cwiseAbs().maxCoeff())) {
      out.converged = true;
      return out;
    }
  }
  return out;
}

std::string describe(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t;
  return s.str();
}

}  // namespace

ring::TimeHistory respond_energy_momentum(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                          const ring::ResponseOptions& response,
                                          const IntegrationControls& controls) {
  check_response(spec, options, response);
  const auto start = std::chrono::steady_clock::now();
  const Chain chain(spec, options, response.load.angle);
  const Natural c =
      make_natural(chain, response.load.angle, Eigen::Vector2d(response.load.force[0], response.load.force[1]));

  std::vector<int> rec;
  for (double a : response.record) rec.push_back(chain.hinge_at(a));
  const int gap = detail::contact_gap(chain, spec.section.depth());
  const double depth = spec.section.depth();
  const long steps = std::lround(response.t_end / response.dt);
  std::vector<long> snap_steps;
  for (int i = 0; i < controls.snapshots; ++i)
    snap_steps.push_back(controls.snapshots == 1 ? steps : std::lround(double(steps) * i / (controls.snapshots - 1)));

  Vec x = rest(chain), v = Vec::Zero(2 * c.n), lambda = Vec::Zero(c.rows());
  double work = 0.0, t = 0.0;

  ring::TimeHistory th;
  th.solver = "multibody";
  th.unknowns = c.size();
  th.record_angles = response.record;
  th.ux.assign(rec.size(), {});
  th.uy.assign(rec.size(), {});
  auto record = [&](int iterations, long k) {
    th.t.push_back(t);
    for (std::size_t i = 0; i < rec.size(); ++i) {
      const Eigen::Vector2d u = hinge(x, rec[i]) - chain.hinge_rest(rec[i]);
      th.ux[i].push_back(u.x());
      th.uy[i].push_back(u.y());
    }
    const double T = 0.5 * v.dot(mass_times(c, v)), V = spring_energy(c, x);
    th.kinetic.push_back(T);
    th.strain.push_back(V);
    th.work.push_back(work);
    th.energy_error.push_back(T + V - work);
    th.constraint_residual.push_back(constraints(c, x).head(c.n).cwiseAbs().maxCoeff());
    th.newton_iterations.push_back(iterations);
    for (long ks : snap_steps)
      if (ks == k) {
        th.snapshot_t.push_back(t);
        std::vector<double> sx, sy;
        for (int j = 0; j < c.n; ++j) {
          sx.push_back(x(2 * j));
          sy.push_back(x(2 * j + 1));
        }
        th.snapshot_x.push_back(sx);
        th.snapshot_y.push_back(sy);
        break;
      }
  };
  auto fail = [&](IntegrationFailure::Reason why, const std::string& msg) {
    th.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    throw IntegrationFailure(why, th.t.empty() ? 0.0 : th.t.back(), th, msg);
  };
  record(0, 0);
  ring::EnergyGuard guard(spec, c.n, response.load.force);
  guard.start(th.kinetic.back(), th.strain.back(), th.work.back());

  BandedKkt kkt(c);
  Work buffers(c);
  Vec x1, l1;
  const double min_dt = controls.min_dt_factor * response.dt;
  double h = response.dt;
  int successes = 0;
  for (long k = 1; k <= steps; ++k) {
    const double t_target = response.dt * k;
    int iterations = 0;
    while (t_target - t > 1e-7 * response.dt) {
      const double remaining = t_target - t;
      const bool last = remaining <= h * (1.0 + 1e-9);
      const double hs = last ? remaining : (remaining < 2.0 * h ? 0.5 * remaining : h);
      x1 = x + hs * v;
      l1 = lambda;
      const double f = response.load.history.factor(t + 0.5 * hs);
      const Step st = step(c, x, v, hs, f, x1, l1, kkt, buffers);
      iterations += st.iterations;
      if (!st.converged) {
        h = 0.5 * hs;
        successes = 0;
        if (h < min_dt)
          fail(IntegrationFailure::Reason::step_too_small,
               "multibody::respond (energy-momentum): Newton did not converge at t = " + describe(t) +
                   " s even with the step halved to " + describe(h) + " s");
        continue;
      }
      work += f * c.F.dot(hinge(x1, c.load) - hinge(x, c.load));
      guard.step(hs, f);
      v = 2.0 / hs * (x1 - x) - v;
      x.swap(x1);
      lambda.swap(l1);
      t = last ? t_target : t + hs;
      if (!x.allFinite() || !v.allFinite())
        fail(IntegrationFailure::Reason::not_finite,
             "multibody::respond (energy-momentum): non-finite state at t = " + describe(t) + " s");
      if (controls.check_contact) {
        Eigen::Matrix2Xd hp(2, c.n);
        for (int j = 0; j < c.n; ++j) hp.col(j) = hinge(x, j);
        const auto cp = c.n >= 128 ? detail::closest_nonadjacent_grid(hp, c.l, gap, depth)
                                   : detail::closest_nonadjacent(hp, gap, depth);
        if (cp.distance < depth)
          fail(IntegrationFailure::Reason::self_contact,
               "multibody::respond (energy-momentum): the ring touches itself at t = " + describe(t) +
                   " s: " + detail::describe_contact(cp) + "; the chain model does not include contact");
      }
      if (h < response.dt && ++successes >= 2) {
        h = std::min(2.0 * h, response.dt);
        successes = 0;
      }
    }
    t = t_target;
    record(iterations, k);
    // The scheme conserves the balance to round-off; a gain is a failure as for the other
    // integrators (the one rule: ring/energy_guard.hpp).
    const ring::EnergyGuard::Verdict verdict =
        guard.check(th.kinetic.back(), th.strain.back(), work);
    if (verdict.gained)
      fail(IntegrationFailure::Reason::energy_growth,
           "multibody::respond (energy-momentum): " + ring::describe(verdict, t));
  }
  th.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return th;
}

}  // namespace multibody
