// The kinds of failure a user can meet, with the exit codes of docs/commands.md ("Exit codes").
#pragma once

#include <stdexcept>
#include <string>

#include "ring/results.hpp"

namespace ring {

/// Bad input or usage (exit code 2). The message names the file, the key and
/// what was expected; nothing has been written when it is thrown.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string key, const std::string& what)
      : std::runtime_error(format(file, key, what)), file_(std::move(file)), key_(std::move(key)) {}
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& file, const std::string& key, const std::string& what) {
    std::string s = file.empty() ? std::string() : file + ": ";
    if (!key.empty()) s += key + ": ";
    return s + what;
  }
  std::string file_, key_;
};

/// A numerical failure (exit code 3): NaN, divergence, Newton not converging,
/// constraint drift, an indefinite mass matrix. Never printed as a result.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A time integration that could not go on (exit code 3): every solver's response
/// throws this, carrying the history of every accepted step up to the failure.
class IntegrationFailure : public NumericalError {
 public:
  enum class Reason { step_too_small, self_contact, not_finite, energy_growth };
  IntegrationFailure(Reason reason, double t_reached, TimeHistory partial, const std::string& what)
      : NumericalError(what), reason_(reason), t_(t_reached), partial_(std::move(partial)) {}
  Reason reason() const { return reason_; }
  /// Time of the last accepted step, s.
  double t_reached() const { return t_; }
  /// The history up to t_reached (every accepted step).
  const TimeHistory& partial() const { return partial_; }

 private:
  Reason reason_;
  double t_;
  TimeHistory partial_;
};

}  // namespace ring
