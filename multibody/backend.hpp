// Dense or banded: the one rule that picks the multibody backend of each analysis.
//
// Dense: segment angles with n x n matrices, O(n^2) memory, O(n^3) per factorization.
// Banded: nothing of size n^2, O(n) per solve (ShiftedSolve's sweep for the modes;
// BorderedBands for the response, SparseSaddle, and the statics, natural::BandedKkt).
// multibody.method = "dense" or "sparse" forces one for every analysis; "auto" takes the
// banded one from the analysis's crossover on (evidence: docs/measured.md):
//
//   analysis  banded from n  why
//   modes     257            as fast as the dense full eigensolver from a few hundred;
//                            robust dependent angles only, at most a third of the spectrum
//   statics   1000           faster from n ~ 160, but only the dense path continues
//                            through limit points: kept where it costs seconds at most
//   response  100            time per step equal near n = 80-100
//
// The energy-momentum response is banded whatever this says (hinge positions only).
#pragma once

#include <algorithm>
#include <string>

#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace multibody {

enum class Backend { dense, banded };
enum class Analysis { modes, statics, response };

/// The table: from this many segments on, "auto" is "sparse".
constexpr int kSparseModesCrossover = 257, kSparseStaticsCrossover = 1000, kSparseResponseCrossover = 100;
constexpr int sparse_crossover(Analysis a) {
  return a == Analysis::modes ? kSparseModesCrossover
                              : (a == Analysis::statics ? kSparseStaticsCrossover : kSparseResponseCrossover);
}

/// The backend of `analysis` for these options (file comment). O(1).
inline Backend backend(const ring::MultibodyOptions& options, Analysis analysis) {
  using Method = ring::MultibodyOptions::Method;
  if (options.method != Method::automatic) return options.method == Method::sparse ? Backend::banded : Backend::dense;
  if (analysis == Analysis::modes && options.dependent != ring::MultibodyOptions::Dependent::robust)
    return Backend::dense;
  return options.n >= sparse_crossover(analysis) ? Backend::banded : Backend::dense;
}

/// The backend of `analysis` on `spec`: "auto" also stays dense when the spec has terms
/// beyond the paper's (supports.pins, clamp, springs, masses, foundation), which only the
/// dense paths of the modes and the response assemble (attachments.hpp), and for the
/// Timoshenko chain (linear_model.hpp). The statics' rule takes the loads: the next overload. O(1).
inline Backend backend(const ring::MultibodyOptions& options, const ring::RingSpec& spec, Analysis analysis) {
  if (options.method == ring::MultibodyOptions::Method::automatic &&
      (!spec.paper_terms_only() || spec.theory == ring::Theory::timoshenko))
    return Backend::dense;
  return backend(options, analysis);
}

/// What the O(n) statics cannot take of `spec`, as the words of a refusal ("" when it takes
/// the scene): it assembles every term (attachments.hpp: foundation, springs, clamp,
/// further pins; point masses weigh under gravity) and every load (loading.hpp) on hinge
/// positions (statics_natural.cpp), pinned or free, but has no shear angles. O(1).
inline std::string banded_statics_lacks(const ring::RingSpec& spec) {
  return spec.theory == ring::Theory::timoshenko ? "Timoshenko chain (ring.theory = \"timoshenko\")" : "";
}

/// The backend of a nonlinear analysis under `loads`: "auto" also stays dense for what the
/// O(n) path of `analysis` does not assemble: for the statics, banded_statics_lacks; for the
/// response, loads beyond one point load (several, pressure, gravity) and the terms beyond
/// the paper's ring (loading.hpp, attachments.hpp). O(1).
inline Backend backend(const ring::MultibodyOptions& options, const ring::RingSpec& spec, const ring::Loads& loads,
                       Analysis analysis) {
  if (analysis == Analysis::statics) {
    if (options.method == ring::MultibodyOptions::Method::automatic && !banded_statics_lacks(spec).empty())
      return Backend::dense;
    return backend(options, analysis);
  }
  if (options.method == ring::MultibodyOptions::Method::automatic && !loads.beyond_one_point("").empty())
    return Backend::dense;
  return backend(options, spec, analysis);
}

/// The statics' backend: the rule above under `statics.loads`, and "auto" also stays dense
/// for static.path = true, whose branch switching takes the dense tangent's eigenvectors
/// (check_static refuses it on a forced "sparse"). O(1).
inline Backend backend(const ring::MultibodyOptions& options, const ring::RingSpec& spec,
                       const ring::StaticOptions& statics) {
  if (options.method == ring::MultibodyOptions::Method::automatic && statics.path) return Backend::dense;
  return backend(options, spec, statics.loads, Analysis::statics);
}

/// The modes' backend for `count` modes of `spec`: "auto" also stays dense when the pairs
/// computed, nev = min(r, count + rigid modes + 2), exceed a third of the r = n [+ 2 free] - c
/// unknowns or 4 nev + 60 reaches r, and when the spec has terms beyond the paper's (supports.pins, clamp,
/// springs, masses, foundation), which only the dense path assembles. O(1).
inline Backend backend(const ring::MultibodyOptions& options, const ring::RingSpec& spec, int count) {
  const ring::Supports& supports = spec.supports;
  const int r = options.n + (supports.free() ? 2 : 0) - (supports.roller ? 3 : 2);
  // And when its Lanczos would need the whole space (lanczos.cpp: 4 nev + 60 steps at most):
  // a Krylov basis that fills all r unknowns has lost its orthogonality (measured: 64 modes
  // of a free n = 320 chain, relative residual 1.0), where the dense path costs milliseconds.
  const int nev = std::min(r, count + spec.rigid_modes() + 2);
  if (options.method == ring::MultibodyOptions::Method::automatic && (3 * nev > r || 4 * nev + 60 >= r))
    return Backend::dense;
  return backend(options, spec, Analysis::modes);
}

}  // namespace multibody
