// The [lumped] section of a scene: its keys, defaults, ranges and help (the schema the
// scene reader checks and `ringvib keys` prints), and the options it fills.
#pragma once

#include "ring/options_schema.hpp"
#include "ring/memory_query.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The keys of [lumped], declared once.
const ring::OptionSchema& option_schema();

/// The lumped-mass options from the values the reader read against option_schema(). O(1).
ring::LumpedOptions read_options(const ring::OptionValues& values);

/// The working memory of the analyses `q` asks of this solver, bytes (beyond the process,
/// which the cost guard adds: compare/guard.cpp). Fitted to the peak RSS measured (the
/// comment above the definition); tests/compare/test_memory_estimate.cpp holds it within
/// [1, 1.5] of the measured peak.
double memory_estimate(const ring::RingSpec& spec, const ring::LumpedOptions& o, const ring::MemoryQuery& q);

}  // namespace lumped
