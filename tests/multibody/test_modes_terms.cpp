// The O(n) linear modes with the terms beyond the paper's ring (hinge positions,
// multibody/position_modes.hpp): the foundation, translational and rotational springs, the
// clamp, further pins, point masses. Oracles: the dense path (segment angles: the same
// chain's pencil in other coordinates, assembled by linear_model.cpp and solved by a dense
// eigensolver), and at large n, where only the O(n) path runs, the closed form of the free
// inextensible ring on a Winkler foundation at the chain's order-2 error.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <string>
#include <vector>

#include "multibody/backend.hpp"
#include "multibody/checks.hpp"
#include "multibody/modes.hpp"
#include "ring/closed_form.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/paper.hpp"
#include "tests/multibody/common.hpp"

namespace {

using mbtest::chain_options;
using mbtest::foundation_spectrum;
using mbtest::on_foundation;
using Method = ring::MultibodyOptions::Method;

struct TermScene {
  std::string name;
  ring::RingSpec spec;
};

/// One scene per term, at EI/R^4-scaled stiffnesses where bending and the term both count.
/// Every point is a multiple of 18 deg from the pin at 180: a hinge for n = 40, 120, 300.
std::vector<TermScene> scenes() {
  std::vector<TermScene> out;
  const ring::RingSpec base = ringtest::pinned_ring(180.0);
  const double EI_R4 = base.EI() / std::pow(base.radius, 4), R = base.radius;
  const double ring_mass = 2.0 * M_PI * R * base.rhoA();
  {
    TermScene s{"kx, ky springs", base};
    s.spec.supports.springs = {{90.0, 30.0 * EI_R4 * R, 10.0 * EI_R4 * R, 0.0}, {0.0, 0.0, 50.0 * EI_R4 * R, 0.0}};
    out.push_back(s);
  }
  {
    TermScene s{"kr spring", ringtest::pin_roller_ring()};
    s.spec.supports.springs = {{90.0, 0.0, 0.0, 5.0 * base.EI() / R}};
    out.push_back(s);
  }
  {
    TermScene s{"clamp", base};
    s.spec.supports.clamp = 180.0;
    out.push_back(s);
  }
  {
    TermScene s{"two further pins", base};
    s.spec.supports.pins = {36.0, 270.0};
    out.push_back(s);
  }
  {
    TermScene s{"two point masses", ringtest::pin_roller_ring()};
    s.spec.masses = {{90.0, 0.05 * ring_mass, 0.0}, {306.0, 0.1 * ring_mass, 0.0}};
    out.push_back(s);
  }
  {
    TermScene s{"foundation on a pinned ring", base};
    s.spec.foundation = {20.0 * EI_R4, 5.0 * EI_R4};
    out.push_back(s);
  }
  out.push_back({"free ring on a foundation (tyre)", ringtest::tyre_ring()});
  return out;
}

/// The smallest cosine of the principal angles between the column spaces of A and B.
double subspace_cosine(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  const Eigen::MatrixXd qa = Eigen::HouseholderQR<Eigen::MatrixXd>(A).householderQ() *
                             Eigen::MatrixXd::Identity(A.rows(), A.cols());
  const Eigen::MatrixXd qb = Eigen::HouseholderQR<Eigen::MatrixXd>(B).householderQ() *
                             Eigen::MatrixXd::Identity(B.rows(), B.cols());
  return Eigen::JacobiSVD<Eigen::MatrixXd>(qa.transpose() * qb).singularValues().minCoeff();
}

struct DenseVsBanded : ::testing::TestWithParam<int> {};

// Frequencies to 1e-10 relative: the dense path's are accurate to ~1e-13 at these n
// (modes.hpp), the Lanczos's to ~(1e-10 nu)^2 / gap (modal/lanczos.hpp, tol 1e-10), the
// bordered band's rounding (measured <= 1e-12 here). Shapes: MAC, or for (near-)double
// pairs the squared cosines of the principal angles, > 1 - 1e-8 (an eigenvector's error is
// the eigenvalue's square root over the gap).
TEST_P(DenseVsBanded, EveryTermGivesTheDensePathsModes) {
  const int n = GetParam(), count = 11;
  for (const TermScene& s : scenes()) {
    SCOPED_TRACE(s.name + ", n = " + std::to_string(n));
    const multibody::ModalSolution dense = multibody::solve_modes(s.spec, chain_options(n, Method::dense), count);
    const multibody::ModalSolution banded = multibody::solve_modes(s.spec, chain_options(n, Method::sparse), count);
    ASSERT_EQ(std::get<std::string>(banded.result.model.at("method")), "sparse");
    ASSERT_EQ(banded.result.rigid_modes, dense.result.rigid_modes);
    ASSERT_EQ(banded.result.omega.size(), dense.result.omega.size());
    for (int k = 0; k < count; ++k)
      EXPECT_TRUE(ringtest::IsClose(banded.result.omega[k], dense.result.omega[k], 1e-10)) << "mode " << k + 1;
    // Clusters of frequencies within 1e-6: compared as subspaces, those that end before the
    // last mode computed (whose partner may be the next, not computed).
    for (int k = 0; k < count;) {
      int e = k + 1;
      while (e < count && dense.result.omega[e] - dense.result.omega[e - 1] < 1e-6 * dense.result.omega[e]) ++e;
      if (e == count) break;
      const double c = subspace_cosine(dense.dq.middleCols(k, e - k), banded.dq.middleCols(k, e - k));
      EXPECT_GT(c * c, 1.0 - 1e-8) << "modes " << k + 1 << " .. " << e;
      k = e;
    }
    EXPECT_LT(banded.backward_error, 1e-10);
    EXPECT_LT(banded.result.max_residual.value(), 1e-6);
  }
}

INSTANTIATE_TEST_SUITE_P(Segments, DenseVsBanded, ::testing::Values(40, 120, 300));


// Where the dense path cannot go: n = 2000 .. 16000 on the O(n) path alone, against
// ring::closed_form::ring_on_foundation_inextensional. The chain converges at order 2 in
// 1/n (tests/multibody/test_attachments.cpp at n = 40 .. 160): each doubling of n divides the
// error by 4, log2 of the ratio within 0.1 of 2 (the discretization error ~ (2 pi k / n)^2 / 12
// is 1e-6 .. 1e-9 here, far above the path's rounding).
TEST(MultibodyModesTerms, FreeRingOnAFoundationConvergesAtOrderTwoAtLargeN) {
  const ring::RingSpec spec = on_foundation();
  const int count = 9;  // k = 0 and the pairs k = 1 .. 4
  const std::vector<double> exact = foundation_spectrum(spec, count);
  const std::vector<int> ns{2000, 4000, 8000, 16000};
  std::vector<std::vector<double>> err;
  for (int n : ns) {
    const multibody::ModalSolution sol = multibody::solve_modes(spec, chain_options(n, Method::sparse), count);
    ASSERT_EQ(sol.result.rigid_modes, 0) << "the foundation holds every rigid motion";
    EXPECT_LT(sol.backward_error, 1e-10) << "n = " << n;
    std::vector<double> e;
    for (int i = 0; i < count; ++i) e.push_back(ringtest::rel(sol.result.omega[i], exact[i]));
    err.push_back(e);
  }
  for (int i = 0; i < count; ++i) {
    if (i == 1 || i == 2) {  // k = 1, the translations: lumped foundation and chain mass are exact for them
      EXPECT_LT(err.back()[i], 1e-10) << "mode " << i + 1;
      continue;
    }
    for (std::size_t j = 0; j + 1 < ns.size(); ++j)  // each refinement's two-point order
      EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(std::vector<int>{ns[j], ns[j + 1]}, {err[j][i], err[j + 1][i]}), 2.0,
                                      0.1))
          << "mode " << i + 1 << ", n = " << ns[j] << " -> " << ns[j + 1];
    RecordProperty("mode" + std::to_string(i + 1) + "_error_n16000", mbtest::sci(err.back()[i]));
  }
}

