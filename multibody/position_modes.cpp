// The linear modes' pencil in hinge positions (position_modes.hpp).
#include "multibody/position_modes.hpp"

#include <cmath>
#include <string>

#include "ring/errors.hpp"

namespace multibody::natural {

ShiftedKkt::ShiftedKkt(const Chain& chain, const detail::Attachments& terms)
    : chain_(chain),
      terms_(terms),
      c_(make_natural(chain, terms.pinned_hinges())),
      N_(2 * c_.n),
      kappa_(c_.K / (c_.l * c_.l)),
      kkt_(c_),
      normal_(2, c_.n),
      kr_(c_.n),
      B_(c_.n) {
  for (int k = 0; k < c_.n; ++k) {
    const Eigen::Vector2d e = chain.hinge_rest((k + 1) % c_.n) - chain.hinge_rest(k);
    normal_.col(k) = Eigen::Vector2d(-e.y(), e.x()) / e.norm();
    kr_[k] = terms.rotation_stiffness(k);
  }
}

void ShiftedKkt::set_shift(double sigma) {
  const Vec x = rest(chain_);
  Vec force = Vec::Zero(N_);  // zero at rest: the springs' rest angles, u = 0
  kkt_.clear();
  add_stiffness(chain_, c_, terms_, x, force, kkt_);
  add_mass(c_, -sigma, kkt_);
  add_point_masses(c_, terms_, -sigma, x, nullptr, &kkt_);
  add_constraint_jacobian(c_, x, N_, true, kappa_, kkt_, nullptr, nullptr);
  add_constraint_jacobian(c_, x, N_, false, kappa_, kkt_, nullptr, nullptr);
  sigma_ = sigma;
  for (int k = 0; k < c_.n; ++k)
    B_[k] = terms_.hinge_stiffness(k) - sigma * terms_.hinge_mass(k) * Eigen::Matrix2d::Identity();
  if (!kkt_.factor())
    throw ring::NumericalError("multibody: K - sigma M in hinge positions is singular (sigma = " +
                               std::to_string(sigma) + ", n = " + std::to_string(c_.n) + ")");
}

void ShiftedKkt::perform_op(const double* x_in, double* y_out) const {
  const Eigen::Map<const Vec> x(x_in, N_);
  Vec z = Vec::Zero(c_.size()), scratch, r(c_.size());
  z.head(N_) = x;
  kkt_.solve(z, scratch);
  // z = (y, mu / kappa): the multipliers of the scaled rows (natural.hpp).
  double previous = HUGE_VAL;
  for (int step = 0; step < kMaxRefinementSteps; ++step) {
    Vec rx = x, rc = Vec::Zero(c_.rows());
    subtract_product(z.head(N_), kappa_ * z.tail(c_.rows()), rx, rc);
    r << rx, kappa_ * rc;
    kkt_.solve(r, scratch);
    const double correction = r.head(N_).norm();
    if (!(correction < previous)) break;  // at the rounding floor, or diverging: keep z
    z += r;
    if (correction <= 1e-14 * z.head(N_).norm() || correction > 0.5 * previous) break;
    previous = correction;
  }
  Eigen::Map<Vec>(y_out, N_) = z.head(N_);
}

void ShiftedKkt::subtract_product(const Vec& y, const Vec& mu, Vec& r_x, Vec& r_c) const {
  const int n = c_.n;
  const double l = c_.l;
  // Link rotations and stretches from differences; the link constraints' rows are the stretches.
  Vec dphi(n);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d d = hinge(y, (k + 1) % n) - hinge(y, k);
    dphi[k] = normal_.col(k).dot(d) / l;
    const Eigen::Vector2d e(normal_(1, k), -normal_(0, k));
    r_c[k] -= e.dot(d);
    // G^T mu: the link's multiplier pulls its two hinges along it.
    r_x.segment<2>(2 * k) += mu[k] * e;
    r_x.segment<2>(2 * ((k + 1) % n)) -= mu[k] * e;
  }
  // Link torques tau_k = dE/d dphi_k: the hinge springs K (dphi_k - dphi_{k-1}) at hinges k
  // and k + 1, kr (dphi_{k-1} + dphi_k) / 2 at the hinges that have one.
  Vec tau(n);
  for (int k = 0; k < n; ++k) {
    const int a = (k + n - 1) % n, b = (k + 1) % n;
    tau[k] = c_.K * ((dphi[k] - dphi[a]) - (dphi[b] - dphi[k])) + 0.25 * kr_[k] * (dphi[a] + dphi[k]) +
             0.25 * kr_[b] * (dphi[k] + dphi[b]);
  }
  for (int k = 0; k < n; ++k) {
    const int a = (k + n - 1) % n;
    r_x.segment<2>(2 * k) -= (tau[a] * normal_.col(a) - tau[k] * normal_.col(k)) / l + B_[k] * hinge(y, k);
  }
  Vec my;
  mass_times(c_, y, my);
  r_x += sigma_ * my;
  // The pin, the roller and the further pins: rows on single hinges.
  auto row = [&](int at, int k, const Eigen::Vector2d& g) {
    r_c[at] -= g.dot(hinge(y, k));
    r_x.segment<2>(2 * k) -= mu[at] * g;
  };
  if (c_.pinned) {
    row(n, 0, Eigen::Vector2d::UnitX());
    row(n + 1, 0, Eigen::Vector2d::UnitY());
  }
  if (c_.roller >= 0) row(c_.roller_row(), c_.roller, c_.nu);
  for (std::size_t i = 0; i < c_.pins.size(); ++i) {
    row(c_.pins_row() + 2 * static_cast<int>(i), c_.pins[i], Eigen::Vector2d::UnitX());
    row(c_.pins_row() + 2 * static_cast<int>(i) + 1, c_.pins[i], Eigen::Vector2d::UnitY());
  }
}

PositionMass::PositionMass(const Natural& c, const detail::Attachments& terms) : c_(c), terms_(terms) {}

void PositionMass::perform_op(const double* x_in, double* y_out) const {
  const Eigen::Map<const Vec> x(x_in, rows());
  Vec y;
  mass_times(c_, x, y);
  add_point_masses(c_, terms_, 1.0, x, &y, nullptr);
  Eigen::Map<Vec>(y_out, rows()) = y;
}

Matrix chain_coordinates(const Chain& chain, const Matrix& u) {
  const int n = chain.n();
  const double l = chain.l();
  const Vector &cos0 = chain.cos0(), &sin0 = chain.sin0();
  Matrix dq(chain.dofs(), u.cols());
  for (Eigen::Index col = 0; col < u.cols(); ++col) {
    for (int k = 0; k < n; ++k) {
      const int j = (k + 1) % n;
      const double dx = u(2 * j, col) - u(2 * k, col), dy = u(2 * j + 1, col) - u(2 * k + 1, col);
      dq(k, col) = (cos0[k] * dy - sin0[k] * dx) / l;
    }
    if (chain.free()) dq.block<2, 1>(n, col) = u.block<2, 1>(0, col);
  }
  return dq;
}

}  // namespace multibody::natural
