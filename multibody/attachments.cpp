#include "multibody/attachments.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace multibody::detail {

namespace {

/// The hinge at `deg`, or std::invalid_argument naming `key`.
int hinge(const Chain& chain, double deg, const std::string& key) {
  const int k = chain.hinge_index(deg);
  if (k < 0)
    throw std::invalid_argument("multibody: " + key + " (= " + std::to_string(deg) +
                                " deg) is not a hinge of the n = " + std::to_string(chain.n()) +
                                (chain.arch() ? " arch chain (valid: from + span k / n)"
                                              : " chain (valid: anchor + 360 k / n)"));
  return k;
}

/// K += sum_k (d u_k/dq)^T B[k] (d u_k/dq) at the angles of q, through the suffix sums of B
/// (file comment). O(n^2).
void add_pull_back(const Chain& chain, const Vector& q, const std::vector<Eigen::Matrix2d>& B, Eigen::Ref<Matrix> K) {
  const int n = chain.n(), N = chain.dofs();
  std::vector<Eigen::Matrix2d> S(n + 1, Eigen::Matrix2d::Zero());
  for (int k = n - 1; k >= 0; --k) S[k] = S[k + 1] + B[k];
  Eigen::Matrix2Xd c(2, n);
  for (int j = 0; j < n; ++j) c.col(j) << -chain.l() * std::sin(q[j]), chain.l() * std::cos(q[j]);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < i; ++j) {
      const double v = c.col(i).dot(S[i + 1] * c.col(j));
      K(i, j) += v;
      K(j, i) += v;
    }
    K(i, i) += c.col(i).dot(S[i + 1] * c.col(i));
    if (chain.free()) {
      const Eigen::RowVector2d r = c.col(i).transpose() * S[i + 1];
      K.block(i, n, 1, 2) += r;
      K.block(n, i, 2, 1) += r.transpose();
    }
  }
  if (chain.free()) K.bottomRightCorner(2, 2) += S[0];
  (void)N;
}

/// grad += sum_k (d u_k/dq)^T f_k for the suffix sums F_m = sum_{k >= m} f_k of hinge forces
/// f_k at the angles of q: grad_j += c_j . F_{j+1}, and F_0 on a free ring's (x_0, y_0) (file
/// comment). O(n).
void add_pulled_back(const Chain& chain, const Vector& q, const std::vector<Eigen::Vector2d>& F, Vector& grad) {
  const int n = chain.n();
  for (int j = 0; j < n; ++j) {
    const Eigen::Vector2d c(-chain.l() * std::sin(q[j]), chain.l() * std::cos(q[j]));
    grad[j] += c.dot(F[j + 1]);
  }
  if (chain.free()) grad.tail<2>() += F[0];
}

/// The mean rotation of hinge h's segments (attachments.hpp, mean_rotation) as a row on q,
/// times `scale`, added to v.
void add_mean_rotation(const Chain& chain, int h, double scale, Vector& v) {
  for (const auto& [segment, weight] : mean_rotation(chain, h)) v[segment] += weight * scale;
}

/// A += sum_h w[h] a_h a_h^T with a_h the mean rotation of hinge h (n x n on the segments'
/// rotations). O(n) nonzeros, O(n^2) with the dense A.
void add_mean_rotations(const Chain& chain, const std::vector<double>& w, Eigen::Ref<Matrix> A) {
  const int n = chain.n();
  for (int h = 0; h < chain.hinges(); ++h)
    if (w[h] > 0.0) {
      Vector a = Vector::Zero(n);
      add_mean_rotation(chain, h, 1.0, a);
      A += w[h] * a * a.transpose();
    }
}

}  // namespace

void add_hinge_term(const Chain& chain, const Vector& q, const std::vector<Eigen::Vector2d>& f,
                    const std::vector<Eigen::Matrix2d>* B, Vector& grad, Eigen::Ref<Matrix>* hess) {
  const int n = chain.n();
  std::vector<Eigen::Vector2d> F(n + 1, Eigen::Vector2d::Zero());
  for (int k = n - 1; k >= 0; --k) F[k] = F[k + 1] + f[k];
  add_pulled_back(chain, q, F, grad);
  if (!hess) return;
  add_pull_back(chain, q, *B, *hess);
  for (int j = 0; j < n; ++j)
    (*hess)(j, j) -= chain.l() * (std::cos(q[j]) * F[j + 1].x() + std::sin(q[j]) * F[j + 1].y());
}

