// Internal variables of a path-dependent model (plastic curvature and hardening per hinge,
// node or quadrature point): a committed value, the state of the last accepted step or load
// level, and a trial value that the Newton iterations of the current step evaluate from it.
// A model evaluates the trial at every iterate from the committed value (a return mapping),
// so a rejected step or a failed Newton solve leaves nothing behind: the next attempt starts
// from the committed value again (discard() makes that explicit for a model that updates the
// trial incrementally). The drivers call the model's accept when a step or level is accepted,
// and there the model commits; paths::Stepper::reject and paths::Equilibrium::reject tell it
// an attempt was thrown away.
//
// Usage (T: any copyable value, e.g. std::vector<double> of plastic curvatures):
//   paths::InternalVariables<std::vector<double>> plastic(std::vector<double>(n, 0.0));
//   ... in linearize(): plastic.trial() = return_map(plastic.committed(), iterate);
//   ... in accept():    plastic.commit();
//   ... in reject():    plastic.discard();
#pragma once

#include <utility>

namespace paths {

template <class T>
class InternalVariables {
 public:
  InternalVariables() = default;
  explicit InternalVariables(T initial) : committed_(initial), trial_(std::move(initial)) {}
  /// The value of the last accepted step or level.
  const T& committed() const { return committed_; }
  /// The current attempt's value.
  const T& trial() const { return trial_; }
  T& trial() { return trial_; }
  /// The attempt is accepted: its value becomes the committed one.
  void commit() { committed_ = trial_; }
  /// The attempt is thrown away: the trial returns to the committed value.
  void discard() { trial_ = committed_; }

 private:
  T committed_{}, trial_{};
};

}  // namespace paths
