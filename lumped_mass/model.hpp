// Assembly of the lumped-mass models of a ring, written independently of
// multibody/: the four variants are built in CARTESIAN node coordinates on the
// regular n-gon whose side is l = 2 pi R / n (perimeter = circumference).
//
// Geometry. Node k (k = 0..n-1) sits at polar angle a_k = anchor + 360 k / n degrees
// (ring::node_angles), at distance rho = l / (2 sin(pi/n)) from the centre; side k
// joins node k to node k+1 (mod n), counter-clockwise.
// An arch (ring.arc = [from, to], span alpha rad; the chain only, checks.hpp): an OPEN chain of
// n links, l = R alpha / n (the chain's length = the arc's), nodes k = 0..n at from + span k / n
// at rho = l / (2 sin(alpha / (2n))); the ring's closing link is absent. Model::n then counts
// the n + 1 nodes and Model::links the n links.
//
// DOF order (node-major), stated once for every matrix below:
//   chain:  {ux_0, uy_0, ux_1, uy_1, ...}                 (2 per node, hinge displacements)
//   frame:  {ux_0, uy_0, th_0, ux_1, uy_1, th_1, ...}     (3 per node, th = nodal rotation, ccw;
//           the Timoshenko frame's th is the rotation of the cross-section)
// in the ring-centred frame, m and rad.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "ring/spec.hpp"

