// A multibody static equilibrium (multibody/static_equilibria.hpp) followed through the
// continuation driver with every accepted equilibrium kept, for the tests that check each
// state of a path, and the energy balance of a pinch along it (the plastic statics' tests).
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "multibody/chain.hpp"
#include "multibody/natural.hpp"
#include "multibody/static_equilibria.hpp"
#include "paths/continuation.hpp"
#include "ring/analysis.hpp"

namespace ringtest {

/// Follows eq through the driver and keeps every accepted equilibrium.
class Recorder : public paths::Equilibrium {
 public:
  explicit Recorder(multibody::detail::StaticEquilibrium& eq) : eq_(eq) {}
  Eigen::Index size() const override { return eq_.size(); }
  Eigen::Index arc_size() const override { return eq_.arc_size(); }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    return eq_.linearize(x, w, ws, r);
  }
  bool solve(paths::Vector& y) override { return eq_.solve(y); }
  double move(const paths::Vector& dz) const override { return eq_.move(dz); }
  bool converged(const paths::State& x, const paths::Vector& dz, int i) override { return eq_.converged(x, dz, i); }
  std::optional<paths::Touch> accept(const paths::State& from, const paths::State& to) override {
    if (states.empty()) states.push_back(from);
    states.push_back(to);
    return eq_.accept(from, to);
  }
  void reject() override { eq_.reject(); }
  std::vector<paths::State> states;

 private:
  multibody::detail::StaticEquilibrium& eq_;
};

/// The energies of a pinch followed to the end of its history.
struct PinchBalance {
  bool reached = false;  ///< the path reached the history's end
  double work = 0.0;     ///< the loads' work along the path, J
  double peak_work = 0.0;///< its largest value on the way, J
  double stored = 0.0;   ///< the elastic energy stored at the end (bending.hpp, stored), J
  double dissipated = 0.0;  ///< the plastic work, J
};

/// The pinch `st` (its two loads at the hinges at 90 and 270 deg) on `chain`, in the angle
/// formulation (`dense`) or in hinge positions, through paths::follow: the work trapezoidal in
/// the load factor between accepted equilibria (the displacement between two taken as
/// straight).
inline PinchBalance pinch_balance(const ring::RingSpec& spec, const multibody::Chain& chain, bool dense,
                                  const ring::StaticOptions& st) {
  std::unique_ptr<multibody::detail::StaticEquilibrium> eq =
      dense ? multibody::detail::angle_equilibrium(chain, spec, st.loads, spec.section.depth())
            : multibody::natural::static_equilibrium(chain, spec, st.loads, spec.section.depth());
  Recorder rec(*eq);
  paths::Continuation policy;
  policy.steps = st.steps;
  policy.history = st.history;
  PinchBalance out;
  out.reached = paths::follow(rec, {eq->rest(), 0.0}, policy).end == paths::Trace::End::reached;
  const int a = chain.hinge_at(90.0), b = chain.hinge_at(270.0);
  const Eigen::Vector2d Fa(st.loads.points[0].force[0], st.loads.points[0].force[1]);
  const Eigen::Vector2d Fb(st.loads.points[1].force[0], st.loads.points[1].force[1]);
  for (std::size_t i = 1; i < rec.states.size(); ++i) {
    const Eigen::Matrix2Xd p0 = eq->hinges(rec.states[i - 1].z), p1 = eq->hinges(rec.states[i].z);
    const double s = 0.5 * (rec.states[i - 1].s + rec.states[i].s);
    out.work += s * (Fa.dot(p1.col(a) - p0.col(a)) + Fb.dot(p1.col(b) - p0.col(b)));
    out.peak_work = std::max(out.peak_work, out.work);
  }
  const Eigen::VectorXd e = eq->hinge_strains(rec.states.back().z);
  for (int k = 0; k < chain.n(); ++k) out.stored += eq->bending().stored(k, e[k]);
  out.dissipated = eq->dissipated();
  return out;
}

}  // namespace ringtest
