// The geometrically exact FE beam (fem_reference/nonlinear.hpp) against oracles outside
// it: finite differences of its own energy (the consistent tangent), the linear FE model
// (its small-load limit), the inextensible elastica of the diametrally loaded ring
// (tests/support/elastica.hpp, an ODE shooting solution), and measured convergence orders.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "fem_reference/modes.hpp"
#include "fem_reference/nonlinear.hpp"
#include "fem_reference/ring_model.hpp"
#include "ring/errors.hpp"
#include "tests/fem_reference/paper_ring.hpp"
#include "tests/support/close.hpp"
#include "tests/support/elastica.hpp"

namespace {

using ringtest::IsClose;
using namespace dealii;

/// The paper's ring held as in its section 5: pin at A (180 deg), roller at C (0 deg).
ring::RingSpec held_ring() {
  ring::RingSpec s = femtest::paper_ring(180.0);
  s.supports.roller = 0.0;
  return s;
}

/// P pushing C (0 deg) toward A: the diametral squeeze.
ring::StaticOptions squeeze(double force) {
  ring::StaticOptions st;
  st.load.angle = 0.0;
  st.load.force = {-force, 0.0};
  st.steps = 10;
  st.record = {0.0, 90.0, 270.0};
  return st;
}

fem::detail::Setup small_setup(const ring::RingSpec& spec, int elements, int degree) {
  fem::detail::Setup s;
  s.elements = elements;
  s.degree = degree;
  s.EA = spec.EA();
  return s;
}

// Oracle: central finite differences of the energy (for the internal force) and of the
// internal force (for the tangent), at a state with rotations near 1 rad and strains of
// a few per cent. Step 1e-6 m: truncation ~ h^2 V''' ~ 1e-9 relative, round-off
// ~ eps V / h ~ 1e-9; the bound 1e-6 leaves both a factor 1000.
TEST(FemBeamKernel, InternalForceAndTangentAreTheEnergysDerivatives) {
  const ring::RingSpec spec = held_ring();
  const fem::detail::RingModel model(spec, small_setup(spec, 8, 3));
  const unsigned int N = model.n_free();
  Vector<double> q(N);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (unsigned int i = 0; i < N; ++i) q[i] = u(rng);
  Vector<double> f;
  SparseMatrix<double> K(model.sparsity());
  model.beam_energy(q, &f, &K);
  const double h = 1e-6;
  double fd_err = 0.0, k_err = 0.0, k_scale = 0.0;
  Vector<double> fp, fm;
  for (unsigned int j = 0; j < N; ++j) {
    Vector<double> qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    const double dE = (model.beam_energy(qp, &fp, nullptr) - model.beam_energy(qm, &fm, nullptr)) / (2 * h);
    fd_err = std::max(fd_err, std::abs(dE - f[j]));
    for (unsigned int i = 0; i < N; ++i) {
      const double dk = (fp[i] - fm[i]) / (2 * h);
      k_err = std::max(k_err, std::abs(dk - K.el(i, j)));
      k_scale = std::max(k_scale, std::abs(K.el(i, j)));
    }
  }
  EXPECT_LT(fd_err, 1e-6 * f.linfty_norm());
  EXPECT_LT(k_err, 1e-6 * k_scale);
}

// Oracle: the linear FE model. At rest the energy and force vanish and the tangent is
// the linear stiffness (same tables, same quadrature: equal to round-off, 1e-12 of the
// largest entry), so the linearized beam has the linear model's frequencies: Rayleigh
// quotients (accumulated in long double: the membrane entries make a double q^T K q
// cancel to ~eps lambda_max / lambda ~ 1e-9) of the dense eigenvectors of
// (tangent at rest, M) against fem::compute_modes, 1e-9.
TEST(FemBeamKernel, LinearizedAboutTheRestStateIsTheLinearModel) {
  const ring::RingSpec spec = held_ring();
  const fem::detail::RingModel model(spec, small_setup(spec, 10, 3));
  const unsigned int N = model.n_free();
  Vector<double> q(N), f;
  SparseMatrix<double> K(model.sparsity());
  EXPECT_EQ(model.beam_energy(q, &f, &K), 0.0);
  EXPECT_EQ(f.linfty_norm(), 0.0);
  double diff = 0.0, scale = 0.0;
  for (unsigned int i = 0; i < N; ++i)
    for (unsigned int j = 0; j < N; ++j) {
      diff = std::max(diff, std::abs(K.el(i, j) - model.stiffness().el(i, j)));
      scale = std::max(scale, std::abs(K.el(i, j)));
    }
  EXPECT_LT(diff, 1e-12 * scale);

  LAPACKFullMatrix<double> Kd(N, N), Md(N, N);
  for (unsigned int i = 0; i < N; ++i)
    for (unsigned int j = 0; j < N; ++j) {
      Kd(i, j) = K.el(i, j);
      Md(i, j) = model.mass().el(i, j);
    }
  std::vector<Vector<double>> vectors(N, Vector<double>(N));
  Kd.compute_generalized_eigenvalues_symmetric(Md, vectors);
  std::vector<double> lambda;
  for (unsigned int k = 0; k < N; ++k) {
    long double qkq = 0, qmq = 0;
    for (unsigned int i = 0; i < N; ++i)
      for (unsigned int j = 0; j < N; ++j) {
        qkq += static_cast<long double>(vectors[k][i]) * K.el(i, j) * vectors[k][j];
        qmq += static_cast<long double>(vectors[k][i]) * model.mass().el(i, j) * vectors[k][j];
      }
    lambda.push_back(static_cast<double>(qkq / qmq));
  }
  std::sort(lambda.begin(), lambda.end());
  ring::FemOptions o;
  o.elements = 10;
  const auto modes = fem::compute_modes(spec, o, 12);
  for (int i = 0; i < 12; ++i) EXPECT_TRUE(IsClose(std::sqrt(lambda[i]), modes.omega[i], 1e-9)) << "mode " << i + 1;
}

// Oracle: the inextensible elastica of the diametrally squeezed ring. The reference
// (fem.reference: degree raised until the displacements change by < 1e-10) with the
// inextensible option must match it to 1e-6 (the bound) in both diameters, at
// P R^2/EI = 0.5, 1, 2, 5 (rotations up to about 1 rad at 5).
TEST(FemBeamStatics, ReferenceMatchesTheElastica) {
  const ring::RingSpec spec = held_ring();
  for (double p : {0.5, 1.0, 2.0, 5.0}) {
    const double P = p * spec.EI() / (spec.radius * spec.radius);
    ring::FemOptions o;
    o.extensible = false;
    o.reference = true;
    o.tolerance = 1e-10;
    const auto r = fem::solve_static(spec, o, squeeze(P));
    const auto exact = elastica::diametral(p);
    const double along = -r.displacements[0].ux / spec.radius;
    const double across = (r.displacements[1].uy - r.displacements[2].uy) / spec.radius;
    EXPECT_TRUE(IsClose(along, exact.along, 1e-6)) << "p = " << p << ": " << along << " vs " << exact.along;
    EXPECT_TRUE(IsClose(across, exact.across, 1e-6)) << "p = " << p << ": " << across << " vs " << exact.across;
  }
}

}  // namespace
