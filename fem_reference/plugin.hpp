// The dlopen boundary of the FE reference: the `ringvib` executable loads
// libringvib_fem.so on first use, so that scenes without FE never load deal.II.
// NO deal.II includes here. Both sides must be built by the same compiler and
// standard library (std::string and the ring:: types cross the boundary).
#pragma once

#include <string>

#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem {

struct Plugin {
  int abi_version;  // 1
  // Returns 0 on success, 2 for bad input (ring::InputError / std::invalid_argument), 3 for a numerical failure
  // (ring::NumericalError); on failure `error` holds the message. Never lets an exception cross the boundary.
  int (*modes)(const ring::RingSpec& spec, const ring::FemOptions& options, int count, ring::ModalResult& out, std::string& error);
  // Writes the `count` lowest mode shapes as VTU (deal.II DataOut) into directory `dir` (which exists).
  int (*write_vtu)(const ring::RingSpec& spec, const ring::FemOptions& options, int count, const std::string& dir, std::string& error);
};

}  // namespace fem

/// The plug-in's only exported entry point (C linkage, so dlsym finds it by name).
extern "C" const fem::Plugin* ringvib_fem_plugin();
