// A multibody static equilibrium (multibody/static_equilibria.hpp) followed through the
// continuation driver with every accepted equilibrium kept, for the tests that check each
// state of a path (the plastic statics' energy balance).
#pragma once

#include <optional>
#include <vector>

#include "multibody/static_equilibria.hpp"
#include "paths/continuation.hpp"

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

}  // namespace ringtest
