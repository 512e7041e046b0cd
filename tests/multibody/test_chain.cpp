// Chain kinematics and dynamics terms against independent oracles: finite differences
// of the positions (velocities, Jacobians), of the energies (forces), and the geometry
// of the regular n-gon. Oracles never use the quantity under test.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "multibody/chain.hpp"
#include "support/paper.hpp"
#include "tests/support/close.hpp"

namespace {

using multibody::Chain;
using multibody::Matrix;
using multibody::Vector;

/// The paper's ring, pinned at 180 deg or free.
ring::RingSpec pinned_or_free(bool pinned) { return pinned ? ringtest::pinned_ring() : ringtest::free_ring(); }

ring::MultibodyOptions opts(int n, bool rot = true) {
  ring::MultibodyOptions o;
  o.n = n;
  o.rotary_inertia = rot;
  return o;
}

// A deformed configuration: rest plus a fixed-seed random perturbation of 0.3 rad.
Vector perturbed(const Chain& c, unsigned seed, double amp = 0.3) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-amp, amp);
  Vector q = c.q0();
  for (int i = 0; i < q.size(); ++i) q[i] += u(g);
  return q;
}

// Central difference step: h = 1e-6 balances truncation (h^2) and rounding (eps/h):
// errors ~1e-10 relative, hence the 1e-7 tolerances below.
constexpr double kH = 1e-6;
constexpr double kFd = 1e-7;

TEST(MultibodyChain, RestGeometryIsTheRegularPolygon) {
  for (bool pinned : {true, false}) {
    // The free ring's hinge 0 at its free_anchor (what the scene reader sets from a load at 30).
    ring::RingSpec spec = pinned_or_free(pinned);
    if (!pinned) spec.free_anchor = 30.0;
    const Chain c(spec, opts(40), pinned ? std::nullopt : std::optional<double>(30.0));
    const Vector q = c.q0();
    const auto p = c.hinge_positions(q);
    const double rp = c.l() / (2.0 * std::sin(M_PI / c.n()));
    for (int k = 0; k < c.n(); ++k) {
      const double a = (pinned ? 180.0 : 30.0) + 360.0 * k / c.n();
      EXPECT_TRUE(ringtest::IsClose(p(0, k), rp * std::cos(a * M_PI / 180), 0, 1e-12 * rp));
      EXPECT_TRUE(ringtest::IsClose(p(1, k), rp * std::sin(a * M_PI / 180), 0, 1e-12 * rp));
    }
    // closure gap vanishes at rest (rounding of n unit vectors: 1e-12 of the perimeter)
    EXPECT_LT(c.closure(q).norm(), 1e-12 * c.n() * c.l());
    // perimeter equals the circumference (definition of l)
    EXPECT_TRUE(ringtest::IsClose(c.n() * c.l(), 2 * M_PI * 10.0, 1e-15));
  }
}

TEST(MultibodyChain, MassMatrixIsTheKineticEnergyOfMidpointVelocities) {
  for (bool pinned : {true, false}) {
    const Chain c(pinned_or_free(pinned), opts(12));
    const Vector q = perturbed(c, 7);
    const Vector qd = perturbed(c, 8, 1.0) - c.q0();
    // Oracle: midpoint velocities by central differences of midpoints(), plus Jr qd^2.
    const auto xp = c.midpoints(q + kH * qd), xm = c.midpoints(q - kH * qd);
    const Eigen::Matrix2Xd v = (xp - xm) / (2 * kH);
    double T = 0.0;
    for (int i = 0; i < c.n(); ++i) T += 0.5 * c.m() * v.col(i).squaredNorm() + 0.5 * c.Jr() * qd[i] * qd[i];
    const Matrix M = c.mass_matrix(q);
    EXPECT_TRUE(ringtest::IsClose(0.5 * qd.dot(M * qd), T, kFd));
    EXPECT_TRUE(ringtest::IsClose(c.kinetic_energy(q, qd), T, kFd));
    EXPECT_LT((c.mass_times(q, qd) - M * qd).norm(), 1e-13 * (M * qd).norm());
    EXPECT_LT((M - M.transpose()).norm(), 1e-15 * M.norm());
  }
}

// M(q) times several columns at once (the Newmark step's correction columns) against
// the dense mass matrix, pinned and free.
TEST(MultibodyChain, MassTimesColumnsEqualsTheMassMatrix) {
  for (bool pinned : {true, false}) {
    const Chain c(pinned_or_free(pinned), opts(10));
    const Vector q = perturbed(c, 41);
    const Matrix V = Matrix::Random(c.dofs(), 3);
    const Matrix expect = c.mass_matrix(q) * V;
    EXPECT_LT((c.mass_times_columns(q, V) - expect).norm(), 1e-12 * expect.norm()) << (pinned ? "pinned" : "free");
  }
}

TEST(MultibodyChain, PaperMassMatrixEntries) {
  // The paper's eq. (12) with the corrected L^T L: (L^T L)_jj = n - j + 1/4 and
  // (L^T L)_jk = n - max(j,k) + 1/2 (1-based), times m l^2 cos(phi_j - phi_k).
  const Chain c(ringtest::pinned_ring(), opts(9, false));
  const Vector q = perturbed(c, 3);
  const Matrix M = c.mass_matrix(q);
  const int n = c.n();
  for (int j = 1; j <= n; ++j)
    for (int k = 1; k <= n; ++k) {
      const double lt = j == k ? n - j + 0.25 : n - std::max(j, k) + 0.5;
      EXPECT_TRUE(ringtest::IsClose(M(j - 1, k - 1), c.m() * c.l() * c.l() * lt * std::cos(q[j - 1] - q[k - 1]), 1e-14, 1e-14 * c.m() * c.l() * c.l()));
    }
}

