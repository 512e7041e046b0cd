// The bracket of a bifurcation as the statics report it (paths::failure_message: "... a
// bifurcation point between load factors A and B ..."), for the tests of every solver.
#pragma once

#include <cstdio>
#include <optional>
#include <string>

namespace ringtest {

struct Bracket {
  double low = 0.0, high = 0.0;
};

/// A and B of "between load factors A and B" in `message`; nullopt when it has none.
inline std::optional<Bracket> bifurcation_bracket(const std::string& message) {
  const auto at = message.find("between load factors ");
  Bracket b;
  if (at == std::string::npos ||
      std::sscanf(message.c_str() + at, "between load factors %lf and %lf", &b.low, &b.high) != 2)
    return std::nullopt;
  return b;
}

}  // namespace ringtest
