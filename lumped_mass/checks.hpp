// What the lumped-mass models refuse before they compute: a request that can never work is
// std::invalid_argument naming the key. The nonlinear analyses call these first, and the
// driver calls them for every analysis a scene asks of the lumped models before any solver
// runs, so a refusal never comes after another solver's work. O(1).
//
// An arch (ring.arc, model.hpp: the chain as an open chain of n links) is taken by the chain's
// linear modes, linear buckling (a follower pressure with both ends pinned, no other load), nonlinear statics (point loads, gravity, static.path, ring.plastic at the interior
// hinges) and response; refused with ring::InputError naming ring.arc: the frames (every
// analysis), a pressure in the statics and the response, the dead and central pressures, a
// roller and the modes under load. Its points (supports, masses, loads, records)
// are nodes from + span k / n, k = 0..n.
#pragma once

#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The variant is the model's theory, ring.theory the ring's physics, and any variant is
/// taken on either: "chain", "frame" and "frame-consistent" are the Euler-Bernoulli models
/// (on a Timoshenko ring, its thin-ring model), "timoshenko-frame" the Timoshenko model (on
/// an Euler-Bernoulli ring it adds shear and the section's rotary inertia, as
/// fem.theory = "timoshenko" does). The Timoshenko frame needs a shear stiffness
/// kappa G A > 0: refused for a section given by {area, inertia} without
/// ring.shear_coefficient.
void check_theory(const ring::RingSpec& spec, const ring::LumpedOptions& options);
/// Linear modes: the shear stiffness of the Timoshenko frame (check_theory); every term of RingSpec (supports, masses,
/// foundation) is in the model; n >= 4 and every point (pins, clamp, springs, masses) a node:
/// anchor + 360 k / n (an arch: from + span k / n; the chain only, no roller).
/// ring.variations: taken on a closed ring at rest by every variant (model.hpp, terms.hpp);
/// with rotation.speed or ring.arc, std::invalid_argument naming ring.variations.
/// A spinning ring (rotation.speed, spin.hpp): "chain" (lumped.n <= kMaxPreloadHinges) and
/// "timoshenko-frame" (lumped.n <= modal::kMaxGyroscopicUnknowns / 3), on a closed ring without
/// rigid modes; "frame" and "frame-consistent" refuse it naming lumped.variant and
/// rotation.speed, and every other analysis refuses a spin (ring::refuse_rotation).
void check_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options);
/// ring.plastic (the resultant law, bending.hpp) is taken by the chain's nonlinear statics;
/// the frames (checks.cpp says why), the fibre law, and ring.plastic in any other analysis are
/// ring::InputError naming ring.plastic (exit 2).
/// Nonlinear statics: every variant (static.path: the chain only), n >= 4, a positive section and
/// material, every point of the spec (pins, clamp, springs, masses) and every point load on a
/// node (none at the pin), a pin (or springs / a foundation that hold every rigid motion),
/// supports and terms that leave no rigid motion (RingSpec::rigid_modes() == 0), finite
/// pressure and gravity, static.steps >= 1.
/// static.displacement (the chain and the frames on a closed ring): no loads beside it, a finite
/// non-zero value, the driven point a node on no pinned point or roller (ring::InputError naming
/// static.displacement or static.displacement.at; an arch is refused naming
/// static.displacement), and it counts as a pin in the rigid-mode rule.
/// [plates]: a closed ring without loads, static.displacement or supports (pin, roller, pins,
/// clamp), both points of first contact nodes, travel in (0, 2 R), stiffness > 0; the frames
/// elastic and without static.path (ring::InputError naming plates, the key or static.path).
void check_static(const ring::RingSpec& spec, const ring::LumpedOptions& options, const ring::StaticOptions& statics);
/// Linear buckling (buckling.hpp): every variant, as statics for the ring and the loads (named
/// buckling.*), at least one load,
/// buckling.count >= 1, and supports and terms that hold the ring at rest
/// (RingSpec::rigid_modes() == 0: K_0 must be positive definite, so a ring that only hangs
/// from its pin under gravity is refused).
void check_buckling(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                    const ring::BucklingOptions& buckling);
/// Modes under load (modes.preload = "static", preload.hpp): every variant but "frame" (its
/// rotations are massless), lumped.n <=
/// kMaxPreloadHinges (the dense eigen step), then everything check_static checks. Point masses
/// are taken (their translational mass is the chain's constant mass matrix, their rotary
/// inertia J the mass of their hinge's own rotation, preload.hpp).
void check_preloaded_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                           const ring::StaticOptions& statics);
/// Forced response of every variant but "frame" (its rotations are massless;
/// response.hinge_damping: the chain only): as statics, but rigid motions are allowed when a pin holds
/// the ring (it swings about it); the integrator "midpoint"
/// or "newmark" (the same implicit midpoint rule, nonlinear.hpp), 0 < dt <= t_end.
/// "energy-momentum" is refused: the midpoint rule does not conserve the energy of the
/// chain's non-quadratic springs, and the refusal names "midpoint".
void check_response(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                    const ring::ResponseOptions& response);

}  // namespace lumped
