// The two backends of the response's Newton iteration (newton_backend.hpp).
#include "multibody/newton_backend.hpp"

#include <Eigen/LU>

#include "multibody/dynamics_sparse.hpp"

namespace multibody::detail {
namespace {

/// n x n matrices: the inertia constants, K, C, the tangent and an LU of the
/// saddle-point matrix. O(n^2) memory.
class DenseBackend final : public NewtonBackend {
 public:
  DenseBackend(const Chain& chain, const DeadLoad& load, const Damping& damping, const Loading* loading,
               const Attachments* terms)
      : NewtonBackend(chain, load, damping, loading, terms), inertia_(inertia_constants(chain)), K_(chain.stiffness_matrix()) {
    if (damping.any())
      C_ = damping.mass * chain.mass_matrix(chain.q0()) + (damping.cyclic / chain.K()) * K_;
    else
      C_ = Matrix::Zero(K_.rows(), K_.cols());
  }

  Vector damping_times(const Vector& v) const override { return C_ * v; }

  bool initial_acceleration(const Vector& q, const Vector& v, double f, Vector& qdd, Vector& lambda) const override {
    const int n = chain_.dofs(), c = chain_.constraint_count();
    const Matrix G = chain_.constraint_jacobian(q);
    Vector xi;
    const Vector phi = load_forces_at(q, f, nullptr);
    inertia_terms(inertia_, q, v, Vector::Zero(n), 0.0, 0.0, xi, nullptr);
    Matrix A = Matrix::Zero(n + c, n + c);
    A.topLeftCorner(n, n) = chain_.mass_matrix(q);
    A.topRightCorner(n, c) = G.transpose();
    A.bottomLeftCorner(c, n) = G;
    Vector b(n + c);
    Vector elastic = chain_.spring_forces(q);
    if (terms_) terms_->add_stiffness(q, elastic, nullptr);
    b.head(n) = f * phi - xi - C_ * v - elastic;
    b.tail(c) = -chain_.constraint_jdot_qdot(q, v);
    const Vector x = A.partialPivLu().solve(b);
    qdd = x.head(n);
    lambda = x.tail(c);
    return x.allFinite();
  }

  void residual(const Vector& q, const Vector& v, const Vector& qdd, double f, double cm, double cv, Vector& r,
                bool tangent) override {
    if (tangent) T_ = K_;
    inertia_terms(inertia_, q, v, qdd, cm, cv, r, tangent ? &T_ : nullptr);
    if (tangent && damping_.any()) T_ += cv * C_;
    r += chain_.spring_forces(q) - f * load_forces_at(q, f, tangent ? &T_ : nullptr);
    if (terms_) {
      Eigen::Ref<Matrix> t(T_);
      terms_->add_stiffness(q, r, tangent ? &t : nullptr);
    }
    if (damping_.any()) r += C_ * v;
  }

  void add_to_tangent_diagonal(const Vector& d) override { T_.diagonal() += d; }

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
  Inertia inertia_;
  Matrix K_, C_, T_;
  Eigen::PartialPivLU<Matrix> lu_;
};

/// The structured O(n) forms of dynamics_sparse.hpp; nothing of size n^2.
class StructuredBackend final : public NewtonBackend {
 public:
  StructuredBackend(const Chain& chain, const DeadLoad& load, const Damping& damping)
      : NewtonBackend(chain, load, damping) {}

  Vector damping_times(const Vector& v) const override {
    Vector y = damping_.mass * chain_.mass_times(chain_.q0(), v);
    const Eigen::Index n = v.size();
    for (Eigen::Index k = 0; k < n; ++k)
      y[k] += damping_.cyclic * (2.0 * v[k] - v[(k + n - 1) % n] - v[(k + 1) % n]);
    return y;
  }

  bool initial_acceleration(const Vector& q, const Vector& v, double f, Vector& qdd, Vector& lambda) const override {
    Vector phi;
    load_forces(chain_, load_, q, phi, nullptr);
    const Vector b = f * phi - chain_.quadratic_velocity(q, v) - damping_times(v) - chain_.spring_forces(q);
    SparseSaddle lu;
    return lu.factor(mass_structured(chain_, q), chain_.constraint_jacobian(q), 1.0) &&
           lu.solve(b, -chain_.constraint_jdot_qdot(q, v), qdd, lambda, 2);
  }

  void residual(const Vector& q, const Vector& v, const Vector& qdd, double f, double cm, double cv, Vector& r,
                bool tangent) override {
    Vector phi, dphi;
    load_forces(chain_, load_, q, phi, tangent ? &dphi : nullptr);
    if (tangent) {
      T_ = StructuredMatrix{};
      T_.diag = Vector::Zero(q.size());
      T_.cyclic = chain_.K();
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
    r += chain_.spring_forces(q) - f * phi;
    if (damping_.any()) r += damping_times(v);
    if (tangent) T_.diag -= f * dphi;
  }

  void add_to_tangent_diagonal(const Vector& d) override { T_.diag += d; }

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

Vector NewtonBackend::load_forces_at(const Vector& q, double f, Matrix* tangent) const {
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
                                                   const Attachments* terms) {
  if (structured && (loading || terms))
    throw std::invalid_argument("multibody: the O(n) response takes the paper's ring and one point load only");
  if (structured) return std::make_unique<StructuredBackend>(chain, load, damping);
  return std::make_unique<DenseBackend>(chain, load, damping, loading, terms);
}

}  // namespace multibody::detail
