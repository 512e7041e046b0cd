// The CalculiX column of the forced nonlinear response: *DYNAMIC, DIRECT with NLGEOM and
// ALPHA = 0 (Newmark's average acceleration, the paper's; fixed dt to t_end), from rest,
// every load (deck.hpp) times its history (*AMPLITUDE).
//
// The history has the recorded points' displacements (the beam nodes' means) at t = 0 and
// after every increment; newton_iterations from ccx's .sta. ccx's energies are not read:
// kinetic, strain, work, energy_error and constraint_residual are NaN (ringvib's energy
// guard does not apply to this column). Refused (exit 2, naming the key): another
// integrator, damping.
//
// Cost: ccx's: about 13 s of CPU for 40 B32R elements and 140 increments on one thread.
#pragma once

#include <string>

#include "calculix/ccx.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace calculix {

/// What the response refuses before running (ring::InputError naming the key), and no ccx.
void check_response(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::ResponseOptions& rs);

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                          const ring::ResponseOptions& rs, const Hooks& hooks = {}, const std::string& title = "");

}  // namespace calculix
