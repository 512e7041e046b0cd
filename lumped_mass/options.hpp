// The [lumped] section of a scene: its keys, defaults, ranges and help (the schema the
// scene reader checks and `ringvib keys` prints), and the options it fills.
#pragma once

#include "ring/options_schema.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The keys of [lumped], declared once.
const ring::OptionSchema& option_schema();

/// The lumped-mass options from the values the reader read against option_schema(). O(1).
ring::LumpedOptions read_options(const ring::OptionValues& values);

}  // namespace lumped
