#include "multibody/plates.hpp"

#include <cmath>

#include "multibody/attachments.hpp"

namespace multibody::detail {

PlateContact::PlateContact(const Chain& chain, const ring::RingSpec& spec, const ring::StaticOptions::Plates& plates)
    : chain_(chain),
      pair_(spec, plates),
      a_(chain.hinge_at(plates.axis)),
      b_(chain.hinge_at(plates.axis + 180.0)),
      e_(-pair_.d[1], pair_.d[0]),
      scale_(spec.radius / chain.circumradius()) {}

Eigen::Matrix2Xd PlateContact::points(const Eigen::Matrix2Xd& p) const {
  Eigen::Matrix2Xd x = p;
  for (int k = 0; k < chain_.n(); ++k) x.col(k) -= (1.0 - scale_) * chain_.hinge_rest(k);
  return x;
}

double PlateContact::energy(const Eigen::Matrix2Xd& p, double s) const {
  const Eigen::Matrix2Xd x = points(p);
  double e = 0.0;
  for (int k = 0; k < chain_.n(); ++k)
    for (int plate = 0; plate < 2; ++plate) e += pair_.energy(pair_.gap(plate, x(0, k), x(1, k), s));
  return chain_.l() * e;
}

void PlateContact::by_hinge(const Eigen::Matrix2Xd& p, double s, std::vector<Eigen::Vector2d>& f,
                            std::vector<Eigen::Matrix2d>& B, std::vector<Eigen::Vector2d>& rate) const {
  const int n = chain_.n();
  const Eigen::Matrix2Xd x = points(p);
  const Eigen::Vector2d d0(pair_.d[0], pair_.d[1]);
  const Eigen::Matrix2d dd = d0 * d0.transpose();
  f.assign(n, Eigen::Vector2d::Zero());
  rate.assign(n, Eigen::Vector2d::Zero());
  B.assign(n, Eigen::Matrix2d::Zero());
  const double l = chain_.l();
  for (int k = 0; k < n; ++k)
    for (int plate = 0; plate < 2; ++plate) {
      const double g = pair_.gap(plate, x(0, k), x(1, k), s);
      if (!pair_.in_contact(g)) continue;
      const Eigen::Vector2d dp = plate == 0 ? d0 : Eigen::Vector2d(-d0);
      f[k] += l * pair_.pressure(g) * dp;
      B[k] += l * pair_.k * dd;
      rate[k] += l * pair_.k * 0.5 * pair_.travel * dp;
    }
}

void PlateContact::add(const Vector& q, double s, Vector& grad, Eigen::Ref<Matrix>* hess, Vector& rate) const {
  std::vector<Eigen::Vector2d> f, df;
  std::vector<Eigen::Matrix2d> B;
  by_hinge(chain_.hinge_positions(q), s, f, B, df);
  add_hinge_term(chain_, q, f, &B, grad, hess);
  add_hinge_term(chain_, q, df, nullptr, rate, nullptr);
}

Chain::ConstraintKinematics PlateContact::slide_rows(const Vector& q) const {
  const int dofs = chain_.dofs();
  Chain::ConstraintKinematics k{Vector(3), Matrix::Zero(3, dofs), Matrix::Zero(3, dofs)};
  const int hinges[2] = {a_, b_};
  const Eigen::Vector2d d = normal();
  // d^2 (v . p_h) / dq_j^2 = -l v . e(phi_j) for the segments j < h before hinge h
  auto curvature = [&](int r, int h, const Eigen::Vector2d& v) {
    for (int j = 0; j < h; ++j) k.hess(r, j) += -chain_.l() * (v.x() * std::cos(q[j]) + v.y() * std::sin(q[j]));
  };
  k.g(2) = 0.0;
  for (int r = 0; r < 2; ++r) {
    const int h = hinges[r];
    const Eigen::Vector2d u = chain_.hinge_position(q, h) - chain_.hinge_rest(h);
    const Matrix J = chain_.hinge_jacobian(q, h);
    k.g(r) = e_.dot(u);
    k.G.row(r) = e_.transpose() * J;
    curvature(r, h, e_);
    k.g(2) += d.dot(u);  // the centre row
    k.G.row(2) += d.transpose() * J;
    curvature(2, h, d);
  }
  return k;
}

std::array<double, 2> PlateContact::reaction(const Eigen::Matrix2Xd& p, double s) const {
  const Eigen::Matrix2Xd x = points(p);
  double pressed = 0.0;  // sum_k l k <-g_0>, N
  for (int k = 0; k < chain_.n(); ++k) pressed += chain_.l() * pair_.pressure(pair_.gap(0, x(0, k), x(1, k), s));
  return {-pressed * pair_.d[0], -pressed * pair_.d[1]};
}

std::array<double, 2> PlateContact::contact_lengths(const Eigen::Matrix2Xd& p, double s) const {
  const Eigen::Matrix2Xd x = points(p);
  const std::vector<double> xs(x.row(0).begin(), x.row(0).end()), ys(x.row(1).begin(), x.row(1).end());
  return pair_.contact_lengths(xs, ys, s);
}

}  // namespace multibody::detail
