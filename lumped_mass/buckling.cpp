#include "lumped_mass/buckling.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/QR>
#include <Eigen/SparseCore>

#include <chrono>
#include <functional>
#include <optional>
#include <stdexcept>

#include "lumped_mass/chain.hpp"
#include "lumped_mass/frame.hpp"
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
Sparse tangent_at_chain(const Chain& c, const ChainLoads& loads, const Vec& x, const Vec& lambda, double s) {
  const Triplets t = tangent(c, loads, x, lambda, s, 1.0).hess;
  Sparse T(2 * c.n, 2 * c.n);
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

/// Relative hinge move of the differences for K_1 (buckling.hpp): large enough that the
/// rounding of T (its entries ~ (R/l)^4 times the pencil's scale) stays far below the
/// change, small enough that Richardson's fourth order leaves ~(1e-3)^4.
constexpr double kRelativeMove = 1e-3;

/// A model's tangent T(x, mu, s) (the multipliers' rows already in it), N x N.
using TangentAt = std::function<Sparse(const Vec& x, const Vec& mu, double s)>;

/// The linear buckling pencil of a model whose constraints at rest have the Jacobian G^T
/// (`gt`, N x R): the tangent space at rest, the linear prebuckling state from rest, K_1 =
/// dT/ds along it, and the lowest positive factors (buckling.hpp), one code for the chain
/// and the frame. `length`: the model's element length, the scale of the differences' step.
struct Pencil {
  Dense Z;
  modal::CriticalFactors factors;
};
Pencil buckling_pencil(const Dense& gt, const Vec& x0, const Vec& gP, double length, const TangentAt& tangent_at,
                       int count) {
  const Eigen::Index N = gt.rows();
  // The constraints' tangent space at rest: ker G = the last N - rank columns of the
  // orthogonal factor of G^T = Q [R; 0] (rank-revealing: redundant support rows drop out).
  const Eigen::ColPivHouseholderQR<Dense> qr(gt);
  const Dense Z = Dense(qr.householderQ()).rightCols(N - qr.rank());

  // 1. Linear statics at rest: x1 on ker G, then the multiplier rates from the force balance.
  const Sparse T0 = tangent_at(x0, Vec::Zero(gt.cols()), 0.0);
  const Dense K0r = Z.transpose() * (T0 * Z);
  const Eigen::LLT<Dense> llt(K0r);
  if (llt.info() != Eigen::Success)
    throw std::invalid_argument("lumped buckling: the stiffness at rest is not positive definite: the ring has a "
                                "rigid mode that the supports leave free; add a support");
  const Vec x1 = Z * llt.solve(-(Z.transpose() * gP));
  const Vec mu1 = qr.solve(Vec(-(gP + T0 * x1)));

  // 2. K_1 along the linear prebuckling path (central differences at h and 2h, Richardson's
  // extrapolation; step h: buckling.hpp).
  const double move = x1.cwiseAbs().maxCoeff();
  const double h = move > 0.0 ? kRelativeMove * length / move : 1.0;
  auto central = [&](double d) {
    return Sparse((tangent_at(x0 + d * x1, d * mu1, d) - tangent_at(x0 - d * x1, -d * mu1, -d)) / (2.0 * d));
  };
  const Sparse K1 = move > 0.0 ? Sparse((4.0 * central(h) - central(2.0 * h)) / 3.0) : central(h);

  // 3. The pencil on ker G and the one eigen step.
  const Dense K1r = Z.transpose() * (K1 * Z);
  return {Z, modal::critical_factors(K0r, K1r, count, "lumped buckling")};
}

ring::BucklingResult result(const ring::LumpedOptions& options, const Pencil& p, double anchor_deg,
                            int dofs_per_node, const std::optional<ring::Arc>& arc = std::nullopt) {
  ring::BucklingResult r;
  r.solver = "lumped";
  r.model["n"] = static_cast<long long>(options.n);
  r.model["variant"] = ring::to_string(options.variant);
  r.unknowns = p.Z.cols();
  r.factors.assign(p.factors.factors.data(), p.factors.factors.data() + p.factors.factors.size());
  for (Eigen::Index i = 0; i < p.factors.vectors.cols(); ++i)
    r.shapes.push_back(arc ? sample_arch_shape(*arc, p.Z * p.factors.vectors.col(i))
                           : sample_shape(anchor_deg, dofs_per_node, p.Z * p.factors.vectors.col(i)));
  return r;
}

/// The corotational Timoshenko frame's buckling (frame.hpp): its supports are linear rows,
/// so T = Hess V + s Hess P, and the multipliers leave no Hessian.
ring::BucklingResult frame_buckling(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                    const ring::BucklingOptions& buckling) {
  const Frame f = make_frame(spec, options);
  const FrameLoads loads(f, spec, buckling.loads, "buckling");
  const int N = 3 * f.n;
  const TangentAt tangent_at = [&](const Vec& q, const Vec&, double s) {
    Springs sp = frame_energy(f, q, 1.0);
    loads.add_hessian(q, s, sp.hess);
    Sparse T(N, N);
    T.setFromTriplets(sp.hess.begin(), sp.hess.end());
    return T;
  };
  const Pencil p = buckling_pencil(Dense(Dense(f.S).transpose()), f.rest, loads.gradient(f.rest), f.l, tangent_at,
                                   buckling.count);
  return result(options, p, f.geometry.anchor_deg, 3);
}

}  // namespace

ring::BucklingResult compute_buckling(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                      const ring::BucklingOptions& buckling) {
  const auto t0 = std::chrono::steady_clock::now();
  check_buckling(spec, options, buckling);
  ring::BucklingResult r;
  if (options.variant != ring::LumpedOptions::Variant::chain) {
    r = frame_buckling(spec, options, buckling);
  } else {
    const Chain c = make_chain(spec, options);
    const int N = 2 * c.n, R = c.rows();
    const ChainLoads loads(buckling.loads, c.rest, c.l, mass_matrix(c), load_hinges(c, spec, buckling.loads, "buckling"),
                           c.open);
    Triplets gt;
    jacobian(c, c.rest, 0, 1.0, true, gt);
    const TangentAt tangent_at = [&](const Vec& x, const Vec& lambda, double s) {
      return tangent_at_chain(c, loads, x, lambda, s);
    };
    r = result(options, buckling_pencil(dense(N, R, gt), c.rest, loads.gradient(c.rest), c.l, tangent_at, buckling.count),
               c.anchor_deg, 2, spec.arc);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace lumped
