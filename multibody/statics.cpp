#include "multibody/statics.hpp"

#include "multibody/checks.hpp"

#include <Eigen/LU>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "ring/errors.hpp"

#include "multibody/chain.hpp"
#include "multibody/natural.hpp"
#include "multibody/dynamics_model.hpp"

namespace multibody {
namespace {

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
};

/// The scaled saddle-point tangent [T sG^T; sG 0] at (q, lambda, s), T = K + diag(lambda .
/// Hess g) - s dPhi/dq (all corrections diagonal, see dynamics_model.hpp), its LU, and the
/// residuals r = K theta + G^T lambda - s Phi, g, and Phi itself. O(n^3).
struct Linearization {
  Eigen::PartialPivLU<Matrix> lu;
  Vector r, g, phi;
  double sc = 1.0;  ///< scaling of the constraint rows and the multipliers
};
Linearization linearize_at(const Chain& ch, const detail::DeadLoad& load, const Matrix& K,
                           double s, const Vector& q, const Vector& lambda) {
  const int n = ch.dofs(), c = ch.constraint_count();
  Linearization L;
  const Chain::ConstraintKinematics ck = ch.constraint_kinematics(q);
  const Matrix& G = ck.G;
  Vector dphi;
  detail::load_forces(ch, load, q, L.phi, &dphi);
  L.r = ch.spring_forces(q) + G.transpose() * lambda - s * L.phi;
  L.g = ck.g;
  Matrix A = Matrix::Zero(n + c, n + c);
  A.topLeftCorner(n, n) = K;
  A.diagonal().head(n) += ck.hess.transpose() * lambda - s * dphi;
  L.sc = ch.K() / ch.l();  // puts G on the scale of the springs
  A.topRightCorner(n, c) = L.sc * G.transpose();
  A.bottomLeftCorner(c, n) = L.sc * G;
  L.lu.compute(A);
  return L;
}

/// Solves the linearization for right-hand sides (-r, -g) (`residual`) or (Phi, 0):
/// returns the angle part and writes the multiplier part. O(n^2).
Vector solve_lin(const Linearization& L, bool residual, Vector& dl) {
  const Eigen::Index n = L.r.size(), c = L.g.size();
  Vector rhs(n + c);
  if (residual) {
    rhs.head(n) = -L.r;
    rhs.tail(c) = -L.sc * L.g;
  } else {
    rhs.head(n) = L.phi;
    rhs.tail(c).setZero();
  }
  const Vector x = L.lu.solve(rhs);
  dl = L.sc * x.tail(c);
  return x.head(n);
}

/// Newton on K theta + G^T lambda - s Phi(q) = 0, g(q) = 0 at load factor s, from (q, lambda).
NewtonOutcome newton(const Chain& ch, const detail::DeadLoad& load, const Matrix& K, double s,
                     Vector& q, Vector& lambda) {
  NewtonOutcome out;
  for (int it = 1; it <= 25; ++it) {
    out.iterations = it;
    const Linearization L = linearize_at(ch, load, K, s, q, lambda);
    Vector dl;
    const Vector dq = solve_lin(L, true, dl);
    if (!dq.allFinite()) return out;
    // Left the basin: reject and let the caller cut the increment.
    if (dq.cwiseAbs().maxCoeff() > detail::kBasin) return out;
    q += dq;
    lambda += dl;
    if (dq.cwiseAbs().maxCoeff() <= 1e-12) {
      out.converged = true;
      return out;
    }
  }
  return out;
}

/// One arc-length step (Crisfield 1981, cylindrical: |q - q_start| = len) from the
/// converged (q, lambda, s), continuing in the direction `prev` (the previous step's
/// change of q). Predictor along the tangent dq/ds = A^{-1} (Phi, 0); corrector: Newton
/// on the equilibrium with the load factor as an unknown, bordered by the arc
/// condition (the root of its quadratic closest in direction to the step so far).
/// O(n^3) per iteration.
NewtonOutcome arc_step(const Chain& ch, const detail::DeadLoad& load, const Matrix& K, double len,
                       const Vector& prev, Vector& q, Vector& lambda, double& s) {
  NewtonOutcome out;
  const Vector q0 = q, l0 = lambda;
  const double s0 = s;
  {
    const Linearization L = linearize_at(ch, load, K, s, q, lambda);
    Vector dlF;
    const Vector dqF = solve_lin(L, false, dlF);
    const double nF = dqF.norm();
    if (!(nF > 0.0) || !dqF.allFinite()) return out;
    const double ds = (prev.size() && prev.dot(dqF) < 0.0 ? -1.0 : 1.0) * len / nF;
    q += ds * dqF;
    lambda += ds * dlF;
    s += ds;
  }
  for (int it = 1; it <= 25; ++it) {
    out.iterations = it;
    const Linearization L = linearize_at(ch, load, K, s, q, lambda);
    Vector dlR, dlF;
    const Vector aR = solve_lin(L, true, dlR), aF = solve_lin(L, false, dlF);
    if (!aR.allFinite() || !aF.allFinite()) return out;
    const Vector d = q - q0;
    // |d + aR + x aF|^2 = len^2
    const double a = aF.squaredNorm(), b = 2.0 * aF.dot(d + aR), c = (d + aR).squaredNorm() - len * len;
    const double disc = b * b - 4.0 * a * c;
    if (!(disc >= 0.0) || !(a > 0.0)) return out;
    const double r1 = (-b + std::sqrt(disc)) / (2.0 * a), r2 = (-b - std::sqrt(disc)) / (2.0 * a);
    const double dot1 = d.dot(d + aR + r1 * aF), dot2 = d.dot(d + aR + r2 * aF);
    const double x = dot1 >= dot2 ? r1 : r2;
    const Vector dq = aR + x * aF;
    if (dq.cwiseAbs().maxCoeff() > 0.5) return out;
    q += dq;
    lambda += dlR + x * dlF;
    s += x;
    if (dq.cwiseAbs().maxCoeff() <= 1e-12 && std::abs(x) <= 1e-12) {
      out.converged = true;
      return out;
    }
  }
  q = q0;
  lambda = l0;
  s = s0;
  return out;
}

}  // namespace

