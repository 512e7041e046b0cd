#include "multibody/chain.hpp"

#include "multibody/bending.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "ring/sampling.hpp"

namespace multibody {

namespace {
constexpr double kPi = 3.14159265358979323846;
inline Eigen::Vector2d e(double a) { return {std::cos(a), std::sin(a)}; }
inline Eigen::Vector2d eprime(double a) { return {-std::sin(a), std::cos(a)}; }
std::string num(double x) {
  std::string s = std::to_string(x);
  return s;
}
}  // namespace

Chain::Chain(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
             std::optional<double> loaded_angle)
    : n_(options.n), where_(spec), free_(spec.supports.free()) {
  if (n_ < 4)
    throw std::invalid_argument("multibody: n = " + std::to_string(n_) + " must be >= 4");
  if (!(spec.radius > 0.0) || !(spec.A() > 0.0) || !(spec.I() > 0.0) || !(spec.E > 0.0) ||
      !(spec.rho > 0.0))
    throw std::invalid_argument("multibody: radius, A, I, E and rho must all be > 0");
  arch_ = spec.is_arch();
  span_ = spec.opening();
  // The chain's length is the centroid line's (file comment): l = R span / n.
  l_ = span_ * spec.radius / n_;
  m_ = spec.rhoA() * l_;
  jr_ = options.rotary_inertia ? m_ * l_ * l_ / 12.0 : 0.0;
  k_ = hinge_stiffness(spec, l_);
  rp_ = l_ / (2.0 * std::sin(span_ / (2.0 * n_)));

  anchor_deg_ = ring::wrap_degrees(spec.anchor());
  angles_ = ring::node_angles(spec, n_);
  if (arch_) {
    if (spec.supports.roller)
      throw std::invalid_argument("multibody: an arch (ring.arc) takes no supports.roller");
    // Its ends: hinge 0 held by the coordinates, hinge n by the closure rows (file comment).
    free_ = true;
    for (double p : spec.supports.pinned()) {
      const int h = hinge_index(p);
      if (h == 0) free_ = false;
      if (h == n_) end_pinned_ = true;
    }
  }
  if (loaded_angle && hinge_index(*loaded_angle) < 0)
    throw std::invalid_argument("multibody: loaded point at " + num(*loaded_angle) +
                                " deg is not a hinge of the n = " + std::to_string(n_) +
                                " chain anchored at " + num(anchor_deg_) +
                                (arch_ ? " deg (valid: from + span k / n)" : " deg (valid: anchor + 360 k / n)"));
  phi0_.resize(n_);
  const double a0 = anchor_deg_ * kPi / 180.0;
  for (int i = 0; i < n_; ++i) phi0_[i] = a0 + span_ * i / n_ + 0.5 * kPi + span_ / (2.0 * n_);
  cos0_ = phi0_.array().cos();
  sin0_ = phi0_.array().sin();

  if (spec.supports.roller) {
    if (free_) throw std::invalid_argument("multibody: a roller needs a pin");
    const double r = *spec.supports.roller;
    if (!ring::on_node(r, anchor_deg_, n_))
      throw std::invalid_argument("multibody: roller at " + num(r) + " deg is not a hinge of the n = " +
                                  std::to_string(n_) + " chain anchored at the pin " +
                                  num(anchor_deg_) + " deg (valid: pin + 360 k / n)");
    const int h = hinge_at(r);
    if (h == 0) throw std::invalid_argument("multibody: roller coincides with the pin");
    roller_ = h;
    const Eigen::Vector2d d = (hinge_rest(h) - hinge_rest(0)).normalized();
    roller_normal_ = {-d.y(), d.x()};
  }
}

int Chain::hinge_index(double deg) const { return ring::node_index(where_, deg, n_); }

int Chain::hinge_at(double deg) const {
  const int k = hinge_index(deg);
  if (k < 0)
    throw std::invalid_argument("multibody: " + num(deg) + " deg is not a hinge (anchor " +
                                num(anchor_deg_) + " deg, n = " + std::to_string(n_) +
                                (arch_ ? ", arch)" : ")"));
  return k;
}

Vector Chain::q0() const {
  Vector q = Vector::Zero(dofs());
  q.head(n_) = phi0_;
  return q;
}

Eigen::Vector2d Chain::hinge_rest(int k) const {
  const double a = anchor_deg_ * kPi / 180.0 + span_ * k / n_;
  return rp_ * e(a);
}

void Chain::check(const Vector& q) const {
  if (q.size() != dofs())
    throw std::invalid_argument("multibody: coordinate vector has " + std::to_string(q.size()) +
                                " entries, expected dofs() = " + std::to_string(dofs()));
}

Eigen::Vector2d Chain::base(const Vector& q) const {
  Eigen::Vector2d p = hinge_rest(0);
  if (free_) p += q.tail<2>();
  return p;
}

Eigen::Vector2d Chain::hinge_position(const Vector& q, int k) const {
  check(q);
  if (k < 0 || k > n_)
    throw std::invalid_argument("multibody: hinge " + std::to_string(k) + " out of range (0 .. " +
                                std::to_string(n_) + ")");
  Eigen::Vector2d p = base(q);
  for (int j = 0; j < k; ++j) p += l_ * e(q[j]);
  return p;
}

Eigen::Matrix2Xd Chain::hinge_positions(const Vector& q) const {
  check(q);
  Eigen::Matrix2Xd p(2, hinges());
  Eigen::Vector2d x = base(q);
  for (int k = 0; k < n_; ++k) {
    p.col(k) = x;
    x += l_ * e(q[k]);
  }
  if (arch_) p.col(n_) = x;
  return p;
}

Eigen::Matrix2Xd Chain::midpoints(const Vector& q) const {
  check(q);
  Eigen::Matrix2Xd p(2, n_);
  Eigen::Vector2d x = base(q);
  for (int i = 0; i < n_; ++i) {
    const Eigen::Vector2d t = e(q[i]);
    p.col(i) = x + 0.5 * l_ * t;
    x += l_ * t;
  }
  return p;
}

Matrix Chain::hinge_jacobian(const Vector& q, int k) const {
  check(q);
  if (k < 0 || k > n_)
    throw std::invalid_argument("multibody: hinge " + std::to_string(k) + " out of range (0 .. " +
                                std::to_string(n_) + ")");
  Matrix J = Matrix::Zero(2, dofs());
  for (int j = 0; j < k; ++j) J.col(j) = l_ * eprime(q[j]);
  if (free_) J.rightCols<2>().setIdentity();
  return J;
}

Matrix Chain::mass_matrix(const Vector& q) const {
  check(q);
  const int n = n_;
  Matrix M(dofs(), dofs());
  const double ml2 = m_ * l_ * l_;
  Vector c = q.head(n).array().cos(), s = q.head(n).array().sin();
  for (int k = 0; k < n; ++k) {
    for (int j = k + 1; j < n; ++j) {
      // (L^T L)_jk = n - 1 - max(j,k) + 1/2 for j != k (0-based)
      const double v = ml2 * (n - 1 - j + 0.5) * (c[j] * c[k] + s[j] * s[k]);
      M(j, k) = v;
      M(k, j) = v;
    }
    M(k, k) = ml2 * (n - 1 - k + 0.25) + jr_;
  }
  if (free_) {
    for (int j = 0; j < n; ++j) {
      const double cj = m_ * l_ * (n - 1 - j + 0.5);  // m l sum_i L_ij
      M(j, n) = M(n, j) = -cj * s[j];
      M(j, n + 1) = M(n + 1, j) = cj * c[j];
    }
    M.bottomRightCorner<2, 2>() = n * m_ * Eigen::Matrix2d::Identity();
  }
  return M;
}

namespace {

/// Generalized force of point masses m at the segment midpoints with accelerations (or
/// velocities) A_i = a0 + sum_{j<i} t_j + t_i / 2: y_j = l e'(phi_j) . (sum_{i>j} m A_i +
/// m A_j / 2) for the angles and, for a free chain, sum_i m A_i for (x_0, y_0).
/// `ep` holds e'(phi_j) column by column. O(n).
Vector project_midpoints(const Eigen::Matrix2Xd& ep, const Eigen::Matrix2Xd& t, Eigen::Vector2d a0, double m,
                         double l, bool free) {
  const Eigen::Index n = t.cols();
  Eigen::Matrix2Xd A(2, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    A.col(i) = a0 + 0.5 * t.col(i);
    a0 += t.col(i);
  }
  Vector y(n + (free ? 2 : 0));
  Eigen::Vector2d back = Eigen::Vector2d::Zero();  // sum_{i>j} m A_i
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    y[j] = l * ep.col(j).dot(back + 0.5 * m * A.col(j));
    back += m * A.col(j);
  }
  if (free) y.tail<2>() = back;
  return y;
}

/// e'(phi_j) = (-sin phi_j, cos phi_j) for the n angles of q.
Eigen::Matrix2Xd eprimes(const Vector& q, int n) {
  Eigen::Matrix2Xd ep(2, n);
  for (int j = 0; j < n; ++j) ep.col(j) = eprime(q[j]);
  return ep;
}

}  // namespace

