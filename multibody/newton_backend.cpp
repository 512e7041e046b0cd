// The two backends of the response's Newton iteration (newton_backend.hpp).
#include "multibody/newton_backend.hpp"

#include <Eigen/LU>
#include <optional>

#include "multibody/dynamics_sparse.hpp"

namespace multibody::detail {
namespace {

/// N x N matrices (N = n, + n with the Timoshenko chain's shear angles, + the point inertias'
/// hinge rotations): the inertia
/// constants, K, C, the tangent and an LU of the saddle-point matrix. O(N^2) memory.
class DenseBackend final : public NewtonBackend {
 public:
  DenseBackend(const Chain& chain, const DeadLoad& load, const Damping& damping, const Loading* loading,
               const Attachments* terms, const Sections* sections, const HingeInertias* hinges,
               const HingeBending* bending)
      : NewtonBackend(chain, load, damping, loading, terms, sections, hinges, bending),
        inertia_(inertia_constants(chain, terms)),
        K_(chain.stiffness_matrix()),
        n_(chain.dofs()),
        N_(n_ + (sections ? sections->n() : 0) + (hinges ? hinges->n() : 0)) {
    C_ = Matrix::Zero(N_, N_);
    if (!damping.any()) return;
    const Matrix cyclic = (damping.cyclic / chain.K()) * K_;
    C_.topLeftCorner(n_, n_) = damping.mass * mass_matrix(chain, terms, chain.q0()) + cyclic;
    if (sections) {  // the mass [M + J, J; J, J]; the dampers between the sections' rotations
      sections->add_mass(damping.mass, C_);
      C_.block(0, n_, n_, n_) += cyclic;
      C_.block(n_, 0, n_, n_) += cyclic;
      C_.block(n_, n_, n_, n_) += cyclic;
    }
    if (hinges) {  // the mass J on chi; the dampers on the split springs (on the sections' rotations)
      hinges->add_mass(damping.mass, C_);
      hinges->add_stiffness(damping.cyclic / chain.K(), C_, true);
    }
  }

  Vector damping_times(const Vector& v) const override { return C_ * v; }

  bool initial_acceleration(const Vector& q, const Vector& v, double f, Vector& qdd, Vector& lambda) const override {
    const Vector qc = q.head(n_), vc = v.head(n_);
    const Chain::ConstraintKinematics ck = constraint_kinematics(chain_, terms_, qc);
    const Matrix& G = ck.G;
    const Eigen::Index c = G.rows();
    Vector xi;
    const Vector phi = load_forces_at(qc, f, nullptr);
    inertia_terms(inertia_, qc, vc, Vector::Zero(n_), 0.0, 0.0, xi, nullptr);
    Matrix A = Matrix::Zero(N_ + c, N_ + c);
    A.topLeftCorner(n_, n_) = mass_matrix(chain_, terms_, qc);
    if (sections_) sections_->add_mass(1.0, A.topLeftCorner(N_, N_));
    if (hinges_) hinges_->add_mass(1.0, A.topLeftCorner(N_, N_));
    A.block(0, N_, n_, c) = G.transpose();
    A.block(N_, 0, c, n_) = G;
    Vector b = Vector::Zero(N_ + c);
    b.head(N_) = -elastic_forces(q) - C_ * v;
    b.head(n_) += f * phi - xi;
    b.tail(c) = -constraint_jdot_qdot(ck, vc);
    if (sections_ && !(sections_->shear().inertia > 0.0)) {
      // No rotary inertia: gamma is algebraic, dV/dgamma = A psi + S gamma (+ the split
      // springs' H of the point inertias) = 0 at all times (linear, so also its second
      // derivative): those rows, the Hessian's on gamma, in place of the massless ones.
      const int s = sections_->n();
      Matrix H = Matrix::Zero(N_, N_);
      sections_->add_stiffness(H);
      if (hinges_) hinges_->add_stiffness(1.0, H);
      A.middleRows(n_, s).setZero();
      A.block(n_, 0, s, N_) = H.middleRows(n_, s);
      b.segment(n_, s).setZero();
    }
    const Vector x = A.partialPivLu().solve(b);
    qdd = x.head(N_);
    lambda = x.tail(c);
    return x.allFinite();
  }

