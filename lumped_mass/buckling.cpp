#include "lumped_mass/buckling.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/QR>
#include <Eigen/SparseCore>

#include <chrono>
#include <stdexcept>

#include "lumped_mass/chain.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/modes.hpp"
#include "modal/buckling.hpp"

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;

Dense dense(int rows, int cols, const Triplets& t) {
  Eigen::SparseMatrix<double> A(rows, cols);
  A.setFromTriplets(t.begin(), t.end());
  return Dense(A);
}

using Sparse = Eigen::SparseMatrix<double>;

/// The chain's tangent (chain.hpp) at (x, lambda, s), 2n x 2n, banded plus the closing
/// corners (sparse, so that Z^T T Z costs one dense product).
Sparse tangent_at(const Chain& c, const ChainLoads& loads, const Vec& x, const Vec& lambda, double s) {
  const Triplets t = tangent(c, loads, x, lambda, s, 1.0).hess;
  Sparse T(2 * c.n, 2 * c.n);
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

/// Relative hinge move of the differences for K_1 (buckling.hpp): large enough that the
/// rounding of T (its entries ~ (R/l)^4 times the pencil's scale) stays far below the
/// change, small enough that Richardson's fourth order leaves ~(1e-3)^4.
constexpr double kRelativeMove = 1e-3;

}  // namespace

ring::BucklingResult compute_buckling(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                      const ring::BucklingOptions& buckling) {
  const auto t0 = std::chrono::steady_clock::now();
  check_buckling(spec, options, buckling);
  const Chain c = make_chain(spec, options);
  const int N = 2 * c.n, R = c.rows();
  const ChainLoads loads(buckling.loads, c.rest, c.l, mass_matrix(c), load_hinges(c, spec, buckling.loads, "buckling"));
  const Vec& x0 = c.rest;

  // The constraints' tangent space at rest: ker G = the last N - rank columns of the
  // orthogonal factor of G^T = Q [R; 0] (rank-revealing: redundant support rows drop out).
  Triplets gt;
  jacobian(c, x0, 0, 1.0, true, gt);
  const Eigen::ColPivHouseholderQR<Dense> qr(dense(N, R, gt));
  const Eigen::Index free = N - qr.rank();
  const Dense Z = Dense(qr.householderQ()).rightCols(free);

  // 1. Linear statics at rest: x1 on ker G, then the multiplier rates from the force balance.
  const Sparse T0 = tangent_at(c, loads, x0, Vec::Zero(R), 0.0);
  const Dense K0r = Z.transpose() * (T0 * Z);
  const Eigen::LLT<Dense> llt(K0r);
  if (llt.info() != Eigen::Success)
    throw std::invalid_argument("lumped buckling: the stiffness at rest is not positive definite: the ring has a "
                                "rigid mode that the supports leave free; add a support");
  const Vec gP = loads.gradient(x0);
  const Vec x1 = Z * llt.solve(-(Z.transpose() * gP));
  const Vec mu1 = qr.solve(Vec(-(gP + T0 * x1)));

  // 2. K_1 along the linear prebuckling path (central differences at h and 2h, Richardson's
  // extrapolation; step h: buckling.hpp).
  const double move = x1.cwiseAbs().maxCoeff();
  const double h = move > 0.0 ? kRelativeMove * c.l / move : 1.0;
  auto central = [&](double d) {
    return Sparse((tangent_at(c, loads, x0 + d * x1, d * mu1, d) - tangent_at(c, loads, x0 - d * x1, -d * mu1, -d)) /
                  (2.0 * d));
  };
  const Sparse K1 = move > 0.0 ? Sparse((4.0 * central(h) - central(2.0 * h)) / 3.0) : central(h);

  // 3. The pencil on ker G, the one eigen step, and the modes at the common stations.
  const Dense K1r = Z.transpose() * (K1 * Z);
  const modal::CriticalFactors cf = modal::critical_factors(K0r, K1r, buckling.count, "lumped buckling");

  ring::BucklingResult r;
  r.solver = "lumped";
  r.model["n"] = static_cast<long long>(options.n);
  r.model["variant"] = ring::to_string(options.variant);
  r.unknowns = free;
  r.factors.assign(cf.factors.data(), cf.factors.data() + cf.factors.size());
  for (Eigen::Index i = 0; i < cf.vectors.cols(); ++i)
    r.shapes.push_back(sample_shape(c.anchor_deg, 2, Z * cf.vectors.col(i)));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace lumped
