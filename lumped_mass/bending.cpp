#include "lumped_mass/bending.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lumped {

namespace {

/// The law of `spec` at stiffness k: ring.plastic's Mp, hardening and rule, or an infinite
/// yield (every rotation elastic: the return map never leaves the band, M = k e).
ring::BilinearLaw law_of(const ring::RingSpec& spec, double k) {
  if (!spec.plastic) return ring::BilinearLaw(k, std::numeric_limits<double>::infinity(), 0.0, ring::Plastic::Rule::kinematic);
  const ring::Plastic& p = *spec.plastic;
  return ring::BilinearLaw(k, p.moment, p.hardening, p.rule);
}

}  // namespace

Bending::Bending(const ring::RingSpec& spec, int points, double length, double stiffness)
    : law_(law_of(spec, stiffness)),
      state_(static_cast<std::size_t>(points)),
      length_(length),
      plastic_(spec.plastic.has_value()) {}

void Bending::commit(const std::vector<double>& e) {
  if (!plastic_) return;  // the elastic states never change
  for (std::size_t i = 0; i < state_.size(); ++i) {
    // Only a point past its band changes: ring::BilinearLaw::commit of an elastic step returns
    // e - k e / k, which differs from the committed e_p by round-off and would drift it.
    if (!law_.at(state_[i], e[i]).yielding) continue;
    dissipated_ += law_.dissipated(state_[i], e[i]);
    state_[i] = law_.commit(state_[i], e[i]);
  }
}

double Bending::stored(const std::vector<double>& e) const {
  double u = 0.0;
  for (std::size_t i = 0; i < state_.size(); ++i) u += law_.stored(state_[i], e[i]);
  return u;
}

double Bending::plastic_curvature() const {
  double most = 0.0;
  for (const ring::PlasticState& s : state_) most = std::max(most, std::abs(s.plastic));
  return most / length_;
}

}  // namespace lumped
