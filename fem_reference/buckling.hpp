// Linear buckling of the geometrically exact FE beam (nonlinear.hpp) about the undeformed
// ring, by the one definition of every solver (ring/analysis.hpp, BucklingOptions):
//
//   (K_0 + lambda K_1) phi = 0,   K_1 = d/ds T(s u_1, s) at s = 0,   K_0 u_1 = f,
//
// T(q, s) = hess V(q) - s hess Phi(q) the beam's Newton tangent under s times the loads
// (BeamPotential: the beam, springs, foundation, and the load stiffness of follower and
// central pressure), f = grad Phi(0) the load vector at load factor 1. NO deal.II
// includes here (see modes.hpp).
//
// Method (buckling.cpp), one discretization (fem.elements cells of fem.degree):
//  - T_0 = T(0, 0), assembled on the reduced unknowns of the beam (make_beam: RingModel, or
//    the Reissner TimoshenkoModel for ring.theory = "timoshenko"; pin, roller, further
//    pins and clamp eliminated as the statics eliminate them: the constraints are linear
//    and exact at any displacement, so the reduced space is the constraints' tangent space
//    and they carry no multiplier term); it is the linear model's stiffness K_0;
//  - u_1 = T_0^-1 f (sparse LU, UMFPACK);
//  - K_1 = [8 (T(h) - T(-h)) - (T(2h) - T(-2h))] / 12h, T(t) = T(t u_1, t): the five-point
//    central difference of the assembled tangent along the linear prebuckling path, with
//    h max|u_1| = 3e-3 R. Why that h: the tangent's entries are the membrane stiffness EA
//    and its change along the path is EA times the strains and rotations of h u_1; the
//    difference keeps ~eps / 3e-3 of it, and that noise reaches a bending mode's factor
//    amplified by the membrane-to-bending spread of K_0, while the stencil's truncation is
//    O((3e-3)^4). Measured on the paper's ring: 2e-11 of the factors (the two-point
//    difference at 1e-6 R, the first choice, left 1e-7; buckling.cpp, kPathStrain). An
//    analytic K_1 would need the third derivatives of the beam's energy, which the code
//    does not have;
//  - the lowest buckling.count positive lambda (and 8 guards) by modal::critical_factors
//    on the dense K_0, K_1 (the shared eigen step), then refined as the modes refine theirs
//    (Rayleigh-Ritz with K_0 applied in extended precision from the strain fields, and
//    inverse-iteration corrections; pencil.cpp, refine()): the dense step in double
//    loses 3e-9 (extensible) to 1e-7 (inextensible) of the bending factors to the membrane
//    stiffness, the refined factors keep ~2e-11; shapes sampled at the ring::kStations
//    common stations by the modes' sample().
// Inextensible (fem.extensible = false): the modes' rule (modes.hpp): EA = beta EI / R^2
// for beta = 1e6 and 2e6, lambda(beta) = lambda_inf + c / beta + O(beta^-2) extrapolated
// to 2 lambda(2 beta) - lambda(beta); shapes of 2 beta. The extensible beam's factors
// differ from the inextensible ring's closed forms by O(I / (A R^2)) (9e-6 for the paper's
// ring; measured in tests/fem_reference/fem_buckling_test.cpp).
// Reference (fem.reference = true): the statics' refinement (nonlinear.cpp,
// refine_until in reference.hpp): the degree raised to fem::kMaxDegree, then the cells
// split, until the requested factors change by less than fem.tolerance (relative, the
// largest over the factors); error_estimate is that last change.
//
// Accuracy: converged factors match the inextensible closed forms to ~2e-11 (measured,
// tests/fem_reference/fem_buckling_test.cpp); a refined pair whose residual stays above
// 1e-4 is a ring::NumericalError. The dense step stops at kDenseBucklingLimit unknowns (a
// request beyond it is refused, a reference refinement that reaches it fails).
//
// Cost per discretization of N reduced unknowns (N ~ 2 p cells): five assemblies,
// O(cells (p+2) (2p+3)^2), one sparse LU, O(N p^2), the dense eigen step, O(N^3) time
// and O(N^2) memory, and the refinement, O(rounds m (N p + N^2)) for m = count + 8 pairs;
// twice that when inextensible. Measured (release build): the paper's ring on 16
// elements of degree 8 (N = 269), 0.05 s extensible, 0.1 s inextensible.
#pragma once

#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem {

/// Largest number of reduced unknowns the dense buckling eigen step takes (O(N^3)): a
/// request or a reference refinement beyond it is refused (invalid_argument) or fails
/// (NumericalError). 3000 unknowns: 72 MB per dense matrix (three are held).
constexpr long long kDenseBucklingLimit = 3000;

/// What linear buckling refuses before it computes (std::invalid_argument naming the key):
/// everything the statics refuse (check_static: the curved geometry; loads on vertices;
/// supports that hold every rigid motion the loads leave free; a Timoshenko ring buckles as
/// the Reissner beam), buckling.count >= 1. The
/// upper bound of buckling.count (the model's positive factors) is known only after the
/// solve (compute_buckling). No deal.II: compiled into the driver's fem_checks. O(1).
void check_buckling(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::BucklingOptions& buckling);

/// The lowest buckling.count positive critical load factors of buckling.loads and their
/// shapes (file comment).
/// \return solver "fem"; model {elements, cells, subdivisions, degree, extensible,
///         reference, refinements, path_step, max_residual (the refined pairs', dual norm
///         of K_0)}; factors ascending; shapes at ring::kStations
///         stations (ModeShape's scaling); unknowns (reduced); seconds; error_estimate
///         (reference runs only).
/// \throws std::invalid_argument for input that can never work (check_buckling; a count
///         above the unknowns or the model's positive factors, naming buckling.count; a
///         discretization above kDenseBucklingLimit), ring::NumericalError for a failed
///         factorization or a reference that does not converge.
ring::BucklingResult compute_buckling(const ring::RingSpec& spec, const ring::FemOptions& options,
                                      const ring::BucklingOptions& buckling);

}  // namespace fem
