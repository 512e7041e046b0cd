#include "lumped_mass/preload.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lumped_mass/chain.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "modal/buckling.hpp"
#include "modal/modes.hpp"
#include "ring/errors.hpp"

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;
using Sparse = Eigen::SparseMatrix<double>;

/// The chain's mass about the configuration x: the constant mass_matrix (chain.hpp) plus
/// J g(x) g(x)^T for every point mass with rotary inertia J, g the gradient of the tangent's
/// rotation at its hinge (terms.hpp). O(n).
Sparse mass_at(const Chain& c, const Vec& x) {
  Sparse M = mass_matrix(c);
  Triplets t;
  for (const Terms::Inertia& in : c.terms->inertia()) {
    if (!(in.rotary > 0.0)) continue;
    const Measure g = c.terms->rotation(x - c.rest, in.node, false);
    for (std::size_t a = 0; a < g.dofs.size(); ++a)
      for (std::size_t b = 0; b < g.dofs.size(); ++b)
        t.emplace_back(g.dofs[a], g.dofs[b],
                       in.rotary * g.grad[static_cast<Eigen::Index>(a)] * g.grad[static_cast<Eigen::Index>(b)]);
  }
  if (t.empty()) return M;
  Sparse J(M.rows(), M.cols());
  J.setFromTriplets(t.begin(), t.end());
  return M + J;
}

}  // namespace

ring::ModalResult compute_modes_under_load(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                           const ring::StaticOptions& statics, int count) {
  const auto t0 = std::chrono::steady_clock::now();
  check_preloaded_modes(spec, options, statics);
  if (count < 1) throw std::invalid_argument("lumped modes under load: modes.count (=" + std::to_string(count) + ") must be >= 1");
  const Chain c = make_chain(spec, options);
  const int N = 2 * c.n;
  const ChainLoads loads(statics.loads, c.rest, c.l, mass_matrix(c), load_hinges(c, spec, statics.loads, "static"));

  // 1. The equilibrium at the full load, on the statics' own path.
  const detail::StaticState eq =
      detail::follow_statics(c, loads, spec, statics, nullptr, InertiaRoute::automatic, "lumped modes under load");

  // 2. The tangent there and the constraints' tangent space at the deformed state.
  const Triplets tt = tangent(c, loads, eq.x, eq.lambda, 1.0, 1.0).hess;
  Sparse T(N, N);
  T.setFromTriplets(tt.begin(), tt.end());
  Triplets gt;
  jacobian(c, eq.x, 0, 1.0, false, gt);
  Sparse G(c.rows(), N);
  G.setFromTriplets(gt.begin(), gt.end());
  const Dense Z = modal::kernel_basis(Dense(G), N);
  const Eigen::Index r = Z.cols();
  if (count > r)
    throw std::invalid_argument("lumped modes under load: modes.count (=" + std::to_string(count) +
                                ") exceeds the chain's " + std::to_string(r) + " modes (lumped.n = " +
                                std::to_string(c.n) + ")");

  // 3-4. The pencil (Z^T T Z, Z^T M Z) by the shifted inverse of the multibody version: the
  // largest mu of S^-1 M_r, S = T_r + sigma M_r (sigma the bending scale), omega^2 = 1/mu - sigma.
  const Dense Tr = Z.transpose() * (T * Z);
  const Dense Mr = Z.transpose() * (mass_at(c, eq.x) * Z);
  const double shift = modal::bending_scale(spec);
  const Eigen::LLT<Dense> llt(0.5 * (Tr + Tr.transpose()) + shift * Mr);
  if (llt.info() != Eigen::Success)
    throw ring::NumericalError("lumped modes under load: the loaded ring is at or past a critical load (T + s M is "
                               "not positive definite on the constraints' tangent space)");
  Dense C = llt.matrixL().solve(Mr);
  C = llt.matrixL().solve(C.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Dense> eig(0.5 * (C + C.transpose()));

  ring::ModalResult res;
  res.solver = "lumped";
  res.model["n"] = static_cast<long long>(c.n);
  res.model["variant"] = ring::to_string(options.variant);
  res.model["preload"] = std::string("static");
  res.unknowns = r;
  for (int k = 0; k < count; ++k) {
    const double mu = eig.eigenvalues()[r - 1 - k];
    const double w2 = 1.0 / mu - shift;
    if (!(w2 > 0.0))
      throw ring::NumericalError("lumped modes under load: omega^2 = " + std::to_string(w2) +
                                 " <= 0 at the equilibrium: the loaded ring is at or past a critical load");
    const Vec y = llt.matrixU().solve(eig.eigenvectors().col(r - 1 - k));
    const double resid = (Tr * y - w2 * Mr * y).norm() / ((Tr * y).norm() + w2 * (Mr * y).norm());
    res.max_residual = std::max(res.max_residual, resid);
    res.omega.push_back(std::sqrt(w2));
    res.shapes.push_back(sample_shape(c.anchor_deg, 2, Z * y));
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace lumped
