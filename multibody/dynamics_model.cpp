#include "multibody/dynamics_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multibody::detail {

Matrix mass_matrix(const Chain& chain, const Attachments* terms, const Vector& q) {
  Matrix M = chain.mass_matrix(q);
  if (terms) terms->add_mass(q, M);
  return M;
}

Inertia inertia_constants(const Chain& chain, const Attachments* terms) {
  Inertia in;
  in.C0 = mass_matrix(chain, terms, Vector::Zero(chain.dofs()));
  in.diag = in.C0.diagonal();
  in.C0.diagonal().setZero();
  in.angles = chain.n();
  return in;
}

void inertia_terms(const Inertia& in, const Vector& q, const Vector& v, const Vector& qdd,
                   double cm, double cv, Vector& r, Matrix* T) {
  const Eigen::Index n = in.angles;
  const Eigen::ArrayXd c = q.array().cos(), s = q.array().sin();
  r = in.diag.cwiseProduct(qdd);
  Vector tdiag = cm * in.diag;
  // Column j: M_ij = C0_ij cos(phi_i - phi_j), S_ij = C0_ij sin(phi_i - phi_j), i != j.
  for (Eigen::Index j = 0; j < n; ++j) {
    const double cj = c[j], sj = s[j], aj = qdd[j], wj = v[j] * v[j];
    const double mcoef = cm - wj, scoef = aj + 2.0 * cv * v[j];
    const double* C0j = in.C0.col(j).data();
    double* Tj = T ? T->col(j).data() : nullptr;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double Mij = C0j[i] * (c[i] * cj + s[i] * sj);
      const double Sij = C0j[i] * (s[i] * cj - c[i] * sj);
      r[i] += Mij * aj + Sij * wj;
      if (Tj) {
        Tj[i] += Mij * mcoef + Sij * scoef;
        tdiag[i] += Mij * wj - Sij * aj;
      }
    }
  }
  if (q.size() > n) {
    // The free chain's translation (Inertia): r_j += b_j (-s_j aX + c_j aY) on the angles,
    // r_X += sum_j -b_j (s_j qdd_j + c_j v_j^2), r_Y += sum_j b_j (c_j qdd_j - s_j v_j^2)
    // (the velocity products of the angle rows cancel in Lagrange's equations).
    const Eigen::Index X = n, Y = n + 1;
    const double aX = qdd[X], aY = qdd[Y];
    for (Eigen::Index j = 0; j < n; ++j) {
      const double b = in.C0(Y, j), aj = qdd[j], wj = v[j] * v[j];
      r[j] += b * (-s[j] * aX + c[j] * aY);
      r[X] -= b * (s[j] * aj + c[j] * wj);
      r[Y] += b * (c[j] * aj - s[j] * wj);
      if (T) {
        Matrix& t = *T;
        t(j, X) += -b * s[j] * cm;
        t(j, Y) += b * c[j] * cm;
        tdiag[j] += b * (-c[j] * aX - s[j] * aY);
        t(X, j) += -b * s[j] * cm - b * c[j] * aj + b * s[j] * wj - 2.0 * b * c[j] * v[j] * cv;
        t(Y, j) += b * c[j] * cm - b * s[j] * aj - b * c[j] * wj - 2.0 * b * s[j] * v[j] * cv;
      }
    }
  }
  if (T) T->diagonal().head(tdiag.size()) += tdiag;
}

Kinematic evaluate(const Chain& chain, const Vector& q, bool values, bool hessian) {
  if (hessian) {  // one pass of sines and cosines for all three
    Chain::ConstraintKinematics ck = chain.constraint_kinematics(q);
    return {std::move(ck.G), std::move(ck.g), std::move(ck.hess)};
  }
  Kinematic k;
  k.G = chain.constraint_jacobian(q);
  if (values) k.g = chain.constraints(q);
  return k;
}

void load_forces(const Chain& chain, const DeadLoad& load, const Vector& q, Vector& phi,
                 Vector* dphi) {
  phi = chain.point_load_forces(q, load.hinge, load.force);
  if (!dphi) return;
  Vector& dphi_diag = *dphi;
  // Phi_j = l e'(phi_j) . F for j < hinge, so dPhi_j/dphi_j = -l e(phi_j) . F, and the
  // segment direction e(phi_j) is (p_{j+1} - p_j) / l.
  const Eigen::Matrix2Xd p = chain.hinge_positions(q);
  dphi_diag = Vector::Zero(chain.dofs());
  for (int j = 0; j < load.hinge; ++j) {  // an arch's far end is column n
    const Eigen::Vector2d d = p.col((j + 1) % p.cols()) - p.col(j);
    dphi_diag[j] = -d.dot(load.force);
  }
}

double segment_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                        const Eigen::Vector2d& d) {
  auto point_segment = [](const Eigen::Vector2d& x, const Eigen::Vector2d& s0, const Eigen::Vector2d& s1) {
    const Eigen::Vector2d ab = s1 - s0;
    const double t = std::clamp((x - s0).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (s0 + t * ab - x).norm();
  };
  auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) return 0.0;  // the centre lines cross
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
}

ClosestPair closest_nonadjacent(const Eigen::Matrix2Xd& p, int min_gap, double reach, bool closed) {
  const int m = static_cast<int>(p.cols()), n = closed ? m : m - 1;  // hinges, segments
  ClosestPair best{reach, -1, -1};
  // Bounding boxes of the segments i = (p_i, p_{i+1}).
  std::vector<Eigen::Vector2d> lo(n), hi(n);
  for (int i = 0; i < n; ++i) {
    const auto a = p.col(i), b = p.col((i + 1) % m);
    lo[i] = a.cwiseMin(b);
    hi[i] = a.cwiseMax(b);
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + min_gap; j < n; ++j) {
      if (closed && n - (j - i) < min_gap) break;  // cyclic gap
      if (lo[j].x() > hi[i].x() + reach || lo[i].x() > hi[j].x() + reach ||
          lo[j].y() > hi[i].y() + reach || lo[i].y() > hi[j].y() + reach)
        continue;
      const Eigen::Vector2d a = p.col(i), b = p.col((i + 1) % m);
      const double dist = segment_distance(a, b, p.col(j), p.col((j + 1) % m));
      if (dist < best.distance) best = {dist, i, j};
    }
  }
  return best;
}

std::string describe_contact(const ClosestPair& cp) {
  std::string s = "segments " + std::to_string(cp.i) + " and " + std::to_string(cp.j);
  if (cp.distance == 0.0) return s + " cross (the ring has passed through itself)";
  return s + " are " + std::to_string(cp.distance) + " m apart";
}

int contact_gap(const Chain& chain, double depth) {
  return 2 + static_cast<int>(std::floor(2.0 * depth / chain.l()));
}

}  // namespace multibody::detail
