// One entry point for the driver to every solver. The FE solver lives in a plug-in
// (libringvib_fem.so) that is dlopen()ed on first use, so that a scene without FE
// never maps deal.II's shared libraries.
#pragma once

#include <string>

#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// The `count` lowest elastic modes of `solver` ("multibody", "lumped", "fem") with the
/// scene's options. Throws ring::InputError when the solver is not built (exit 2) and
/// ring::NumericalError on a numerical failure (exit 3).
ring::ModalResult solve_modes(const ring::Scene& scene, const std::string& solver, int count);

/// The converged FE reference: the FE options of the scene with reference = true.
ring::ModalResult reference_modes(const ring::Scene& scene, int count);

/// Writes the `count` lowest FE mode shapes as VTU files into `dir` (ParaView).
void write_fem_vtu(const ring::Scene& scene, int count, const std::string& dir);

/// True once the FE plug-in has been loaded in this process (tests use it to show that
/// a scene without FE never loads it).
bool fem_module_loaded();

/// True when the solver was built into this program (or its plug-in exists on disk).
bool solver_available(const std::string& solver);

}  // namespace cmp