Vector Chain::mass_times(const Vector& q, const Vector& v) const {
  check(v);
  return mass_times_columns(q, v);
}

Vector Chain::quadratic_velocity(const Vector& q, const Vector& qd) const {
  check(q);
  check(qd);
  // Centripetal midpoint accelerations a_i = -l sum_j L_ij e(phi_j) qd_j^2, projected
  // back as in mass_times.
  const Eigen::Matrix2Xd ep = eprimes(q, n_);
  Eigen::Matrix2Xd t(2, n_);
  for (int i = 0; i < n_; ++i) t.col(i) = -l_ * qd[i] * qd[i] * e(q[i]);
  return project_midpoints(ep, t, Eigen::Vector2d::Zero(), m_, l_, free_);
}

Matrix Chain::mass_times_columns(const Vector& q, const Matrix& V) const {
  check(q);
  if (V.rows() != dofs()) throw std::invalid_argument("multibody: mass_times_columns needs dofs() rows");
  // Midpoint velocities V_i = v_t + l sum_j L_ij e'(phi_j) v_j, then M v collects
  // m V_i back through the same kinematics (L^T) plus the rotary inertia.
  const Eigen::Matrix2Xd ep = eprimes(q, n_);
  Matrix out(dofs(), V.cols());
  Eigen::Matrix2Xd t(2, n_);
  for (Eigen::Index k = 0; k < V.cols(); ++k) {
    for (int i = 0; i < n_; ++i) t.col(i) = l_ * V(i, k) * ep.col(i);
    out.col(k) = project_midpoints(ep, t, free_ ? Eigen::Vector2d(V.col(k).tail<2>()) : Eigen::Vector2d::Zero(),
                                   m_, l_, free_);
    out.col(k).head(n_) += jr_ * V.col(k).head(n_);
  }
  return out;
}