// "auto" takes the O(n) path for the terms from the modes' crossover on, and stays dense
// for what it lacks (backend.hpp, banded_modes_lacks): a point inertia, the Timoshenko chain.
TEST(MultibodyModesTerms, AutoTakesTheTermsFromTheCrossover) {
  using multibody::Backend;
  const int from = multibody::sparse_crossover(multibody::Analysis::modes);
  for (const TermScene& s : scenes()) {
    SCOPED_TRACE(s.name);
    EXPECT_EQ(multibody::backend(chain_options(from - 1, Method::automatic), s.spec, 10), Backend::dense);
    EXPECT_EQ(multibody::backend(chain_options(from, Method::automatic), s.spec, 10), Backend::banded);
    EXPECT_TRUE(multibody::banded_modes_lacks(s.spec).empty());
  }
  ring::RingSpec inertia = ringtest::pin_roller_ring();
  inertia.masses = {{90.0, 10.0, 0.0}, {270.0, 10.0, 1e-3}};
  EXPECT_EQ(multibody::backend(chain_options(10000, Method::automatic), inertia, 10), Backend::dense);
  ring::RingSpec thick = ringtest::tyre_ring();
  thick.theory = ring::Theory::timoshenko;
  EXPECT_EQ(multibody::backend(chain_options(10000, Method::automatic), thick, 10), Backend::dense);
}

// A forced "sparse" with what the O(n) modes lack is an input error (exit 2) naming the key.
TEST(MultibodyModesTerms, ForcedSparseRefusesAPointInertia) {
  ring::RingSpec spec = ringtest::pin_roller_ring();
  spec.masses = {{90.0, 10.0, 0.0}, {270.0, 10.0, 1e-3}};
  try {
    multibody::check_modes(spec, chain_options(400, Method::sparse));
    ADD_FAILURE() << "the O(n) modes took a point inertia";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("masses[2].inertia"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("multibody.method"), std::string::npos) << e.what();
  }
  // Its translational mass alone the O(n) path takes; "auto" and "dense" take the inertia.
  spec.masses[1].inertia = 0.0;
  EXPECT_NO_THROW(multibody::check_modes(spec, chain_options(400, Method::sparse)));
  spec.masses[1].inertia = 1e-3;
  EXPECT_NO_THROW(multibody::check_modes(spec, chain_options(400, Method::automatic)));
}

// Beyond kPositionModesMaxN the refined band solve in hinge positions no longer holds the
// low modes (position_modes.hpp): an input error naming multibody.n, forced or "auto"; the
// paper's ring keeps its angle path at any n.
TEST(MultibodyModesTerms, RefusesTheTermsBeyondItsPrecisionLimit) {
  const int most = multibody::kPositionModesMaxN;
  ASSERT_EQ(multibody::backend(chain_options(most + 2, Method::automatic), ringtest::tyre_ring(), 15), multibody::Backend::banded);
  EXPECT_NO_THROW(multibody::check_modes(ringtest::tyre_ring(), chain_options(most, Method::sparse)));
  for (Method m : {Method::sparse, Method::automatic}) {
    try {
      multibody::check_modes(ringtest::tyre_ring(), chain_options(most + 2, m));
      ADD_FAILURE() << "the O(n) modes took the terms beyond n = " << most;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("multibody.n = " + std::to_string(most)), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("foundation"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(multibody::check_modes(ringtest::pinned_ring(), chain_options(10 * most, Method::automatic)));
}

}  // namespace
