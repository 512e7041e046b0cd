#include "lumped_mass/bending.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lumped {

namespace {

/// The rotation law of `spec` at stiffness k: ring.plastic's Mp, hardening and rule, or an
/// infinite yield (every rotation elastic: the return map never leaves the band, M = k e). The
/// fibre law's lives in the section (ring::SectionLaw); this one then only gives k.
ring::BilinearLaw law_of(const ring::RingSpec& spec, double k) {
  if (!spec.plastic || spec.plastic->law != ring::Plastic::Law::resultant)
    return ring::BilinearLaw(k, std::numeric_limits<double>::infinity(), 0.0, ring::Plastic::Rule::kinematic);
  const ring::Plastic& p = *spec.plastic;
  return ring::BilinearLaw(k, p.moment, p.hardening, p.rule);
}

}  // namespace

Bending::Bending(const ring::RingSpec& spec, int points, double length, double stiffness)
    : law_(law_of(spec, stiffness)), length_(length), plastic_(spec.plastic.has_value()) {
  if (spec.plastic && spec.plastic->law == ring::Plastic::Law::fibre) {
    section_.emplace(spec);
    states_ = section_->states();
    committed_.assign(static_cast<std::size_t>(points), 0.0);
  }
  state_.resize(static_cast<std::size_t>(points * states_));
}

void Bending::commit(const std::vector<double>& e) {
  if (!plastic_) return;  // the elastic states never change
  const int points = static_cast<int>(state_.size()) / states_;
  for (int i = 0; i < points; ++i) {
    const double ei = e[static_cast<std::size_t>(i)];
    ring::PlasticState* s = &state_[static_cast<std::size_t>(i * states_)];
    if (section_) {
      committed_[static_cast<std::size_t>(i)] = ei;
      const ring::HingeLaw hinge(*section_, length_);
      if (!hinge.at(s, ei).yielding) continue;  // no fibre past its band: nothing changes
      dissipated_ += hinge.dissipated(s, ei);
      hinge.commit(s, ei);
      continue;
    }
    // Only a point past its band changes: ring::BilinearLaw::commit of an elastic step returns
    // e - k e / k, which differs from the committed e_p by round-off and would drift it.
    if (!law_.at(*s, ei).yielding) continue;
    dissipated_ += law_.dissipated(*s, ei);
    *s = law_.commit(*s, ei);
  }
}

double Bending::stored(const std::vector<double>& e) const {
  double u = 0.0;
  const int points = static_cast<int>(state_.size()) / states_;
  for (int i = 0; i < points; ++i) {
    const double ei = e[static_cast<std::size_t>(i)];
    u += section_ ? ring::HingeLaw(*section_, length_).stored(state(i), ei) : law_.stored(*state(i), ei);
  }
  return u;
}

double Bending::plastic_curvature() const {
  double most = 0.0;
  if (section_) {
    if (!plastic_) return 0.0;
    const ring::HingeLaw hinge(*section_, length_);
    for (std::size_t i = 0; i < committed_.size(); ++i) {
      // A point that never yielded has kappa - M / EI at round-off, not zero: report it as 0.
      const ring::PlasticState* s = state(static_cast<int>(i));
      bool virgin = true;
      for (int f = 0; f < states_ && virgin; ++f) virgin = s[f].plastic == 0.0;
      if (!virgin) most = std::max(most, std::abs(hinge.plastic_curvature(s, committed_[i])));
    }
    return most;
  }
  for (const ring::PlasticState& s : state_) most = std::max(most, std::abs(s.plastic));
  return most / length_;
}

}  // namespace lumped
