// The analytic tangent of the nonlinear chain (multibody/dynamics_model.hpp) against
// central differences of multibody::Chain's own functions, at a random deformed,
// moving state. Oracle: the Chain (validated on its own by the modes tests) and the definition of the derivative.
#include <gtest/gtest.h>

#include <random>

#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"
#include "tests/multibody/common.hpp"

namespace {

using ringtest::pin_roller_ring;

using multibody::Chain;
using multibody::Matrix;
using multibody::Vector;

struct State {
  Vector q, v, a, lambda;
};

State random_state(const Chain& ch, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = ch.dofs();
  State s{ch.q0(), Vector(n), Vector(n), Vector(ch.constraint_count())};
  for (int i = 0; i < n; ++i) {
    s.q[i] += 0.2 * u(gen);
    s.v[i] = u(gen);
    s.a[i] = 3.0 * u(gen);
  }
  for (int i = 0; i < s.lambda.size(); ++i) s.lambda[i] = 1e4 * u(gen);
  return s;
}

/// Relative max-norm difference of two matrices.
double rel_diff(const Matrix& a, const Matrix& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// Central differences have truncation error O(h^2 |f'''|) and round-off O(eps |f| / h);
// with h = 1e-6 rad both are below 1e-7 relative for these O(1)-scaled functions.
constexpr double kFdStep = 1e-6;
constexpr double kFdTol = 1e-7;

/// inertia_terms on `spec`'s chain of 12 segments against finite differences of the chain's
/// own mass matrix and velocity products.
void expect_inertia_tangent_matches_finite_differences(const ring::RingSpec& spec) {
  ring::MultibodyOptions o;
  o.n = 12;
  const Chain ch(spec, o, 0.0);
  const State s = random_state(ch, 7);
  const int n = ch.dofs();
  auto f = [&](const Vector& q, const Vector& v) -> Vector {
    return ch.mass_matrix(q) * s.a + ch.quadratic_velocity(q, v);
  };
  Matrix fd_q(n, n), fd_v(n, n);
  for (int j = 0; j < n; ++j) {
    Vector qp = s.q, qm = s.q, vp = s.v, vm = s.v;
    qp[j] += kFdStep;
    qm[j] -= kFdStep;
    vp[j] += kFdStep;
    vm[j] -= kFdStep;
    fd_q.col(j) = (f(qp, s.v) - f(qm, s.v)) / (2 * kFdStep);
    fd_v.col(j) = (f(s.q, vp) - f(s.q, vm)) / (2 * kFdStep);
  }
  const auto in = multibody::detail::inertia_constants(ch);
  // T(cm, cv) = cm M + cv d xi/dv + d(M a + xi)/dq, so three evaluations separate the parts.
  Vector r;
  Matrix T00 = Matrix::Zero(n, n), T10 = T00, T01 = T00;
  multibody::detail::inertia_terms(in, s.q, s.v, s.a, 0.0, 0.0, r, &T00);
  multibody::detail::inertia_terms(in, s.q, s.v, s.a, 1.0, 0.0, r, &T10);
  multibody::detail::inertia_terms(in, s.q, s.v, s.a, 0.0, 1.0, r, &T01);
  EXPECT_LT(rel_diff(T00, fd_q), kFdTol);
  EXPECT_LT(rel_diff(T01 - T00, fd_v), kFdTol);
  // The mass matrix and the force itself: the chain's own, to round-off.
  EXPECT_LT(rel_diff(T10 - T00, ch.mass_matrix(s.q)), 1e-13);
  EXPECT_LT((r - f(s.q, s.v)).cwiseAbs().maxCoeff(), 1e-12 * f(s.q, s.v).cwiseAbs().maxCoeff());
}

TEST(MultibodyDynamicsModel, InertiaTangentMatchesFiniteDifferences) {
  expect_inertia_tangent_matches_finite_differences(pin_roller_ring());
}

// A free chain (no pin: the first hinge's translation is two more coordinates, whose
// inertia couples to each angle through sin and cos of that angle alone): the same oracle.
// The angles' cosine structure applied to the translation gave the free tyre ring a peak
// 24 % high (tests/compare/test_nonlinear_cli.cpp).
TEST(MultibodyDynamicsModel, InertiaTangentOfAFreeChainMatchesFiniteDifferences) {
  ring::RingSpec free_ring = pin_roller_ring();
  free_ring.supports = {};
  free_ring.foundation.radial = 1e4;  // holds the ring (the chain needs nothing of it here)
  expect_inertia_tangent_matches_finite_differences(free_ring);
}

TEST(MultibodyDynamicsModel, ConstraintAndLoadTangentsMatchFiniteDifferences) {
  ring::MultibodyOptions o;
  o.n = 12;
  const Chain ch(pin_roller_ring(), o, 0.0);
  const State s = random_state(ch, 11);
  const int n = ch.dofs();
  const multibody::detail::DeadLoad load{ch.hinge_at(0.0), {-2e4, 3e3}};
  auto gtl = [&](const Vector& q) -> Vector {
    return ch.constraint_jacobian(q).transpose() * s.lambda;
  };
  auto phi = [&](const Vector& q) -> Vector { return ch.point_load_forces(q, load.hinge, load.force); };
  Matrix fd_g(n, n), fd_p(n, n);
  for (int j = 0; j < n; ++j) {
    Vector qp = s.q, qm = s.q;
    qp[j] += kFdStep;
    qm[j] -= kFdStep;
    fd_g.col(j) = (gtl(qp) - gtl(qm)) / (2 * kFdStep);
    fd_p.col(j) = (phi(qp) - phi(qm)) / (2 * kFdStep);
  }
  const auto k = multibody::detail::evaluate(ch, s.q);
  Matrix hg = Matrix::Zero(n, n);
  hg.diagonal() = k.hess_g.transpose() * s.lambda;
  EXPECT_LT(rel_diff(hg, fd_g), kFdTol);
  Vector p, dp;
  multibody::detail::load_forces(ch, load, s.q, p, &dp);
  Matrix dpm = Matrix::Zero(n, n);
  dpm.diagonal() = dp;
  EXPECT_LT(rel_diff(dpm, fd_p), kFdTol);
}

TEST(MultibodyDynamicsModel, ClosestPairFindsCrossingAndClearance) {
  // A square of side 2 with one vertex pushed through the opposite side.
  Eigen::Matrix2Xd p(2, 6);
  p << 0, 1, 2, 2, 1, 0,  //
      0, 0, 0, 2, 2, 2;
  auto cp = multibody::detail::closest_nonadjacent(p, 2, 10.0);
  EXPECT_NEAR(cp.distance, 1.0, 1e-14);  // segments 0 and 2 meet the corner (2,0) 1 apart
  p(1, 1) = 3.0;                          // vertex 1 crosses the top side
  cp = multibody::detail::closest_nonadjacent(p, 2, 10.0);
  EXPECT_EQ(cp.distance, 0.0);
}

}  // namespace
