// Reading a number pair out of a command's JSON text without parsing it whole: the CLI suites
// that look at one field of `ringvib static --json` ("reaction", "contact_length").
#pragma once

#include <array>
#include <cmath>
#include <string>

namespace ringtest {

/// The two numbers of the JSON array after the first `key` in `out` (NaN, NaN without one).
inline std::array<double, 2> pair_after(const std::string& out, const std::string& key) {
  const auto at = out.find(key);
  if (at == std::string::npos) return {NAN, NAN};
  const auto open = out.find('[', at), comma = out.find(',', open);
  return {std::stod(out.substr(open + 1)), std::stod(out.substr(comma + 1))};
}

}  // namespace ringtest
