// The O(n) path of the forced response (multibody/dynamics_sparse.hpp).
// Oracles: the dense path's own pieces (the O(n^2) tangent of dynamics_model.hpp, a
// dense LU of the assembled saddle-point matrix, the O(n^2) contact loop) and the
// dense path's whole time histories on the paper's 20 kN scene.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>

#include "multibody/backend.hpp"
#include "multibody/chain.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "tests/support/close.hpp"
#include "tests/multibody/common.hpp"

namespace {

using mbtest::sci;
using ringtest::pin_roller_ring;

using multibody::Matrix;
using multibody::Vector;
using Integrator = ring::ResponseOptions::Integrator;

ring::ResponseOptions paper_scene(Integrator integrator, double t_end = 5.0) {
  return mbtest::forced_scene(integrator, t_end);
}

ring::MultibodyOptions opts(int n, ring::MultibodyOptions::Method m) {
  ring::MultibodyOptions o;
  o.n = n;
  o.method = m;
  return o;
}

// The structured inertia force and tangent equal the dense ones of dynamics_model.hpp
// entry by entry at a random state. Tolerance 1e-12 of the largest entry: both sum n
// terms of size max|entry| in a different order (n = 12: round-off ~ 1e-15 each).
TEST(MultibodySparseDynamics, StructuredTangentEqualsDenseTangent) {
  for (bool rotary : {true, false}) {
    ring::MultibodyOptions o;
    o.n = 12;
    o.rotary_inertia = rotary;
    const multibody::Chain ch(pin_roller_ring(), o, 0.0);
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = ch.n();
    Vector q = ch.phi0(), v(n), a(n);
    for (int i = 0; i < n; ++i) {
      q[i] += 0.3 * u(gen);
      v[i] = 2.0 * u(gen);
      a[i] = 5.0 * u(gen);
    }
    const double cm = 4e4, cv = 200.0;  // 1/(beta h^2), gamma/(beta h) at h = 0.01
    Vector r_dense, r_sparse;
    Matrix T_dense = Matrix::Zero(n, n);
    multibody::detail::inertia_terms(multibody::detail::inertia_constants(ch), q, v, a, cm, cv,
                                     r_dense, &T_dense);
    multibody::detail::StructuredMatrix T;
    multibody::detail::inertia_terms_structured(ch, q, v, a, cm, cv, r_sparse, &T);
    const Matrix T_sparse = T.dense();
    const double rscale = r_dense.cwiseAbs().maxCoeff(), tscale = T_dense.cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i) {
      EXPECT_TRUE(ringtest::IsClose(r_sparse[i], r_dense[i], 0.0, 1e-12 * rscale)) << i;
      for (int j = 0; j < n; ++j)
        EXPECT_TRUE(ringtest::IsClose(T_sparse(i, j), T_dense(i, j), 0.0, 1e-12 * tscale))
            << i << "," << j;
    }
    EXPECT_TRUE((T.diagonal() - T_sparse.diagonal()).cwiseAbs().maxCoeff() <= 1e-12 * tscale);
    // The structured mass matrix is the chain's own mass_matrix.
    const Matrix M = multibody::detail::mass_structured(ch, q).dense(), M_ref = ch.mass_matrix(q);
    EXPECT_LE((M - M_ref).cwiseAbs().maxCoeff(), 1e-12 * M_ref.cwiseAbs().maxCoeff());
  }
}

