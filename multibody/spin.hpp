// The modes of a spinning ring on the rigid-segment chain (issue 49): the gyroscopic
// eigenproblem of the frame that turns with the ring at rotation.speed (modal/gyroscopic.hpp),
//
//   M x'' + G x' + K x = 0   on the constraints' tangent space,
//
// in the dense path's unknowns (segment angles [, the free ring's x_0, y_0], [the Timoshenko
// chain's shear angles], [the point inertias' hinge rotations]), as the modes under load
// (statics.hpp) take them:
// - K, the tangent in the turning frame. rotation.tension = "spin": the chain's equilibrium
//   under the centrifugal body force (loading.hpp: each segment's mass at its centroid, the
//   point masses at their hinges), followed from rest by the statics' continuation; its
//   tangent holds the springs, the terms, the centrifugal force's Hessian (the softening
//   -speed^2 M_trans) and the constraints' multipliers (the prestress: the hoop tension
//   rho A speed^2 R^2 of the free ring). rotation.tension = "none": the linear stiffness at the
//   undeformed chain minus speed^2 M_trans, no prestress.
// - M, the chain's mass at that state (rotary inertias included).
// - G = 2 speed sum_s m_s J_s^T S J_s, S the quarter turn [[0, -1], [1, 0]], J_s the Jacobian
//   of mass point s (the segments' centroids, the point masses' hinges) in the chain's
//   coordinates: the Coriolis term of the turning frame's kinetic energy
//   m/2 |x' + speed S x|^2. A segment's rotary inertia gives none in the plane (its cross term
//   J speed phi' is a time derivative), nor do the shear angles and hinge rotations.
// The frequencies are the turning frame's, ascending; each mode's shape is its complex vector's
// real part sampled as the modes at rest sample (Chain::shape_at), its wave from
// modal::travelling_mode. Cost O(N^3) (N unknowns; modal::kMaxGyroscopicUnknowns bounds N,
// checks.hpp refuses a larger chain by multibody.n).
#pragma once

#include "multibody/attachments.hpp"
#include "multibody/chain.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace multibody {

namespace detail {

/// The translations' mass and Coriolis products at q, on the chain's coordinates (dofs x dofs):
///   mass     = sum_s m_s J_s^T J_s        (the chain's mass without its rotary inertias),
///   coriolis = sum_s m_s J_s^T S J_s      (skew; G = 2 speed coriolis),
/// over the segments' centroids (mass rho A l) and `terms`' point masses (when given). With
/// J_s = l sum_j w_sj e'(phi_j) e_j^T (+ the identity on the free ring's x_0, y_0) both are
/// l^2 W_jk times cos(phi_j - phi_k) and sin(phi_j - phi_k) on the angles, W_jk = sum_s m_s
/// w_sj w_sk (the chain's L^T L structure). O(n^2).
struct TranslationProducts {
  Matrix mass, coriolis;
};
TranslationProducts translation_products(const Chain& chain, const Attachments* terms, const Vector& q);

}  // namespace detail

/// The `count` lowest modes of the spinning ring `spec` (spec.rotation.spinning(); file
/// comment), dense path: omega in the turning frame, ascending; shapes, waves,
/// frame = "rotating", rigid_modes = 0, the gyroscopic residual. Throws std::invalid_argument
/// (check_modes: what the spinning modes refuse, by key) and ring::NumericalError when the
/// spin's equilibrium is not reached or K is not positive definite (a divergence speed).
ring::ModalResult compute_spinning_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options, int count);

}  // namespace multibody