namespace lumped {

using SpMat = Eigen::SparseMatrix<double>;  // column-major, int indices

/// The linearised model about the undeformed n-gon: K x = omega^2 M x subject to
/// C x = 0 (internal constraints) and S x = 0 (supports).
struct Model {
  ring::LumpedOptions::Variant variant = ring::LumpedOptions::Variant::chain;
  int n = 0;                 ///< nodes (= links / elements on a ring; links + 1 on an arch)
  int links = 0;             ///< links / elements: options.n
  bool open = false;         ///< an arch (ring.arc): node 0 at `from`, node n - 1 at `to`
  int dofs_per_node = 2;     ///< 2 (chain) or 3 (frame variants, timoshenko_frame included)
  double anchor_deg = 0.0;   ///< polar angle of node 0 (the pin, or 0 for a free ring)
  double side = 0.0;         ///< l = 2 pi R / n, m (an arch: R alpha / n)
  double circumradius = 0.0; ///< rho = l / (2 sin(pi / n)), m (an arch: l / (2 sin(alpha / 2n)))
  /// Unknowns: the node DOFs (dofs_per_node * n, the order above), then, for the chain in
  /// the linear modes, the rotation chi of every hinge with a point inertia and no clamp
  /// (Terms::hinge_rotations' order, rad; add_terms in model.cpp). N = node_dofs() + those.
  int node_dofs() const { return dofs_per_node * n; }
  SpMat K;                   ///< stiffness, N x N, N/m; K = B^T diag(D) B
  /// The stiffness in factored form, strain energy = 1/2 sum_i D_i (B x)_i^2. Rows of B:
  /// chain: the hinge turning angles theta_j (n rows, rad/m; an arch: its n - 1 interior
  /// hinges, the ends have no hinge spring), D_j = EI/l;
  /// frames: per element j, rows 3j = axial strain (u2 - u1) . t / l, D = EA l, and
  /// 3j+1, 3j+2 = curvature at the two Gauss points x = l/2 (1 -+ 1/sqrt 3), D = EI l/2
  /// (two-point Gauss integrates the linear curvature's energy exactly);
  /// timoshenko_frame: per element j, rows 4j (axial strain, D = EA l), 4j+1, 4j+2 (the
  /// curvature th' at the Gauss points, D = EI l/2) and 4j+3 (the shear strain, constant
  /// along the element, D = kappa G A l).
  /// Then, for every variant, one row per positive stiffness of the spec's terms
  /// (assemble()): foundation (2 per node), springs kx, ky, kr, the chain's clamp; and per
  /// chain hinge rotation chi, a row m_h - chi (D = 4 EI/l) and, if kr > 0, a row chi (D = kr)
  /// (model.cpp, add_terms).
  /// The solvers work with B and D, never with the assembled K: K's entries are of
  /// order EI/l^3 while a smooth mode's K x is of order EI/R^4 |x|, so rounding K costs
  /// eps (R/l)^4 relative accuracy in the low eigenvalues; through B it costs eps (R/l)^2.
  SpMat B;
  Eigen::VectorXd D;
  SpMat M;                   ///< mass, N x N, kg (singular for the chain, and the
                             ///< lumped frame's rotation rows are zero; the Timoshenko
                             ///< frame's is diagonal and positive)
  SpMat C;                   ///< internal constraints: chain link lengths (n x N, rows
                             ///< t_j . (u_{j+1} - u_j) = 0, t_j the unit side vector); empty (0 x N) for frames
  SpMat S;                   ///< supports: one row per blocked direction, a unit vector on one
                             ///< node's (ux, uy) or on a frame node's rotation alone: 2 rows per
                             ///< pinned point, roller 1 row (normal to pin-roller line), a frame's clamp 1 row
  std::vector<char> massless;///< per DOF: 1 if it carries no mass and is condensed statically
                             ///< (the lumped frame's rotations without a point inertia), else 0
  int expected_rigid = 0;    ///< rigid modes the spec leaves, RingSpec::rigid_modes() (0 to 3)
  double lambda_scale = 0.0; ///< EI / (rho A R^4), rad^2/s^2: scale of every bending omega^2
};

/// Builds the chosen variant. Checks (std::invalid_argument, naming the key and the valid
/// range): n >= 4; positive radius, E, rho, A, I; a roller needs a pin, must fall on a node
/// (ring::on_node) and differ from the pin node; pins, clamp, springs and masses on nodes
/// (anchor + 360 k / n), the clamp at a pinned point, stiffnesses, masses and inertias
/// finite and >= 0. O(n) time and memory.
///
/// ring.variations (terms.hpp, written once): every variant on a closed ring at rest. The chain's
///   link mass is rho A integrated over the link's arc (3-point Gauss), its hinge spring EI / l
///   the local EI at the hinge; a frame element takes the section at its midpoint's angle
///   (the midpoint rule). Each O(l^2) or better: the models keep their order 2.
/// chain: point masses m = rho A l at the side midpoints, rigid massless links (rows of C),
///   rotational springs k = EI/l at all n hinges. An arch: the n links' midpoint masses (an
///   end node carries one link's, m/4 [I I; I I] with its neighbour: on the diagonal, lumped,
///   half a link's mass at an end and a whole link's at an interior node), springs at the n - 1
///   interior hinges; an end has none, except a clamp's half hinge 2 EI/l to the wall on the
///   end link's rotation (terms.hpp). The spring angle at hinge j is the
///   turning angle between sides j-1 and j, theta_j(P) = atan2(a x b, a . b) with
///   a = P_j - P_{j-1}, b = P_{j+1} - P_j; K = k sum_j grad theta_j grad theta_j^T is its
///   exact Hessian at the unstressed n-gon (the term with the Hessian of theta_j is
///   multiplied by the spring moment, zero there; link forces are zero too).
/// frame / frame_consistent: straight two-node Euler-Bernoulli elements on the sides,
///   linear axial (EA), cubic Hermite bending (EI); masses rho A l / 2 per element end on
///   the translations only (frame, rotations massless -> condensed) or the consistent
///   mass matrix (frame_consistent).
/// timoshenko_frame (the Timoshenko model, on either ring.theory; checks.hpp check_theory): straight
///   two-node shear-flexible elements on the sides, Przemieniecki's (Theory of Matrix
///   Structural Analysis, 1968, sec. 5.6: the exact static solution of a Timoshenko beam
///   without span load, cubic deflection and quadratic section rotation coupled through
///   phi = 12 EI / (kappa G A l^2)), linear axial (EA); masses lumped: rho A l / 2 per
///   element end on the translations, rho I l / 2 on the section rotations (every DOF
///   inertial). phi -> 0 is the Hermite element exactly: no shear locking in a thin ring.
///   The rotational terms below (kr, J, clamp) act on the node's rotation unknown, the
///   section rotation: the only rotation that is single-valued at a node (the centroid
///   line's tangent jumps there by the two elements' shear strains).
/// Terms of every variant (ring/spec.hpp), each written once in terms.hpp (energy, gradient and
/// Hessian at any configuration, shared with the nonlinear chain; here their rows at rest):
///   rotation of the tangent at node h: the frames' rotation unknown th_h; the chain has none
///     and uses the chord through the node's neighbours, the mean of its two links' rotations;
///   pins: both translations of the node in S;
///   springs: kx, ky on ux_h, uy_h, kr on the rotation (rows of B, D = k);
///   point masses: m on ux_h, uy_h, J on the rotation; a lumped-frame rotation with J > 0 is
///     inertial and kept, not condensed;
///   clamp: frames: their rotation = 0, in S before any condensation; the chain: kr -> infinity
///     in the chain's convention below;
///   the chain's rotational terms follow multibody/attachments.hpp, so both chains are one
///     model: its hinge spring K = EI/l is two halves 2K from each link to the hinge's own
///     rotation chi; without a point inertia chi is massless and condensed: kr from chi to
///     the ground is 4K and kr in series on the chord rotation, a clamp is 4K on it (order 2;
///     a constraint on the chord rotation would be order 1, terms_test.cpp); with a point
///     inertia (and no clamp) chi is an unknown after the node DOFs carrying J and kr (order
///     2; J condensed onto the chord rotation quasi-statically was order 1, terms.hpp);
///   foundation: lumped at the nodes, each standing for one side l of ring: l k_r (r.u)^2 +
///     l k_t (t.u)^2, r and t the undeformed node's radial and tangential unit vectors. With the
///     nodal (trapezoidal) rule on a periodic integrand the error is the n-gon's O(h^2), like
///     the rest of each model (tests/lumped_mass/terms_test.cpp measures the order).
Model assemble(const ring::RingSpec& spec, const ring::LumpedOptions& options);

/// A frame variant's element natural stiffness, for its corotational form (frame.hpp): the
/// energy of an element of rest length l is 1/2 axial e^2 + 1/2 t^T bending t, e the
/// elongation and t = (th1 - beta, th2 - beta) the section rotations relative to the chord
/// rotation beta. Taken from the variant's linear element above: axial = EA/l and bending =
/// its (th1, th2) block, EI / ((1 + phi) l) [4 + phi, 2 - phi; 2 - phi, 4 + phi] for
/// Przemieniecki's (timoshenko_frame), phi = 0 for the Hermite element (frame,
/// frame_consistent: the same stiffness) (the element matrix annihilates the rigid motions,
/// so that block is all of it). std::invalid_argument for the chain. O(1).
struct NaturalStiffness {
  double axial = 0.0;       ///< N/m
  Eigen::Matrix2d bending;  ///< N m/rad
};
NaturalStiffness natural_stiffness(const ring::RingSpec& spec, double l, ring::LumpedOptions::Variant variant);

}  // namespace lumped
