#include "multibody/dynamics.hpp"

#include "multibody/checks.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "multibody/backend.hpp"
#include "multibody/bending.hpp"
#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "multibody/energy_momentum.hpp"
#include "multibody/integrators.hpp"
#include "multibody/newton_backend.hpp"
#include "multibody/sections.hpp"
#include "paths/time_stepping.hpp"
#include "ring/energy_guard.hpp"

namespace multibody {
namespace {

using detail::Coefficients;
using detail::Problem;
using detail::State;
using detail::StepOutcome;


/// The chain's newmark and generalized-alpha steps for the time-stepping driver
/// (paths/time_stepping.hpp): the dense or O(n) Newton backend, the dead load's work
/// (trapezoidal in time; exact for a constant force), the damping's dissipation and, with
/// ring.plastic, the hinges' plastic states as internal variables (paths/internal.hpp):
/// every Newton iterate of a step evaluates the law from the states committed at the last
/// accepted step (HingeBending changes only in commit), accept() commits them at the step's
/// hinge rotations and adds the step's plastic work, and a rejected or halved attempt leaves
/// nothing behind. The record's strain is then the elastic energy stored, its plastic the
/// plastic work (paths::Sample::plastic: the driver records it and counts it in the balance).
class ChainStepper : public paths::Stepper {
 public:
  ChainStepper(const Chain& chain, const Problem& p, const Coefficients& co, const IntegrationControls& controls,
               detail::NewtonBackend& nb, bool partitioned, bool damped, const std::vector<double>& record,
               double depth, State start, HingeBending* bending)
      : chain_(chain), p_(p), co_(co), controls_(controls), nb_(nb), partitioned_(partitioned), damped_(damped),
        gap_(detail::contact_gap(chain, depth)), depth_(depth), s_(std::move(start)), bending_(bending) {
    for (double a : record) rec_.push_back(chain.hinge_at(a));
    x_load_ = chain.hinge_position(coordinates(s_.q), p.load.hinge);
    if (p.loading) potential_ = p.loading->potential(coordinates(s_.q));
  }

  paths::StepOutcome try_step(double, double h) override {
    h_ = h;
    const StepOutcome o = partitioned_ ? detail::step_partitioned(p_, co_, s_, h, controls_, nb_, s1_)
                                       : detail::step_index3(p_, co_, s_, h, controls_, nb_, s1_);
    if (!o.converged) nb_.invalidate();  // the next try builds a Newton matrix of this state
    return {o.converged, o.reused, o.iterations, 0.5 * (p_.history.factor(s_.t) + p_.history.factor(s1_.t))};
  }

  void accept(double t) override {
    const double f = 0.5 * (p_.history.factor(s_.t) + p_.history.factor(s1_.t));
    if (p_.loading) {  // W = -sum f (Pi(q_n+1) - Pi(q_n)): exact for constant forces, as below
      const double potential1 = p_.loading->potential(coordinates(s1_.q));
      work_ -= f * (potential1 - potential_);
      potential_ = potential1;
    } else {
      const Eigen::Vector2d x1 = chain_.hinge_position(coordinates(s1_.q), p_.load.hinge);
      work_ += f * p_.load.force.dot(x1 - x_load_);
      x_load_ = x1;
    }
    if (damped_) {
      // Midpoint form h (v_n + v_{n+1})^T C (v_n + v_{n+1}) / 4: for newmark on a linear
      // system this is exactly the energy the discrete damping force removes.
      const Vector vm = s_.v + s1_.v;
      dissipated_ += 0.25 * h_ * vm.dot(nb_.damping_times(vm));
    }
    // The step is accepted: its hinges' trial states become the committed ones.
    if (bending_) bending_->commit(chain_.hinge_rotations(coordinates(s1_.q)));
    s_ = std::move(s1_);
    s_.t = t;  // no round-off drift of the sub-steps
  }

  /// Nothing to discard: the trial states are evaluated from the committed ones at every
  /// iterate and never stored (bending.hpp).
  void reject() override {}

  bool finite() const override { return s_.q.allFinite() && s_.v.allFinite(); }

