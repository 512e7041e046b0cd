// The CalculiX column of the nonlinear statics: the ring under its loads (point loads,
// pressure, gravity: deck.hpp),
// *STATIC with NLGEOM (ccx's geometrically nonlinear continuum: large displacements and
// rotations of the expanded bricks), load stepped in static.steps increments.
//
// Displacements are those of the beam nodes (ccx prints the mean of the expanded section's
// nodes) at the recorded points; node_x/node_y the deformed beam nodes. Newton iterations
// are the sum of the ITRS column of ccx's .sta file. A run that does not reach the full
// load is exit 3 with ccx's last lines.
//
// Cost: ccx's: about 9 s for 160 B32R elements and 20 increments on one thread.
#pragma once

#include <string>

#include "calculix/ccx.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace calculix {

/// What the statics refuse before running: the deck's refusals, the load and the recorded
/// points off the nodes (ring::InputError naming the key), no ccx.
void check_static(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::StaticOptions& st);

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                                const ring::StaticOptions& st, const Hooks& hooks = {},
                                const std::string& title = "");

}  // namespace calculix
