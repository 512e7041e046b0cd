// What the FE beam refuses before it computes: a request that can never work is
// std::invalid_argument naming the key and the valid range. Each analysis calls its check
// first, and the driver calls them for every analysis a scene asks of the FE beam before
// any solver runs (and before the deal.II plug-in is loaded). No deal.II here: this file
// is compiled into the driver as well as into the plug-in. O(1).
#pragma once

#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace fem {

/// The element degrees p (of the bending field; the curved tangential field has p + 1) the
/// FE beam offers: fem.degree must lie in kMinDegree..kMaxDegree, and the converged
/// references (modes, statics, response) raise p up to kMaxDegree before they split cells.
/// The cap is the modes reference's (FE_Q on Gauss-Lobatto points stays well conditioned
/// there) and holds for every analysis: at p = 16 the free ring's k = 2..13 match the closed
/// form to 1.5e-12 and the squeezed ring the elastica to 1.5e-12 (fem_validation_test,
/// fem_nonlinear_test: TheDegreeCap...). Higher degrees also lower the elements that double
/// precision resolves (modes.hpp, kPrecisionLimit). The driver's memory estimate of a
/// reference run takes p = kMaxDegree, and the scene reader takes the range from the registry.
constexpr int kMinDegree = 2;
constexpr int kMaxDegree = 16;

/// Largest eps lambda_max / |sigma| that the modes' eigen-solve resolves. The shift-invert
/// solve factors K - sigma M in double; when its spectrum spans more than ~1/eps the
/// factorization no longer represents the low end of the operator. Measured on the
/// paper's pinned ring (lambda_max by row sums, ring_model.hpp precision_ratio()): ratio
/// 2.0e4 (10^4 cells, p = 6) and 2.8e4 (3000, p = 12): the lowest frequencies to 1e-7
/// after the refinement; 1.6e5 (10^4, p = 8): 0.09 % off, residual 2e-2; 2.1e5 (5000,
/// p = 12), 8.2e5 (7000, p = 12), 3.4e6 (10^4, p = 12): wrong by 4 % to 40 times
/// (lambda_1 = 234 instead of 6.17 at 10^4), iterative refinement of a solve against
/// apply() diverging 16-fold per step; 340 at 1000 cells of p = 12 (docs/measured.md, "FE
/// precision limit"). The limit sits between the last good and the first bad ratio.
constexpr double kPrecisionLimit = 6e4;

/// A lower bound of that ratio from the element count and degree alone, for the curved
/// Euler-Bernoulli ring, whose bending sets lambda_max: 2.0e4 (elements / 10^4)^4 (p / 6)^q,
/// q = 7 for p >= 6, 8 below (the lower envelope of the measured ratios; checks.cpp).
/// check_modes refuses a discretization whose bound exceeds kPrecisionLimit before
/// anything is assembled. O(1).
double precision_ratio_bound(int elements, int degree);

/// Linear modes: positive geometry and material, elements >= 4, degree in kMinDegree..kMaxDegree,
/// tolerances in (0, 1) for a reference, a roller only with a pin, on an FE vertex; further
/// pins and a clamp only with a pin, the clamp at a pinned point; pins, springs and masses on
/// FE vertices (the message names the key); stiffnesses, masses and foundation moduli
/// finite and >= 0; the terms beyond the paper's ring only on the curved geometry; an
/// Euler-Bernoulli curved ring whose precision_ratio_bound exceeds kPrecisionLimit.
void check_modes(const ring::RingSpec& spec, const ring::FemOptions& options);
/// Nonlinear statics: as modes, plus the curved geometry, supports holding every rigid motion,
/// every point load and record point on an FE vertex, finite forces, pressure and gravity;
/// static.path with neither fem.reference nor fem.extensible = false (the message names the key).
void check_static(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::StaticOptions& statics);
/// Frequencies under load (modes.preload = "static", preload.hpp): what the statics refuse
/// (static.path aside: the modes need only the full load's equilibrium), and
/// fem.rotary_inertia (the geometrically exact beam has no cross-section rotary inertia,
/// as its response).
void check_preloaded_modes(const ring::RingSpec& spec, const ring::FemOptions& options,
                           const ring::StaticOptions& statics);
/// Forced response: as statics, but a pin alone suffices (a pin, or no rigid motion left
/// free); no rotary inertia, no hinge damping, the integrator "newmark" or
/// "generalized-alpha" (no other), 0 < dt <= t_end.
void check_response(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::ResponseOptions& response);

}  // namespace fem
