// What a check or solve refuses: the key of the ring::InputError it throws, for tests that
// assert which key a refusal names (exit 2 names it to the user).
#pragma once

#include <string>

#include "ring/errors.hpp"

namespace ringtest {

/// The key named by the ring::InputError that f() throws, or "" when it throws none.
template <class F>
std::string refused_key(F&& f) {
  try {
    f();
  } catch (const ring::InputError& e) {
    return e.key();
  }
  return "";
}

}  // namespace ringtest
