// A test proves its property at the smallest size that shows it; the full-size run of the
// same code is a study, run by bench/studies.sh (RINGVIB_STUDY=1), never by CI.
//   const int steps = ringtest::study_size(10000, 100000);
// Each call site says what the smaller size still catches (the break it was checked against).
#pragma once

#include <cstdlib>
#include <cstring>

namespace ringtest {

/// True when RINGVIB_STUDY is set to anything but "" or "0" (bench/studies.sh).
inline bool study() {
  const char* v = std::getenv("RINGVIB_STUDY");
  return v != nullptr && *v != '\0' && std::strcmp(v, "0") != 0;
}

/// `test` in the suite, `full` in the study.
template <typename T>
T study_size(T test, T full) {
  return study() ? full : test;
}

}  // namespace ringtest
