// Geometrically nonlinear statics of the rigid-segment chain: equilibrium of the
// hinge springs with a dead point load under the closure and support constraints,
//
//   K theta + G(phi)^T lambda = s Phi(phi),   g(phi) = 0,   s: load factor 0 -> 1,
//
// by load stepping with full Newton (analytic tangent K + sum_k lambda_k Hess g_k
// - s dPhi/dphi). An increment whose Newton iteration fails (no convergence in 25
// iterations, or a step turning a segment by more than 0.5 rad) is halved; below
// 1e-6 of the requested increment a ring::NumericalError names the load factor
// reached. No arc-length continuation: the diametrally loaded ring (pin + roller,
// force along the pin-roller line) has no limit point up to self-contact (its load-
// deflection curve rises monotonically, checked against the elastica in the tests),
// so a limit point, if some other load produced one, is reported, not passed.
// Self-contact (non-adjacent segments closer than the section depth) is reported as a
// ring::NumericalError. Kinematics from multibody/chain.hpp unchanged.
#pragma once

#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// Static equilibrium under `statics.load` (its history is ignored: full load).
/// Returns the displacements of the recorded points (ring-centred frame, m), the
/// number of accepted load steps, the total Newton iterations, and every hinge's
/// deformed position. Cost: O(n^3) per Newton iteration (dense).
/// Requires a pin and a roller (otherwise the rigid rotation about the pin is free).
/// Throws std::invalid_argument for inputs that can never work and
/// ring::NumericalError when no equilibrium path is found or the ring touches itself.
ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::StaticOptions& statics);

}  // namespace multibody
