// Internal to lumped_mass/: the implicit midpoint rule of the lumped responses, written once for
// the chain (nonlinear.cpp) and the frames (frame_nonlinear.cpp). On the unknowns q with a
// constant mass M and damping C, and multipliers mu of the model's constraints:
//   M (q_1 - q_0 - h v_0) 2 / h^2 + grad V(q_m) + f(t_m) grad P(q_m) + C v_m + (constraint forces) = 0,
//   (constraints at q_1) = 0,   v_1 = 2 (q_1 - q_0) / h - v_0,   q_m = (q_0 + q_1) / 2,
// v_m = (q_1 - q_0) / h. The kinetic energy v^T M v / 2 is quadratic, so the rule conserves it
// with the quadratic part of V exactly; the balance error is O(h^2) of the rest (not an
// energy-momentum scheme). The loads' work over a step is -f(t_m) (P(q_1) - P(q_0)): exact for
// a constant load factor, whatever the configuration dependence of the load.
//
// This class holds the state, the predictor q_1 = q_0 + h v_0, the energy bookkeeping (kinetic,
// the loads' work, C's dissipation) and the driver's interface (paths/time_stepping.hpp); a
// model supplies its Newton iterations on (q_1, mu_1), its energies, its record and its shape.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

#include "paths/time_stepping.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped::detail {

class MidpointStepper : public paths::Stepper {
 public:
  using Vec = Eigen::VectorXd;
  using Sparse = Eigen::SparseMatrix<double>;

  paths::StepOutcome try_step(double t, double h) final {
    h_ = h;
    f_ = r_.history.factor(t + 0.5 * h);
    q1_ = q_ + h * v_;
    mu1_ = mu_;
    paths::StepOutcome out;
    out.load_factor = f_;
    out.converged = newton(h, f_, out.iterations);
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

  paths::Sample sample() const final {
    paths::Sample out;
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

  /// Newton's iterations on (q1_, mu1_) from the predictor, for the step h at load factor `factor`
  /// (the midpoint's); counts them in `iterations`; true when converged.
  virtual bool newton(double h, double factor, int& iterations) = 0;
  /// The loads' potential P(q) at load factor 1 (loads.hpp), J.
  virtual double potential(const Vec& q) const = 0;
  /// The strain energy V(q) of the elements and terms, J.
  virtual double strain(const Vec& q) const = 0;
  /// The largest violation of the model's constraints at q.
  virtual double constraint_residual(const Vec& q) const = 0;
  /// The recorded points' displacements at q into out.ux, out.uy.
  virtual void record(const Vec& q, paths::Sample& out) const = 0;
  /// Dissipation of the step from q0 to q1 beyond C's (the chain's hinge dampers), J.
  virtual double own_dissipation(const Vec& /*q0*/, const Vec& /*q1*/, double /*h*/) const { return 0.0; }

  const ring::ResponseOptions& r_;
  const Sparse M_, C_;
  const bool damped_;
  Vec q_, v_, mu_, q1_, mu1_;  ///< the state, the multipliers, and the step's unknowns

 private:
  double h_ = 0.0, f_ = 0.0, work_ = 0.0, dissipated_ = 0.0;
};

/// Rayleigh damping C = a M + b K0 on the unknowns (`r`'s rayleigh_mass and
/// rayleigh_stiffness), K0 from the Hessian triplets of the springs and terms at rest that
/// `k0()` returns: called only when a coefficient is not zero (C is empty then). O(nonzeros).
template <class RestHessian>
Eigen::SparseMatrix<double> rayleigh_damping(const ring::ResponseOptions& r, const Eigen::SparseMatrix<double>& M,
                                             const RestHessian& k0) {
  Eigen::SparseMatrix<double> C(M.rows(), M.cols());
  if (r.rayleigh_mass > 0 || r.rayleigh_stiffness > 0) {
    const auto triplets = k0();
    Eigen::SparseMatrix<double> K0(M.rows(), M.cols());
    K0.setFromTriplets(triplets.begin(), triplets.end());
    C = r.rayleigh_mass * M + r.rayleigh_stiffness * K0;
  }
  return C;
}

/// Runs `stepper` on the response's time grid with the one energy guard (ring/energy_guard.hpp:
/// the midpoint rule's O(h^2) balance error, either sign; a gain beyond its bound is a failed
/// integration), as `who` in messages; the history names the solver and its unknowns (its
/// seconds are the caller's).
ring::TimeHistory integrate_midpoint(MidpointStepper& stepper, const ring::RingSpec& spec, int nodes,
                                     const ring::ResponseOptions& r, const std::string& who, int unknowns);

}  // namespace lumped::detail
