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
#include "paths/time_stepping.hpp"
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
    add_mass(c, cm, kkt);
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

/// The discrete-gradient step in hinge positions for the time-stepping driver
/// (paths/time_stepping.hpp); the load's work at the step's midpoint factor.
class EnergyMomentumStepper : public paths::Stepper {
 public:
  EnergyMomentumStepper(const Chain& chain, const Natural& c, const ring::ResponseOptions& response, double depth)
      : chain_(chain), c_(c), response_(response), gap_(detail::contact_gap(chain, depth)), depth_(depth),
        x_(rest(chain)), v_(Vec::Zero(2 * c.n)), lambda_(Vec::Zero(c.rows())), kkt_(c), buffers_(c) {
    for (double a : response.record) rec_.push_back(chain.hinge_at(a));
  }

  paths::StepOutcome try_step(double t, double h) override {
    h_ = h;
    x1_ = x_ + h * v_;
    l1_ = lambda_;
    f_ = response_.history.factor(t + 0.5 * h);
    const Step st = step(c_, x_, v_, h, f_, x1_, l1_, kkt_, buffers_);
    return {st.converged, false, st.iterations, f_};
  }

  void accept(double) override {
    work_ += f_ * c_.F.dot(hinge(x1_, c_.load) - hinge(x_, c_.load));
    v_ = 2.0 / h_ * (x1_ - x_) - v_;
    x_.swap(x1_);
    lambda_.swap(l1_);
  }

  bool finite() const override { return x_.allFinite() && v_.allFinite(); }

  paths::Sample sample() const override {
    paths::Sample out;
    for (int h : rec_) {
      const Eigen::Vector2d u = hinge(x_, h) - chain_.hinge_rest(h);
      out.ux.push_back(u.x());
      out.uy.push_back(u.y());
    }
    out.kinetic = 0.5 * v_.dot(mass_times(c_, v_));
    out.strain = spring_energy(c_, x_);
    out.work = work_;
    out.constraint_residual = constraints(c_, x_).head(c_.n).cwiseAbs().maxCoeff();
    return out;
  }

  void shape(std::vector<double>& x, std::vector<double>& y) const override {
    paths::interleaved_shape(x_, c_.n, x, y);
  }

  std::optional<std::string> contact() const override {
    Eigen::Matrix2Xd hp(2, c_.n);
    for (int j = 0; j < c_.n; ++j) hp.col(j) = hinge(x_, j);
    const auto cp = detail::closest_contact(hp, c_.l, gap_, depth_);
    if (cp.distance >= depth_) return std::nullopt;
    return detail::describe_contact(cp);
  }

 private:
  const Chain& chain_;
  const Natural& c_;
  const ring::ResponseOptions& response_;
  const int gap_;
  const double depth_;
  std::vector<int> rec_;
  Vec x_, v_, lambda_, x1_, l1_;
  BandedKkt kkt_;
  Work buffers_;
  double h_ = 0.0, f_ = 0.0, work_ = 0.0;
};

}  // namespace

ring::TimeHistory respond_energy_momentum(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                          const ring::ResponseOptions& response,
                                          const IntegrationControls& controls) {
  check_response(spec, options, response);
  const auto start = std::chrono::steady_clock::now();
  const ring::PointLoad& load = ring::one_point_load(response.loads, "response", "multibody");
  const Chain chain(spec, options, load.angle);
  const Natural c = make_natural(chain, load.angle, Eigen::Vector2d(load.force[0], load.force[1]));

  EnergyMomentumStepper stepper(chain, c, response, spec.section.depth());
  // The scheme conserves the balance to round-off; a gain is a failure as for the other
  // integrators (the one rule: ring/energy_guard.hpp).
  ring::EnergyGuard guard(spec, c.n, ring::load_scale(spec, response.loads));
  ring::TimeHistory th = paths::integrate(
      stepper, detail::response_grid(response, controls, guard, "multibody::respond (energy-momentum)"),
      response.record);
  th.solver = "multibody";
  th.unknowns = c.size();
  th.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return th;
}

}  // namespace multibody
