// Internal to multibody/: the ring's terms beyond the paper's chain (ring/spec.hpp: further
// pins, a clamp, elastic supports, point masses, the Winkler foundation), each written once
// as a term on hinge displacements and pulled back to the chain's coordinates.
//
// ## Terms (hinge k at rest P_k, displacement u_k = p_k(q) - P_k)
// - foundation: a spring l (k_r r_k r_k^T + k_t t_k t_k^T) at every hinge (r_k, t_k the
//   radial and tangential unit vectors of the rest hinge, l the length of ring a hinge
//   stands for): the Winkler foundation lumped at the hinges, its energy exactly quadratic
//   in u_k since its directions are those of the undeformed point;
// - an elastic support at hinge h: diag(kx, ky) on u_h, and kr on the hinge's rotation psi;
// - a point mass at hinge h: m on u_h, its inertia on psi;
// - a further pin at hinge h: u_h = 0 (2 constraint rows);
// - a clamp at hinge h: psi = 0.
// The hinge's rotation psi: the spring EI/l at a hinge stands for the bending from one
// segment's midpoint to the next; split in two halves of 2EI/l, each from a segment to the
// hinge's own (massless) rotation psi, it is the same spring with psi = the mean m of the two
// segments' rotations. A rotational spring kr from psi to the ground, psi condensed, is a
// spring 4EI/l and kr in series on m (4K kr / (4K + kr) with K = EI/l), and
// psi = 4K m / (4K + kr). A clamp is kr -> infinity: 4K on m. (A constraint m = 0 instead
// converges at order 1 only, 1.04 measured over n = 80 .. 320: the curvature jumps at a
// clamp, so m = O(l) there.)
//
// ## Pull-back
// u_k is linear in the angles to first order, u_k = sum_{j<k} c_j dphi_j [+ (dx_0, dy_0)],
// c_j = l e'(phi0_j), so sum_k P_k^T B_k P_k has the entries c_i^T S_{max(i,j)+1} c_j with
// the suffix sums S_m = sum_{k >= m} B_k: O(n^2) for the dense matrices, as the dense path.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "multibody/chain.hpp"
#include "ring/spec.hpp"

namespace multibody::detail {

/// The spec's terms linearized about the rest n-gon, in the chain's coordinates.
struct LinearTerms {
  Matrix K;  ///< dofs x dofs stiffness (foundation, springs)
  Matrix M;  ///< dofs x dofs mass (point masses)
  Matrix J;  ///< extra constraint rows (further pins) x dofs
  bool empty() const { return J.rows() == 0 && K.isZero(0.0) && M.isZero(0.0); }
};

/// The terms of `spec` on `chain` (whose anchor is spec.supports.pin or the free ring's
/// fallback). Throws std::invalid_argument naming the key when a point is not a hinge.
/// O(n^2) time and memory.
LinearTerms linear_terms(const Chain& chain, const ring::RingSpec& spec);

}  // namespace multibody::detail