  void residual(const Vector& q, const Vector& v, const Vector& qdd, double f, double cm, double cv, Vector& r,
                bool tangent) override {
    const Vector qc = q.head(n_);
    // The chain's terms on phi (inertia, loads, the terms on the translations) into rc and
    // T_'s block on phi (in T_'s own storage: no second N x N); the springs on the rotations
    // (the sections', with the shear angles) after them.
    std::optional<Eigen::Ref<Matrix>> tc;
    if (tangent) {
      T_.setZero(N_, N_);
      if (bending_)  // the hinges' tangents at the iterate, from their committed states
        bending_->add_tangent_on_angles(chain_, qc, T_.topLeftCorner(n_, n_));
      else if (!sections_)
        T_.topLeftCorner(n_, n_) = K_;
      tc.emplace(T_.topLeftCorner(n_, n_));
    }
    Vector rc;
    inertia_terms(inertia_, qc, v.head(n_), qdd.head(n_), cm, cv, rc, tangent ? &T_ : nullptr);
    rc -= f * load_forces_at(qc, f, tc ? &*tc : nullptr);
    if (terms_) terms_->add_stiffness(qc, rc, tc ? &*tc : nullptr, !sections_);
    r = elastic_forces(q, false);
    r.head(n_) += rc;
    if (sections_) sections_->add_inertia_forces(qdd, r);
    if (hinges_) hinges_->add_inertia_forces(qdd, r);
    if (tangent && sections_) {
      sections_->add_stiffness(T_);
      sections_->add_mass(cm, T_);
    }
    if (tangent && hinges_) {
      hinges_->add_stiffness(1.0, T_);
      hinges_->add_mass(cm, T_);
    }
    if (tangent && damping_.any()) T_ += cv * C_;
    if (damping_.any()) r += C_ * v;
  }

  void add_to_tangent_diagonal(const Vector& d) override { T_.diagonal() += d; }
  const Matrix* dense_tangent() const override { return &T_; }

  bool factor(const Matrix& G, double l, double h) override {
    const Eigen::Index n = T_.rows(), c = G.rows();
    sc_ = T_.diagonal().cwiseAbs().maxCoeff() / l;
    Matrix A(n + c, n + c);
    A.topLeftCorner(n, n) = T_;
    A.topRightCorner(n, c) = sc_ * G.transpose();
    A.bottomLeftCorner(c, n) = sc_ * G;
    A.bottomRightCorner(c, c).setZero();
    lu_.compute(A);
    h_ = h;
    valid_ = true;
    return true;
  }

  bool solve(const Vector& r, const Vector& g, Vector& dq, Vector& dl) const override {
    const Eigen::Index n = r.size(), c = g.size();
    Vector rhs(n + c);
    rhs.head(n) = -r;
    rhs.tail(c) = -sc_ * g;
    if (!rhs.allFinite()) return false;
    const Vector x = lu_.solve(rhs);
    if (!x.allFinite()) return false;
    dq = x.head(n);
    dl = sc_ * x.tail(c);
    return true;
  }

  bool solve_columns(const Matrix& R, Matrix& DQ, Matrix& DL) const override {
    const Eigen::Index n = R.rows(), c = lu_.rows() - n;
    Matrix rhs = Matrix::Zero(n + c, R.cols());
    rhs.topRows(n) = -R;
    const Matrix x = lu_.solve(rhs);
    DQ = x.topRows(n);
    DL = sc_ * x.bottomRows(c);
    return DQ.allFinite() && DL.allFinite();
  }

 private:
  /// The springs' forces on the rotations (N entries): the hinge springs on phi, or the
  /// sections' springs and shear on (phi, gamma); with `terms`, also the terms' forces on phi
  /// (the translations' and, without sections, the rotations'). O(n) or O(n^2).
  Vector elastic_forces(const Vector& q, bool terms = true) const {
    Vector e = Vector::Zero(N_);
    const Vector qc = q.head(n_);
    if (sections_) sections_->add_forces(q, e);
    else e.head(n_) = bending_ ? bending_->forces_on_angles(chain_, qc) : chain_.spring_forces(qc);
    if (hinges_) hinges_->add_forces(q, e);
    if (terms && terms_) {
      Vector et = Vector::Zero(n_);
      terms_->add_stiffness(qc, et, nullptr, !sections_);
      e.head(n_) += et;
    }
    return e;
  }

  Inertia inertia_;
  Matrix K_, C_, T_;
  const Eigen::Index n_, N_;
  Eigen::PartialPivLU<Matrix> lu_;
};

/// The structured O(n) forms of dynamics_sparse.hpp; nothing of size n^2. The loads: one
/// point load (DeadLoad) or constant hinge forces (`loading` without a shape-dependent part:
/// point loads, gravity, dead pressure), whose stiffness is diagonal in the angles.
class StructuredBackend final : public NewtonBackend {
 public:
  StructuredBackend(const Chain& chain, const DeadLoad& load, const Damping& damping, const Loading* loading,
                    const HingeBending* bending)
      : NewtonBackend(chain, load, damping, loading, nullptr, nullptr, nullptr, bending) {}

  Vector damping_times(const Vector& v) const override {
    Vector y = damping_.mass * chain_.mass_times(chain_.q0(), v);
    const Eigen::Index n = v.size();
    for (Eigen::Index k = 0; k < n; ++k)
      y[k] += damping_.cyclic * (2.0 * v[k] - v[(k + n - 1) % n] - v[(k + 1) % n]);
    return y;
  }

