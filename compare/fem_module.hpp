// The FE solver lives in a plug-in (libringvib_fem.so) that is dlopen()ed on first use,
// so that a scene without FE never maps deal.II's shared libraries. The registry's FE
// entry calls these; nothing else does.
#pragma once

#include <string>
#include <vector>

#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace cmp::fem_module {

/// Each throws ring::InputError when the plug-in cannot be loaded or the input cannot
/// work (exit 2) and ring::NumericalError on a numerical failure (exit 3).
ring::ModalResult modes(const ring::RingSpec& spec, const ring::FemOptions& options, int count);
void write_vtu(const ring::RingSpec& spec, const ring::FemOptions& options, int count, const std::string& dir);
/// statics and respond throw std::invalid_argument for input the solver refuses (the
/// registry turns it into a ring::InputError naming the scene and key).
ring::StaticResult statics(const ring::RingSpec& spec, const ring::FemOptions& options,
                           const ring::StaticOptions& statics);
/// Throws ring::IntegrationFailure (with the partial history) when the integration fails.
ring::TimeHistory respond(const ring::RingSpec& spec, const ring::FemOptions& options,
                          const ring::ResponseOptions& response);

/// Linear buckling (fem::compute_buckling); throws std::invalid_argument for input the
/// solver refuses, as statics does.
ring::BucklingResult buckling(const ring::RingSpec& spec, const ring::FemOptions& options,
                              const ring::BucklingOptions& buckling);

/// Frequencies under load (fem::compute_modes_under_load, modes.preload = "static"); throws
/// std::invalid_argument for input the solver refuses, as statics does.
ring::ModalResult modes_under_load(const ring::RingSpec& spec, const ring::FemOptions& options,
                                   const ring::StaticOptions& statics, int count);

/// True once the plug-in has been loaded in this process (tests use it to show that a
/// scene without FE never loads it).
bool loaded();
/// True when the plug-in exists on disk.
bool available();
/// The plug-in this process loads on first FE use: $RINGVIB_FEM_MODULE when set, otherwise
/// the first that exists of plugin_candidates(); empty when none exists. Nothing is loaded.
std::string plugin_path();
/// Where the plug-in is looked for, in order: $RINGVIB_FEM_MODULE alone when set; else beside
/// the executable (build tree) and in ../lib/ringvib (installed), or, in the Python module,
/// the build tree's bin/ and the installed plug-in folder, each relative to the module's file.
std::vector<std::string> plugin_candidates();

}  // namespace cmp::fem_module
