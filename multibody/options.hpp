// The [multibody] section of a scene: its keys, defaults, ranges and help (the schema the
// scene reader checks and `ringvib keys` prints), and the options it fills. No other file
// states a default of the chain's options.
#pragma once

#include "ring/options_schema.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// The keys of [multibody], declared once.
const ring::OptionSchema& option_schema();

/// The chain's options from the values the reader read against option_schema() (every key
/// present, defaults filled). O(1).
ring::MultibodyOptions read_options(const ring::OptionValues& values);

}  // namespace multibody
