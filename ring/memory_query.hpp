// What a solver's memory estimate needs of the analyses a scene asks for: the driver fills
// it from the scene (compare/registry.cpp), so that a solver's estimate (its options.hpp)
// reads the ring, its own options and this, never the scene.
#pragma once

#include "ring/analysis.hpp"

namespace ring {

struct MemoryQuery {
  int count = 0;                           ///< modes asked (0: the nonlinear analyses)
  bool preload = false;                    ///< modes.preload = "static": modes about the loaded equilibrium
  bool response = false;                   ///< a forced response is asked
  const StaticOptions* statics = nullptr;  ///< the nonlinear statics asked, or null
  bool reference = false;                  ///< the converged FE reference runs (fem.reference or a reference column)
};

}  // namespace ring