// The sparse saddle-point solve equals a dense LU of [T sG^T; sG 0] built from T.dense().
// Tolerance 1e-10 relative: the dense LU's own error bound kappa * eps with kappa of the
// scaled system ~ 1e4-1e5 at n = 50 (measured by Eigen's rcond estimate below).
TEST(MultibodySparseDynamics, SaddleSolveEqualsDenseLU) {
  ring::MultibodyOptions o;
  o.n = 50;
  const multibody::Chain ch(pin_roller_ring(), o, 0.0);
  const int n = ch.n(), c = ch.constraint_count();
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vector q = ch.phi0(), v(n), a(n), b(n);
  for (int i = 0; i < n; ++i) {
    q[i] += 0.2 * u(gen);
    v[i] = u(gen);
    a[i] = u(gen);
    b[i] = u(gen) * 1e5;
  }
  multibody::detail::StructuredMatrix T;
  Vector r;
  multibody::detail::inertia_terms_structured(ch, q, v, a, 4e4, 200.0, r, &T);
  T.cyclic = ch.K();
  // A second term, as mass-proportional damping adds.
  auto M0 = multibody::detail::mass_structured(ch, ch.q0());
  M0.terms[0].coef *= 3.0;
  T.terms.push_back(M0.terms[0]);
  const Matrix G = ch.constraint_jacobian(q);
  const double sc = T.diagonal().cwiseAbs().maxCoeff() / ch.l();
  const Vector d = Vector::Random(c) * 1e-3;
  multibody::detail::SparseSaddle lu;
  ASSERT_TRUE(lu.factor(T, G, sc));
  Vector x, y;
  ASSERT_TRUE(lu.solve(b, d, x, y));
  Matrix A = Matrix::Zero(n + c, n + c);
  A.topLeftCorner(n, n) = T.dense();
  A.topRightCorner(n, c) = sc * G.transpose();
  A.bottomLeftCorner(c, n) = sc * G;
  Vector rhs(n + c);
  rhs << b, d;
  const Vector ref = A.partialPivLu().solve(rhs);
  EXPECT_LE((x - ref.head(n)).cwiseAbs().maxCoeff(), 1e-10 * ref.head(n).cwiseAbs().maxCoeff());
  EXPECT_LE((y - ref.tail(c)).cwiseAbs().maxCoeff(), 1e-10 * ref.tail(c).cwiseAbs().maxCoeff());
  RecordProperty("assembled_nonzeros", std::to_string(lu.nonzeros()));
  RecordProperty("factor_nonzeros", std::to_string(lu.factor_nonzeros()));
  // Several right-hand sides at once (the partitioned step's correction columns): the
  // same operations as one by one, so the same result to round-off of the Schur step.
  Matrix B(n, 3), X, Y;
  for (int k = 0; k < 3; ++k) B.col(k) = b * (k + 1.0) + Vector::Constant(n, 1e3 * k);
  ASSERT_TRUE(lu.solve_columns(B, Matrix::Zero(c, 3), X, Y));
  for (int k = 0; k < 3; ++k) {
    ASSERT_TRUE(lu.solve(B.col(k), Vector::Zero(c), x, y));
    EXPECT_LE((X.col(k) - x).cwiseAbs().maxCoeff(), 1e-13 * x.cwiseAbs().maxCoeff()) << k;
    EXPECT_LE((Y.col(k) - y).cwiseAbs().maxCoeff(), 1e-13 * y.cwiseAbs().maxCoeff()) << k;
  }
}

// The grid contact search returns exactly what the O(n^2) loop returns, on rings
// squeezed flat (many near pairs), crossing, and wavy.
TEST(MultibodySparseDynamics, GridContactEqualsBruteForce) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {16, 64, 257, 1000}) {
    for (int trial = 0; trial < 20; ++trial) {
      const double l = 2.0 * M_PI / n;
      // A closed polygon: an ellipse of aspect down to 0.002 (near-touching flanks),
      // perturbed; the contact code does not need equal lengths, the grid needs
      // segments no longer than l_max, so pass the measured maximum.
      const double aspect = trial < 10 ? 0.002 + 0.05 * trial : 0.5;
      Eigen::Matrix2Xd p(2, n);
      for (int k = 0; k < n; ++k) {
        const double t = 2.0 * M_PI * k / n;
        p.col(k) = Eigen::Vector2d(std::cos(t), aspect * std::sin(t)) +
                   0.3 * l * Eigen::Vector2d(u(gen), u(gen));
      }
      double lmax = 0.0;
      for (int k = 0; k < n; ++k) lmax = std::max(lmax, (p.col((k + 1) % n) - p.col(k)).norm());
      for (double reach : {0.001, 0.02, 0.1}) {
        const int gap = 2 + trial % 3;
        const auto a = multibody::detail::closest_nonadjacent(p, gap, reach);
        const auto b = multibody::detail::closest_nonadjacent_grid(p, lmax, gap, reach);
        EXPECT_EQ(a.distance, b.distance) << n << " " << trial << " " << reach;
        EXPECT_EQ(a.i, b.i);
        EXPECT_EQ(a.j, b.j);
      }
    }
  }
}

/// Largest difference of two histories' recorded quantities, each relative to the
/// dense run's peak of that quantity.
struct Diff {
  double u = 0.0, energy = 0.0;
  double max_g = 0.0;
};
Diff compare(const ring::TimeHistory& a, const ring::TimeHistory& b) {
  Diff d;
  double peak_u = 0.0, peak_e = 0.0;
  for (size_t p = 0; p < b.ux.size(); ++p)
    for (size_t i = 0; i < b.t.size(); ++i)
      peak_u = std::max(peak_u, std::hypot(b.ux[p][i], b.uy[p][i]));
  for (size_t i = 0; i < b.t.size(); ++i) peak_e = std::max(peak_e, b.work[i]);
  for (size_t p = 0; p < b.ux.size(); ++p)
    for (size_t i = 0; i < b.t.size(); ++i)
      d.u = std::max(d.u, std::hypot(a.ux[p][i] - b.ux[p][i], a.uy[p][i] - b.uy[p][i]) / peak_u);
  for (size_t i = 0; i < b.t.size(); ++i) {
    d.energy = std::max({d.energy, std::abs(a.kinetic[i] - b.kinetic[i]) / peak_e,
                         std::abs(a.strain[i] - b.strain[i]) / peak_e,
                         std::abs(a.work[i] - b.work[i]) / peak_e});
    d.max_g = std::max(d.max_g, a.constraint_residual[i]);
  }
  return d;
}

