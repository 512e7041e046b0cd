// What the FE beam refuses before it computes: a request that can never work is
// std::invalid_argument naming the key and the valid range. Each analysis calls its check
// first, and the driver calls them for every analysis a scene asks of the FE beam before
// any solver runs (and before the deal.II plug-in is loaded). No deal.II here: this file
// is compiled into the driver as well as into the plug-in. O(1).
#pragma once

#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace fem {

/// Linear modes: positive geometry and material, elements >= 4, degree in 2..12,
/// tolerances in (0, 1) for a reference, a roller only with a pin, on an FE vertex.
void check_modes(const ring::RingSpec& spec, const ring::FemOptions& options);
/// Nonlinear statics: as modes, plus the curved geometry, a pin and a roller, the load and
/// the record points on FE vertices, a finite force.
void check_static(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::StaticOptions& statics);
/// Forced response: as statics without the roller, no rotary inertia, no hinge damping,
/// the integrator "newmark" or "generalized-alpha", 0 < dt <= t_end.
void check_response(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::ResponseOptions& response);

}  // namespace fem
