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
#include "lumped_mass/frame.hpp"
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

ring::ModalResult describe(const ring::LumpedOptions& options, const modal::LoadedModes& m, const Dense& Z,
                           Eigen::Index unknowns, double anchor_deg, int dofs_per_node, int count) {
  ring::ModalResult res;
  res.solver = "lumped";
  res.model["n"] = static_cast<long long>(options.n);
  res.model["variant"] = ring::to_string(options.variant);
  res.model["preload"] = std::string("static");
  res.unknowns = unknowns;
  res.max_residual = m.max_residual;
  for (int k = 0; k < count; ++k) {
    res.omega.push_back(std::sqrt(m.omega2(k)));
    res.shapes.push_back(sample_shape(anchor_deg, dofs_per_node, Z * m.vectors.col(k).head(Z.cols())));
  }
  return res;
}

/// The corotational Timoshenko frame's frequencies under load (frame.hpp): its equilibrium on
/// the statics' path, the tangent Hess V + Hess P there, its constant mass (J of the point
/// masses on th), both on ker S (the supports are linear rows: the same space at every state).
ring::ModalResult frame_modes_under_load(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                         const ring::StaticOptions& statics, int count) {
  const Frame f = make_frame(spec, options);
  const FrameLoads loads(f, spec, statics.loads, "static");
  const int N = 3 * f.n;
  const std::string who = "lumped modes under load (" + ring::to_string(options.variant) + ")";
  const Vec q = frame_path(f, loads, spec.radius, statics, who).state.z.head(N);
  Springs sp = frame_energy(f, q, 1.0);
  loads.add_hessian(q, 1.0, sp.hess);
  Sparse T(N, N);
  T.setFromTriplets(sp.hess.begin(), sp.hess.end());
  const Dense Z = modal::kernel_basis(Dense(f.S), N);
  const Dense Tr = Z.transpose() * (T * Z), Mr = Z.transpose() * (f.M * Z);
  const modal::LoadedModes m = modal::loaded_modes(Tr, Mr, modal::bending_scale(spec), count, who);
  return describe(options, m, Z, Tr.rows(), f.geometry.anchor_deg, 3, count);
}

}  // namespace

ring::ModalResult compute_modes_under_load(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                           const ring::StaticOptions& statics, int count) {
  const auto t0 = std::chrono::steady_clock::now();
  check_preloaded_modes(spec, options, statics);
  if (options.variant != ring::LumpedOptions::Variant::chain) {
    ring::ModalResult res = frame_modes_under_load(spec, options, statics, count);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  }
  const Chain c = make_chain(spec, options);
  const int N = 2 * c.n;
  const ChainLoads loads(statics.loads, c.rest, c.l, mass_matrix(c), load_hinges(c, spec, statics.loads, "static"));

  // 1. The equilibrium at the full load, on the statics' own path.
  const detail::StaticState eq =
      detail::follow_statics(c, loads, spec, statics, nullptr, InertiaRoute::automatic, "lumped modes under load");

  // 2. The tangent there and the constraints' tangent space at the deformed state. The
  //    unknowns q = (x, chi): the positions, then the rotation of every hinge with a point
  //    inertia (Terms::hinge_rotations, the linear modes' and the response's), at the chi in
  //    equilibrium with x (relaxed_rotations: the statics' condensed kr is its minimum), so
  //    that the tangent on q holds the split springs (chain.hpp, springs()).
  const int Q = N + static_cast<int>(c.terms->hinge_rotations().size());
  Vec q(Q);
  q << eq.x, relaxed_rotations(c, eq.x);
  const Triplets tt = tangent(c, loads, q, eq.lambda, 1.0, 1.0).hess;
  Sparse T(Q, Q);
  T.setFromTriplets(tt.begin(), tt.end());
  Triplets gt;
  jacobian(c, eq.x, 0, 1.0, false, gt);
  Sparse G(c.rows(), N);
  G.setFromTriplets(gt.begin(), gt.end());
  const Dense Z = modal::kernel_basis(Dense(G), N);
  // 3-4. The pencil (Zq^T T Zq, Zq^T M Zq) at the equilibrium (modal::loaded_modes), Zq =
  //    diag(Z, I): ker G in the positions, every chi free; M the constant mass on q.
  Dense Zq = Dense::Zero(Q, Z.cols() + (Q - N));
  Zq.topLeftCorner(N, Z.cols()) = Z;
  Zq.bottomRightCorner(Q - N, Q - N).setIdentity();
  const Dense Tr = Zq.transpose() * (T * Zq);
  const Dense Mr = Zq.transpose() * (mass_matrix(c, HingeRotations::unknowns) * Zq);
  const modal::LoadedModes m = modal::loaded_modes(Tr, Mr, modal::bending_scale(spec), count, "lumped modes under load");
  ring::ModalResult res = describe(options, m, Z, Tr.rows(), c.anchor_deg, 2, count);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace lumped