Attachments::Attachments(const Chain& chain, const ring::RingSpec& spec)
    : chain_(chain),
      stiff_(chain.hinges(), Eigen::Matrix2d::Zero()),
      mass_(chain.hinges(), Eigen::Matrix2d::Zero()),
      rot_k_(chain.hinges(), 0.0),
      q0_(chain.q0()) {
  const int n = chain.n();
  if (spec.foundation.any())
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d r = chain.hinge_rest(k).normalized(), t(-r.y(), r.x());
      stiff_[k] += chain.l() * (spec.foundation.radial * r * r.transpose() + spec.foundation.tangential * t * t.transpose());
    }
  std::vector<double> kr(chain.hinges(), 0.0);  // rotational springs to the ground, by hinge (a clamp: infinite)
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i) {
    const ring::Spring& s = spec.supports.springs[i];
    const int h = hinge(chain, s.angle, "supports.springs[" + std::to_string(i + 1) + "]");
    stiff_[h].diagonal() += Eigen::Vector2d(s.kx, s.ky);
    kr[h] += s.kr;
  }
  if (spec.supports.clamp) kr[hinge(chain, *spec.supports.clamp, "supports.clamp")] = HUGE_VAL;
  // psi condensed: 4K and kr in series on the mean rotation, psi = 4K m / (4K + kr) (file comment).
  for (int h = 0; h < chain.hinges(); ++h)
    if (kr[h] > 0.0) rot_k_[h] = condensed_rotation_stiffness(kr[h], chain.K(), is_end(chain, h));
  std::vector<double> inertia(n, 0.0);
  for (std::size_t i = 0; i < spec.masses.size(); ++i) {
    const ring::PointMass& pm = spec.masses[i];
    const int h = hinge(chain, pm.angle, "masses[" + std::to_string(i + 1) + "]");
    mass_[h].diagonal().array() += pm.mass;
    inertia[h] += pm.inertia;
  }
  for (int h = 0; h < n; ++h)
    if (kr[h] > 0.0 || inertia[h] > 0.0) rotations_.push_back({h, kr[h], inertia[h]});
  if (chain.arch() && kr[n] > 0.0) rotations_.push_back({n, kr[n], 0.0});
  // The pinned hinges that the chain does not hold itself (Chain::holds: a ring's pin, an
  // arch's pinned ends) are rows of their own.
  for (double p : spec.supports.pinned()) {
    const int h = hinge(chain, p, p == spec.supports.pin ? "supports.pin" : "supports.pins");
    if (!chain.holds(h)) pins_.push_back(h);
  }
  has_stiffness_ = spec.foundation.any() || spec.supports.clamp || !spec.supports.springs.empty();
  has_mass_ = !spec.masses.empty();
}

double Attachments::energy(const Vector& q, bool rotations) const {
  const Eigen::Matrix2Xd p = chain_.hinge_positions(q);
  double e = 0.0;
  for (int k = 0; k < chain_.n(); ++k) e += 0.5 * (p.col(k) - chain_.hinge_rest(k)).dot(hinge_force(k, p.col(k)));
  if (rotations)
    for (int k = 0; k < chain_.hinges(); ++k)
      if (rot_k_[k] > 0.0) {
        const int j = is_end(chain_, k) ? (k == 0 ? 0 : k - 1) : (k + chain_.n() - 1) % chain_.n();
        const int i = is_end(chain_, k) ? j : k;  // an arch's end: its one segment (mean_rotation)
        const double dm = 0.5 * (q[j] - q0_[j] + q[i] - q0_[i]);
        e += 0.5 * rot_k_[k] * dm * dm;
      }
  return e;
}

void Attachments::add_stiffness(const Vector& q, Vector& grad, Eigen::Ref<Matrix>* hess, bool rotations) const {
  if (!has_stiffness_) return;
  const int n = chain_.n();
  const Eigen::Matrix2Xd p = chain_.hinge_positions(q);
  // F_m = sum_{k >= m} B_k u_k; grad_j = c_j . F_{j+1} (file comment).
  std::vector<Eigen::Vector2d> F(n + 1, Eigen::Vector2d::Zero());
  for (int k = n - 1; k >= 0; --k) F[k] = F[k + 1] + hinge_force(k, p.col(k));
  add_pulled_back(chain_, q, F, grad);
  if (rotations) add_rotation_forces(q - q0_, grad);
  if (!hess) return;
  add_pull_back(chain_, q, stiff_, *hess);
  for (int j = 0; j < n; ++j)
    (*hess)(j, j) -= chain_.l() * (std::cos(q[j]) * F[j + 1].x() + std::sin(q[j]) * F[j + 1].y());
  if (rotations) add_mean_rotations(chain_, rot_k_, hess->topLeftCorner(n, n));
}

