// Dense or banded: the one rule that picks the multibody backend of each analysis.
//
// Dense: segment angles with n x n matrices, O(n^2) memory, O(n^3) per factorization.
// Banded: nothing of size n^2, O(n) per solve (ShiftedSolve's sweep for the paper's ring's
// modes, natural::BandedKkt for the modes with the terms beyond it and the statics;
// BorderedBands for the response, SparseSaddle).
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
// An arch (ring.arc) is dense for every analysis: "auto" keeps it dense, and checks.hpp
// refuses a forced "sparse" (the O(n) paths close the chain).
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

/// What the O(n) linear modes cannot take of `spec`, as the words of a refusal ("" when they
/// take it): the paper's ring runs in segment angles (shifted_solve.hpp), its terms beyond
/// (attachments.hpp: foundation, springs, clamp, further pins, point masses) in hinge
/// positions (position_modes.hpp), pinned or free; neither has the shear angles, nor a point
/// inertia's own hinge rotation (the dense path's unknown chi, linear_model.hpp), nor the
/// spinning ring's gyroscopic modes (spin.hpp: dense). The modes under load (modes.preload)
/// are the dense path's as well: check_preloaded_modes. O(masses).
inline std::string banded_modes_lacks(const ring::RingSpec& spec) {
  if (spec.rotation.spinning()) return "spinning ring (rotation.speed: its gyroscopic modes are dense)";
  if (spec.varies()) return "ring.variations (the local masses and springs are on the dense path only)";
  if (spec.theory == ring::Theory::timoshenko) return "Timoshenko chain (ring.theory = \"timoshenko\")";
  for (std::size_t i = 0; i < spec.masses.size(); ++i)
    if (spec.masses[i].inertia > 0.0)
      return "point inertia (masses[" + std::to_string(i + 1) + "].inertia = " + std::to_string(spec.masses[i].inertia) +
             " kg m^2: its hinge's own rotation is an unknown of the dense path only)";
  return "";
}

/// The largest n of the O(n) modes in hinge positions (the terms beyond the paper's ring):
/// their refined band solve contracts while eps (n / 2 pi)^4 stays well below 1
/// (position_modes.hpp). Measured on scenes/tyre-ring.toml: order-2 errors against the closed
/// form to n = 80000 (1.4e-9 for k = 0 at 60000), no eigenpairs at n = 10^5 (residual 0.02 -
/// 0.9, exit 3); the bound keeps a margin below the first success that stopped converging.
constexpr int kPositionModesMaxN = 60000;

/// The backend of `analysis` on `spec`: "auto" also stays dense for what the O(n) path of
/// the analysis does not assemble: for the modes, banded_modes_lacks; for the others, the
/// terms beyond the paper's ring (supports.pins, clamp, springs, masses, foundation; the
/// statics' rule takes them and the loads: the next overload) and the Timoshenko chain
/// (linear_model.hpp). O(masses).
inline Backend backend(const ring::MultibodyOptions& options, const ring::RingSpec& spec, Analysis analysis) {
  if (options.method == ring::MultibodyOptions::Method::automatic && spec.is_arch()) return Backend::dense;
  if (options.method == ring::MultibodyOptions::Method::automatic &&
      (analysis == Analysis::modes ? !banded_modes_lacks(spec).empty()
                                   : !spec.paper_terms_only() || spec.theory == ring::Theory::timoshenko))
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
/// response, shape-dependent loads (follower and central pressure; point loads, gravity and
/// dead pressure it takes: constant hinge forces, loading.hpp) and the terms beyond the
/// paper's ring (attachments.hpp). O(1).
inline Backend backend(const ring::MultibodyOptions& options, const ring::RingSpec& spec, const ring::Loads& loads,
                       Analysis analysis) {
  if (analysis == Analysis::statics) {
    if (options.method == ring::MultibodyOptions::Method::automatic &&
        (!banded_statics_lacks(spec).empty() || spec.is_arch()))
      return Backend::dense;
    return backend(options, analysis);
  }
  if (options.method == ring::MultibodyOptions::Method::automatic && loads.shape_dependent()) return Backend::dense;
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
/// unknowns (c: closure, roller, two rows per further pin) or 4 nev + 60 reaches r, and for
/// what the O(n) modes lack (banded_modes_lacks). O(masses).
inline Backend backend(const ring::MultibodyOptions& options, const ring::RingSpec& spec, int count) {
  if (options.method == ring::MultibodyOptions::Method::automatic && spec.is_arch()) return Backend::dense;
  const ring::Supports& supports = spec.supports;
  const int r = options.n + (supports.free() ? 2 : 0) - (supports.roller ? 3 : 2) -
                2 * static_cast<int>(supports.pins.size());
  // And when its Lanczos would need the whole space (lanczos.cpp: 4 nev + 60 steps at most):
  // a Krylov basis that fills all r unknowns has lost its orthogonality (measured: 64 modes
  // of a free n = 320 chain, relative residual 1.0), where the dense path costs milliseconds.
  const int nev = std::min(r, count + spec.rigid_modes() + 2);
  if (options.method == ring::MultibodyOptions::Method::automatic && (3 * nev > r || 4 * nev + 60 >= r))
    return Backend::dense;
  return backend(options, spec, Analysis::modes);
}

}  // namespace multibody
