// Linear buckling of the rigid-segment chain (ring/analysis.hpp, BucklingOptions) on the
// dense path of its statics (statics.hpp, detail::DenseTangent), in the paper's segment
// angles:
//  - the linear prebuckling state (dq, dlambda) from [T_0 G^T; G 0] (dq, dlambda) = (Phi, 0)
//    at rest, T_0 = K + the terms' Hessian;
//  - K_1 = dT/ds along it: the load stiffness at rest (follower and central pressure, and
//    point loads and gravity, whose constant hinge forces are not constant in the angles),
//    diag(dlambda . Hess g) (the links' prebuckling forces: the hoop force of a pressure,
//    the further pins' reactions), and the terms' Hessian differentiated along dq (a central
//    difference with h max|dq| = 1e-6 rad: truncation O(1e-12), rounding O(1e-10));
//  - both on the constraints' tangent space at rest (an orthonormal basis Z of ker G from a
//    Householder QR of G^T), and the pencil's lowest positive factors (modal/buckling.hpp).
// On an inextensible chain a uniform pressure leaves dq = 0: lambda is then the chain's
// exact bifurcation load, which converges to the ring's closed forms at O(1/n^2).
// Cost: O(n^3) time (the dense LU, QR and eigensolve), O(n^2) memory.
#pragma once

#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// What the chain's buckling refuses (std::invalid_argument naming the key):
/// multibody.method = "sparse" (the O(n) path has no buckling), a ring that the
/// supports leave free to move rigidly under the loads. O(1).
void check_buckling(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                    const ring::BucklingOptions& buckling);

/// The lowest buckling.count positive critical load factors of buckling.loads and their
/// mode shapes at the common stations. Throws std::invalid_argument for fewer positive
/// factors than asked (modal::critical_factors).
ring::BucklingResult compute_buckling(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                      const ring::BucklingOptions& buckling);

}  // namespace multibody