  paths::Sample sample() const override {
    paths::Sample out;
    const Vector q = coordinates(s_.q), v = coordinates(s_.v);
    const Eigen::Matrix2Xd hp = chain_.hinge_positions(q);
    for (int h : rec_) {
      const Eigen::Vector2d u = hp.col(h) - chain_.hinge_rest(h);
      out.ux.push_back(u.x());
      out.uy.push_back(u.y());
    }
    out.kinetic = chain_.kinetic_energy(q, v) + (p_.terms ? p_.terms->kinetic_energy(q, v) : 0.0);
    if (p_.hinges) out.kinetic += p_.hinges->kinetic_energy(s_.v);
    if (p_.sections) {  // the springs on the sections' rotations and the shear; the terms' on translations
      out.kinetic += p_.sections->kinetic_energy(s_.v);
      out.strain = p_.sections->energy(s_.q) + (p_.terms ? p_.terms->energy(q, false) : 0.0);
    } else {
      // ring.plastic: the elastic energy stored in the committed states (bending.hpp).
      out.strain = (bending_ ? bending_->stored_on_angles(chain_, q) : chain_.spring_energy(q)) +
                   (p_.terms ? p_.terms->energy(q) : 0.0);
    }
    if (p_.hinges) out.strain += p_.hinges->energy(s_.q);
    out.work = work_;
    out.dissipated = dissipated_;
    if (bending_) out.plastic = bending_->dissipated();
    // Values only: the kinematics (G, its Hessian) are the step's business, not the sample's.
    const Vector g = detail::constraint_values(chain_, p_.terms, q);
    out.constraint_residual = g.size() ? g.cwiseAbs().maxCoeff() : 0.0;
    return out;
  }

  void shape(std::vector<double>& x, std::vector<double>& y) const override {
    const Eigen::Matrix2Xd hp = chain_.hinge_positions(coordinates(s_.q));
    x.assign(hp.row(0).begin(), hp.row(0).end());
    y.assign(hp.row(1).begin(), hp.row(1).end());
  }

  std::optional<std::string> contact() const override {
    const auto cp = detail::closest_contact(chain_.hinge_positions(coordinates(s_.q)), chain_.l(), gap_, depth_,
                                            !chain_.arch());
    if (cp.distance >= depth_) return std::nullopt;
    std::ostringstream m;
    m << detail::describe_contact(cp) << " (section depth " << depth_ << " m)";
    return m.str();
  }

 private:
  /// The chain's coordinates of a state vector (the head; the tail: the shear angles).
  Vector coordinates(const Vector& x) const { return x.head(chain_.dofs()); }

