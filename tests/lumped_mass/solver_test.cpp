// The lumped-mass solver's own guarantees: eigen-residuals and mass-orthonormality
// (computed here with the assembled K, M, C, S, not with the solver's factored form),
// dense and sparse paths agreeing, the two derivations of the frame stiffness agreeing,
// rigid modes counted, invalid input rejected.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "lumped_mass/modes.hpp"
#include "ring/closed_form.hpp"
#include "ring/sampling.hpp"
#include "common.hpp"
#include "tests/support/close.hpp"

namespace {

using lumptest::kChain;
using lumptest::kConsistent;
using lumptest::kFrame;
using ring::LumpedOptions;
using Eigen::MatrixXd;
using Eigen::VectorXd;

/// "free", "pin", "roller": the paper's supports. With the terms beyond the paper (every
/// stiffness ~10-100 times the ring's own scale, so that each term matters):
/// "clamped_terms": pin + clamp at 180 deg, a spring (kx, ky, kr) at 90, a point mass with
/// inertia at 270, a radial + tangential foundation; "free_terms": no pin, the foundation,
/// a point mass with inertia at 0 deg and a kr spring at 90.
ring::RingSpec with_supports(const std::string& s) {
  ring::RingSpec spec = ringtest::free_ring();
  if (s != "free" && s != "free_terms") spec.supports.pin = 180.0;
  if (s == "roller") spec.supports.roller = 0.0;
  const double R = spec.radius, EI = spec.EI(), mass = 2.0 * M_PI * R * spec.rhoA();
  if (s == "clamped_terms") {
    spec.supports.clamp = 180.0;
    spec.supports.springs.push_back({90.0, 50.0 * EI / (R * R * R), 20.0 * EI / (R * R * R), 10.0 * EI / R});
    spec.masses.push_back({270.0, 0.05 * mass, 0.05 * mass * 0.5 * 0.5});
  }
  if (s == "free_terms") {
    spec.masses.push_back({0.0, 0.05 * mass, 0.05 * mass * 0.5 * 0.5});
    spec.supports.springs.push_back({90.0, 0.0, 0.0, 10.0 * EI / R});
  }
  if (s == "clamped_terms" || s == "free_terms") {
    spec.foundation.radial = 30.0 * EI / std::pow(R, 4);
    spec.foundation.tangential = 10.0 * EI / std::pow(R, 4);
  }
  return spec;
}

/// The eigenproblem's dimension counted by hand: inertial DOFs (chain n after its n link
/// rows, frame 2n translations plus a rotation carrying a point inertia, frame-consistent
/// 3n) minus the constraint rows: the paper's supports leave n - 3, 2n - 3, 3n - 3 elastic
/// modes plus the rigid ones; "clamped_terms" removes pin (2) and clamp (1 for
/// frame-consistent; for the lumped frame it blocks a massless rotation, for the chain it is
/// a spring), "free_terms" removes nothing.
int expected_unknowns(const std::string& s, LumpedOptions::Variant v, int n, int rigid) {
  const int per_node = v == kChain ? 1 : v == kFrame ? 2 : 3;
  // The point mass's rotation: kept by the lumped frame, an unknown of its own in the chain
  // (lumped_mass/model.hpp); the consistent frame has every rotation already.
  const int inertia = v == kFrame || v == kChain ? 1 : 0;
  if (s == "clamped_terms") return per_node * n - 2 - (v == kConsistent ? 1 : 0) + inertia;
  if (s == "free_terms") return per_node * n + inertia;
  return per_node * n - 3 + rigid;
}

std::string name(LumpedOptions::Variant v) {
  return v == kChain ? "chain" : v == kFrame ? "frame" : "frame_consistent";
}

struct Case {
  LumpedOptions::Variant variant;
  const char* supports;
  int n;
};

class LumpedSolver : public ::testing::TestWithParam<Case> {};

// Normwise backward error of each pair, eta = ||P (K x - lambda M x)|| /
// ((||K||_1 + lambda ||M||_1) ||x||) (Higham & Tisseur's backward error for the pencil,
// restricted to the admissible space by the orthogonal projector P onto null([C; S])),
// and ||X^T M X - I||_max. Both below 1e-10 (the solvers' specified accuracy): the dense and sparse
// paths are backward stable, so eta is a few eps; orthonormality is limited by the
// eigenvectors' rounding relative to the gaps (1e-12 measured for the free ring's
// exact double eigenvalues, whose basis Lanczos orthogonalizes explicitly).
TEST_P(LumpedSolver, ResidualsAndMassOrthonormality) {
  const Case c = GetParam();
  const ring::RingSpec spec = with_supports(c.supports);
  const lumped::Model m = lumped::assemble(spec, lumptest::options(c.n, c.variant));
  for (lumped::Method method : {lumped::Method::dense, lumped::Method::sparse}) {
    const lumped::Eigenpairs p = lumped::solve(m, 12, method);
    ASSERT_EQ(p.rigid, spec.rigid_modes());
    const MatrixXd K(m.K), M(m.M);
    MatrixXd CS(m.C.rows() + m.S.rows(), m.K.cols());
    CS << MatrixXd(m.C), MatrixXd(m.S);
    // Orthonormal basis of the constraint rows' span: P = I - Q Q^T.
    const MatrixXd Q = Eigen::HouseholderQR<MatrixXd>(CS.transpose()).householderQ() *
                       MatrixXd::Identity(CS.cols(), CS.rows());
    const double knorm = K.cwiseAbs().colwise().sum().maxCoeff(), mnorm = M.cwiseAbs().colwise().sum().maxCoeff();
    double worst_eta = 0.0, worst_drift = 0.0;
    for (int i = 0; i < p.X.cols(); ++i) {
      const VectorXd x = p.X.col(i);
      VectorXd r = K * x - p.lambda[i] * (M * x);
      r -= Q * (Q.transpose() * r);
      worst_eta = std::max(worst_eta, r.norm() / ((knorm + std::abs(p.lambda[i]) * mnorm) * x.norm()));
      worst_drift = std::max(worst_drift, (CS * x).norm() / x.norm());
    }
    const MatrixXd G = p.X.transpose() * M * p.X - MatrixXd::Identity(p.X.cols(), p.X.cols());
    std::printf("[lumped %s %s n=%d %s] backward error %.2e, constraint drift %.2e, |X^T M X - I| %.2e, "
                "solver max_residual %.2e\n",
                name(c.variant).c_str(), c.supports, c.n, method == lumped::Method::dense ? "dense" : "sparse",
                worst_eta, worst_drift, G.cwiseAbs().maxCoeff(), p.max_residual);
    EXPECT_LT(worst_eta, 1e-10);
    EXPECT_LT(worst_drift, 1e-10);  // constraints hold to rounding
    EXPECT_LT(G.cwiseAbs().maxCoeff(), 1e-10);
  }
}

// Dense (SVD of the factored stiffness) and sparse (shift-invert Lanczos on the mixed
// system) share only the model. 1e-10 relative: both are accurate to eps (R/l)^2 x a
// few (eigen.hpp), 1e-12 at n = 160; the rigid counts must match the supports.
TEST_P(LumpedSolver, DenseAndSparseAgree) {
  const Case c = GetParam();
  const ring::RingSpec spec = with_supports(c.supports);
  const LumpedOptions o = lumptest::options(c.n, c.variant);
  const ring::ModalResult d = lumped::compute_modes(spec, o, 12, lumped::Method::dense);
  const ring::ModalResult s = lumped::compute_modes(spec, o, 12, lumped::Method::sparse);
  EXPECT_EQ(std::get<std::string>(d.model.at("method")), "dense");
  EXPECT_EQ(std::get<std::string>(s.model.at("method")), "sparse");
  EXPECT_EQ(d.rigid_modes, spec.rigid_modes());
  EXPECT_EQ(s.rigid_modes, spec.rigid_modes());
  // The eigenproblem's dimension: admissible DOFs (expected_unknowns).
  EXPECT_EQ(d.unknowns, expected_unknowns(c.supports, c.variant, c.n, spec.rigid_modes()));
  EXPECT_EQ(s.unknowns, d.unknowns);
  ASSERT_EQ(d.omega.size(), 12u);
  ASSERT_EQ(s.omega.size(), 12u);
  for (int i = 0; i < 12; ++i) {
    EXPECT_TRUE(ringtest::IsClose(s.omega[i], d.omega[i], 1e-10)) << "mode " << i + 1;
    EXPECT_EQ(d.shapes[i].radial.size(), static_cast<std::size_t>(ring::kStations));
    // Supported rings have simple eigenvalues: the shapes must match too (MAC = cos^2
    // of the angle between them; 1e-8 allows eigenvector rounding ~1e-10 / gap).
    if (spec.supports.pin) {
      EXPECT_GT(ring::mac(d.shapes[i], s.shapes[i]), 1.0 - 1e-8) << "mode " << i + 1;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    All, LumpedSolver,
    ::testing::Values(Case{kChain, "free", 40}, Case{kChain, "pin", 40}, Case{kChain, "roller", 40},
                      Case{kFrame, "free", 40}, Case{kFrame, "pin", 40}, Case{kFrame, "roller", 40},
                      Case{kConsistent, "free", 40}, Case{kConsistent, "pin", 40}, Case{kConsistent, "roller", 40},
                      Case{kChain, "free", 160}, Case{kChain, "pin", 160}, Case{kFrame, "free", 160},
                      Case{kFrame, "pin", 160}, Case{kConsistent, "free", 160}, Case{kConsistent, "pin", 160},
                      Case{kChain, "clamped_terms", 40}, Case{kFrame, "clamped_terms", 40},
                      Case{kConsistent, "clamped_terms", 40}, Case{kChain, "free_terms", 40},
                      Case{kFrame, "free_terms", 40}, Case{kConsistent, "free_terms", 40},
                      Case{kChain, "clamped_terms", 160}, Case{kFrame, "free_terms", 160}),
    [](const ::testing::TestParamInfo<Case>& i) {
      return name(i.param.variant) + "_" + i.param.supports + "_n" + std::to_string(i.param.n);
    });

// The frame stiffness two ways: the textbook element matrices (EA/l, EI/l^3 [12 6l ...])
// assembled in K, and B^T diag(D) B from the Gauss-point curvatures the solvers use.
// Equal to rounding (1e-12 of the largest entry): two-point Gauss is exact for the
// linear curvature's quadratic energy.
TEST(LumpedModel, FactoredStiffnessEqualsAssembled) {
  for (auto v : {kChain, kFrame, kConsistent}) {
    const lumped::Model m = lumped::assemble(ringtest::pinned_ring(), lumptest::options(12, v));
    const MatrixXd K(m.K), F = MatrixXd(m.B).transpose() * m.D.asDiagonal() * MatrixXd(m.B);
    EXPECT_LT((K - F).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff()) << name(v);
  }
}

// Masses: every variant carries the ring's mass 2 pi R rho A in each direction
// (rigid translation x: x^T M x = total mass). Oracle: the ring's mass.
TEST(LumpedModel, TranslationCarriesRingMass) {
  const ring::RingSpec spec = ringtest::free_ring();
  const double total = 2.0 * M_PI * spec.radius * spec.rhoA();
  for (auto v : {kChain, kFrame, kConsistent}) {
    const lumped::Model m = lumped::assemble(spec, lumptest::options(24, v));
    VectorXd x = VectorXd::Zero(m.K.rows());
    for (int k = 0; k < m.n; ++k) x[m.dofs_per_node * k] = 1.0;
    EXPECT_TRUE(ringtest::IsClose(x.dot(m.M * x), total, 1e-13)) << name(v);  // rounding of a sum of n terms
    // ... and rigid motions cost no strain: B x = 0 for a translation.
    EXPECT_LT((m.B * x).norm(), 1e-12 * (m.B.cwiseAbs() * x).norm()) << name(v);
  }
}

TEST(LumpedModel, RejectsWhatCanNeverWork) {
  ring::RingSpec spec = ringtest::pinned_ring();
  EXPECT_THROW(lumped::compute_modes(spec, lumptest::options(3, kChain), 1), std::invalid_argument);
  EXPECT_THROW(lumped::compute_modes(spec, lumptest::options(40, kChain), 0), std::invalid_argument);
  // The chain has n - 3 elastic modes whatever the supports.
  EXPECT_NO_THROW(lumped::compute_modes(spec, lumptest::options(40, kChain), 37));
  EXPECT_THROW(lumped::compute_modes(spec, lumptest::options(40, kChain), 38), std::invalid_argument);
  EXPECT_THROW(lumped::compute_modes(spec, lumptest::options(40, kFrame), 78), std::invalid_argument);
  EXPECT_THROW(lumped::compute_modes(spec, lumptest::options(40, kConsistent), 118), std::invalid_argument);
  spec.supports.roller = 181.0;  // not a node of the 40-gon anchored at 180
  EXPECT_THROW(lumped::compute_modes(spec, lumptest::options(40, kChain), 5), std::invalid_argument);
  spec.supports.roller = 180.0;  // on the pin
  EXPECT_THROW(lumped::compute_modes(spec, lumptest::options(40, kChain), 5), std::invalid_argument);
  ring::RingSpec bad = ringtest::free_ring();
  bad.E = 0.0;
  EXPECT_THROW(lumped::compute_modes(bad, lumptest::options(40, kFrame), 5), std::invalid_argument);
}

// The smallest n that works, against a hand derivation: the 4-link chain is a square of
// side l = pi R / 2 with one mechanism, the rhombus mode (interior angles pi/2 +- delta).
// Springs: V = 1/2 (4 k) delta^2. Midpoints of a rhombus sit at (+-d1/4, +-d2/4) in the
// diagonal frame, d1,2 = 2 l cos, sin(alpha/2), so each moves at l delta'/4 about the
// centre: free ring T = 1/2 (m l^2/4) delta'^2, omega^2 = 16 k / (m l^2) = 16 EI/(rho A l^4).
// Pinned at a corner, roller at the opposite one: the centre moves at d1'/2 along the
// diagonal, the midpoints' speeds^2 add up to 3 l^2 delta'^2 / 4, omega^2 = 16 EI/(3 rho A l^4).
TEST(LumpedModel, SmallestChainIsTheRhombusMode) {
  ring::RingSpec spec = ringtest::pinned_ring();
  spec.supports.roller = 0.0;
  const double l = M_PI * spec.radius / 2.0;
  const double free_w2 = 16.0 * spec.EI() / (spec.rhoA() * std::pow(l, 4));
  const ring::ModalResult r = lumped::compute_modes(spec, lumptest::options(4, kChain), 1);
  EXPECT_EQ(r.rigid_modes, 0);
  ASSERT_EQ(r.omega.size(), 1u);
  EXPECT_TRUE(ringtest::IsClose(r.omega[0], std::sqrt(free_w2 / 3.0), 1e-12));  // rounding only
  const ring::ModalResult f = lumped::compute_modes(ringtest::free_ring(), lumptest::options(4, kChain), 1);
  EXPECT_EQ(f.rigid_modes, 3);
  EXPECT_TRUE(ringtest::IsClose(f.omega[0], std::sqrt(free_w2), 1e-12));
}

// Very thin (R / r_g = 40000, d = 1 mm) and very thick (R / r_g = 20, d = 2 m) rings:
// the rigid count, the agreement of the two paths and the discretization error must not
// depend on slenderness (the bending error is a function of k h only; the frames'
// membrane stiffness EA/l grows against bending as (R/r_g)^2 and must not spoil the
// conditioning). Oracle: the closed-form free ring; 3e-4 bounds the n = 160 errors of
// every variant for k = 2, 3 (convergence_test: largest 2.4e-4, chain k = 3).
TEST(LumpedModel, SlendernessExtremes) {
  for (double d : {0.001, 2.0}) {
    ring::RingSpec spec = ringtest::free_ring();
    spec.section.diameter = d;
    for (auto v : {kChain, kFrame, kConsistent}) {
      const LumpedOptions o = lumptest::options(160, v);
      const ring::ModalResult dn = lumped::compute_modes(spec, o, 4, lumped::Method::dense);
      const ring::ModalResult sp = lumped::compute_modes(spec, o, 4, lumped::Method::sparse);
      EXPECT_EQ(dn.rigid_modes, 3);
      EXPECT_EQ(sp.rigid_modes, 3);
      for (int k : {2, 3}) {
        const double exact = v == kChain ? ring::closed_form::free_ring_inextensional(spec, k)
                                         : ring::closed_form::free_ring_extensible(spec, k)[0];
        const int i = 2 * (k - 2);
        EXPECT_TRUE(ringtest::IsClose(sp.omega[i], dn.omega[i], 1e-10)) << name(v) << " d = " << d;
        EXPECT_TRUE(ringtest::IsClose(sp.omega[i], exact, 3e-4)) << name(v) << " d = " << d << " k = " << k;
      }
    }
  }
}

// Mode shapes at the common stations honour the supports: the pin (station 180) does not
// move; the roller (station 0, opposite the pin) moves only along the pin-roller line,
// i.e. radially at 0 deg. Oracle: the support definitions of docs/scenes.md (supports.pin, supports.roller).
TEST(LumpedModel, ShapesHonourSupports) {
  ring::RingSpec spec = ringtest::pinned_ring();
  spec.supports.roller = 0.0;
  for (auto v : {kChain, kFrame, kConsistent}) {
    const ring::ModalResult r = lumped::compute_modes(spec, lumptest::options(40, v), 9);
    for (const auto& sh : r.shapes) {
      ASSERT_EQ(sh.radial.size(), static_cast<std::size_t>(ring::kStations));
      // 1e-12: rounding of normalized shapes (largest component 1).
      EXPECT_LT(std::abs(sh.radial[180]), 1e-12) << name(v);
      EXPECT_LT(std::abs(sh.tangential[180]), 1e-12) << name(v);
      EXPECT_LT(std::abs(sh.tangential[0]), 1e-12) << name(v);
    }
  }
}

}  // namespace
