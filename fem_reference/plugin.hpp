// The dlopen boundary of the FE reference: the `ringvib` executable loads
// libringvib_fem.so on first use, so that scenes without FE never load deal.II.
// NO deal.II includes here. Both sides must be built by the same compiler and
// standard library (std::string and the ring:: types cross the boundary).
#pragma once

#include <string>

#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem {

/// Every entry returns 0 on success, 2 for bad input (ring::InputError /
/// std::invalid_argument), 3 for a numerical failure (ring::NumericalError); on failure
/// `error` holds the message. No exception crosses the boundary; a failed response's
/// partial history comes back in `out` with `t_reached` set.
struct Plugin {
  int abi_version;  // kAbiVersion
  int (*modes)(const ring::RingSpec& spec, const ring::FemOptions& options, int count, ring::ModalResult& out,
               std::string& error);
  /// Writes the `count` lowest mode shapes as VTU (deal.II DataOut) into directory `dir` (which exists).
  int (*write_vtu)(const ring::RingSpec& spec, const ring::FemOptions& options, int count, const std::string& dir,
                   std::string& error);
  int (*statics)(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::StaticOptions& statics,
                 ring::StaticResult& out, std::string& error);
  /// On an integration failure (3): `out` is the history so far, `reason` the
  /// ring::IntegrationFailure::Reason as an int, `t_reached` its time.
  int (*respond)(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::ResponseOptions& response,
                 ring::TimeHistory& out, int& reason, double& t_reached, std::string& error);
  int (*buckling)(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::BucklingOptions& buckling,
                  ring::BucklingResult& out, std::string& error);
  /// Frequencies under load (modes.preload = "static"): fem::compute_modes_under_load.
  int (*modes_under_load)(const ring::RingSpec& spec, const ring::FemOptions& options,
                          const ring::StaticOptions& statics, int count, ring::ModalResult& out, std::string& error);
};

/// Version 2 added statics and respond (the geometrically exact beam), 3 buckling, 4
/// modes_under_load, 5 ResponseOptions::progress (a std::function, called inside the plug-in;
/// safe because both sides share one compiler and standard library, as for std::string), 6
/// RingSpec::rotation and ModalResult's waves, frame and spin_pairs (a spinning ring), 7
/// StaticOptions::displacement and the reactions of StaticResult and PathPoint, 8
/// StaticOptions::plates and the contact lengths of StaticResult and PathPoint.
constexpr int kAbiVersion = 8;

}  // namespace fem

/// The plug-in's only exported entry point (C linkage, so dlsym finds it by name).
extern "C" const fem::Plugin* ringvib_fem_plugin();