  bool initial_acceleration(const Vector& q, const Vector& v, double f, Vector& qdd, Vector& lambda) const override {
    Vector phi;
    forces(q, phi, nullptr);
    const Vector b = f * phi - chain_.quadratic_velocity(q, v) - damping_times(v) - springs(q);
    SparseSaddle lu;
    return lu.factor(mass_structured(chain_, q), chain_.constraint_jacobian(q), 1.0) &&
           lu.solve(b, -chain_.constraint_jdot_qdot(q, v), qdd, lambda, 2);
  }

  void residual(const Vector& q, const Vector& v, const Vector& qdd, double f, double cm, double cv, Vector& r,
                bool tangent) override {
    Vector phi, dphi;
    forces(q, phi, tangent ? &dphi : nullptr);
    if (tangent) {
      T_ = StructuredMatrix{};
      T_.diag = Vector::Zero(q.size());
      if (bending_) {  // the hinges' tangents at the iterate, from their committed states
        const Vector r = chain_.hinge_rotations(q);
        T_.hinge.resize(r.size());
        for (Eigen::Index k = 0; k < r.size(); ++k) T_.hinge[k] = bending_->tangent(static_cast<int>(k), r[k]);
      } else {
        T_.cyclic = chain_.K();
      }
    }
    inertia_terms_structured(chain_, q, v, qdd, cm, cv, r, tangent ? &T_ : nullptr);
    if (tangent && damping_.any()) {
      T_.cyclic += cv * damping_.cyclic;
      if (damping_.mass > 0.0) {
        StructuredMatrix M0 = mass_structured(chain_, chain_.q0());
        T_.diag += cv * damping_.mass * M0.diag;
        M0.terms[0].coef *= cv * damping_.mass;
        T_.terms.push_back(std::move(M0.terms[0]));
      }
    }
    r += springs(q) - f * phi;
    if (damping_.any()) r += damping_times(v);
    if (tangent) T_.diag -= f * dphi;
  }

  void add_to_tangent_diagonal(const Vector& d) override { T_.diag += d; }

  /// The hinge springs' forces on the angles: the elastic K theta, or the hinges' law. O(n).
  Vector springs(const Vector& q) const {
    return bending_ ? bending_->forces_on_angles(chain_, q) : chain_.spring_forces(q);
  }

  /// The loads' generalized forces phi at q and, if `dphi`, their derivative's diagonal (the
  /// whole of it: load_forces.hpp's point load and constant hinge forces). O(n).
  void forces(const Vector& q, Vector& phi, Vector* dphi) const {
    if (!loading_) return load_forces(chain_, load_, q, phi, dphi);
    phi = loading_->forces(q);
    if (dphi) *dphi = -loading_->constant_stiffness_diagonal(q);  // phi = -dPi/dq
  }

  bool factor(const Matrix& G, double l, double h) override {
    sc_ = T_.diagonal().cwiseAbs().maxCoeff() / l;
    h_ = h;
    valid_ = slu_.factor(T_, G, sc_);
    return valid_;
  }

  bool solve(const Vector& r, const Vector& g, Vector& dq, Vector& dl) const override {
    if (!slu_.solve(-r, -sc_ * g, dq, dl)) return false;
    dl *= sc_;
    return true;
  }

  bool solve_columns(const Matrix& R, Matrix& DQ, Matrix& DL) const override {
    if (!slu_.solve_columns(-R, Matrix::Zero(slu_.constraints(), R.cols()), DQ, DL)) return false;
    DL *= sc_;
    return true;
  }

 private:
  StructuredMatrix T_;
  SparseSaddle slu_;
};

}  // namespace

Vector NewtonBackend::load_forces_at(const Vector& q, double f, Eigen::Ref<Matrix>* tangent) const {
  if (loading_) {
    if (tangent) loading_->add_stiffness(q, f, *tangent);
    return loading_->forces(q);
  }
  Vector phi, dphi;
  load_forces(chain_, load_, q, phi, tangent ? &dphi : nullptr);
  if (tangent) tangent->diagonal() -= f * dphi;
  return phi;
}

std::unique_ptr<NewtonBackend> make_newton_backend(const Chain& chain, const DeadLoad& load, const Damping& damping,
                                                   bool structured, const Loading* loading,
                                                   const Attachments* terms, const Sections* sections,
                                                   const HingeInertias* hinges, const HingeBending* bending) {
  if (structured && ((loading && loading->shape_dependent()) || terms || sections || hinges))
    throw std::invalid_argument(
        "multibody: the O(n) response takes the paper's Euler-Bernoulli ring and constant loads only");
  if (structured) return std::make_unique<StructuredBackend>(chain, load, damping, loading, bending);
  return std::make_unique<DenseBackend>(chain, load, damping, loading, terms, sections, hinges, bending);
}

}  // namespace multibody::detail
