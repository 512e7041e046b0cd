// The dlopen boundary: wraps fem::compute_modes / fem::write_vtu so that no exception
// crosses it; errors become the exit codes of the README (2 bad input, 3 numerical).
#include "fem_reference/plugin.hpp"

#include <exception>
#include <stdexcept>

#include "fem_reference/modes.hpp"
#include "ring/errors.hpp"

namespace {

template <class F>
int guarded(std::string& error, F&& f) {
  try {
    f();
    error.clear();
    return 0;
  } catch (const ring::InputError& e) {
    error = e.what();
    return 2;
  } catch (const std::invalid_argument& e) {
    error = e.what();
    return 2;
  } catch (const ring::NumericalError& e) {
    error = e.what();
    return 3;
  } catch (const std::exception& e) {  // deal.II's ExcMessage etc.: a numerical failure
    error = std::string("fem: ") + e.what();
    return 3;
  } catch (...) {
    error = "fem: unknown exception";
    return 3;
  }
}

int modes(const ring::RingSpec& spec, const ring::FemOptions& options, int count,
          ring::ModalResult& out, std::string& error) {
  return guarded(error, [&] { out = fem::compute_modes(spec, options, count); });
}

int write_vtu(const ring::RingSpec& spec, const ring::FemOptions& options, int count,
              const std::string& dir, std::string& error) {
  return guarded(error, [&] { fem::write_vtu(spec, options, count, dir); });
}

constexpr fem::Plugin kPlugin{1, &modes, &write_vtu};

}  // namespace

extern "C" __attribute__((visibility("default"))) const fem::Plugin* ringvib_fem_plugin() {
  return &kPlugin;
}
