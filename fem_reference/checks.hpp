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

/// Linear modes: positive geometry and material, elements >= 4, degree in kMinDegree..kMaxDegree,
/// tolerances in (0, 1) for a reference, a roller only with a pin, on an FE vertex; further
/// pins and a clamp only with a pin, the clamp at a pinned point; pins, springs and masses on
/// FE vertices (the message names the key); stiffnesses, masses and foundation moduli
/// finite and >= 0; the terms beyond the paper's ring only on the curved geometry.
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
