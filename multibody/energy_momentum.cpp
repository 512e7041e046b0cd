// The energy-momentum integrator in natural coordinates (energy_momentum.hpp).
#include "multibody/energy_momentum.hpp"

#include "multibody/checks.hpp"

#include <chrono>
#include <optional>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "multibody/attachments.hpp"
#include "multibody/bending.hpp"
#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "multibody/loading.hpp"
#include "multibody/natural.hpp"
#include "paths/newton.hpp"
#include "paths/time_stepping.hpp"
#include "ring/energy_guard.hpp"

namespace multibody {
namespace {

using namespace natural;
/// A spring's discrete-gradient correction is applied where it exceeds this many times
/// its round-off (see step()).
constexpr double kResolved = 1e3;
constexpr double kEps = 2.220446049250313e-16;
// Newton's stopping rule: natural::NewtonStop (bounds relative to R = n l / 2 pi: the
// round-off of positions is ~eps R, so a bound in l could not be met at large n).

struct Step {
  bool converged = false;
  int iterations = 0;
};

/// The ring's terms and loads as the scheme takes them, by hinge (attachments.hpp,
/// loading.hpp, each written there once): point masses on the constant mass, the
/// foundation's and the springs' quadratic energy u^T B u / 2, kr and the clamp on the mean
/// rotation of a hinge's links, the loads' hinge gradients at the step's midpoint.
class Terms {
 public:
  Terms(const Chain& chain, const ring::RingSpec& spec, const ring::Loads& loads)
      : chain_(chain), attached_(chain, spec), loading_(chain, spec, loads, "response") {
    for (int k = 0; k < chain.n(); ++k) {
      if (!attached_.hinge_stiffness(k).isZero()) springs_.push_back(k);
      if (attached_.rotation_stiffness(k) > 0.0) rotations_.push_back(k);
    }
    // Constant hinge forces (point loads, gravity, dead pressure) are evaluated once.
    if (!loading_.shape_dependent()) g_ = loading_.hinge_gradient(Eigen::Matrix2Xd::Zero(2, chain.n() + 1), nullptr);
  }
  const detail::Attachments& attached() const { return attached_; }

  /// The mean rotation of hinge k's links from rest (kr's and the clamp's angle).
  Turn rotation(int k, const Vec6& y, bool hessian) const {
    return mean_rotation(y, rest_link(chain_, k - 1), rest_link(chain_, k), hessian);
  }
  const std::vector<int>& rotations() const { return rotations_; }
  /// The quadratic terms' discrete gradient, B_k (u_k at the midpoint) (exact for a quadratic
  /// energy), with its Jacobian in x1, B_k / 2. O(springs).
  void add_springs(const Vec& xm, Vec& rx, BandedKkt& kkt) const {
    for (int k : springs_) add_hinge_spring(attached_, k, xm, 0.5, rx, kkt);
  }
  /// The energy of the foundation, the springs and kr at x, J. O(n).
  double energy(const Natural& c, const Vec& x) const {
    double e = 0.0;
    for (int k : springs_) e += 0.5 * (hinge(x, k) - chain_.hinge_rest(k)).dot(attached_.hinge_force(k, hinge(x, k)));
    for (int k : rotations_) {
      const double a = rotation(k, local(c, x, k), false).theta;
      e += 0.5 * attached_.rotation_stiffness(k) * a * a;
    }
    return e;
  }
  /// The loads' hinge gradients dPi/dp at the hinge positions x (p_n = p_0 folded onto hinge
  /// 0) times f, added to rx, and if `kkt` their Jacobian in x1 at the midpoint, f/2 d2Pi. O(n).
  void add_loads(const Vec& x, double f, Vec& rx, BandedKkt* kkt) const {
    const int n = chain_.n();
    std::vector<detail::Loading::Block> blocks;
    if (loading_.shape_dependent()) g_ = loading_.hinge_gradient(positions(x), kkt ? &blocks : nullptr);
    for (int k = 0; k <= n; ++k) rx.segment<2>(2 * (k % n)) += f * g_.col(k);
    for (const detail::Loading::Block& b : blocks) {
      const int dofs[4] = {2 * (b.k % n), 2 * (b.k % n) + 1, 2 * (b.m % n), 2 * (b.m % n) + 1};
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) kkt->add(dofs[i], dofs[2 + j], 0.5 * f * b.h(i, j));
    }
  }
  /// The loads' work from x0 to x1 at factor f, the scheme's own: -f dPi(x_m) . (x1 - x0). O(n).
  double work(const Vec& x0, const Vec& x1, double f) const {
    Vec g = Vec::Zero(x0.size());
    add_loads(0.5 * (x0 + x1), 1.0, g, nullptr);
    return -f * g.dot(x1 - x0);
  }

