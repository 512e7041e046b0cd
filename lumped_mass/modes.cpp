#include "lumped_mass/modes.hpp"

#include <chrono>
#include <cmath>

#include "ring/sampling.hpp"

namespace lumped {

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count) {
  return compute_modes(spec, options, count, Method::automatic);
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count,
                                Method method) {
  const auto t0 = std::chrono::steady_clock::now();
  const Model model = assemble(spec, options);
  const Eigenpairs pairs = solve(model, count, method);

  ring::ModalResult r;
  r.solver = "lumped";
  r.model["n"] = static_cast<long long>(options.n);
  r.model["variant"] = ring::to_string(options.variant);
  r.model["method"] = std::string(pairs.method == Method::dense ? "dense" : "sparse");
  if (pairs.method == Method::sparse) {
    r.model["system_order"] = pairs.system_order;
    r.model["factor_nonzeros"] = pairs.factor_nonzeros;
  }
  r.rigid_modes = pairs.rigid;
  r.unknowns = pairs.unknowns;
  r.max_residual = pairs.max_residual;
  const int dpn = model.dofs_per_node;
  std::vector<double> ux(model.n), uy(model.n);
  for (std::size_t c = pairs.rigid; c < pairs.lambda.size(); ++c) {
    r.omega.push_back(std::sqrt(pairs.lambda[c]));
    for (int k = 0; k < model.n; ++k) {
      ux[k] = pairs.X(dpn * k, c);
      uy[k] = pairs.X(dpn * k + 1, c);
    }
    r.shapes.push_back(ring::sample_polygon(model.anchor_deg, ux, uy));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace lumped