void Attachments::add_rotation_forces(const Vector& dq, Vector& grad) const {
  for (int h = 0; h < chain_.hinges(); ++h)
    if (rot_k_[h] > 0.0) {
      double dm = 0.0;
      for (const auto& [segment, weight] : mean_rotation(chain_, h)) dm += weight * dq[segment];
      add_mean_rotation(chain_, h, rot_k_[h] * dm, grad);
    }
}

void Attachments::add_rest_products(const Vector& v, Vector* kv, Vector* mv) const {
  const int n = chain_.n();
  const Eigen::Matrix2Xd du = chain_.rest_displacements(v);
  auto add = [&](const std::vector<Eigen::Matrix2d>& B, Vector& out) {
    std::vector<Eigen::Vector2d> F(n + 1, Eigen::Vector2d::Zero());
    for (int k = n - 1; k >= 0; --k) F[k] = F[k + 1] + B[k] * du.col(k);
    add_pulled_back(chain_, q0_, F, out);
  };
  if (kv) {
    add(stiff_, *kv);
    add_rotation_forces(v, *kv);
  }
  if (mv) add(mass_, *mv);
}

void Attachments::add_rotation_stiffness(Eigen::Ref<Matrix> A) const { add_mean_rotations(chain_, rot_k_, A); }

Matrix Attachments::rest_mass() const {
  Matrix M = Matrix::Zero(chain_.dofs(), chain_.dofs());
  add_mass(q0_, M);
  return M;
}

void Attachments::add_mass(const Vector& q, Eigen::Ref<Matrix> M) const {
  if (has_mass_) add_pull_back(chain_, q, mass_, M);
}

double Attachments::kinetic_energy(const Vector& q, const Vector& v) const {
  if (!has_mass_) return 0.0;
  const Eigen::Matrix2Xd w = chain_.displacements_at(q, v);  // the hinges' velocities
  double T = 0.0;
  for (int k = 0; k < chain_.n(); ++k) T += 0.5 * w.col(k).dot(mass_[k] * w.col(k));
  return T;
}

std::vector<HingeRotation> Attachments::hinge_rotations() const { return rotations_; }

Chain::ConstraintKinematics Attachments::pins(const Vector& q) const {
  const int rows = pin_rows();
  Chain::ConstraintKinematics k{Vector(rows), Matrix::Zero(rows, chain_.dofs()), Matrix::Zero(rows, chain_.dofs())};
  for (std::size_t i = 0; i < pins_.size(); ++i) {
    const int h = pins_[i], r = 2 * static_cast<int>(i);
    k.g.segment<2>(r) = chain_.hinge_position(q, h) - chain_.hinge_rest(h);
    k.G.middleRows(r, 2) = chain_.hinge_jacobian(q, h);
    for (int j = 0; j < h; ++j) k.hess.block(r, j, 2, 1) = -chain_.l() * Eigen::Vector2d(std::cos(q[j]), std::sin(q[j]));
  }
  return k;
}

Chain::ConstraintKinematics Attachments::constraints(const Vector& q) const {
  Chain::ConstraintKinematics ck = chain_.constraint_kinematics(q);
  if (pin_rows() == 0) return ck;
  const Chain::ConstraintKinematics p = pins(q);
  const Eigen::Index c = ck.g.size() + p.g.size();
  ck.g.conservativeResize(c);
  ck.g.tail(p.g.size()) = p.g;
  ck.G.conservativeResize(c, Eigen::NoChange);
  ck.G.bottomRows(p.G.rows()) = p.G;
  ck.hess.conservativeResize(c, Eigen::NoChange);
  ck.hess.bottomRows(p.hess.rows()) = p.hess;
  return ck;
}

Chain::ConstraintKinematics constraint_kinematics(const Chain& chain, const Attachments* terms, const Vector& q) {
  return terms ? terms->constraints(q) : chain.constraint_kinematics(q);
}

