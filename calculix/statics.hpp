// The CalculiX column of the nonlinear statics: the ring under its loads (point loads,
// pressure, gravity: deck.hpp),
// *STATIC with NLGEOM (ccx's geometrically nonlinear continuum: large displacements and
// rotations of the expanded bricks), load stepped in static.steps increments.
//
// Displacement control (static.displacement): no loads; the driven beam node's two
// displacements are a *BOUNDARY at s times the value (ramped over the step as ccx ramps a
// *STATIC step's boundaries), and its reaction is the node's RF (*NODE PRINT), the force the
// rig applies to the ring: ccx holds the mean displacement of the expanded section by MPCs,
// and the node's RF is the whole force through them (the driven pinch converges to the thick
// ring's closed form, tests/calculix/calculix_driven_test.cpp).
// Rigid plates ([plates]): ring::PlatePair's penalty as nonlinear springs from the beam nodes
// to plate nodes driven along the plates' normal (deck.hpp, plates_block); the reaction is plate
// 0's nodes' total RF, the contact lengths PlatePair::contact_lengths on the deformed beam
// nodes (a gap within the .dat's 7-digit resolution counting as touching).
// A history (static.history): one *STEP per leg, every load and the driven displacement times
// an amplitude in total time whose rows are the legs' factors (a leg to 0 unloads); the
// results at the last factor. static.path: every converged increment from rest as the path
// (ccx's load stepping: no limit point passed or located, no branch switched, no contact).
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

/// What the statics refuse before running: the deck's refusals (the resultant law, driven or
/// not), the loads, the driven point and the recorded points off the nodes (ring::InputError
/// naming the key), no ccx.
void check_static(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::StaticOptions& st);

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                                const ring::StaticOptions& st, const Hooks& hooks = {},
                                const std::string& title = "");

}  // namespace calculix