 private:
  Eigen::Matrix2Xd positions(const Vec& x) const {
    const int n = chain_.n();
    Eigen::Matrix2Xd p(2, n + 1);
    p.leftCols(n) = Eigen::Map<const Eigen::Matrix2Xd>(x.data(), 2, n);
    p.col(n) = p.col(0);
    return p;
  }
  const Chain& chain_;
  const detail::Attachments attached_;
  const detail::Loading loading_;
  std::vector<int> springs_, rotations_;  ///< hinges with such a term
  mutable Eigen::Matrix2Xd g_;  ///< the last hinge gradients (constant ones: computed once)
};

/// The vectors of a Newton iteration, sized once for the chain: allocated per iteration,
/// the allocator returned them to the system and faulted them back in (~5% of an
/// iteration at n = 10^4).
struct Work {
  explicit Work(const Natural& c)
      : V0(c.n), R0(c.n), xm(2 * c.n), w(2 * c.n), rx(2 * c.n), g(c.rows()), z(c.size()), scratch(c.size()) {}
  Vec V0, R0, xm, w, rx, g, z, scratch;
};

/// An angle spring's law at the change d = a - a0 of its angle: energy, moment, tangent
/// (HingeBending::Point's potential, force, tangent). The elastic spring k d^2 / 2.
struct Elastic {
  double k;
  HingeBending::Point operator()(double d) const {
    HingeBending::Point p;
    p.potential = 0.5 * k * d * d;
    p.force = k * d;
    p.tangent = k;
    return p;
  }
};

/// Adds the discrete gradient of an angle spring at hinge `at` between its coordinates y0
/// and y1 (file comment: the midpoint gradient plus the correction along dy where that is
/// resolved above round-off) and its exact Jacobian in y1 to rx and the KKT matrix.
/// `angle(y, hessian)` evaluates a as a Turn; `law(a - a0)` the spring's energy, moment and
/// tangent (Elastic, or a plastic hinge's incremental potential from its committed states:
/// HingeBending::at, which is C1 and piecewise quadratic); V0 is the energy at y0.
template <class Angle, class Law>
void add_discrete_spring(const Natural& c, int at, const Law& law, double a0, const Vec6& y0, const Vec6& y1,
                         double V0, const Angle& angle, Vec& rx, BandedKkt& kkt) {
  const Vec6 dy = y1 - y0;
  const Turn tm = angle(0.5 * (y0 + y1), true);
  const HingeBending::Point pm = law(tm.theta - a0);
  const Vec6 gm = pm.force * tm.d;
  const Mat6 Hm = pm.tangent * tm.d * tm.d.transpose() + pm.force * tm.dd;
  Vec6 g = gm;
  Mat6 J = 0.5 * Hm;
  const double ss = dy.squaredNorm();
  const Turn t1 = angle(y1, false);
  const HingeBending::Point p1 = law(t1.theta - a0);
  const double V1 = p1.potential;
  const double e = V1 - V0 - gm.dot(dy);
  // The correction only where e is resolved above its round-off; elsewhere it would
  // be noise (and its Jacobian noise / |dy|^2), and leaving it out costs an energy
  // error below kResolved eps V per spring and step.
  if (ss > 0 && std::abs(e) > kResolved * kEps * (std::abs(V0) + std::abs(V1) + std::abs(gm.dot(dy)))) {
    g += e / ss * dy;
    const Vec6 de = p1.force * t1.d - 0.5 * Hm * dy - gm;
    J += dy * de.transpose() / ss + e / ss * (Mat6::Identity() - 2.0 * dy * dy.transpose() / ss);
  }
  add_spring(c, at, g, J, rx, kkt);
}

/// One step of the scheme from (x0, v0) over h with load factor f at the midpoint;
/// x1 and lambda are the starting guess and the result.
Step step(const Natural& c, const Terms& terms, const HingeBending* bending, const Vec& x0, const Vec& v0, double h,
          double f, Vec& x1, Vec& lambda, BandedKkt& kkt, Work& work) {
  const int N = 2 * c.n;
  const double cm = 2.0 / (h * h);
  const double s = 0.25 * c.m, r = c.Jr / (c.l * c.l);
  const double kappa = cm * (s + r);
  Step out;
  NewtonStop stop(c.radius());
  // The angle springs' energies at x0 (constant over the iterations).
  Vec &V0 = work.V0, &R0 = work.R0;
  // ring.plastic: each hinge's incremental potential from its committed states (bending.hpp),
  // whose discrete gradient makes the hinge's work over the step the change of the stored
  // energy plus the step's plastic work (ring/plastic.hpp).
  for (int k = 0; k < c.n; ++k) {
    const double d0 = turn_angle(local(c, x0, k)) - c.theta0;
    V0[k] = bending ? bending->potential(k, d0) : 0.5 * c.K * d0 * d0;
  }
  for (int k : terms.rotations()) {
    const double a = terms.rotation(k, local(c, x0, k), false).theta;
    R0[k] = 0.5 * terms.attached().rotation_stiffness(k) * a * a;
  }
  const auto turning = [](const Vec6& y, bool hessian) { return turn(y, hessian); };
  Vec &xm = work.xm, &rx = work.rx, &dz = work.z;
  // Full Newton through the one Newton (paths/newton.hpp) with NewtonStop's rule.
  paths::NewtonFunctions system;
  system.linearize_at = [&](bool) {
    kkt.clear();
    xm = 0.5 * (x0 + x1);
    // Inertia: (2/h^2) M (x1 - x0 - h v0), the point masses' included.
    work.w = x1 - x0 - h * v0;
    mass_times(c, work.w, rx);
    rx *= cm;
    add_point_masses(c, terms.attached(), cm, work.w, &rx, &kkt);
    terms.add_loads(xm, f, rx, &kkt);
    add_mass(c, cm, kkt);
    // Constraint forces at the midpoint: d/dx1 of G(xm)^T lambda = 1/2 sum lambda_i Hess c_i.
    add_constraint_curvature(c, lambda, 0.5, kkt);
    // Springs: each one's discrete gradient and its exact Jacobian in y1.
    for (int k = 0; k < c.n; ++k) {
      if (bending)
        add_discrete_spring(c, k, [&](double d) { return bending->at(k, d); }, c.theta0, local(c, x0, k),
                            local(c, x1, k), V0[k], turning, rx, kkt);
      else
        add_discrete_spring(c, k, Elastic{c.K}, c.theta0, local(c, x0, k), local(c, x1, k), V0[k], turning, rx, kkt);
    }
    for (int k : terms.rotations())
      add_discrete_spring(
          c, k, Elastic{terms.attached().rotation_stiffness(k)}, 0.0, local(c, x0, k), local(c, x1, k), R0[k],
          [&](const Vec6& y, bool hessian) { return terms.rotation(k, y, hessian); }, rx, kkt);
    terms.add_springs(xm, rx, kkt);
    // Constraint rows and multiplier columns scaled by the inertia's diagonal so that the
    // KKT matrix is balanced (unscaled, its solve loses ~8 digits to the 1e8 ratio).
    add_constraint_jacobian(c, xm, N, true, kappa, kkt, &lambda, &rx);  // G(xm)^T as columns
    add_constraint_jacobian(c, x1, N, false, kappa, kkt, nullptr, nullptr);  // G(x1) as rows
    constraints(c, x1, work.g);
    dz << -rx, -kappa * work.g;
    return kkt.factor();
  };
  system.solve_for = [&](paths::Correction& k) {
    kkt.solve(dz, work.scratch);
    if (!dz.allFinite()) return false;
    k.size = dz.head(N).cwiseAbs().maxCoeff();
    k.move = turns_a_link_by(c, dz.head(N)) / detail::kBasin;
    return true;
  };
  system.apply_correction = [&] {
    x1 += dz.head(N);
    lambda += kappa * dz.tail(c.rows());
  };
  system.settle_at = [&](bool, const paths::Correction& k) {
    constraints(c, x1, work.g);
    return stop.converged(k.size, work.g.cwiseAbs().maxCoeff()) ? paths::Verdict::converged
                                                                : paths::Verdict::iterate;
  };
  const paths::NewtonResult result = paths::newton(system, {});
  out.converged = result.converged;
  out.iterations = result.iterations;
  return out;
}

/// The discrete-gradient step in hinge positions for the time-stepping driver
/// (paths/time_stepping.hpp); the loads' work at the step's midpoint factor.
class EnergyMomentumStepper : public paths::Stepper {
 public:
  EnergyMomentumStepper(const Chain& chain, const Natural& c, const Terms& terms,
                        const ring::ResponseOptions& response, double depth, HingeBending* bending)
      : chain_(chain), c_(c), terms_(terms), response_(response), bending_(bending), gap_(detail::contact_gap(chain, depth)),
        depth_(depth), x_(rest(chain)), v_(Vec::Zero(2 * c.n)), lambda_(Vec::Zero(c.rows())), kkt_(c),
        buffers_(c) {
    for (double a : response.record) rec_.push_back(chain.hinge_at(a));
  }

