#include "lumped_mass/modes.hpp"
#include "lumped_mass/checks.hpp"
#include "lumped_mass/spin.hpp"

#include <chrono>

#include "modal/modes.hpp"
#include "ring/sampling.hpp"

namespace lumped {

ring::ModeShape sample_shape(double anchor_deg, int dofs_per_node, const Eigen::Ref<const Eigen::VectorXd>& x) {
  const int n = static_cast<int>(x.size()) / dofs_per_node;
  std::vector<double> ux(n), uy(n);
  for (int k = 0; k < n; ++k) {
    ux[k] = x[dofs_per_node * k];
    uy[k] = x[dofs_per_node * k + 1];
  }
  return ring::sample_polygon(anchor_deg, ux, uy);
}

ring::ModeShape sample_arch_shape(const ring::Arc& arc, const Eigen::Ref<const Eigen::VectorXd>& x) {
  const int n = static_cast<int>(x.size()) / 2;
  std::vector<double> ux(n), uy(n);
  for (int k = 0; k < n; ++k) {
    ux[k] = x[2 * k];
    uy[k] = x[2 * k + 1];
  }
  return ring::sample_arc(arc, ux, uy);
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count) {
  return compute_modes(spec, options, count, Method::automatic);
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count,
                                Method method) {
  check_modes(spec, options);
  if (spec.rotation.spinning()) return spinning_modes(spec, options, count);  // spin.hpp
  const auto t0 = std::chrono::steady_clock::now();
  const Model model = assemble(spec, options);
  const Eigenpairs pairs = solve(model, count, method);

  // The layer's assembly: rigid count and omega = sqrt(lambda) of the `count` lowest
  // elastic pairs (solve() already checked the rigid count against the supports).
  const Eigen::VectorXd lambda = Eigen::Map<const Eigen::VectorXd>(pairs.lambda.data(),
                                                                   static_cast<Eigen::Index>(pairs.lambda.size()));
  const modal::Selection sel = modal::select_modes("lumped", lambda, model.lambda_scale, count);
  ring::ModalResult r;
  modal::assemble(r, "lumped", lambda, sel, {pairs.max_residual});
  r.model["n"] = static_cast<long long>(options.n);
  r.model["variant"] = ring::to_string(options.variant);
  r.model["method"] = std::string(pairs.method == Method::dense ? "dense" : "sparse");
  if (pairs.method == Method::sparse) {
    r.model["system_order"] = pairs.system_order;
    r.model["factor_nonzeros"] = pairs.factor_nonzeros;
  }
  r.unknowns = pairs.unknowns;
  // The shapes are the nodes' displacements; the chain's hinge rotations after them are not.
  for (int c : sel.elastic)
    r.shapes.push_back(model.open ? sample_arch_shape(*spec.arc, pairs.X.col(c).head(model.node_dofs()))
                                  : sample_shape(model.anchor_deg, model.dofs_per_node, pairs.X.col(c).head(model.node_dofs())));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace lumped
