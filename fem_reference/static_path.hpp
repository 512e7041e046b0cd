// Internal to fem_reference/: the statics of one discretization of the geometrically
// exact beam as an equilibrium path from rest (static_path.cpp): load stepping with
// Newton, arc-length continuation through limit points, the limit point located,
// self-contact checked. nonlinear.hpp documents the method; nonlinear.cpp drives it
// (the inextensible extrapolation, the reference refinement).
#pragma once

#include "fem_reference/nonlinear.hpp"
#include "fem_reference/ring_model.hpp"

namespace fem::detail {

/// One discretization's static path and, when it reached the full load, its equilibrium.
struct StaticSolve {
  enum class End { reached, contact, arc_steps_exhausted, stalled };
  End end = End::reached;
  std::vector<std::array<double, 2>> record;  ///< displacement at each record point (reached)
  std::vector<double> node_x, node_y;         ///< deformed vertices (reached)
  int steps = 0, iterations = 0;              ///< accepted load and arc steps; their Newton iterations
  long long unknowns = 0;
  std::vector<StaticPath::Point> path;        ///< every accepted equilibrium, from rest
  double limit = std::numeric_limits<double>::quiet_NaN();  ///< first maximum of the load factor
  bool continuation = false;
  int arc_steps = 0;
  double stepping_stopped = 0.0;  ///< load factor where load stepping handed over
  double end_load = 0.0;          ///< where the path ended (contact: the load factor of the touch)
  std::string contact;            ///< where the ring touched itself
  double depth = 0.0;             ///< the section depth (m), the self-contact distance
};

/// Traces the path of `st` with the discretization `setup` (no throw on a failed path:
/// see StaticSolve::end). Cost: per Newton iteration an assembly and a sparse LU
/// (nonlinear.hpp); per accepted step a self-contact check, O(2 pi R / depth).
StaticSolve trace_path(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st,
                       const ContinuationOptions& continuation);

/// The ring::NumericalError message of a path that did not reach the full load.
std::string failure_message(const StaticSolve& s, const ContinuationOptions& continuation);

}  // namespace fem::detail
