// The implicit midpoint rule, written once (the lumped chain's and frames' responses use it).
// On the unknowns q with a constant mass M and damping C, and multipliers mu of the model's
// constraints:
//   M (q_1 - q_0 - h v_0) 2 / h^2 + grad V(q_m) + f(t_m) grad P(q_m) + C v_m + (constraint forces) = 0,
//   (constraints at q_1) = 0,   v_1 = 2 (q_1 - q_0) / h - v_0,   q_m = (q_0 + q_1) / 2,
// v_m = (q_1 - q_0) / h. The kinetic energy v^T M v / 2 is quadratic, so the rule conserves it
// with the quadratic part of V exactly; the balance error is O(h^2) of the rest (not an
// energy-momentum scheme). The loads' work over a step is -f(t_m) (P(q_1) - P(q_0)): exact for
// a constant load factor, whatever the configuration dependence of the load.
//
// This class holds the state, the predictor q_1 = q_0 + h v_0, the energy bookkeeping (kinetic,
// the loads' work, C's dissipation), the driver's interface (paths/time_stepping.hpp) and the
// step's solve by the one Newton (paths/newton.hpp); a model supplies the Newton system of
// (q_1, mu_1) (its linearization, correction and settling, at step_size() and load_factor()),
// its energies, its record and its shape.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

#include "paths/newton.hpp"
#include "paths/time_stepping.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace paths {

class MidpointStepper : public Stepper, protected NewtonSystem {
 public:
  using Vec = Eigen::VectorXd;
  using Sparse = Eigen::SparseMatrix<double>;

  StepOutcome try_step(double t, double h) final {
    h_ = h;
    f_ = r_.history.factor(t + 0.5 * h);
    q1_ = q_ + h * v_;
    mu1_ = mu_;
    const NewtonResult n = newton(*this, rule());
    StepOutcome out;
    out.load_factor = f_;
    out.converged = n.converged;
    out.iterations = n.iterations;
    return out;
  }

  void accept(double) final {
    const Vec vm = (q1_ - q_) / h_;
    work_ -= f_ * (potential(q1_) - potential(q_));
    if (damped_) dissipated_ += h_ * vm.dot(C_ * vm);
    dissipated_ += own_dissipation(q_, q1_, h_);
    v_ = 2.0 * vm - v_;
    q_ = q1_;
    mu_ = mu1_;
  }

  bool finite() const final { return q_.allFinite() && v_.allFinite(); }

  Sample sample() const final {
    Sample out;
    record(q_, out);
    out.kinetic = 0.5 * v_.dot(M_ * v_);
    out.strain = strain(q_);
    out.work = work_;
    out.dissipated = dissipated_;
    out.constraint_residual = constraint_residual(q_);
    return out;
  }

 protected:
  /// M, C: mass and damping on q (C empty: undamped); rest: q at rest; `multipliers`: the
  /// constraints' count.
  MidpointStepper(const ring::ResponseOptions& r, Sparse M, Sparse C, Vec rest, Eigen::Index multipliers)
      : r_(r), M_(std::move(M)), C_(std::move(C)), damped_(C_.nonZeros() > 0), q_(std::move(rest)),
        v_(Vec::Zero(q_.size())), mu_(Vec::Zero(multipliers)) {}

  /// The Newton rule of the step (its tolerance in the model's norm). The Newton system
  /// (NewtonSystem) iterates on (q1_, mu1_) from the predictor.
  virtual Rule rule() const = 0;
  /// The current step's size and its load factor (the midpoint's).
  double step_size() const { return h_; }
  double load_factor() const { return f_; }
  /// The loads' potential P(q) at load factor 1 (loads.hpp), J.
  virtual double potential(const Vec& q) const = 0;
  /// The strain energy V(q) of the elements and terms, J.
  virtual double strain(const Vec& q) const = 0;
  /// The largest violation of the model's constraints at q.
  virtual double constraint_residual(const Vec& q) const = 0;
  /// The recorded points' displacements at q into out.ux, out.uy.
  virtual void record(const Vec& q, Sample& out) const = 0;
  /// Dissipation of the step from q0 to q1 beyond C's (the chain's hinge dampers), J.
  virtual double own_dissipation(const Vec& /*q0*/, const Vec& /*q1*/, double /*h*/) const { return 0.0; }

  const ring::ResponseOptions& r_;
  const Sparse M_, C_;
  const bool damped_;
  Vec q_, v_, mu_, q1_, mu1_;  ///< the state, the multipliers, and the step's unknowns

 private:
  double h_ = 0.0, f_ = 0.0, work_ = 0.0, dissipated_ = 0.0;
};

}  // namespace paths