double Chain::kinetic_energy(const Vector& q, const Vector& qd) const {
  check(q);
  check(qd);
  double T = 0.0;
  Eigen::Vector2d acc = free_ ? Eigen::Vector2d(qd.tail<2>()) : Eigen::Vector2d::Zero();
  for (int i = 0; i < n_; ++i) {
    const Eigen::Vector2d t = l_ * qd[i] * eprime(q[i]);
    T += m_ * (acc + 0.5 * t).squaredNorm() + jr_ * qd[i] * qd[i];
    acc += t;
  }
  return 0.5 * T;
}

Vector Chain::hinge_rotations(const Vector& q) const {
  check(q);
  Vector r = Vector::Zero(n_);
  for (int k = first_spring(); k < n_; ++k) {
    const int km = (k + n_ - 1) % n_;
    r[k] = (q[k] - phi0_[k]) - (q[km] - phi0_[km]);
  }
  return r;
}

double Chain::spring_energy(const Vector& q) const {
  return 0.5 * k_ * hinge_rotations(q).squaredNorm();
}

void Chain::accumulate(const Vector& cos, const Vector& sin, const Eigen::Ref<const Vector>& dq, double* ux,
                       double* uy) const {
  double px = free_ ? dq(n_) : 0.0, py = free_ ? dq(n_ + 1) : 0.0;
  for (int j = 0; j < n_; ++j) {
    ux[j] = px;
    uy[j] = py;
    px -= l_ * dq(j) * sin[j];
    py += l_ * dq(j) * cos[j];
  }
  if (arch_) {
    ux[n_] = px;
    uy[n_] = py;
  }
}

