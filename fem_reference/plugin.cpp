// The dlopen boundary: wraps fem::compute_modes, write_vtu, solve_static, respond,
// compute_buckling and compute_modes_under_load so that no exception
// crosses it; errors become the exit codes of the README (2 bad input, 3 numerical).
#include "fem_reference/plugin.hpp"

#include <exception>
#include <stdexcept>

#include "fem_reference/buckling.hpp"
#include "fem_reference/modes.hpp"
#include "fem_reference/nonlinear.hpp"
#include "fem_reference/preload.hpp"
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

int statics(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::StaticOptions& st,
            ring::StaticResult& out, std::string& error) {
  return guarded(error, [&] { out = fem::solve_static(spec, options, st); });
}

int respond(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::ResponseOptions& response,
            ring::TimeHistory& out, int& reason, double& t_reached, std::string& error) {
  reason = -1;
  return guarded(error, [&] {
    try {
      out = fem::respond(spec, options, response);
    } catch (const ring::IntegrationFailure& e) {
      out = e.partial();
      reason = static_cast<int>(e.reason());
      t_reached = e.t_reached();
      throw;
    }
  });
}

int buckling(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::BucklingOptions& b,
             ring::BucklingResult& out, std::string& error) {
  return guarded(error, [&] { out = fem::compute_buckling(spec, options, b); });
}

int modes_under_load(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::StaticOptions& st,
                     int count, ring::ModalResult& out, std::string& error) {
  return guarded(error, [&] { out = fem::compute_modes_under_load(spec, options, st, count); });
}

constexpr fem::Plugin kPlugin{fem::kAbiVersion, &modes, &write_vtu, &statics, &respond, &buckling, &modes_under_load};

}  // namespace

extern "C" __attribute__((visibility("default"))) const fem::Plugin* ringvib_fem_plugin() {
  return &kPlugin;
}
