// Natural frequencies and mode shapes of the lumped-mass ring models,
// independent of multibody/: the only shared code is ring/.
//
// Usage:
//   ring::RingSpec spec;                       // the paper's ring: R = 10, d = 0.12, steel
//   spec.section.diameter = 0.12;
//   spec.supports.pin = 180.0;
//   ring::LumpedOptions opt;                    // n = 40, variant chain
//   ring::ModalResult r = lumped::compute_modes(spec, opt, 9);
//   // r.omega[0] ~ 2.47 rad/s, r.rigid_modes == 1
#pragma once

#include "lumped_mass/eigen.hpp"
#include "lumped_mass/model.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The `count` lowest elastic modes of the variant in `options` (model.hpp), solved as
/// in eigen.hpp, reported as ring::ModalResult: solver = "lumped"; model = {n, variant,
/// method ("dense" | "sparse"), and for sparse system_order and factor_nonzeros of the
/// factorized mixed system}; rigid_modes (counted
/// with kRigidThreshold, not numbered); omega (rad/s, ascending, elastic only); shapes at
/// the common stations (ring::sample_polygon of the node displacements, anchor = pin
/// angle or 0 for a free ring); unknowns (dimension of the eigenproblem: n - 2 for a
/// pinned chain, 2n - 2 / 3n - 2 for the pinned frames); seconds (wall time of this call);
/// max_residual (largest relative residual of the elastic pairs, eigen.hpp residuals()).
/// \param count 1 <= count <= elastic_dofs() (n - 3 for the chain, 2n - 3 for frame,
///              3n - 3 for frame-consistent and timoshenko-frame with the paper's
///              supports; docs/solvers.md's model
///              table for further pins, a clamp, point inertias and rigid modes held).
/// Every term of `spec` is modelled (model.hpp): pins, clamp, roller, springs, point
/// masses, foundation; a point off the nodes is std::invalid_argument naming the key, and so
/// is a Timoshenko frame without a shear stiffness (checks.hpp check_theory; the variant,
/// not ring.theory, is the model's theory).
/// Cost: dense O(n^3); sparse O(n (count + rigid)) per Lanczos restart, O(n) memory.
ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count);

/// A shape of the lumped models' node displacements x (node-major, `dofs_per_node` per node,
/// (ux, uy) first: model.hpp's order) at the common stations: ring::sample_polygon from
/// node 0 at `anchor_deg`, with ModeShape's scaling. The one sampling of every lumped shape
/// (modes, buckling). O(n + kStations).
/// The chain's n + 1 node displacements (ux, uy interleaved) on an arch, sampled by
/// ring::sample_arc (stations off the arch are 0). O(n + stations).
ring::ModeShape sample_arch_shape(const ring::Arc& arc, const Eigen::Ref<const Eigen::VectorXd>& x);
ring::ModeShape sample_shape(double anchor_deg, int dofs_per_node, const Eigen::Ref<const Eigen::VectorXd>& x);

/// The same with the eigen-solution path chosen explicitly (tests, benchmarks).
ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::LumpedOptions& options, int count,
                                Method method);

}  // namespace lumped