ring::ModeShape Chain::sample(const std::vector<double>& ux, const std::vector<double>& uy) const {
  return arch_ ? ring::sample_arc(*where_.arc, ux, uy) : ring::sample_polygon(anchor_deg_, ux, uy);
}

Eigen::Matrix2Xd Chain::displacements_at(const Vector& q, const Vector& dq) const {
  Eigen::Matrix<double, Eigen::Dynamic, 2> u(hinges(), 2);
  accumulate(q.head(n_).array().cos(), q.head(n_).array().sin(), dq, u.col(0).data(), u.col(1).data());
  return u.transpose();
}

Eigen::Matrix2Xd Chain::rest_displacements(const Vector& dq) const {
  Eigen::Matrix<double, Eigen::Dynamic, 2> u(hinges(), 2);
  accumulate(cos0_, sin0_, dq, u.col(0).data(), u.col(1).data());
  return u.transpose();
}

ring::ModeShape Chain::shape_at(const Vector& q, const Vector& dq) const {
  std::vector<double> ux(hinges()), uy(hinges());
  accumulate(q.head(n_).array().cos(), q.head(n_).array().sin(), dq, ux.data(), uy.data());
  return sample(ux, uy);
}

ring::ModeShape Chain::rest_shape(const Vector& dq) const { return rest_shapes(dq).front(); }

std::vector<ring::ModeShape> Chain::rest_shapes(const Matrix& dq) const {
  std::vector<double> ux(hinges()), uy(hinges());
  std::vector<ring::ModeShape> shapes;
  shapes.reserve(static_cast<std::size_t>(dq.cols()));
  for (Eigen::Index k = 0; k < dq.cols(); ++k) {
    accumulate(cos0_, sin0_, dq.col(k), ux.data(), uy.data());
    shapes.push_back(sample(ux, uy));
  }
  return shapes;
}

Vector Chain::spring_forces(const Vector& q) const {
  const Vector r = hinge_rotations(q);
  Vector f = Vector::Zero(dofs());
  // f_k = K (r_k - r_{k+1}), cyclic on the ring; an arch has no spring at its ends (r_0 = 0
  // by hinge_rotations, r_n = 0 here).
  for (int k = 0; k < n_; ++k) f[k] = k_ * (r[k] - (arch_ && k + 1 == n_ ? 0.0 : r[(k + 1) % n_]));
  return f;
}

Matrix Chain::stiffness_matrix() const {
  Matrix S = Matrix::Zero(dofs(), dofs());
  for (int k = first_spring(); k < n_; ++k) {  // spring k joins segments a = k - 1 and k
    const int a = (k + n_ - 1) % n_;
    S(k, k) += k_;
    S(a, a) += k_;
    S(k, a) -= k_;
    S(a, k) -= k_;
  }
  return S;
}

Vector Chain::point_load_forces(const Vector& q, int k, const Eigen::Vector2d& F) const {
  return hinge_jacobian(q, k).transpose() * F;
}

Eigen::Vector2d Chain::closure(const Vector& q) const {
  check(q);
  Eigen::Vector2d g = Eigen::Vector2d::Zero();
  for (int j = 0; j < n_; ++j) g += e(q[j]);
  if (arch_) return base(q) + l_ * g - hinge_rest(n_);  // the far end's pin (file comment)
  return l_ * g;
}

Matrix Chain::closure_jacobian(const Vector& q) const {
  check(q);
  Matrix J = Matrix::Zero(2, dofs());
  for (int j = 0; j < n_; ++j) J.col(j) = l_ * eprime(q[j]);
  if (arch_ && free_) J.rightCols<2>().setIdentity();
  return J;
}