  paths::StepOutcome try_step(double t, double h) override {
    h_ = h;
    x1_ = x_ + h * v_;
    l1_ = lambda_;
    f_ = response_.history.factor(t + 0.5 * h);
    const Step st = step(c_, terms_, bending_, x_, v_, h, f_, x1_, l1_, kkt_, buffers_);
    return {st.converged, false, st.iterations, f_};
  }

  void accept(double) override {
    work_ += terms_.work(x_, x1_, f_);
    if (bending_) bending_->commit(turning_changes(c_, x1_));  // the step's states become the committed ones
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
    Vec mv = mass_times(c_, v_);
    add_point_masses(c_, terms_.attached(), 1.0, v_, &mv, nullptr);
    out.kinetic = 0.5 * v_.dot(mv);
    if (bending_) {  // the elastic energy stored in the committed states, and their plastic work
      const Vec e = turning_changes(c_, x_);
      for (int k = 0; k < c_.n; ++k) out.strain += bending_->stored(k, e[k]);
      out.plastic = bending_->dissipated();
    } else {
      out.strain = spring_energy(c_, x_);
    }
    out.strain += terms_.energy(c_, x_);
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
  const Terms& terms_;
  const ring::ResponseOptions& response_;
  HingeBending* bending_;  ///< ring.plastic's hinges, or null
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
  const Chain chain(spec, options,
                    response.loads.points.empty() ? std::nullopt : std::optional<double>(response.loads.points.front().angle));
  const Terms terms(chain, spec, response.loads);
  const Natural c = make_natural(chain, terms.attached().pinned_hinges());

  std::optional<HingeBending> bending;  // ring.plastic: the hinges' law and committed states
  if (spec.plastic) bending.emplace(spec, chain);
  EnergyMomentumStepper stepper(chain, c, terms, response, spec.section.depth(), bending ? &*bending : nullptr);
  // The scheme conserves the balance to round-off; a gain is a failure as for the other
  // integrators (the one rule: ring/energy_guard.hpp).
  ring::EnergyGuard guard(spec, c.n, ring::load_scale(spec, response.loads));
  ring::TimeHistory th = paths::integrate(
      stepper, detail::response_grid(response, controls, guard, "multibody::respond (energy-momentum)"), response.record);
  th.solver = "multibody";
  th.unknowns = c.size();
  th.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return th;
}

}  // namespace multibody
