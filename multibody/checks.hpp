// What the multibody chain refuses before it computes: a request that can never work is
// std::invalid_argument naming the key and the valid range. Each analysis calls its check
// first, and the driver calls them for every analysis a scene asks of the chain before
// any solver runs, so a refusal never comes after another solver's work. O(1).
//
// An arch (ring.arc; chain.hpp, "The arch") runs on the dense angle paths: the linear modes;
// the statics under point loads, and pressure and gravity with both ends pinned (static.path
// included; ring.plastic with pinned ends); linear buckling and the modes under load with the
// statics' loads; the newmark / generalized-alpha response under point loads (and gravity
// with both ends pinned) with its `to` end pinned. Refused by key, each message naming ring.arc: multibody.method = "sparse",
// dependent = "paper", the Timoshenko chain, a roller, springs, masses, the foundation,
// ring.plastic with a clamped end and in the response, pressure and gravity without both ends
// pinned, pressure in the response, the energy-momentum integrator and a free `to` end in the
// response.
#pragma once

#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// Linear buckling on an arch (buckling.hpp): the arch's refusals of the statics (point loads,
/// pressure with both ends pinned; no ring.plastic); nothing for a ring. O(supports).
void check_arch_buckling(const ring::RingSpec& spec, const ring::MultibodyOptions& options, const ring::Loads& loads);
/// Linear modes: n >= 4, a positive section and material, method = "sparse" only with
/// dependent = "robust" and n >= 10. A spinning ring (rotation.speed; spin.hpp): a finite
/// speed, a closed ring whose rigid motions are held, the dense path (method = "sparse"
/// refused), dependent = "robust", the Timoshenko chain pinned, at most
/// modal::kMaxGyroscopicUnknowns unknowns (multibody.n). The statics, buckling, response and
/// modes under load refuse a spin (ring::refuse_rotation).
void check_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options);
/// Nonlinear statics: a pin and a roller (else the ring turns freely about the pin), steps >= 1;
/// the Timoshenko chain on the dense path only, and without ring.plastic (ring::InputError:
/// its hinge springs are condensed with the shear, sections.hpp); the fibre law only on a
/// section with a shape (ring::InputError, key ring.plastic.stress). static.displacement
/// (statics.hpp): the driven point counts as a pin; it must be a hinge that is no support
/// (ring::InputError, key static.displacement.at), with no loads and a supports.pin (key
/// static.displacement: the free chain's drive is not measured yet). [plates] (plates.hpp): no
/// loads, drive or supports (pin, roller, pins, clamp) with them, travel in (0, 2 R), a positive
/// stiffness, both contact points hinges, a closed ring, a static.history that never decreases
/// (ring::InputError, key plates or plates.*).
void check_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                  const ring::StaticOptions& statics);
/// Modes under load: the statics' checks, the dense path (multibody.method != "sparse"), a
/// pinned Timoshenko chain, no ring.plastic (ring::InputError: an elastic tangent), no
/// static.displacement (ring::InputError: the pencil holds no driven rows).
void check_preloaded_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                           const ring::StaticOptions& statics);
/// Forced response: ring.plastic (either law; the fibre law on a section with a shape) on the
/// Euler–Bernoulli chain without point inertias, every integrator and backend (else
/// ring::InputError, key ring.plastic, saying why and what to use), a
/// pin, 0 < dt <= t_end (finite), rho_inf in [0, 1], damping >= 0 and
/// none with the energy-momentum integrator; the integrator "newmark", "generalized-alpha"
/// or "energy-momentum" ("midpoint" is the lumped chain's scheme, refused here); the
/// Timoshenko chain on the dense path with "newmark" or "generalized-alpha" only, without
/// point inertias; the terms beyond the paper's ring on the dense path only.
void check_response(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                    const ring::ResponseOptions& response);

}  // namespace multibody
