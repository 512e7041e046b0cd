// The hinge's bending law (bending.hpp).
#include "multibody/bending.hpp"

#include <algorithm>
#include <cmath>

#include "multibody/chain.hpp"
#include "ring/errors.hpp"

namespace multibody {

double hinge_stiffness(const ring::RingSpec& spec, double l) { return spec.EI() / l; }

void check_section_law(const ring::RingSpec& spec) {
  if (spec.plastic && spec.plastic->law == ring::Plastic::Law::fibre &&
      spec.section.shape == ring::Section::Shape::general)
    throw ring::InputError("", "ring.plastic.stress",
                           "the fibre law integrates over the section's shape, and a section given by {area, inertia} "
                           "has none (give ring.section a circle or a rectangle, or use the resultant law "
                           "ring.plastic.moment)");
}

HingeBending::HingeBending(const ring::RingSpec& spec, const Chain& chain)
    : n_(chain.n()), K_(chain.K()), EI_(spec.EI()), l_(chain.l()) {
  if (!spec.plastic) return;
  check_section_law(spec);
  section_.emplace(spec);
  m_ = static_cast<std::size_t>(section_->states());
  states_.assign(static_cast<std::size_t>(n_) * m_, ring::PlasticState{});
  strains_.assign(static_cast<std::size_t>(n_), 0.0);
}

HingeBending::Point HingeBending::at(int k, double e) const {
  if (section_) {
    Point p = law().at(states(k), e);
    // The resultant law inside its band is the elastic spring about the plastic rotation:
    // HingeLaw's EI (e / l - kappa_p) and its potential spelt as the elastic chain's
    // K (e - l kappa_p) and K (e - l kappa_p)^2 / 2 (the same values to one rounding), so that a
    // plastic moment never reached gives the elastic chain's arithmetic bit for bit (its O(n)
    // statics at n = 10^4 sit at their round-off floor), and the potential is exactly zero at
    // the committed plastic rotation.
    if (m_ == 1 && !p.yielding) {
      const double y = e - l_ * states(k)->plastic;
      p.force = K_ * y;
      p.potential = 0.5 * K_ * y * y;
    }
    return p;
  }
  Point p;
  p.force = K_ * e;
  p.tangent = K_;
  p.potential = 0.5 * K_ * e * e;
  return p;
}

void HingeBending::commit(const Eigen::Ref<const Eigen::VectorXd>& strains) {
  if (!section_) return;
  const ring::HingeLaw h = law();
  for (int k = 0; k < n_; ++k) {
    ring::PlasticState* s = &states_[static_cast<std::size_t>(k) * m_];
    dissipated_ += h.dissipated(s, strains[k]);
    h.commit(s, strains[k]);
    strains_[k] = strains[k];
  }
}

double HingeBending::dissipated_by(const Eigen::Ref<const Eigen::VectorXd>& strains) const {
  if (!section_) return 0.0;
  const ring::HingeLaw h = law();
  double d = 0.0;
  for (int k = 0; k < n_; ++k) d += h.dissipated(states(k), strains[k]);
  return d;
}

double HingeBending::stored(int k, double e) const {
  if (section_) return law().stored(states(k), e);
  return at(k, e).potential;
}

double HingeBending::stored_on_angles(const Chain& chain, const Eigen::VectorXd& q) const {
  const Eigen::VectorXd r = chain.hinge_rotations(q);
  double V = 0.0;
  for (int k = chain.first_spring(); k < n_; ++k) V += stored(k, r[k]);
  return V;
}

Eigen::VectorXd HingeBending::forces_on_angles(const Chain& chain, const Eigen::VectorXd& q) const {
  const Eigen::VectorXd r = chain.hinge_rotations(q);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(chain.dofs());
  for (int k = chain.first_spring(); k < n_; ++k) {  // spring k joins segments k - 1 and k
    const double M = moment(k, r[k]);
    f[k] += M;
    f[(k + n_ - 1) % n_] -= M;
  }
  return f;
}

void HingeBending::add_tangent_on_angles(const Chain& chain, const Eigen::VectorXd& q,
                                         Eigen::Ref<Eigen::MatrixXd> T) const {
  const Eigen::VectorXd r = chain.hinge_rotations(q);
  for (int k = chain.first_spring(); k < n_; ++k) {  // r_k = theta_k - theta_{k-1}: t_k grad r_k grad r_k^T
    const int a = (k + n_ - 1) % n_;
    const double t = tangent(k, r[k]);
    T(k, k) += t;
    T(a, a) += t;
    T(k, a) -= t;
    T(a, k) -= t;
  }
}

double HingeBending::largest_plastic_curvature() const {
  if (!section_) return 0.0;
  double most = 0.0;
  for (int k = 0; k < n_; ++k) {
    const ring::PlasticState* s = states(k);
    if (m_ == 1) {  // the resultant law's state is the plastic curvature
      most = std::max(most, std::abs(s->plastic));
      continue;
    }
    const bool yielded = std::any_of(s, s + m_, [](const ring::PlasticState& f) { return f.plastic != 0.0; });
    if (yielded) most = std::max(most, std::abs(law().plastic_curvature(s, strains_[k])));
  }
  return most;
}

}  // namespace multibody
