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
  // 3-4. The pencil (Z^T T Z, Z^T M Z) at the equilibrium (modal::loaded_modes).
  const Dense Tr = Z.transpose() * (T * Z);
  const Dense Mr = Z.transpose() * (mass_at(c, eq.x) * Z);
  const modal::LoadedModes m = modal::loaded_modes(Tr, Mr, modal::bending_scale(spec), count, "lumped modes under load");

  ring::ModalResult res;
  res.solver = "lumped";
  res.model["n"] = static_cast<long long>(c.n);
  res.model["variant"] = ring::to_string(options.variant);
  res.model["preload"] = std::string("static");
  res.unknowns = Z.cols();
  res.max_residual = m.max_residual;
  for (int k = 0; k < count; ++k) {
    res.omega.push_back(std::sqrt(m.omega2(k)));
    res.shapes.push_back(sample_shape(c.anchor_deg, 2, Z * m.vectors.col(k)));
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace lumped
