#include "lumped_mass/spin.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>

#include "lumped_mass/chain.hpp"
#include "lumped_mass/frame.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "modal/buckling.hpp"
#include "modal/gyroscopic.hpp"

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Dense = Eigen::MatrixXd;
using Sparse = Eigen::SparseMatrix<double>;

/// The Coriolis matrix 2 Omega M_t S on q (Q unknowns, `dofs` per node, the translations
/// first at every node; further unknowns take none): M_t's translational 2 x 2 blocks are
/// multiples of I, so (M_t S) has the columns [M_t e_{y_b}, -M_t e_{x_b}] at node b's
/// (x_b, y_b). O(nonzeros of M_t).
Sparse coriolis(const Sparse& Mt, int dofs, int Q, double speed) {
  Triplets t;
  for (int c = 0; c < Mt.outerSize(); ++c)
    for (Sparse::InnerIterator it(Mt, c); it; ++it) {
      const int node = c / dofs, d = c % dofs, r = static_cast<int>(it.row());
      if (d == 1) t.emplace_back(r, dofs * node, 2.0 * speed * it.value());
      if (d == 0) t.emplace_back(r, dofs * node + 1, -2.0 * speed * it.value());
    }
  Sparse C(Q, Q);
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

/// Steps 3-4 of spin.hpp on the unknowns q: K = Zq^T T Zq, M = Zq^T Mq Zq, G = Zq^T C Zq, the
/// gyroscopic modes and their waves through `sample` of the kernel's coordinates.
ring::ModalResult gyroscopic_result(const ring::RingSpec& spec, const ring::LumpedOptions& options, const Sparse& T,
                                    const Sparse& Mq, const Sparse& C, const Dense& Zq,
                                    const std::function<ring::ModeShape(const Vec&)>& sample, int count,
                                    const std::string& who) {
  const Eigen::Index unknowns = Zq.cols();
  if (count < 1 || count > unknowns)
    throw std::invalid_argument("lumped: modes.count (=" + std::to_string(count) + ") must be in [1, " +
                                std::to_string(unknowns) + "] for the spinning " + ring::to_string(options.variant) +
                                " (its unknowns on the constraints' kernel)");
  const Dense K = Zq.transpose() * (T * Zq);
  const Dense M = Zq.transpose() * (Mq * Zq);
  const Dense G = Zq.transpose() * (C * Zq);
  const modal::GyroscopicModes gm = modal::gyroscopic_modes(who, 0.5 * (K + K.transpose()), 0.5 * (M + M.transpose()),
                                                            0.5 * (G - G.transpose()), count);
  ring::ModalResult res;
  res.solver = "lumped";
  res.model["n"] = static_cast<long long>(options.n);
  res.model["variant"] = ring::to_string(options.variant);
  res.model["method"] = std::string("dense");
  res.rigid_modes = 0;
  res.unknowns = unknowns;
  res.max_residual = gm.max_residual;
  res.frame = "rotating";
  for (int k = 0; k < count; ++k) {
    res.omega.push_back(gm.omega[k]);
    auto [shape, wave] = modal::travelling_mode(gm.vectors.col(k), sample, spec.rotation.speed);
    res.shapes.push_back(std::move(shape));
    res.waves.push_back(wave);
  }
  return res;
}

/// The corotational Timoshenko frame (frame.hpp): its equilibrium under the centrifugal force
/// on its statics' path (tension = spin; the frame is extensible: the ring grows by
/// rho Omega^2 R^3 / E), or rest (none); the tangent Hess V + Hess P there, its constant
/// lumped mass, on ker S; the Coriolis term on the translations only (the section's rotation
/// takes none, as the chain's chi).
ring::ModalResult frame_spinning_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count) {
  const Frame f = make_frame(spec, options);
  FrameLoads loads(f, spec, ring::Loads{}, "static");
  loads.set_spin(spec.rotation.speed);
  const int N = 3 * f.n;
  const std::string who = "lumped spinning modes (" + ring::to_string(options.variant) + ")";
  const Vec q = spec.rotation.tension == ring::Rotation::Tension::spin
                    ? Vec(frame_path(f, loads, spec.radius, ring::StaticOptions{}, who).state.z.head(N))
                    : f.rest;
  Springs sp = frame_energy(f, q, 1.0);
  loads.add_hessian(q, 1.0, sp.hess);
  Sparse T(N, N);
  T.setFromTriplets(sp.hess.begin(), sp.hess.end());
  Triplets mt;  // the translational mass on q
  for (int c = 0; c < f.M.outerSize(); ++c)
    for (Sparse::InnerIterator it(f.M, c); it; ++it)
      if (it.row() % 3 != 2 && it.col() % 3 != 2) mt.emplace_back(int(it.row()), int(it.col()), it.value());
  Sparse Mt(N, N);
  Mt.setFromTriplets(mt.begin(), mt.end());
  const Dense Z = modal::kernel_basis(Dense(f.S), N);
  const auto sample = [&](const Vec& y) { return sample_shape(f.geometry.anchor_deg, 3, Z * y); };
  return gyroscopic_result(spec, options, T, f.M, coriolis(Mt, 3, N, spec.rotation.speed), Z, sample, count, who);
}

}  // namespace

