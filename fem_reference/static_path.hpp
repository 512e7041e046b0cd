// Internal to fem_reference/: the statics of one discretization of the geometrically
// exact beam as an equilibrium path from rest (static_path.cpp): the beam's equilibrium
// (its residual, bordered tangent and self-contact check) followed by the shared
// continuation driver (paths/continuation.hpp). nonlinear.hpp documents the method;
// nonlinear.cpp drives it (the inextensible extrapolation, the reference refinement).
#pragma once

#include <limits>

#include "fem_reference/nonlinear.hpp"
#include "fem_reference/ring_model.hpp"
#include "paths/continuation.hpp"

namespace fem::detail {

/// One discretization's static path and, when it reached the full load, its equilibrium.
struct StaticSolve {
  paths::Trace trace;                          ///< how and where the path ended
  bool reached() const { return trace.end == paths::Trace::End::reached; }
  std::vector<std::array<double, 2>> record;  ///< displacement at each record point (reached)
  std::vector<double> node_x, node_y;         ///< deformed vertices (reached)
  long long unknowns = 0;
  std::vector<StaticPath::Point> path;        ///< every accepted equilibrium, from rest
  /// st.path: every accepted equilibrium from rest as ring::PathPoint (the displacements
  /// at st.record, the ovalisation between opposite vertices), the touching one last.
  std::vector<ring::PathPoint> points;
  /// st.path: the located limit points (paths::Trace::limit_state) as ring::PathPoint.
  std::vector<ring::PathPoint> limits;
  /// ring.plastic, at the path's end: the plastic work done (J) and the largest |plastic
  /// curvature| (1/m) of the beam's bending points (plastic_points.hpp); 0 without.
  double dissipated = 0.0;
  double plastic_curvature = 0.0;
  /// static.displacement, at the path's end: the force on the ring at the driven point (N).
  std::array<double, 2> reaction{0.0, 0.0};
  /// [plates], at the path's end: the contact length on each plate (m); reaction is then
  /// the force of the plate at plates.axis (N).
  std::array<double, 2> contact_length{0.0, 0.0};
  /// [plates]: the load factor of the last accepted equilibrium at which neither plate
  /// pressed the ring (backed off past its springback: no equilibrium position along their
  /// normal beyond it), else NaN; failure_message says so.
  double left_plates = std::numeric_limits<double>::quiet_NaN();
};

/// Traces the path of `st` with the discretization `setup` (no throw on a failed path:
/// see paths::Trace::end). st.path: branch switching on (continuation.branch_switch),
/// `points` recorded, and a path that ends in contact also gets `record` and the vertices
/// at its touching equilibrium. Cost: per Newton iteration an assembly and a sparse LU of the
/// bordered tangent (UMFPACK); per accepted step a self-contact check, O(2 pi R / depth).
StaticSolve trace_path(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st,
                       const ContinuationOptions& continuation);

/// The ring::NumericalError message of a path that did not reach the full load.
std::string failure_message(const StaticSolve& s, const ContinuationOptions& continuation);

}  // namespace fem::detail
