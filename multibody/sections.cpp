// The Timoshenko chain's sections (sections.hpp).
#include "multibody/sections.hpp"

#include <stdexcept>

#include "ring/errors.hpp"

namespace multibody::detail {

Sections::Sections(const Chain& chain, const Attachments* terms, const Shear& shear)
    : chain_(chain), n_(chain.n()), shear_(shear), A_(chain.stiffness_matrix().topLeftCorner(chain.n(), chain.n())) {
  if (chain.free()) throw std::invalid_argument("multibody: the nonlinear Timoshenko chain needs a pin (supports.pin)");
  if (!(shear.stiffness > 0.0) || !(shear.inertia >= 0.0))
    throw std::invalid_argument(
        "multibody: the Timoshenko chain needs kGA > 0 and rho I >= 0 (ring.section, "
        "ring.shear_coefficient)");
  if (terms) terms->add_rotation_stiffness(A_);
}

Eigen::LLT<Matrix> Sections::shear_block() const {
  Eigen::LLT<Matrix> llt(n_);
  Matrix B = A_;
  B.diagonal().array() += shear_.stiffness;
  llt.compute(B);
  if (llt.info() != Eigen::Success)
    throw ring::NumericalError("multibody: the Timoshenko chain's shear block A + kGA l I is not positive definite");
  return llt;
}

double Sections::energy(const Vector& x) const {
  const Vector theta = x.head(n_) - chain_.phi0(), gamma = x.segment(n_, n_);
  const Vector psi = theta + gamma;
  return 0.5 * psi.dot(A_ * psi) + 0.5 * shear_.stiffness * gamma.squaredNorm();
}

void Sections::add_forces(const Vector& x, Eigen::Ref<Vector> r) const {
  const Vector psi = x.head(n_) - chain_.phi0() + x.segment(n_, n_);
  const Vector f = A_ * psi;
  r.head(n_) += f;
  r.segment(n_, n_) += f + shear_.stiffness * x.segment(n_, n_);
}

void Sections::add_stiffness(Eigen::Ref<Matrix> T) const {
  T.topLeftCorner(n_, n_) += A_;
  T.block(0, n_, n_, n_) += A_;
  T.block(n_, 0, n_, n_) += A_;
  T.block(n_, n_, n_, n_) += A_;
  T.block(n_, n_, n_, n_).diagonal().array() += shear_.stiffness;
}

double Sections::kinetic_energy(const Vector& v) const {
  return 0.5 * shear_.inertia * (v.head(n_) + v.segment(n_, n_)).squaredNorm();
}

void Sections::add_inertia_forces(const Vector& a, Eigen::Ref<Vector> r) const {
  const Vector f = shear_.inertia * (a.head(n_) + a.segment(n_, n_));
  r.head(n_) += f;
  r.segment(n_, n_) += f;
}

void Sections::add_mass(double c, Eigen::Ref<Matrix> M) const {
  const double j = c * shear_.inertia;
  M.topLeftCorner(n_, n_).diagonal().array() += j;
  M.block(0, n_, n_, n_).diagonal().array() += j;
  M.block(n_, 0, n_, n_).diagonal().array() += j;
  M.block(n_, n_, n_, n_).diagonal().array() += j;
}

void Sections::add_mass_times(const Matrix& E, Eigen::Ref<Matrix> out) const {
  const Matrix f = shear_.inertia * (E.topRows(n_) + E.middleRows(n_, n_));
  out.topRows(n_) += f;
  out.middleRows(n_, n_) += f;
}

Matrix Sections::condensed() const {
  Matrix K = A_;
  {
    const Matrix X = shear_block().solve(A_);
    K.noalias() -= A_ * X;
  }
  for (int j = 0; j < n_; ++j)  // symmetric to round-off; made exactly so in place
    for (int i = 0; i < j; ++i) K(i, j) = K(j, i) = 0.5 * (K(i, j) + K(j, i));
  return K;
}

}  // namespace multibody::detail