Eigen::Vector2d Chain::closure_jdot_qdot(const Vector& q, const Vector& qd) const {
  check(q);
  check(qd);
  Eigen::Vector2d g = Eigen::Vector2d::Zero();
  for (int j = 0; j < n_; ++j) g -= qd[j] * qd[j] * e(q[j]);
  return l_ * g;
}

double Chain::roller(const Vector& q) const {
  if (!roller_) throw std::logic_error("multibody: roller() called on a chain without a roller");
  return roller_normal_.dot(hinge_position(q, *roller_) - hinge_rest(0));
}

Vector Chain::roller_jacobian(const Vector& q) const {
  if (!roller_) throw std::logic_error("multibody: roller_jacobian() without a roller");
  return hinge_jacobian(q, *roller_).transpose() * roller_normal_;
}

double Chain::roller_jdot_qdot(const Vector& q, const Vector& qd) const {
  if (!roller_) throw std::logic_error("multibody: roller_jdot_qdot() without a roller");
  check(q);
  check(qd);
  double g = 0.0;
  for (int j = 0; j < *roller_; ++j) g -= qd[j] * qd[j] * roller_normal_.dot(e(q[j]));
  return l_ * g;
}

Vector Chain::constraints(const Vector& q) const {
  Vector g(constraint_count());
  if (constraint_count() >= 2) g.head<2>() = closure(q);
  if (roller_) g[2] = roller(q);
  return g;
}

Matrix Chain::constraint_jacobian(const Vector& q) const {
  Matrix J(constraint_count(), dofs());
  if (constraint_count() >= 2) J.topRows<2>() = closure_jacobian(q);
  if (roller_) J.row(2) = roller_jacobian(q).transpose();
  return J;
}

Chain::ConstraintKinematics Chain::constraint_kinematics(const Vector& q) const {
  check(q);
  const int c = constraint_count();
  ConstraintKinematics k{Vector(c), Matrix::Zero(c, dofs()), Matrix::Zero(c, dofs())};
  if (arch_) {  // the far end's pin rows, or none (file comment)
    if (c == 0) return k;
    Eigen::Vector2d p = base(q);
    for (int j = 0; j < n_; ++j) {
      const Eigen::Vector2d u = e(q[j]);
      p += l_ * u;
      k.G.col(j) = l_ * eprime(q[j]);
      k.hess.col(j) = -l_ * u;
    }
    k.g = p - hinge_rest(n_);
    if (free_) k.G.rightCols<2>().setIdentity();
    return k;
  }
  // The same operations as closure(), roller() and their Jacobians: g sums the unit
  // vectors e(phi_j) (closure) and the hinge positions (roller); each constraint is a sum
  // of l (a cos phi_j + b sin phi_j), so its second derivative is minus that term.
  Eigen::Vector2d sum = Eigen::Vector2d::Zero(), p = base(q);
  for (int j = 0; j < n_; ++j) {
    const Eigen::Vector2d u = e(q[j]), d = l_ * eprime(q[j]);
    if (roller_ && j == *roller_) k.g[2] = roller_normal_.dot(p - hinge_rest(0));
    sum += u;
    p += l_ * u;
    k.G.col(j).head<2>() = d;
    k.hess.col(j).head<2>() = -l_ * u;
    if (roller_ && j < *roller_) {
      k.G(2, j) = d.dot(roller_normal_);
      k.hess(2, j) = -l_ * u.dot(roller_normal_);
    }
  }
  if (roller_ && *roller_ == n_) k.g[2] = roller_normal_.dot(p - hinge_rest(0));
  k.g.head<2>() = l_ * sum;
  if (roller_ && free_) k.G.row(2).tail<2>() = roller_normal_.transpose();
  return k;
}

Vector Chain::constraint_jdot_qdot(const Vector& q, const Vector& qd) const {
  Vector g(constraint_count());
  if (constraint_count() >= 2) g.head<2>() = closure_jdot_qdot(q, qd);
  if (roller_) g[2] = roller_jdot_qdot(q, qd);
  return g;
}

}  // namespace multibody
