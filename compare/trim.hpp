// `ringvib trim SCENE --mode N --at DEG,DEG`: the point masses at the given angles that bring
// the split of the pair holding mode N (compare/pairs.hpp) below a tolerance, as gyroscope
// makers trim a ring by adding (or removing) mass at chosen angles.
//
// The pair's imperfection is the vector z = s e^{i 2k phi} (s its relative split, phi the
// orientation, k its wave number): to first order a point mass m at theta adds
// c m e^{i 2k theta} to it (Fox 1990; c < 0: the lower mode's antinode moves to the mass).
// Two angles that act alike on pair k (2k (theta_2 - theta_1) a multiple of 180 degrees)
// cannot set both of z's components: refused with exit 2 before anything is computed. The
// trim measures each angle's effect with the solver (one solve per angle with a probe mass),
// then takes chord-Newton steps on the two components of z, one solve each, until the
// relative split is below the tolerance (exit 3 when it does not get there, or when a mass
// would have to be negative: a removal, which a mass at the angle 90/k degrees on acts as).
#pragma once

#include <string>
#include <vector>

#include "compare/commands.hpp"
#include "compare/pairs.hpp"

namespace cmp {

struct TrimArgs {
  int mode = 0;                 ///< 1-based: the pair holding this mode of the untrimmed scene
  std::vector<double> at;       ///< degrees, nodes of every model; one or two
  std::string solver;           ///< "" : the scene's first modal solver
  double tolerance = 1e-6;      ///< relative split to reach
  bool json = false;
  std::string out;              ///< the trimmed scene (TOML), or "" for none
};

/// What a trim found.
struct TrimResult {
  std::string solver;
  int mode = 0, wave = 0, steps = 0;
  std::vector<double> at, masses;  ///< degrees, kg
  SplitPair before, after;         ///< the pair untrimmed and trimmed (after.wave = 0: no split left)
  std::string trimmed_scene;       ///< the scene's text with the masses appended as [[masses]]
};

/// The trim of the scene `text` (named `name`, with `overrides`): ring::InputError for what
/// cannot be trimmed (checked before computing), ring::NumericalError when the trim fails.
TrimResult run_trim(const std::string& text, const std::string& name, const std::vector<std::string>& overrides,
                    const TrimArgs& t);

/// The command: run_trim on the scene file, printed (text or --json), --out written.
int cmd_trim(const CommonArgs& a, const TrimArgs& t);

}  // namespace cmp
