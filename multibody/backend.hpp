// Dense or banded: the one rule that picks the multibody backend of each analysis.
//
// The dense backend works in segment angles with n x n matrices (O(n^2) memory, O(n^3)
// per factorization). The banded one forms nothing of size n^2 and costs O(n) per
// solve: ShiftedSolve's sweep for the modes, SparseSaddle for the response, and
// natural::BandedKkt in hinge positions for the statics (the last two are
// BorderedBands). multibody.method = "dense" or "sparse" forces one backend for every
// analysis; "auto" takes the banded one from the analysis's crossover on:
//
//   analysis   banded from n                  why (evidence in docs/measured.md)
//   modes      kSparseModesCrossover = 257    both paths within 1e-12 of the oracles; the
//                                             dense one (full eigensolver) is as fast up to
//                                             a few hundred ("Crossover of the modes paths")
//   statics    kSparseStaticsCrossover = 1000 the O(n) path is faster from n ~ 160, but only
//                                             the dense one continues through limit points:
//                                             kept where it costs seconds at most
//                                             ("multibody: nonlinear statics")
//   response   kSparseResponseCrossover = 100 time per step equal near n = 80-100
//                                             ("Crossover of the response paths")
//
// The modes also need robust dependent angles (the paper's are dense only) and, for a
// count of modes, at most a third of the spectrum: more is the dense eigensolver's job.
// The energy-momentum response has only the banded form (integrators in hinge
// positions), whatever this says. O(1).
#pragma once

#include <algorithm>

#include "ring/spec.hpp"

namespace multibody {

enum class Backend { dense, banded };
enum class Analysis { modes, statics, response };

/// The crossovers of the table above: "auto" is "sparse" from this many segments on.
constexpr int kSparseModesCrossover = 257;
constexpr int kSparseStaticsCrossover = 1000;
constexpr int kSparseResponseCrossover = 100;

constexpr int sparse_crossover(Analysis analysis) {
  switch (analysis) {
    case Analysis::modes: return kSparseModesCrossover;
    case Analysis::statics: return kSparseStaticsCrossover;
    default: return kSparseResponseCrossover;
  }
}

/// The backend of `analysis` for these options (file comment).
inline Backend backend(const ring::MultibodyOptions& options, Analysis analysis) {
  using Method = ring::MultibodyOptions::Method;
  if (options.method != Method::automatic) return options.method == Method::sparse ? Backend::banded : Backend::dense;
  if (analysis == Analysis::modes && options.dependent != ring::MultibodyOptions::Dependent::robust)
    return Backend::dense;
  return options.n >= sparse_crossover(analysis) ? Backend::banded : Backend::dense;
}

/// The backend of the modes when `count` modes of a ring with these supports are wanted:
/// backend(options, Analysis::modes), but "auto" stays dense when the pairs computed,
/// min(r, count + rigid modes + 2), exceed a third of the r = n [+ 2 free] - c unknowns.
inline Backend backend(const ring::MultibodyOptions& options, const ring::Supports& supports, int count) {
  const Backend b = backend(options, Analysis::modes);
  const int r = options.n + (supports.free() ? 2 : 0) - (supports.roller ? 3 : 2);
  if (options.method == ring::MultibodyOptions::Method::automatic &&
      3 * std::min(r, count + supports.rigid_modes() + 2) > r)
    return Backend::dense;
  return b;
}

}  // namespace multibody