Vector constraint_values(const Chain& chain, const Attachments* terms, const Vector& q) {
  Vector g = chain.constraints(q);
  if (!terms || terms->pin_rows() == 0) return g;
  const std::vector<int>& pins = terms->pinned_hinges();
  const Eigen::Index c = g.size();
  g.conservativeResize(c + terms->pin_rows());
  for (std::size_t i = 0; i < pins.size(); ++i)
    g.segment<2>(c + 2 * static_cast<Eigen::Index>(i)) = chain.hinge_position(q, pins[i]) - chain.hinge_rest(pins[i]);
  return g;
}

HingeInertias::HingeInertias(const Chain& chain, const Attachments& terms, bool shear) : chain_(chain) {
  const int n = chain.n(), dofs = chain.dofs(), s = shear ? n : 0;
  const std::vector<HingeRotation> rotations = terms.hinge_rotations();
  for (const HingeRotation& r : rotations) p_ += r.moves();
  H_ = Matrix::Zero(dofs + s + p_, dofs + s + p_);
  J_ = Vector::Zero(p_);
  // The unknowns a rotation r_i is the sum of: segment i's angle (and its shear angle, the
  // section's rotation psi = theta + gamma), or a moving hinge's chi.
  auto add = [&](int i, int j, double c) {
    const int a[2] = {i < n ? i : dofs + s + i - n, i < n && shear ? dofs + i : -1};
    const int b[2] = {j < n ? j : dofs + s + j - n, j < n && shear ? dofs + j : -1};
    for (int x : a)
      for (int y : b)
        if (x >= 0 && y >= 0) H_(x, y) += c;
  };
  auto spring = [&](int i, int j, double c) {
    add(i, i, c);
    add(j, j, c);
    add(i, j, -c);
    add(j, i, -c);
  };
  std::vector<std::pair<int, double>> ground;  // kr from chi to the ground: H's part beyond the springs'
  split_hinges(
      rotations, n, chain.K(), spring, [&](int i, double c) { ground.emplace_back(i, c); },
      [&](int i, double j) { J_[i - n] = j; });
  springs_ = H_;
  for (const auto& [i, c] : ground) add(i, i, c);
  // Less kr condensed on the mean rotation, which Attachments (and the Sections' A) puts at
  // every hinge with kr.
  for (const HingeRotation& t : rotations)
    if (t.moves() && t.kr > 0.0) {
      const double c = condensed_rotation_stiffness(t.kr, chain.K()) / 4.0;
      for (int i : {(t.hinge + n - 1) % n, t.hinge})
        for (int j : {(t.hinge + n - 1) % n, t.hinge}) add(i, j, -c);
    }
}

Vector HingeInertias::relative(const Vector& x) const {
  Vector y = x;
  y.head(chain_.dofs()) -= chain_.q0();
  return y;
}

double HingeInertias::energy(const Vector& x) const {
  const Vector y = relative(x);
  return 0.5 * y.dot(H_ * y);
}

void HingeInertias::add_forces(const Vector& x, Eigen::Ref<Vector> r) const { r += H_ * relative(x); }

void HingeInertias::add_stiffness(double c, Eigen::Ref<Matrix> T, bool springs_only) const {
  T += c * (springs_only ? springs_ : H_);
}

double HingeInertias::kinetic_energy(const Vector& v) const { return 0.5 * J_.dot(v.tail(p_).cwiseAbs2()); }

void HingeInertias::add_inertia_forces(const Vector& a, Eigen::Ref<Vector> r) const {
  r.tail(p_) += J_.cwiseProduct(a.tail(p_));
}

void HingeInertias::add_mass(double c, Eigen::Ref<Matrix> M) const {
  M.bottomRightCorner(p_, p_).diagonal() += c * J_;
}

void HingeInertias::add_mass_times(const Matrix& E, Eigen::Ref<Matrix> out) const {
  out.bottomRows(p_) += J_.asDiagonal() * E.bottomRows(p_);
}

LinearTerms linear_terms(const Chain& chain, const ring::RingSpec& spec) {
  const Attachments a(chain, spec);
  const Vector q0 = chain.q0();
  LinearTerms t;
  t.K = Matrix::Zero(chain.dofs(), chain.dofs());
  Vector grad = Vector::Zero(chain.dofs());
  Eigen::Ref<Matrix> K(t.K);
  a.add_stiffness(q0, grad, &K, false);  // at rest u = 0: no curvature term, no force
  t.M = a.rest_mass();
  t.rotations = a.hinge_rotations();
  t.J = a.pins(q0).G;
  return t;
}

}  // namespace multibody::detail
