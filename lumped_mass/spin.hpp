// The modes of a spinning ring (rotation.speed != 0, issue 49) in the lumped-mass `chain`,
// in the frame that turns with it: the gyroscopic problem M x'' + G x' + K x = 0 of
// modal/gyroscopic.hpp on the chain of the modes under load (preload.hpp: hinge positions x,
// rigid links and support rows G(x) = 0, hinge springs, the spec's terms; the rotation chi of
// every hinge with a point inertia after them).
//
// ## Method
//  1. tension = "spin": the equilibrium x under the centrifugal body force alone, the potential
//     -Omega^2 / 2 x^T M_t x of the translational masses (the links' midpoint masses and the
//     point masses, loads.hpp, ChainLoads::set_spin), on the statics' own path
//     (detail::follow_statics, load factor = (speed / Omega)^2), with the multipliers lambda
//     there: the links' tensions (rho A Omega^2 R^2 on the free ring: the prestress). The
//     tangent there, T = Hess V + sum lambda_j Hess c_j - Omega^2 M_t (chain.hpp, tangent:
//     the spin's load stiffness is the centrifugal softening).
//     tension = "none": T = Hess V - Omega^2 M_t at the undeformed chain, lambda = 0: the
//     linear stiffness, softened, without prestress.
//  2. Z an orthonormal basis of ker G at x (modal::kernel_basis), Zq = diag(Z, I) with the
//     free hinge rotations chi (preload.hpp, step 3).
//  3. K = Zq^T T Zq, M = Zq^T M Zq (the constant mass: M_t, and J on chi), and the Coriolis
//     matrix G_c = Zq^T (2 Omega M_t S) Zq, S the quarter turn [[0, -1], [1, 0]] on every
//     node's (x, y): M_t's 2 x 2 blocks are multiples of I (m/4 [I I; I I] per link, m I at a
//     point mass), so M_t S = S M_t is skew, and the midpoint mass's term
//     2 Omega m (P^T S P) (P the midpoint's average of its two hinges) is exactly that block.
//     The hinge rotations chi take no Coriolis or centrifugal term (a rotation's kinetic
//     energy J (chi' + Omega)^2 / 2 adds only a total derivative).
//  4. modal::gyroscopic_modes(K, M, G_c) and, per mode, modal::travelling_mode through
//     sample_shape of Z y (the hinges' displacements about x, node 0 at the anchor).
// The corotational Timoshenko frame (lumped.variant = "timoshenko-frame", frame.hpp) the same
// way on its unknowns q = (x, y, th) per node: the equilibrium under the centrifugal force on
// its statics' path (FrameLoads::set_spin; the frame is extensible, so the ring grows by
// ~rho Omega^2 R^3 / E and its elements carry the hoop tension), or rest; T = Hess V + Hess P;
// ker S of the supports; its constant lumped mass (rho I l and J on th), the softening and the
// Coriolis term on the translations only. "frame" (massless rotations, condensed) and
// "frame-consistent" (no lumped translational mass for the Coriolis term) refuse a spin.
// The forward wave (with the spin) is the lower one in the turning frame (spinning_ring.hpp,
// test_spin.cpp checks the sign against the closed form).
//
// Cost: the statics (tension = "spin"), the dense QR of G^T (2n x 2n) and the dense gyroscopic
// eigensolve of order 2 dim ker G: O(n^3) time, O(n^2) memory; lumped.n <= kMaxPreloadHinges.
// Accuracy: the chain's frequencies converge to the inextensible ring's at O(1/n^2)
// (tests/lumped_mass/test_spin.cpp measures the order).
//
// Usage:
//   ring::RingSpec spec = ...;                   // a ring on a foundation (no rigid mode)
//   spec.rotation.speed = 0.5;                   // rad/s, counter-clockwise
//   ring::ModalResult r = lumped::compute_modes(spec, ring::LumpedOptions{}, 6);
//   // r.frame == "rotating", r.waves[i] = {k, +1 forward / -1 backward}
#pragma once

#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The `count` lowest modes of the spinning chain (file comment), in the turning frame.
/// Requires spec.rotation.spinning() and what check_modes checks for a spin (checks.hpp);
/// 1 <= count <= the unknowns on the constraints' kernel (std::invalid_argument naming modes.count).
/// Throws ring::NumericalError when the centrifugal equilibrium is not reached or K is not
/// positive definite (a divergence: the spin past a mode's critical speed).
/// Result: solver "lumped"; model {n, variant, method "dense"}; omega (rad/s,
/// ascending, turning frame); shapes and waves (modal::travelling_mode); frame "rotating";
/// rigid_modes 0; unknowns the size of K; max_residual the gyroscopic residual.
ring::ModalResult spinning_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count);

}  // namespace lumped
