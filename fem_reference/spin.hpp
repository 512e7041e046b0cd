// The modes of a spinning ring in the FE beam (issue 49; ring/spec.hpp, Rotation), in the
// frame that turns with it: M x'' + G x' + K x = 0 solved by modal::gyroscopic_modes. No
// deal.II here (see modes.hpp). fem::compute_modes takes this path when
// spec.rotation.spinning(); at speed 0 nothing of it runs.
//
// The matrices, on the reduced unknowns of the geometrically exact beam (make_beam: the
// Euler-Bernoulli RingModel, or the Reissner TimoshenkoModel for ring.theory = "timoshenko"),
// one discretization (fem.elements cells of fem.degree):
//  - K, the tangent in the turning frame, T(q, 1) = hess V(q) - hess Phi(q) of BeamPotential,
//    whose load potential holds the centrifugal body force speed^2/2 int rho A |x|^2 ds0 (+ the
//    point masses' speed^2/2 m |x|^2), x = X + u t0 + w n0: its Hessian is speed^2 M_trans, the
//    mass of the translations without rotary inertia, so T = K_beam(q) - speed^2 M_trans.
//    rotation.tension = "spin": q = q*, the equilibrium under the centrifugal force, found by
//    the FE statics' own path from rest (static_path.hpp, trace_path) as the modes under load
//    find theirs (preload.hpp): the beam's Hessian there holds the hoop tension's prestress
//    (N0 = rho A speed^2 R^2 on the free ring) and its geometric stiffness.
//    "none": q = 0, the linear stiffness minus speed^2 M_trans (no prestress).
//  - M, the model's mass (LinearModel::mass(): the consistent mass, the point masses' m and
//    J, the rotary inertia with fem.rotary_inertia or the Timoshenko theory), as at rest and as
//    the modes under load use it (constant: the polar basis at fixed theta does not move).
//  - G, the Coriolis matrix (BeamPotential::coriolis): 2 speed int rho A (u_i w_j - w_i u_j)
//    ds0 and 2 speed m S on each point mass's Cartesian velocity, S the quarter turn.
// Frequencies in the turning frame, ascending (gyroscopic_modes); shapes and waves by
// modal::travelling_mode through the model's own sampler (RingModel::sample: radial and
// tangential in the undeformed point's directions at the common stations); a mode without
// radial motion (below 1e-3 of its tangential: the rotation on a tangential foundation) is
// numbered by its tangential shape, as a standing wave (direction 0).
// fem.extensible = false: the modes' rule, omega^2 at EA = beta EI / R^2 for beta = 1e6 and
// 2e6 (each with its own equilibrium), extrapolated to 2 omega^2(2 beta) - omega^2(beta);
// shapes and waves of 2 beta, whose wave numbers must agree with those of beta mode by mode
// (else a ring::NumericalError: the extrapolation would pair different modes).
//
// Reference (fem.reference = true): p-refinement (then h, as the modes' reference) until the
// largest relative change of the `count` frequencies is below fem.tolerance or no longer
// halves: the dense step keeps the rounding of the assembled tangent (not refined, as the
// modes under load's: 1e-9 to 1e-8 of omega on a thin ring), where the changes stop
// contracting (then the coarser of the last two solutions is kept: the finer one's rounding
// is larger); the last change is the error_estimate (so it may exceed fem.tolerance, and
// says so). Reaching modal::kMaxGyroscopicUnknowns first is a ring::NumericalError.
// Refused (checks.cpp, check_modes, by key): fem.geometry = "polygon", an arch, ring.plastic,
// rigid motions left free (K must be positive definite); above modal::kMaxGyroscopicUnknowns
// reduced unknowns (naming fem.elements and fem.degree). The VTU output of a spinning ring's
// complex modes is refused by rotation.speed.
//
// max_residual: gyroscopic_modes' 2-norm ratio ||(K - w^2 M + i w G) x|| / (||K x|| +
// w^2 ||M x|| + w ||G x||) (residual_norm = kResidual2Norm), that of the assembled dense
// problem, not the discretization's error.
//
// Cost per discretization of N reduced unknowns: the statics' path (tension "spin": per Newton
// iteration an assembly and a sparse LU, O(N p)), two assemblies, the dense Hermitian solve
// O((2N)^3) time and O((2N)^2) complex memory; twice that when inextensible.
#pragma once

#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem::detail {

/// The `count` lowest modes of the spinning ring (file comment): solver "fem", model as the
/// modes at rest report it (reference, refinements, error_estimate), omega in the turning frame
/// ascending, shapes (the real part at t = 0) and waves, frame "rotating", rigid_modes 0,
/// unknowns (reduced), max_residual (2-norm), seconds.
/// \throws std::invalid_argument (check_modes; count outside 1..unknowns; above
///         modal::kMaxGyroscopicUnknowns), ring::NumericalError when the equilibrium is not
///         reached, or K is not positive definite (a spin at or past a divergence).
ring::ModalResult spinning_modes(const ring::RingSpec& spec, const ring::FemOptions& options, int count);

}  // namespace fem::detail
