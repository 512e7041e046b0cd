// Geometrically nonlinear statics of the rigid-segment chain: equilibrium of the
// hinge springs with a dead point load under the closure and support constraints,
//
//   K theta + G(phi)^T lambda = s Phi(phi),   g(phi) = 0,   s: load factor 0 -> 1,
//
// by load stepping with full Newton (analytic tangent K + sum_k lambda_k Hess g_k
// - s dPhi/dphi). An increment whose Newton iteration fails (no convergence in 25
// iterations, or a step turning a segment by more than 0.5 rad) is halved. When the
// increment falls below 1e-6 of the requested one (a limit point in the load), the
// solver switches to arc-length continuation (Crisfield 1981, cylindrical: the norm of
// the change of the angles per step is fixed, the load factor is an unknown) from the
// last equilibrium and follows the path through the limit point until it comes back to
// the full load (then a final Newton at s = 1), or reports why not.
// Self-contact (non-adjacent segments closer than the section depth) ends the solve
// with a ring::NumericalError naming the load factor (and the limit point, if the path
// went through one): the chain model has no contact. Measured: the diametral load along
// the pin-roller line has no limit point up to contact (P R^2/EI ~ 7.5); a load at 90
// deg pushing toward the centre has one at P R^2/EI ~ 7.5, past which the top snaps
// down onto the bottom. Kinematics from multibody/chain.hpp unchanged.
#pragma once

#include "multibody/backend.hpp"
#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// Static equilibrium under `statics.load` (its history is ignored: full load).
/// Returns the displacements of the recorded points (ring-centred frame, m), the
/// number of accepted load steps, the total Newton iterations, and every hinge's
/// deformed position. Cost: O(n^3) per Newton iteration on the dense path, O(n) on the
/// O(n) path (multibody.method = "sparse", or "auto" from kSparseStaticsCrossover).
/// Requires a pin and a roller (otherwise the rigid rotation about the pin is free).
/// Throws std::invalid_argument for inputs that can never work and
/// ring::NumericalError when no equilibrium path reaches the full load or the ring
/// touches itself.
ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::StaticOptions& statics);

}  // namespace multibody