TEST(MultibodyChain, QuadraticVelocityFromLagrange) {
  for (bool pinned : {true, false}) {
    const Chain c(pinned_or_free(pinned), opts(10));
    const Vector q = perturbed(c, 11);
    const Vector qd = perturbed(c, 12, 1.0) - c.q0();
    // c = Mdot qd - (1/2) d/dq (qd^T M qd), both by central differences of mass_matrix.
    const Matrix Mdot = (c.mass_matrix(q + kH * qd) - c.mass_matrix(q - kH * qd)) / (2 * kH);
    Vector grad(c.dofs());
    for (int i = 0; i < c.dofs(); ++i) {
      Vector dq = Vector::Zero(c.dofs());
      dq[i] = kH;
      grad[i] = (qd.dot(c.mass_matrix(q + dq) * qd) - qd.dot(c.mass_matrix(q - dq) * qd)) / (2 * kH);
    }
    const Vector expect = Mdot * qd - 0.5 * grad;
    EXPECT_LT((c.quadratic_velocity(q, qd) - expect).norm(), kFd * expect.norm());
  }
}

TEST(MultibodyChain, ForcesAndJacobiansByFiniteDifferences) {
  ring::RingSpec s = ringtest::pinned_ring();
  s.supports.roller = 0.0;
  const Chain c(s, opts(10));
  ASSERT_EQ(c.roller_hinge().value_or(-1), 5);
  const Vector q = perturbed(c, 21);
  const Vector qd = perturbed(c, 22, 1.0) - c.q0();
  const Eigen::Vector2d F(-2e4, 3e3);
  const int k = 4;
  Vector fs(c.dofs()), fl(c.dofs());
  Matrix J(c.constraint_count(), c.dofs());
  for (int i = 0; i < c.dofs(); ++i) {
    Vector dq = Vector::Zero(c.dofs());
    dq[i] = kH;
    fs[i] = (c.spring_energy(q + dq) - c.spring_energy(q - dq)) / (2 * kH);
    fl[i] = F.dot(c.hinge_position(q + dq, k) - c.hinge_position(q - dq, k)) / (2 * kH);
    J.col(i) = (c.constraints(q + dq) - c.constraints(q - dq)) / (2 * kH);
  }
  EXPECT_LT((c.spring_forces(q) - fs).norm(), kFd * fs.norm());
  EXPECT_LT((c.spring_forces(q) - c.stiffness_matrix() * (q - c.q0())).norm(), 1e-12 * fs.norm());
  EXPECT_LT((c.point_load_forces(q, k, F) - fl).norm(), kFd * fl.norm());
  EXPECT_LT((c.constraint_jacobian(q) - J).norm(), kFd * J.norm());
  // Jdot qd = d/dt (J qd) at fixed qd along q + t qd.
  const Vector jd = (c.constraint_jacobian(q + kH * qd) * qd - c.constraint_jacobian(q - kH * qd) * qd) / (2 * kH);
  EXPECT_LT((c.constraint_jdot_qdot(q, qd) - jd).norm(), kFd * jd.norm());
  // The roller holds hinge 5 (0 deg) on the x axis through the pin (180 deg): at rest h = 0.
  EXPECT_LT(std::abs(c.roller(c.q0())), 1e-12 * c.l());
}

// constraint_kinematics (one pass of sines and cosines) against the separate functions,
// bit for bit (the same operations), and its Hessians against central differences of
// constraint_jacobian: pinned with a roller, and free (closure only, x_0 and y_0 as
// unknowns).
TEST(MultibodyChain, ConstraintKinematicsInOnePass) {
  for (bool pinned : {true, false}) {
    ring::RingSpec s = pinned_or_free(pinned);
    if (pinned) s.supports.roller = 0.0;
    const Chain c(s, opts(10));
    ASSERT_EQ(c.constraint_count(), pinned ? 3 : 2);
    ASSERT_EQ(c.dofs(), pinned ? 10 : 12);
    const Vector q = perturbed(c, 31);
    const Chain::ConstraintKinematics k = c.constraint_kinematics(q);
    EXPECT_EQ(k.g, c.constraints(q));
    EXPECT_EQ(k.G, c.constraint_jacobian(q));
    Matrix H(c.constraint_count(), c.dofs());
    for (int j = 0; j < c.dofs(); ++j) {
      Vector dq = Vector::Zero(c.dofs());
      dq[j] = kH;
      H.col(j) = (c.constraint_jacobian(q + dq).col(j) - c.constraint_jacobian(q - dq).col(j)) / (2 * kH);
    }
    EXPECT_LT((k.hess - H).norm(), kFd * H.norm()) << (pinned ? "pinned" : "free");
  }
}

TEST(MultibodyChain, RejectsWhatCanNeverWork) {
  EXPECT_THROW(Chain(ringtest::pinned_ring(), opts(3)), std::invalid_argument);
  ring::RingSpec s = ringtest::pinned_ring();
  s.supports.roller = 1.0;  // not a hinge of the 40-gon anchored at 180 deg
  EXPECT_THROW(Chain(s, opts(40)), std::invalid_argument);
  EXPECT_THROW(Chain(ringtest::pinned_ring(), opts(40), 181.0), std::invalid_argument);
  EXPECT_EQ(Chain(ringtest::pinned_ring(), opts(40), 0.0).hinge_at(0.0), 20);
}

}  // namespace
