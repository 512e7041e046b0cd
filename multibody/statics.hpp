// Geometrically nonlinear statics of the rigid-segment chain: equilibrium of the
// hinge springs with a dead point load under the closure and support constraints,
//
//   K theta + G(phi)^T lambda = s Phi(phi),   g(phi) = 0,   s: load factor 0 -> 1,
//
// followed from rest by the shared continuation driver (paths/continuation.hpp: load
// stepping with full Newton, Crisfield's arc length through limit points, the limit
// point located). Either backend supplies the equilibrium: the dense path in the
// paper's segment angles (analytic tangent K + sum_k lambda_k Hess g_k - s dPhi/dphi,
// the bordered matrix by dense LU), the O(n) path in hinge positions (natural.hpp: the
// banded KKT factorization, the arc's border by block elimination). The arc length is
// measured on the angles (dense) or the positions (O(n)); a step may turn no segment by
// more than detail::kBasin. Self-contact (non-adjacent segments closer than the section
// depth) ends the path with a ring::NumericalError naming the load factor (and the limit
// point, if the path went through one): the chain model has no contact.
#pragma once

#include <memory>
#include <optional>

#include "multibody/backend.hpp"
#include "paths/continuation.hpp"
#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace multibody {

class Chain;

namespace detail {

/// The chain's static equilibrium in one backend's unknowns, for the continuation driver;
/// the self-contact check (the end of the path) is common to both.
class StaticEquilibrium : public paths::Equilibrium {
 public:
  StaticEquilibrium(const Chain& chain, double depth);
  /// Every hinge's position for the unknowns z (ring-centred frame, m).
  virtual Eigen::Matrix2Xd hinges(const paths::Vector& z) const = 0;
  /// The unknowns of the undeformed ring, unloaded.
  virtual paths::Vector rest() const = 0;
  std::optional<paths::Touch> accept(const paths::State& from, const paths::State& to) override;

 protected:
  const Chain& chain_;
  const double depth_;
  const int gap_;
};

}  // namespace detail

/// Static equilibrium under `statics.loads` at full load.
/// Returns the displacements of the recorded points (ring-centred frame, m), the
/// number of accepted load steps, the total Newton iterations, and every hinge's
/// deformed position. Cost: O(n^3) per Newton iteration on the dense path, O(n) on the
/// O(n) path (multibody.method = "sparse", or "auto" from kSparseStaticsCrossover); both
/// pass limit points. Requires a pin and a roller (otherwise the rigid rotation about the
/// pin is free). Throws std::invalid_argument for inputs that can never work and
/// ring::NumericalError when the equilibrium path does not reach the full load (the ring
/// touches itself; no return past a limit point).
ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::StaticOptions& statics);

}  // namespace multibody