  const Chain& chain_;
  const Problem& p_;
  const Coefficients& co_;
  const IntegrationControls& controls_;
  detail::NewtonBackend& nb_;
  const bool partitioned_, damped_;
  const int gap_;
  const double depth_;
  std::vector<int> rec_;
  State s_, s1_;
  double h_ = 0.0, work_ = 0.0, dissipated_ = 0.0;
  Eigen::Vector2d x_load_;
  double potential_ = 0.0;  ///< the loads' potential at the state (Problem::loading)
  HingeBending* bending_;   ///< ring.plastic's hinges, or null (elastic: the chain's springs)
};

}  // namespace

namespace {

ring::TimeHistory respond_chain(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::ResponseOptions& response, const IntegrationControls& controls,
                                std::optional<Shear> shear) {
  check_response(spec, options, response);
  if (controls.max_newton < 1 || !(controls.min_dt_factor > 0 && controls.min_dt_factor <= 1))
    throw std::invalid_argument(
        "multibody::respond: controls need max_newton >= 1 and 0 < min_dt_factor <= 1");
  if (response.integrator == ring::ResponseOptions::Integrator::energy_momentum)
    return respond_energy_momentum(spec, options, response, controls);

  // One point load as the paper's DeadLoad; more loads through Loading (on the O(n) backend
  // the constant ones only: backend.hpp keeps "auto" dense for follower and central pressure).
  const bool one_point = response.loads.beyond_one_point("response").empty() && !response.loads.points.empty();
  const ring::PointLoad load = one_point ? response.loads.points.front() : ring::PointLoad{};
  const Chain chain(spec, options,
                    response.loads.points.empty() ? std::nullopt : std::optional<double>(response.loads.points.front().angle));
  const int n = chain.dofs();
  std::optional<detail::Loading> loading;
  if (!one_point) loading.emplace(chain, spec, response.loads, "response");
  std::optional<detail::Attachments> terms;
  if (!spec.paper_terms_only()) terms.emplace(chain, spec);
  std::optional<detail::Sections> sections;  // the Timoshenko chain (sections.hpp)
  if (spec.theory == ring::Theory::timoshenko)
    sections.emplace(chain, terms ? &*terms : nullptr, shear ? *shear : Shear::of(spec, chain.l()));
  std::optional<detail::HingeInertias> hinges;  // point inertias: their hinges' rotations (attachments.hpp)
  if (terms && detail::has_point_inertia(spec))
    hinges.emplace(chain, *terms, sections.has_value());
  Problem p{chain,
            {one_point ? chain.hinge_at(load.angle) : 0, {load.force[0], load.force[1]}},
            response.history,
            loading ? &*loading : nullptr,
            terms ? &*terms : nullptr,
            sections ? &*sections : nullptr,
            hinges ? &*hinges : nullptr};
  const int N = p.size();
  // Rayleigh damping about the undeformed chain; hinge dampers follow the springs'
  // pattern (cyclic 2, -1, -1), so they add c / K times the stiffness.
  const detail::Damping damping{response.rayleigh_mass,
                                (response.rayleigh_stiffness + response.hinge_damping / chain.K()) * chain.K()};
  const bool damped = damping.any();
  const bool banded = backend(options, spec, response.loads, Analysis::response) == Backend::banded;
  std::optional<HingeBending> bending;  // ring.plastic: the hinges' law and committed states
  if (spec.plastic) bending.emplace(spec, chain);
  const std::unique_ptr<detail::NewtonBackend> newton = detail::make_newton_backend(
      chain, p.load, damping, banded, p.loading, p.terms, p.sections, p.hinges, bending ? &*bending : nullptr);
  detail::NewtonBackend& nb = *newton;
  const Coefficients co = detail::coefficients(response);
  const bool partitioned = response.integrator == ring::ResponseOptions::Integrator::newmark;

  State s;
  s.q = Vector::Zero(N);  // at rest; the shear angles and hinge rotations zero
  s.q.head(n) = chain.q0();
  s.v = Vector::Zero(N);
  if (!nb.initial_acceleration(s.q, s.v, p.history.factor(s.t), s.qdd, s.lambda))
    throw std::runtime_error("multibody::respond: initial accelerations not computable");
  s.a = s.qdd;
  // Both integrators start from the accelerations that the first step's Newton matrix
  // filters (starting_pseudo_acceleration): generalized-alpha's pseudo-acceleration a_0,
  // Newmark's qdd_0 (its partitioned step reads only the independent angles' qdd_0).
  detail::starting_pseudo_acceleration(p, co, response.dt, nb, s);
  if (partitioned) s.qdd = s.a;

  ChainStepper stepper(chain, p, co, controls, nb, partitioned, damped, response.record, spec.section.depth(),
                       std::move(s), bending ? &*bending : nullptr);
  // A run that gains energy has failed, whatever the integrator: its history is not a
  // result (generalized-alpha did on fine chains under a point step load when it started
  // from a_0 = qdd_0; see starting_pseudo_acceleration). The rule: energy_guard.hpp.
  ring::EnergyGuard guard(spec, chain.n(), ring::load_scale(spec, response.loads));
  paths::Grid grid = detail::response_grid(response, controls, guard, "multibody::respond");
  grid.energy_hint = " (try response.integrator = \"energy-momentum\" or \"newmark\")";
  ring::TimeHistory th = paths::integrate(stepper, grid, response.record);
  th.unknowns = N + p.constraint_count();  // angles (shear angles, hinge rotations) and multipliers of the Newton system
  return th;
}

}  // namespace

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          const ring::ResponseOptions& response, const IntegrationControls& controls) {
  return respond_chain(spec, options, response, controls, std::nullopt);
}

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          const ring::ResponseOptions& response, const IntegrationControls& controls,
                          const Shear& shear) {
  if (spec.theory != ring::Theory::timoshenko)
    throw std::invalid_argument("multibody::respond: section constants are given for a Timoshenko ring only "
                                "(ring.theory = \"timoshenko\")");
  return respond_chain(spec, options, response, controls, shear);
}

paths::Grid detail::response_grid(const ring::ResponseOptions& response, const IntegrationControls& controls,
                                  ring::EnergyGuard& guard, const std::string& who) {
  paths::Grid grid;
  grid.dt = response.dt;
  grid.t_end = response.t_end;
  grid.snapshots = controls.snapshots;
  grid.min_dt_factor = controls.min_dt_factor;
  grid.check_contact = controls.check_contact;
  grid.guard = &guard;
  grid.who = who;
  grid.progress = response.progress;
  return grid;
}

}  // namespace multibody