bool use_natural_statics(const ring::MultibodyOptions& options) {
  switch (options.method) {
    case ring::MultibodyOptions::Method::dense: return false;
    case ring::MultibodyOptions::Method::sparse: return true;
    default: return options.n >= kSparseStaticsCrossover;
  }
}

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::StaticOptions& statics) {
  check_static(spec, options, statics);
  const Chain ch(spec, options, statics.load.angle);
  const int n = ch.dofs();
  const detail::DeadLoad load{ch.hinge_at(statics.load.angle),
                              {statics.load.force[0], statics.load.force[1]}};
  std::vector<int> rec;
  for (double a : statics.record) rec.push_back(ch.hinge_at(a));
  const int gap = detail::contact_gap(ch, spec.section.depth());
  if (backend(options, Analysis::statics) == Backend::banded) return natural::solve_static(ch, spec, statics);
  // The dense path's n x n stiffness, built only here: before the O(n) path's dispatch it
  // was allocated there too (80 GB at n = 10^5: std::bad_alloc at once).
  const Matrix K = ch.stiffness_matrix();

  Vector q = ch.q0(), lambda = Vector::Zero(ch.constraint_count());
  ring::StaticResult res;
  res.unknowns = ch.dofs() + ch.constraint_count();  // angles and multipliers of the Newton system
  double s = 0.0, ds = 1.0 / statics.steps;
  const double ds_min = 1e-6 / statics.steps;
  double s_limit = -1.0;  // load factor of the limit point, once one is met
  auto check_contact = [&](const Vector& qq, double at) {
    const auto cp = detail::closest_nonadjacent(ch.hinge_positions(qq), gap, spec.section.depth());
    if (cp.distance < spec.section.depth()) {
      std::ostringstream m;
      m << "multibody::solve_static: ";
      if (s_limit >= 0.0)
        m << "past a limit point at load factor " << s_limit << ", the equilibrium path (arc-"
          << "length continuation) reaches self-contact: ";
      m << "the ring touches itself at load factor " << at
        << ": " << detail::describe_contact(cp) << " (section depth " << spec.section.depth()
        << " m); the chain model does not include contact";
      throw ring::NumericalError(m.str());
    }
  };
  Vector last_dq;  // change of q over the last accepted step
  bool arc = false;
  while (!arc && s < 1.0 - 1e-14) {
    const double s1 = std::min(1.0, s + ds);
    Vector q1 = q, l1 = lambda;
    const NewtonOutcome o = newton(ch, load, K, s1, q1, l1);
    res.newton_iterations += o.iterations;
    if (!o.converged) {
      ds *= 0.5;
      if (ds < ds_min) arc = true;  // a limit point in the load: continue by arc length
      continue;
    }
    last_dq = q1 - q;
    q = q1;
    lambda = l1;
    s = s1;
    ++res.steps;
    check_contact(q, s);
  }
  if (arc) {
    // Arc-length continuation from the last equilibrium, through the limit point, until
    // the path comes back to the full load (s = 1); the length adapts to the iterations.
    double len = std::max(last_dq.size() ? last_dq.norm() : 0.0, 1e-3);
    const double len_min = 1e-9;
    s_limit = s;
    bool done = false;
    for (int k = 0; k < 20000 && !done; ++k) {
      Vector q1 = q, l1 = lambda;
      double s1 = s;
      const NewtonOutcome o = arc_step(ch, load, K, len, last_dq, q1, l1, s1);
      res.newton_iterations += o.iterations;
      if (!o.converged) {
        len *= 0.5;
        if (len < len_min) break;
        continue;
      }
      ++res.steps;
      check_contact(q1, s1);
      if ((s - 1.0) * (s1 - 1.0) <= 0.0) {
        // The path crosses the full load: finish with Newton at s = 1 from the
        // interpolated point.
        const double w = (1.0 - s) / (s1 - s);
        Vector qf = q + w * (q1 - q), lf = lambda + w * (l1 - lambda);
        const NewtonOutcome f = newton(ch, load, K, 1.0, qf, lf);
        res.newton_iterations += f.iterations;
        if (f.converged) {
          q = qf;
          lambda = lf;
          s = 1.0;
          done = true;
          check_contact(q, s);
          break;
        }
      }
      last_dq = q1 - q;
      q = q1;
      lambda = l1;
      s = s1;
      if (o.iterations <= 4) len = std::min(2.0 * len, 0.5);
    }
    if (!done) {
      std::ostringstream m;
      m << "multibody::solve_static: load stepping stopped at a limit point (load factor "
        << s_limit << "), and arc-length continuation did not find the path back to the "
        << "full load (reached load factor " << s << ")";
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