// The sparse path reproduces the dense path's whole history of the paper's 20 kN scene
// (n = 40 and 160, 5 s, both integrators). Both solve the same discrete equations; each
// step stops when the Newton correction is <= tol_q = 1e-9 rad, so a converged state
// may differ from the exact discrete solution by about that (x R = 1e-8 m in the
// displacements, against peaks of ~1 m). Tolerance 1e-8 of the peak displacement and of
// the peak work: one Newton tolerance. (Measured: ~4e-12, because the two paths take the
// same iterates up to round-off; recorded as properties.) A wrong tangent changes the
// iterates and a wrong residual the solution, each by orders more.
class SparseVsDense : public ::testing::TestWithParam<std::tuple<int, Integrator>> {};
TEST_P(SparseVsDense, PaperSceneHistoriesAgree) {
  const auto [n, integrator] = GetParam();
  const ring::ResponseOptions r = paper_scene(integrator);
  const auto dense = multibody::respond(pin_roller_ring(), opts(n, ring::MultibodyOptions::Method::dense), r);
  const auto sparse = multibody::respond(pin_roller_ring(), opts(n, ring::MultibodyOptions::Method::sparse), r);
  ASSERT_EQ(dense.t.size(), sparse.t.size());
  const Diff d = compare(sparse, dense);
  RecordProperty("max_rel_displacement_diff", sci(d.u));
  RecordProperty("max_rel_energy_diff", sci(d.energy));
  RecordProperty("max_constraint_residual_m", sci(d.max_g));
  EXPECT_LE(d.u, 1e-8);
  EXPECT_LE(d.energy, 1e-8);
  EXPECT_LT(d.max_g, 1e-10);  // the specified constraint tolerance (m), every step
  EXPECT_EQ(dense.snapshot_t, sparse.snapshot_t);
  ASSERT_EQ(dense.snapshot_x.size(), sparse.snapshot_x.size());
  // Energy balance error agrees to the same level relative to the work.
  double peak_w = 0.0;
  for (double w : dense.work) peak_w = std::max(peak_w, w);
  for (size_t i = 0; i < dense.t.size(); ++i)
    EXPECT_TRUE(ringtest::IsClose(sparse.energy_error[i], dense.energy_error[i], 0.0, 1e-8 * peak_w));
}
INSTANTIATE_TEST_SUITE_P(PaperScene, SparseVsDense,
                         ::testing::Combine(::testing::Values(40, 160),
                                            ::testing::Values(Integrator::newmark,
                                                              Integrator::generalized_alpha)));

// Damping (Rayleigh mass and stiffness, hinge dampers) takes the extra structured term;
// same histories as the dense path (tolerance: one Newton tolerance, as above).
TEST(MultibodySparseDynamics, DampedSceneAgrees) {
  for (Integrator integ : {Integrator::newmark, Integrator::generalized_alpha}) {
    ring::ResponseOptions r = paper_scene(integ, 2.0);
    r.rayleigh_mass = 0.5;
    r.rayleigh_stiffness = 1e-3;
    r.hinge_damping = 1e4;
    const auto dense = multibody::respond(pin_roller_ring(), opts(40, ring::MultibodyOptions::Method::dense), r);
    const auto sparse = multibody::respond(pin_roller_ring(), opts(40, ring::MultibodyOptions::Method::sparse), r);
    const Diff d = compare(sparse, dense);
    EXPECT_LE(d.u, 1e-8);
    EXPECT_LE(d.energy, 1e-8);
    EXPECT_LT(d.max_g, 1e-10);  // the specified constraint tolerance (m), every step
  }
}

