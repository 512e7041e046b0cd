// Linear buckling of the lumped-mass `chain` and of the corotational Timoshenko frame
// (frame.hpp: the same steps on its tangent Hess V + s Hess P, its supports linear rows whose
// multipliers leave no Hessian) (ring/analysis.hpp, BucklingOptions: the one
// definition (K_0 + lambda K_1) phi = 0 of every solver), on the nonlinear chain's own
// model (nonlinear.hpp: hinge positions x, rigid links c_j(x) = 0 and support rows, hinge
// springs EI/l, the spec's terms, the loads as potentials; chain.hpp's tangent, the statics'
// Newton matrix, is the only stiffness used).
//
// ## Method
// T(x, lambda, s) = Hess V(x) + sum_j lambda_j Hess c_j + s Hess P(x) (chain.hpp, tangent),
// G = the constraint Jacobian at rest x0, Z an orthonormal basis of its kernel (the
// constraints' tangent space at rest: column-pivoted Householder QR of G^T, rank-revealing,
// so that redundant support rows cost nothing).
//  1. Linear statics at rest (lambda = 0, s = 0; the statics' residual grad V + G^T lambda +
//     s grad P): T0 x1 + G^T mu1 = -grad P(x0), G x1 = 0, solved as x1 = Z y,
//     (Z^T T0 Z) y = -Z^T grad P(x0), and mu1 from G^T mu1 = -(grad P + T0 x1) (least
//     squares through the same QR; exact, the right side lies in range G^T). Uniform
//     pressure gives x1 = 0 and mu1 the links' hoop forces.
//  2. K_1 = d/ds T(x0 + s x1, s mu1, s) at s = 0, by central differences
//       D(h) = (T(x0 + h x1, h mu1, h) - T(x0 - h x1, -h mu1, -h)) / (2h)
//     at h and 2h and Richardson's K_1 = (4 D(h) - D(2h)) / 3: the links' hoop-force
//     stiffness mu1 Hess c and the load stiffness Hess P(x0) enter linearly (exact up to
//     rounding for any h), the springs' and terms' Hessians through the displacement h x1.
//     h = 1e-3 l / max|x1| (l the link): truncation ~ (h |x1| / l)^4 ~ 1e-12; the rounding of
//     T, whose entries are ~ (R/l)^4 times the pencil's low eigenvalues, divided by a change
//     200 times larger than a 5e-6 l move gives: agreement with the multibody chain (the
//     same discrete model, analytic K_1) under two point loads to 2e-10 at n = 40, 1e-8 at
//     n = 80, 4e-7 at n = 160 (it was 9e-6 at n = 80 with one 5e-6 l central difference).
//     h = 1 and one difference when x1 = 0 exactly.
//  3. K0r = Z^T T0 Z, K1r = Z^T K_1 Z, then modal::critical_factors (Cholesky of K0r and a
//     symmetric eigensolve); modes x = Z y, sampled at the common stations as the modes are
//     (modes.hpp, sample_shape).
//
// Cost: dense, O(n^3) time and O(n^2) memory (the QR's explicit Q is 2n x 2n, the pencil
// n - 3 square for a chain on a pin and a roller; the tangents stay sparse): measured 0.04 s
// at n = 160, 0.9 s at n = 500, 6 s at n = 1000 (one core, release build).
// Accuracy: the tangent's entries are O(EI/l^3) while the low factors are O(EI/R^3), so
// rounding costs ~eps (R/l)^4 relative (model.hpp's remark on the assembled K): measured as
// the split of the follower pressure's double pair, 2e-10 at n = 160 and 3e-7 at n = 1000,
// against a discretization error of 5e-4 and 4e-5.
//
// Usage:
//   ring::RingSpec spec = ...;                 // pinned at 270 deg, roller at 90 deg
//   ring::BucklingOptions b;
//   b.loads.pressure = {1.0, ring::Pressure::Kind::follower};
//   ring::LumpedOptions o;                     // n = 40, chain
//   ring::BucklingResult r = lumped::compute_buckling(spec, o, b);
//   // r.factors[0] ~ 3 EI / R^3 (N/m per 1 N/m): ring::pinned_ring_critical_pressure
#pragma once

#include "lumped_mass/checks.hpp"  // check_buckling: what compute_buckling refuses
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The `buckling.count` lowest positive critical load factors of `buckling.loads` on the chain
/// (file comment), with their mode shapes. Requires what check_buckling checks (throws
/// std::invalid_argument naming the key otherwise), and as many positive factors as asked
/// (modal::critical_factors: std::invalid_argument naming buckling.count).
/// Result: solver "lumped"; model {n, variant}; unknowns = the pencil's size, dim ker G
/// (n - 3 on a pin and a roller); factors ascending; shapes at the common stations.
ring::BucklingResult compute_buckling(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                      const ring::BucklingOptions& buckling);

}  // namespace lumped
