#include "multibody/statics.hpp"

#include <Eigen/LU>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "ring/errors.hpp"

#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"

namespace multibody {
namespace {

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
};

/// Newton on K theta + G^T lambda - s Phi(q) = 0, g(q) = 0 at load factor s, from (q, lambda).
/// Tangent: K + diag(lambda . Hess g) - s dPhi/dq (all diagonal corrections, see
/// dynamics_model.hpp). O(n^3) per iteration.
NewtonOutcome newton(const Chain& ch, const detail::DeadLoad& load, const Matrix& K, double s,
                     Vector& q, Vector& lambda) {
  const int n = ch.dofs(), c = ch.constraint_count();
  NewtonOutcome out;
  Matrix A(n + c, n + c);
  Vector rhs(n + c), phi, dphi;
  for (int it = 1; it <= 25; ++it) {
    out.iterations = it;
    const Matrix G = ch.constraint_jacobian(q);
    // Diagonal constraint Hessians (dynamics_model.hpp): G at every angle + pi/2.
    const Matrix hess = ch.constraint_jacobian((q.array() + 0.5 * M_PI).matrix());
    detail::load_forces(ch, load, q, phi, &dphi);
    const Vector r = ch.spring_forces(q) + G.transpose() * lambda - s * phi;
    Matrix T = K;
    T.diagonal() += hess.transpose() * lambda - s * dphi;
    const double sc = ch.K() / ch.l();  // puts G on the scale of the springs
    A.setZero();
    A.topLeftCorner(n, n) = T;
    A.topRightCorner(n, c) = sc * G.transpose();
    A.bottomLeftCorner(c, n) = sc * G;
    rhs.head(n) = -r;
    rhs.tail(c) = -sc * ch.constraints(q);
    const Vector x = A.partialPivLu().solve(rhs);
    if (!x.allFinite()) return out;
    // A full Newton step larger than a quarter turn of some segment means the
    // iteration has left the basin: reject and let the caller cut the increment.
    if (x.head(n).cwiseAbs().maxCoeff() > 0.5) return out;
    q += x.head(n);
    lambda += sc * x.tail(c);
    if (x.head(n).cwiseAbs().maxCoeff() <= 1e-12) {
      out.converged = true;
      return out;
    }
  }
  return out;
}

}  // namespace

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::StaticOptions& statics) {
  if (!spec.supports.pin)
    throw std::invalid_argument("multibody::solve_static: the ring needs a pin (supports.pin)");
  if (statics.steps < 1)
    throw std::invalid_argument("multibody::solve_static: steps must be >= 1");
  const Chain ch(spec, options, statics.load.angle);
  const int n = ch.dofs();
  const detail::DeadLoad load{ch.hinge_at(statics.load.angle),
                              {statics.load.force[0], statics.load.force[1]}};
  std::vector<int> rec;
  for (double a : statics.record) rec.push_back(ch.hinge_at(a));
  const Matrix K = ch.stiffness_matrix();
  if (!spec.supports.roller) {
    // Without a roller the rigid rotation about the pin is free and K is singular in it:
    // the dead load then turns the ring until it hangs along its line of action.
    // The tangent stays regular only away from that, so refuse rather than guess.
    throw std::invalid_argument(
        "multibody::solve_static: needs a roller as well as a pin (supports.roller), "
        "otherwise the ring is free to turn about the pin");
  }

  Vector q = ch.q0(), lambda = Vector::Zero(ch.constraint_count());
  ring::StaticResult res;
  double s = 0.0, ds = 1.0 / statics.steps;
  const double ds_min = 1e-6 / statics.steps;
  const int gap = detail::contact_gap(ch, spec.section.depth());
  while (s < 1.0 - 1e-14) {
    const double s1 = std::min(1.0, s + ds);
    Vector q1 = q, l1 = lambda;
    const NewtonOutcome o = newton(ch, load, K, s1, q1, l1);
    res.newton_iterations += o.iterations;
    if (!o.converged) {
      ds *= 0.5;
      if (ds < ds_min) {
        std::ostringstream m;
        m << "multibody::solve_static: Newton did not converge beyond load factor " << s
          << " (increment cut to " << ds << ")";
        throw ring::NumericalError(m.str());
      }
      continue;
    }
    q = q1;
    lambda = l1;
    s = s1;
    ++res.steps;
    const auto cp = detail::closest_nonadjacent(ch.hinge_positions(q), gap, spec.section.depth());
    if (cp.distance < spec.section.depth()) {
      std::ostringstream m;
      m << "multibody::solve_static: the ring touches itself at load factor " << s
        << ": " << detail::describe_contact(cp) << " (section depth " << spec.section.depth()
        << " m); the chain model does not include contact";
      throw ring::NumericalError(m.str());
    }
  }
  const Eigen::Matrix2Xd hp = ch.hinge_positions(q);
  for (size_t i = 0; i < rec.size(); ++i) {
    const Eigen::Vector2d u = hp.col(rec[i]) - ch.hinge_rest(rec[i]);
    res.displacements.push_back({statics.record[i], u.x(), u.y()});
  }
  res.node_x.assign(hp.row(0).begin(), hp.row(0).end());
  res.node_y.assign(hp.row(1).begin(), hp.row(1).end());
  (void)n;
  return res;
}

}  // namespace multibody
