// Finite-element reference for the in-plane vibration of a ring: curved (or polygonal)
// Euler-Bernoulli beam elements, and curved Timoshenko elements (below), on deal.II. This
// header has NO deal.II includes on purpose: the rest of ringvib (and the dlopen boundary in plugin.hpp)
// sees only the shared result types, so that deal.II stays in fem_reference/'s .cpp files.
//
// The model. Mesh: a 1-D mesh in the polar angle theta, from the pin angle
// theta0 to theta0 + 2 pi, closed periodically through AffineConstraints, with
// `elements` equal pieces (vertex k at node_angles(spec, elements)[k]) each split into
// `subdivisions` equal cells.
//  - geometry `curved` (exact circle): fields are the polar components
//    u (tangential, counter-clockwise) and w (radial, outward) as functions of theta;
//    ds = R dtheta, centreline strain eps = (u' + w)/R, change of curvature
//    kappa = (u' - w'')/R^2, rotation phi = (u - w')/R (' = d/dtheta), exactly the
//    kinematics of ring/closed_form.hpp.
//  - geometry `polygon`: straight chords between the vertices (the paper's SAP5 frame):
//    the regular n-gon of side 2 pi R / n, i.e. perimeter = circumference, vertices at
//    radius R (pi/n) / sin(pi/n) in the node directions (docs/paper.md: what SAP5 computed);
//    fields are the Cartesian components (ux, uy); on a chord with unit tangent t and
//    outward normal n, eps = t.U_s, kappa = -n.U_ss, phi = -n.U_s (s: arc length).
// Energies: strain EA/2 int eps^2 + EI/2 int kappa^2 ds, kinetic rho A/2 int |U|^2 ds
// (consistent mass) plus, optionally, rho I/2 int phi^2 ds (cross-section rotary
// inertia). No shear deformation.
//
// C1 continuity of the bending field (deal.II 9.4 has no C1 element) is imposed
// weakly by a symmetric C0 interior penalty at every vertex (as step-47):
//   a_h(U,V) = sum_cells int (EA eps eps + EI kappa kappa) ds
//            + sum_vertices ( {M(U)} [[phi(V)]] + {M(V)} [[phi(U)]]
//                             + sigma EI / h [[phi(U)]] [[phi(V)]] ),
// M = EI kappa, [[phi]] = phi(right cell) - phi(left cell), {M} the average,
// sigma = 2 (q+1)(q+2) with q the largest degree of kappa (above the trace-inverse
// bound (q+1)^2 that makes a_h coercive), h the smaller neighbouring cell length.
// The method is consistent (the exact solution satisfies it), so eigenvalues converge
// like the square of the energy error: O(h^(2(p-1))) for degree p.
//
// Degrees: `degree` p (>= 2) is the degree of the bending field. On the exact circle
// the tangential field u has degree p+1 so that u' and w live in the same space:
// then the inextensional motions (u' = -w) are represented exactly and the thin ring
// (R / radius of gyration = 333 for the paper's ring) shows no membrane locking.
// On the polygon both Cartesian components have degree p (straight elements do not lock).
//
// Supports are AffineConstraints: pin (both components zero at vertex 0), roller
// (the component normal to the line pin-roller zero at the roller's vertex, which
// must be a vertex), further pins (both components zero at their vertices), free (three
// rigid modes without springs or foundation). Rigid modes are spec.rigid_modes(), counted,
// not numbered; on the exact circle rigid translations are represented only approximately
// by the polar fields, so their computed frequencies are small but not exactly zero.
//
// Terms beyond the paper's ring (exact circle only; the polygon refuses them, checks.cpp).
// Every point lies on a vertex (anchor + k 360/elements; anchor = the pin, or 0 deg).
//  - Rotation at a vertex. The field's rotation phi = (u - w')/R is the counter-clockwise
//    rotation of the centroid line's tangent (the tangent R e_theta + (u' + w) e_theta +
//    (w' - u) e_r turns by -(w' - u)/R). The C0 elements have no rotation unknown and phi
//    jumps at a vertex (the interior penalty drives the jump to the discretization error),
//    so a vertex has one rotation per neighbouring cell.
//  - clamp: both cells' phi = 0 at the clamp vertex, two AffineConstraints rows (each
//    eliminates one interior DoF of its cell; the vertex is pinned). The exact solution and
//    every test function satisfy them, so the interior-penalty form stays consistent.
//  - springs: kx/2 Ux^2 + ky/2 Uy^2 on the Cartesian displacement of the vertex
//    (Ux = -u sin a + w cos a, Uy = u cos a + w sin a) and kr/2 {phi}^2 on the mean
//    {phi} = (phi_left + phi_right)/2 of the two cells' rotations (consistent: the
//    vertex's natural condition [[M]] = kr phi pairs with {phi} of the test function). A
//    stiff kr converges to the clamp at rate 1/kr, a stiff kx = ky to a pin
//    (tests/fem_reference/fem_terms_test.cpp).
//  - point masses: m/2 (Ux_dot^2 + Uy_dot^2) and J/2 {phi_dot}^2 in the kinetic energy.
//  - foundation: 1/2 int (k_r w^2 + k_t u^2) ds over every cell, exact on the polar fields
//    (radial and tangential directions of the undeformed point).
// These terms enter K and M and the extended-precision operator of the refinement alike.
//
// Timoshenko (ring.theory = "timoshenko"; curved geometry only, the polygon refuses it by
// name; timoshenko_model.hpp). Fields u (tangential), w (radial) and psi (rotation of the
// cross-section, counter-clockwise), each C0 FE_Q of degree p (`degree`), on the same
// periodic mesh (an FESystem of three components). Strains exactly those of
// ring::closed_form::free_ring_timoshenko: eps = (u' + w)/R, shear gamma = psi - (u - w')/R,
// change of curvature kappa = psi'/R; energy EA/2 eps^2 + kGA/2 gamma^2 + EI/2 kappa^2 per
// length, kinetic rho A/2 (u^2 + w^2) + rho I/2 psi^2 (dots): the theory has the section's
// rotary inertia by definition (ring/spec.hpp), so fem.rotary_inertia is the Euler model's
// switch and the result reports rotary_inertia = true. Only first derivatives: an H1
// problem, no interior penalty.
//  - Locking. As depth/R -> 0, EA and kGA grow like (R/depth)^2 against EI/R^2 and the
//    discrete modes must approach the kernel eps = 0, gamma = 0 (u' = -w, psi = (u - w')/R).
//    Fully integrated, that kernel is poor in C0 P_p: eps = 0 asks the continuous w of degree
//    p to equal the discontinuous u' of degree p-1 (so w of degree p-1 and u in C1), gamma = 0
//    then asks psi = (u + u'')/R continuous (u in C2): the element locks, its error grows
//    like (R/depth)^2 at fixed h. Measured (that variant, depth/R = 1e-3, k = 2): p = 3,
//    32 cells, 7.8e-3 against 8.6e-8 below; p = 2 cannot even separate the rigid modes
//    below 128 cells.
//  - The choice: selective reduced integration, the membrane and shear terms with p Gauss
//    points, bending, foundation and mass with p + 1 (exact). On a cell every strain is a
//    polynomial of degree p in theta (ds = R dtheta, polar fields), and eps - P eps, with P
//    the L2 projection onto P_{p-1}, is a multiple of the Legendre polynomial of degree p,
//    which vanishes at the p Gauss points; (P eps)^2 has degree 2p - 2 <= 2p - 1. So p-point
//    Gauss integrates EA eps^2 as EA (P eps)^2 exactly, and the scheme IS the mixed
//    (Hellinger-Reissner) method with axial and shear force N, Q in discontinuous P_{p-1},
//    condensed cell by cell: conforming, no variational crime, and the closed form is the
//    exact solution of the model it discretizes. Its kernel is rich: P(u' + w) = 0 is
//    u' = -P w, solvable for every continuous w of zero mean, and P gamma = 0 is
//    w' = P u - R P psi. Such mixed rods converge uniformly in the thickness (Arunakirinathar
//    & Reddy, "Mixed finite element methods for elastic rods of arbitrary geometry",
//    Numer. Math. 64, 1993). Displacements in H1 and N, Q in L2 err by O(h^p), so
//    eigenvalues (and frequencies, relatively) by O(h^(2p)) at every depth/R: measured
//    orders 3.98, 5.98, 7.95 for p = 2, 3, 4, the same to three digits, and the same
//    errors, at depth/R = 1e-3 and 0.1 (tests/fem_reference/fem_timoshenko_test.cpp).
//    Not u of degree p+1 as in the Euler model: that cures membrane locking only, the shear
//    would still need a projection, and one rule for both keeps the fields of one degree.
//  - Terms (the Euler model's, where it has them): pin and further pins u = w = 0 at the
//    vertex (psi free); roller as above; clamp psi = 0 at the vertex (psi is a nodal
//    unknown: one row, no cell-end rotations); springs kx, ky on the vertex's Cartesian
//    displacement, kr on its psi; point masses m on the translation, J on psi; the
//    foundation 1/2 int (k_r w^2 + k_t u^2) ds, exact. The inextensible limit is the same
//    extrapolation in EA (the projected membrane term does not lock).
//  - The same eigen-solve (LinearModel, ring_model.hpp), rigid modes, refinement (apply()
//    forms the strains in long double: a bending mode's shear strain is ~(depth/R)^2 below
//    its terms), precision limit and p/h reference; degree p of all three fields, 2..16.
//
// Inextensible limit (extensible = false): EA is replaced by beta EI / R^2 for two
// large beta (1e6 and 2e6) and the squared frequencies are Richardson-extrapolated to
// beta -> infinity (omega^2(beta) = omega^2_inext - c / beta + O(1/beta^2)); shapes
// come from the larger beta.
//
// Eigen-solver: dense LAPACK (dsygv through LAPACKFullMatrix) up to 150 unknowns
// (netlib BLAS makes O(N^3) slow beyond); above, ARPACK (Lanczos, shift-invert mode 3)
// with a sparse UMFPACK factorization of K - sigma M, sigma = -(EI/(rho A R^4)) < 0 so
// that rigid modes keep it regular; only the lowest modes (plus 8 guard modes).
//
// Reference. Each refinement raises p by one (h once p = kMaxDegree). A change c_k between
// successive solutions is the error of the older one; with the contraction r = c_k / c_{k-1}
// the latest has about c_k r / (1 - r). The refinement stops when c_k < tolerance (the
// latest is then far better than the tolerance) or, one solve earlier, when that
// extrapolation is below it, trusted only where both changes are clean of the raw pairs'
// round-off and r <= kTrustedContraction (ring_model.hpp). On the paper's ring (40 cells)
// it stops at p = 7 with an estimate of 5.5e-10 (the change to p = 8 is 3.2e-10), where
// waiting for c_k < 1e-9 took p = 8, 40 % of the reference's time. The refinement is
// uniform (p, then h); adaptive refinement is not offered.
//
// Round-off and refinement. The thin ring's membrane stiffness makes
// lambda_max / lambda_1 ~ 1e9..1e10, so a double-precision eigen-solve returns the
// lowest frequencies with relative errors ~ eps lambda_max / lambda ~ 1e-7. Every
// solve is therefore refined: Rayleigh-Ritz on the computed span with Gram matrices
// accumulated in long double from the strain fields (no cancellation against the stiff
// entries), subspace-iteration steps q -= (K - sigma M)^{-1} r with Ritz after each
// until the residuals are below 1e-11 or stop halving (ring_model.hpp). A discretization
// too fine for double precision (eps lambda_max / |sigma| > kPrecisionLimit) is refused
// before the solve (std::invalid_argument), and a refined elastic pair whose residual
// stays above kAcceptedResidual is a ring::NumericalError (README, "The precision limit").
//
// max_residual: NOT the 2-norm ratio of ring::ModalResult's definition, which this model
// cannot report meaningfully: for a double vector q it cannot drop below
// ~ eps lambda_max / lambda ~ 1e-6 here, however accurate the pair. The FE reports the
// same ratio ||K q - lambda M q||_* / (||K q||_* + lambda ||M q||_*) in the dual norm of
// K - sigma M (||r||_*^2 = r^T (K - sigma M)^{-1} r), the norm in which the residual
// bounds the frequency error, and says so: residual_norm = kDualResidualNorm.
#pragma once

