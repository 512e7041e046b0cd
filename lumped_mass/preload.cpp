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

/// The chain's mass about the configuration x: the constant mass_matrix (chain.hpp) plus
/// J g(x) g(x)^T for every point mass with rotary inertia J, g the gradient of the tangent's
/// rotation at its hinge (terms.hpp), but for the inertias on a hinge rotation of their own
/// (Terms::hinge_rotations, with_hinge_rotations below). O(n).
Sparse mass_at(const Chain& c, const Vec& x) {
  Sparse M = mass_matrix(c);
  Triplets t;
  for (const Terms::Inertia& in : c.terms->inertia()) {
    if (!(in.rotary > 0.0) || c.terms->own_rotation(in.node)) continue;
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

/// The reduced pencil (Tr, Mr) on Z's columns, then the rotation chi of every hinge of
/// Terms::hinge_rotations (terms.hpp: the linear modes' unknowns, model.cpp) after them.
/// tangent() has each such hinge's energy with chi condensed: K theta^2 / 2 + (kr and the
/// half springs in series) m^2 / 2, the minimum over chi of
///   E = K (phi_a - chi)^2 + K (phi_b - chi)^2 + kr chi^2 / 2,
/// quadratic in the links' rotations (phi_a, phi_b) and chi, m = (phi_a + phi_b) / 2. The
/// Hessian of a minimum over chi is E_xx - E_x,chi E_chi,chi^-1 E_chi,x, exactly, at the
/// statics' chi = chi*(x); with E_x,chi = -4K g (g = grad m at x) and E_chi,chi = 4K + kr
/// the full Hessian on (x, chi) is
///   [T + w w^T / (4K + kr), -w; -w^T, 4K + kr],   w = 4K g,
/// and J is chi's mass. At a vanishing load x is the rest n-gon: the linear model's pencil.
/// O(Z.cols()^2) per hinge.
void with_hinge_rotations(const Chain& c, const Vec& x, const Dense& Z, Dense& Tr, Dense& Mr) {
  const auto& hr = c.terms->hinge_rotations();
  if (hr.empty()) return;
  const Eigen::Index r = Z.cols(), e = static_cast<Eigen::Index>(hr.size());
  Dense T = Dense::Zero(r + e, r + e), M = Dense::Zero(r + e, r + e);
  T.topLeftCorner(r, r) = Tr;
  M.topLeftCorner(r, r) = Mr;
  const double k4 = 4.0 * c.k;
  for (Eigen::Index i = 0; i < e; ++i) {
    const Measure g = c.terms->rotation(x - c.rest, hr[i].node, false);
    Vec w = Vec::Zero(Z.rows());
    for (std::size_t a = 0; a < g.dofs.size(); ++a) w[g.dofs[a]] = k4 * g.grad[static_cast<Eigen::Index>(a)];
    const Vec wr = Z.transpose() * w;
    const double kc = k4 + hr[i].kr;
    T.topLeftCorner(r, r) += wr * wr.transpose() / kc;
    T.block(0, r + i, r, 1) = -wr;
    T.block(r + i, 0, 1, r) = -wr.transpose();
    T(r + i, r + i) = kc;
    M(r + i, r + i) = hr[i].inertia;
  }
  Tr = std::move(T);
  Mr = std::move(M);
}

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
  const Vec q = frame_path(f, loads, spec.radius, statics.steps, who).state.z.head(N);
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
  Dense Tr = Z.transpose() * (T * Z);
  Dense Mr = Z.transpose() * (mass_at(c, eq.x) * Z);
  with_hinge_rotations(c, eq.x, Z, Tr, Mr);
  const modal::LoadedModes m = modal::loaded_modes(Tr, Mr, modal::bending_scale(spec), count, "lumped modes under load");
  ring::ModalResult res = describe(options, m, Z, Tr.rows(), c.anchor_deg, 2, count);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace lumped