// Constant loads beyond the one point load (two point loads, gravity on the ring, dead
// pressure: constant hinge forces, loading.hpp) on the O(n) path: the generalized forces by
// suffix sums and their stiffness, diagonal in the angles, in the structured tangent. Same
// histories as the dense path's (which assembles Loading's full Hessian; tolerance one Newton
// tolerance, as above); "auto" takes the O(n) path for them from the crossover on.
TEST(MultibodySparseDynamics, ConstantLoadsHistoriesAgree) {
  for (Integrator integ : {Integrator::newmark, Integrator::generalized_alpha}) {
    ring::ResponseOptions r = paper_scene(integ, 2.0);
    r.loads.points.push_back({90.0, {0.0, 5e3}});
    r.loads.gravity = {0.0, -2.0};
    r.loads.pressure = {500.0, ring::Pressure::Kind::dead};
    for (int n : {40, 160}) {
      const auto dense = multibody::respond(pin_roller_ring(), opts(n, ring::MultibodyOptions::Method::dense), r);
      const auto sparse = multibody::respond(pin_roller_ring(), opts(n, ring::MultibodyOptions::Method::sparse), r);
      ASSERT_EQ(dense.t.size(), sparse.t.size());
      const Diff d = compare(sparse, dense);
      RecordProperty("max_rel_displacement_diff_" + std::to_string(n), sci(d.u));
      EXPECT_LE(d.u, 1e-8) << n;
      EXPECT_LE(d.energy, 1e-8) << n;
      EXPECT_LT(d.max_g, 1e-10) << n;
    }
    EXPECT_EQ(multibody::backend(opts(multibody::kSparseResponseCrossover, ring::MultibodyOptions::Method::automatic),
                                 pin_roller_ring(), r.loads, multibody::Analysis::response),
              multibody::Backend::banded);
  }
}

// Follower and central pressure have a load stiffness that is not diagonal in the angles: a
// forced O(n) path refuses them by key, "auto" stays dense.
TEST(MultibodySparseDynamics, ShapeDependentPressureStaysDense) {
  for (auto kind : {ring::Pressure::Kind::follower, ring::Pressure::Kind::central}) {
    ring::ResponseOptions r = paper_scene(Integrator::newmark, 0.1);
    r.loads.pressure = {500.0, kind};
    EXPECT_EQ(multibody::backend(opts(1000, ring::MultibodyOptions::Method::automatic), pin_roller_ring(), r.loads,
                                 multibody::Analysis::response),
              multibody::Backend::dense);
    try {
      multibody::respond(pin_roller_ring(), opts(40, ring::MultibodyOptions::Method::sparse), r);
      ADD_FAILURE() << "the O(n) response took a shape-dependent pressure";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("response.pressure"), std::string::npos) << e.what();
    }
  }
}

// Self-contact is reported the same way on both paths (the crushing load of
// 150 kN on the paper's scene, test_dynamics_stress.cpp), at n = 40 (O(n^2) contact loop) and n = 160 (grid):
// same reason, same step. With Newmark: under this load generalized-alpha gains more
// than 1 % of the work before the ring closes, which is now a failure of its own
// (energy_growth, tested in test_dynamics_sparse_stress.cpp).
TEST(MultibodySparseDynamics, SelfContactReportedOnBothPaths) {
  for (int n : {40, 160}) {
    ring::ResponseOptions r = paper_scene(Integrator::newmark, 5.0);
    r.loads.points.at(0).force = {-150e3, 0.0};
    double t_dense = -1, t_sparse = -2;
    try {
      multibody::respond(pin_roller_ring(), opts(n, ring::MultibodyOptions::Method::dense), r);
    } catch (const multibody::IntegrationFailure& f) {
      EXPECT_EQ(f.reason(), multibody::IntegrationFailure::Reason::self_contact);
      t_dense = f.t_reached();
    }
    try {
      multibody::respond(pin_roller_ring(), opts(n, ring::MultibodyOptions::Method::sparse), r);
    } catch (const multibody::IntegrationFailure& f) {
      EXPECT_EQ(f.reason(), multibody::IntegrationFailure::Reason::self_contact);
      t_sparse = f.t_reached();
    }
    EXPECT_EQ(t_dense, t_sparse) << n;
    EXPECT_GT(t_dense, 0.0) << n;
  }
}

TEST(MultibodySparseDynamics, AutomaticChoosesByCrossover) {
  auto banded = [](const ring::MultibodyOptions& o) {
    return multibody::backend(o, multibody::Analysis::response) == multibody::Backend::banded;
  };
  EXPECT_FALSE(banded(opts(40, ring::MultibodyOptions::Method::automatic)));
  EXPECT_TRUE(banded(
      opts(multibody::kSparseResponseCrossover, ring::MultibodyOptions::Method::automatic)));
  EXPECT_TRUE(banded(opts(40, ring::MultibodyOptions::Method::sparse)));
  EXPECT_FALSE(banded(opts(4000, ring::MultibodyOptions::Method::dense)));
}

}  // namespace
