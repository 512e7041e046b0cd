// The two formulations of the chain's static equilibrium that multibody::solve_static chooses
// between (backend()), as objects for the continuation driver: for a caller that follows a
// path itself and reads the hinges' committed law between steps (bending.hpp), e.g. to check
// the energy balance of a plastic path.
#pragma once

#include <memory>
#include <optional>

#include "multibody/chain.hpp"
#include "multibody/natural.hpp"
#include "multibody/statics.hpp"

namespace multibody::detail {

/// The dense path: segment angles and multipliers (statics.cpp, AngleStatics), O(n^3) per
/// Newton iteration. The O(n) path in hinge positions is natural::static_equilibrium.
/// `drive` (static.displacement.value, m at load factor 1): the chain's last two constraint
/// rows, the last further pin of `spec` (held_spec), move to s times it and their multipliers
/// give the reaction (statics.hpp, "Displacement control"); `loads` must then be empty.
/// `plates` ([plates], plates.hpp): the plates crush the free chain of `spec` (no loads, no
/// drive); reaction() is then zero and plates() the plates' force and contact lengths.
std::unique_ptr<StaticEquilibrium> angle_equilibrium(const Chain& chain, const ring::RingSpec& spec,
                                                     const ring::Loads& loads, double depth,
                                                     std::optional<Eigen::Vector2d> drive = std::nullopt,
                                                     const ring::StaticOptions::Plates* plates = nullptr);

}  // namespace multibody::detail