#include <string>

#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem {

/// ring::ModalResult::residual_norm of every FE modal result (see the file comment).
inline const char* const kDualResidualNorm = "dual norm of K - sigma M";

/// Natural frequencies and mode shapes of the ring (see the file comment for the model).
/// \param spec    ring, section, material, supports, springs, masses, foundation (every
///                point on a vertex: the pin is vertex 0, the others must satisfy
///                ring::on_node; the terms beyond the paper's ring need the curved geometry).
/// \param options elements >= 4, degree kMinDegree..kMaxDegree (checks.hpp: 2..16);
///                reference = true refines p (to kMaxDegree, then h) until the `count`
///                frequencies change by less than options.tolerance (relative, > 0)
///                between successive refinements, or until the latest solution's error
///                extrapolated from the last two changes is below it ("Reference" above),
///                and reports that estimate as error_estimate.
/// \param count   elastic modes wanted, 1 <= count <= unknowns - rigid modes.
/// \return solver "fem"; model {elements, cells, subdivisions, degree, geometry, theory,
///         extensible, rotary_inertia, reference, refinements} (the final discretization); rigid_modes; omega ascending
///         (rad/s, elastic only); shapes at ring::kStations stations; unknowns (free
///         unknowns after constraints); seconds; max_residual in the dual norm
///         (residual_norm = kDualResidualNorm); error_estimate.
/// \throws std::invalid_argument for options or count that can never work,
///         ring::NumericalError for a failed factorization, eigen-solve or refinement.
/// Cost: O(N (p+1)^2) assembly and, for N > 150, ARPACK with O(N p) work per
/// Lanczos step after an O(N p^2) banded factorization; O(N^3) dense below.
/// A spinning ring (spec.rotation.spinning()): the gyroscopic modes of the turning frame
/// instead (spin.hpp: omega ascending in that frame, waves, frame "rotating", max_residual in
/// the 2-norm; no reference; O((2N)^3) dense, N <= modal::kMaxGyroscopicUnknowns).
ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::FemOptions& options,
                                int count);

/// Writes the `count` lowest mode shapes to `dir`/fem_modes.vtu (not of a spinning ring:
/// std::invalid_argument naming rotation.speed) (deal.II DataOut on the
/// ring as a curve in the plane, Triangulation<1,2>: the circle, or the n-gon). For each
/// mode k (1-based) with frequency w (rad/s): the scalar fields `radial_k_omega_w` and
/// `tangential_k_omega_w` (polygon: `ux_...`, `uy_...`) and the vector
/// `displacement_k_omega_w` (Cartesian, for ParaView's Warp By Vector), scaled so that
/// the largest nodal value is 1. Returns the file written. O(count N).
/// Throws like compute_modes, and ring::NumericalError if the file cannot be written.
std::string write_vtu(const ring::RingSpec& spec, const ring::FemOptions& options, int count,
                      const std::string& dir);

}  // namespace fem
