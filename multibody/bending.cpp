// The hinge's bending law (bending.hpp).
#include "multibody/bending.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "multibody/chain.hpp"
#include "ring/errors.hpp"

namespace multibody {

double hinge_stiffness(const ring::RingSpec& spec, double l) { return spec.EI() / l; }

HingeBending::HingeBending(const ring::RingSpec& spec, const Chain& chain) : n_(chain.n()), K_(chain.K()) {
  if (!spec.plastic) return;
  if (spec.plastic->law != ring::Plastic::Law::resultant)
    throw ring::InputError("", "ring.plastic",
                           "the multibody chain's hinges take the resultant law (ring.plastic.moment) only: a "
                           "hinge has no section fibres for the fibre law");
  law_.emplace(K_, spec.plastic->moment, spec.plastic->hardening, spec.plastic->rule);
  states_.assign(static_cast<std::size_t>(n_), ring::PlasticState{});
}

HingeBending::Point HingeBending::at(int k, double e) const {
  if (law_) return law_->at(states_[k], e);
  Point p;
  p.force = K_ * e;
  p.tangent = K_;
  p.potential = 0.5 * K_ * e * e;
  return p;
}

void HingeBending::commit(const Eigen::Ref<const Eigen::VectorXd>& strains) {
  if (!law_) return;
  for (int k = 0; k < n_; ++k) {
    dissipated_ += law_->dissipated(states_[k], strains[k]);
    states_[k] = law_->commit(states_[k], strains[k]);
  }
}

double HingeBending::stored(int k, double e) const {
  if (law_) return law_->stored(states_[k], e);
  return 0.5 * K_ * e * e;
}

Eigen::VectorXd HingeBending::forces_on_angles(const Chain& chain, const Eigen::VectorXd& q) const {
  const Eigen::VectorXd r = chain.hinge_rotations(q);
  Eigen::VectorXd M(n_), f = Eigen::VectorXd::Zero(chain.dofs());
  for (int k = 0; k < n_; ++k) M[k] = moment(k, r[k]);
  for (int k = 0; k < n_; ++k) f[k] = M[k] - M[(k + 1) % n_];
  return f;
}

void HingeBending::add_tangent_on_angles(const Chain& chain, const Eigen::VectorXd& q,
                                         Eigen::Ref<Eigen::MatrixXd> T) const {
  const Eigen::VectorXd r = chain.hinge_rotations(q);
  for (int k = 0; k < n_; ++k) {  // r_k = theta_k - theta_{k-1}: t_k grad r_k grad r_k^T
    const int a = (k + n_ - 1) % n_;
    const double t = tangent(k, r[k]);
    T(k, k) += t;
    T(a, a) += t;
    T(k, a) -= t;
    T(a, k) -= t;
  }
}

double HingeBending::largest_plastic_rotation() const {
  double most = 0.0;
  for (const ring::PlasticState& s : states_) most = std::max(most, std::abs(s.plastic));
  return most;
}

}  // namespace multibody