ring::ModalResult spinning_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count) {
  const auto t0 = std::chrono::steady_clock::now();
  if (options.variant != ring::LumpedOptions::Variant::chain) {
    ring::ModalResult res = frame_spinning_modes(spec, options, count);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  }
  const std::string who = "lumped spinning modes";
  const double speed = spec.rotation.speed;
  const Chain c = make_chain(spec, options);
  const int N = 2 * c.n;
  const Sparse Mt = mass_matrix(c);
  ChainLoads loads(ring::Loads{}, c.rest, c.l, Mt, {}, c.open);
  loads.set_spin(speed, Mt);

  // 1. The state the modes are about and its multipliers: the centrifugal equilibrium on the
  //    statics' path (tension = spin), or the undeformed chain without prestress (none).
  Vec x = c.rest, lambda = Vec::Zero(c.rows());
  if (spec.rotation.tension == ring::Rotation::Tension::spin) {
    const detail::StaticState eq =
        detail::follow_statics(c, loads, spec, ring::StaticOptions{}, nullptr, InertiaRoute::automatic, who);
    x = eq.x;
    lambda = eq.lambda;
  }
  const int Q = N + static_cast<int>(c.terms->hinge_rotations().size());
  Vec q(Q);
  q << x, relaxed_rotations(c, x);
  // The load factor 1: the spin's load stiffness is the centrifugal softening -Omega^2 M_t.
  const Triplets tt = tangent(c, loads, q, lambda, 1.0, 1.0).hess;
  Sparse T(Q, Q);
  T.setFromTriplets(tt.begin(), tt.end());

  // 2. ker G at x, and every hinge rotation chi free (preload.hpp).
  Triplets gt;
  jacobian(c, x, 0, 1.0, false, gt);
  Sparse Gc(c.rows(), N);
  Gc.setFromTriplets(gt.begin(), gt.end());
  const Dense Z = modal::kernel_basis(Dense(Gc), N);
  Dense Zq = Dense::Zero(Q, Z.cols() + (Q - N));
  Zq.topLeftCorner(N, Z.cols()) = Z;
  Zq.bottomRightCorner(Q - N, Q - N).setIdentity();

  // 3-4. K, M (J on chi) and the Coriolis matrix on the kernel, the modes and their waves.
  const auto sample = [&](const Vec& y) { return sample_shape(c.anchor_deg, 2, Z * y.head(Z.cols())); };
  ring::ModalResult res = gyroscopic_result(spec, options, T, mass_matrix(c, HingeRotations::unknowns),
                                            coriolis(Mt, 2, Q, speed), Zq, sample, count, who);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace lumped
