// Geometrically nonlinear statics of the rigid-segment chain: equilibrium of the
// hinge springs and the terms of attachments.hpp (V) under the loads of loading.hpp (Phi),
// the closure and support constraints,
//
//   K theta + dV/dphi + G(phi)^T lambda = s Phi(phi),   g(phi) = 0,   s: load factor 0 -> 1,
//
// followed from rest by the shared continuation driver (paths/continuation.hpp: load
// stepping with full Newton, Crisfield's arc length through limit points, the limit
// point located). Either backend supplies the equilibrium, with every term and load (the
// O(n) path has no Timoshenko chain): the dense path in the paper's segment angles
// (analytic tangent K + Hess V + sum_k lambda_k Hess g_k - s dPhi/dphi, the bordered
// matrix by dense LU), the O(n) path in hinge positions (natural.hpp: the
// banded KKT factorization, the arc's border by block elimination). The arc length is
// measured on the angles (dense) or the positions (O(n)); a step may turn no segment by
// more than detail::kBasin. Self-contact (non-adjacent segments closer than the section
// depth) ends the path with a ring::NumericalError naming the load factor (and the limit
// point, if the path went through one): the chain model has no contact.
// The Timoshenko chain (ring.theory = "timoshenko", dense path only): its shear angles are
// condensed exactly (sections.hpp), so K theta above is K_c theta, with the terms on the
// rotations inside K_c; the unknowns and the path are the Euler chain's.
// Its frequencies under load restore gamma about the equilibrium: the stiffness
// [T - K_c + A, A; A, A + S] and the mass [M + J, J; J, J] (A, S, J as in sections.hpp;
// statics.cpp).
//
// ## Displacement control (static.displacement)
// No loads act; the driven hinge h is held as a pin whose target moves with the load factor,
// the spec's last further pin (detail::held_spec, attachments.hpp) with the rows
//
//   g_d(z, s) = u_h(z) - s v = 0,   v = static.displacement.value (m at s = 1),
//
// so dR/ds is -v on these two rows and zero on the rest (Phi = 0): the bordered matrix's load
// column of both formulations (scaled as their constraint rows are). Their multipliers are the
// pin's force on the chain: the residual's G^T lambda balances the springs, so the force the
// rig applies on the ring at h is -lambda_d (StaticEquilibrium::reaction; N, x and y). The
// continuation driver varies s as it varies a load factor (history legs, unloading, negative
// s), the arc length measured on the same unknowns; the driven point moves monotonically with
// s, so a falling reaction (a plastic mechanism, a snap) is no limit point of the path.
//
// ## Rigid plates ([plates]; plates.hpp)
// No loads and no supports act; the free chain is crushed between the two plates of
// ring::PlatePair, a penalty lumped at the hinges as the Winkler foundation is, its load column
// dR/ds the penalty's rate, with two roller-like rows that keep the points of first contact in
// place along the plates. The path is followed by load steps (the arc from rest stalled at
// small approaches; statics.cpp), and both formulations take them: the O(n) path adds the
// penalty by hinge to its banded KKT and the no-slide rows as one-row constraints (natural.hpp,
// Natural::slides).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "multibody/attachments.hpp"
#include "multibody/backend.hpp"
#include "multibody/bending.hpp"
#include "multibody/chain.hpp"
#include "multibody/loading.hpp"
#include "paths/continuation.hpp"
#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace multibody {

namespace detail {

/// The dense path's equilibrium pieces in the segment angles q (and the free ring's base),
/// shared by the statics and linear buckling (buckling.hpp): the residual
///   internal_forces(q) + G(q)^T lambda - s loads().forces(q),   constraints g(q) = 0,
/// with the chain's closure rows followed by the further pins' rows, and its tangent
///   T = K + the terms' Hessian + s (load stiffness) + diag(lambda . Hess g)
/// (every constraint Hessian is diagonal in the angles: dynamics_model.hpp). O(n) for the
/// forces and the constraints, O(n^2) for the tangent. For the Timoshenko chain
/// (spec.theory) K is the condensed K_c of sections.hpp, which holds the hinge springs, the
/// shear and the terms on the rotations (kr, the clamp): the shear angles are condensed
/// exactly, and the forces K_c theta cost O(n^2).
class DenseTangent {
 public:
  /// `section` names the keys of the loads in messages ("static", "buckling").
  /// `bending` (bending.hpp), when given, is the hinge springs' law (read at each call, so
  /// its commits show); else the springs are the rest stiffness K (linear buckling).
  DenseTangent(const Chain& chain, const ring::RingSpec& spec, const ring::Loads& loads, const std::string& section,
               const HingeBending* bending = nullptr);
  Eigen::Index dofs() const { return n_; }
  Eigen::Index rows() const { return c_; }
  const Loading& loads() const { return loads_; }
  /// The chain's constraints at q, then the further pins' rows (attachments.hpp).
  Chain::ConstraintKinematics constraints(const Vector& q) const;
  /// The springs' and the terms' forces dV/dq.
  Vector internal_forces(const Vector& q) const;
  /// Adds T(q, lambda, s) to `T` (n x n), `ck` being constraints(q).
  void add_tangent(const Vector& q, const Vector& lambda, double s, const Chain::ConstraintKinematics& ck,
                   Eigen::Ref<Matrix> T) const;
  /// Adds only the terms' Hessian at q (foundation, springs, clamp) to `T`.
  void add_terms(const Vector& q, Eigen::Ref<Matrix> T) const;

 private:
  const Chain& chain_;
  const HingeBending* bending_;  ///< the hinge springs' law, or nullptr: K_
  const Loading loads_;      ///< point loads, pressure, gravity
  const Attachments terms_;  ///< foundation, springs, clamp, further pins
  const bool shear_;         ///< the Timoshenko chain: K_ is K_c, with the terms on the rotations
  const Matrix K_;           ///< the n x n spring stiffness (Timoshenko: K_c, sections.hpp)
  const Eigen::Index n_, c_;
};

/// `spec` with the driven point of `statics` (static.displacement, if any) as its last further
/// pin (supports.pins): the chain, its terms and both formulations then hold it with two rows,
/// the last constraint rows, which a formulation given the drive's value moves with s (file
/// comment). `spec` itself when the path is driven by loads. O(supports).
ring::RingSpec held_spec(const ring::RingSpec& spec, const ring::StaticOptions& statics);

/// The chain's static equilibrium in one backend's unknowns, for the continuation driver;
/// the self-contact check (the end of the path) and the hinges' bending law (bending.hpp:
/// elastic, or ring.plastic's, committed at every accepted equilibrium) are common to both.
class StaticEquilibrium : public paths::Equilibrium {
 public:
  StaticEquilibrium(const Chain& chain, const ring::RingSpec& spec, double depth);
  /// Every hinge's position for the unknowns z (ring-centred frame, m).
  virtual Eigen::Matrix2Xd hinges(const paths::Vector& z) const = 0;
  /// The unknowns of the undeformed ring, unloaded.
  virtual paths::Vector rest() const = 0;
  /// The change of every hinge's turning angle from rest for the unknowns z (n, rad): the
  /// strains of bending.hpp.
  virtual Eigen::VectorXd hinge_strains(const paths::Vector& z) const = 0;
  /// static.displacement: the force the rig applies on the ring at the driven hinge for the
  /// unknowns z, minus the driven rows' multipliers (N, x and y; file comment). {0, 0} when
  /// the path is driven by loads.
  virtual std::array<double, 2> reaction(const paths::Vector& z) const {
    (void)z;
    return {0.0, 0.0};
  }
  /// [plates] at the equilibrium x: the force of plate 0 on the ring (N, x and y), the contact
  /// length on each plate (m) and the penalty's energy (J); plates.hpp.
  struct PlateState {
    std::array<double, 2> reaction{0.0, 0.0}, contact_length{0.0, 0.0};
    double energy = 0.0;
  };
  /// nullopt when the path is not driven by plates.
  virtual std::optional<PlateState> plates(const paths::State& x) const {
    (void)x;
    return std::nullopt;
  }
  /// The path point of the equilibrium x: path_point at its hinges, with its reaction (the
  /// drive's, or plate 0's with the contact lengths).
  ring::PathPoint point(const paths::State& x) const {
    ring::PathPoint pt = path_point(x.s, hinges(x.z));
    pt.reaction = reaction(x.z);
    if (const std::optional<PlateState> p = plates(x)) {
      pt.reaction = p->reaction;
      pt.contact_length = p->contact_length;
    }
    return pt;
  }
  /// Commits the hinges' plastic states at `to` (bending.hpp), records it, checks contact.
  std::optional<paths::Touch> accept(const paths::State& from, const paths::State& to) override;
  /// ring.plastic: the plastic work of the accepted path so far (J), and the largest plastic
  /// curvature (the hinge's plastic rotation over the segment length, 1/m). 0 for the
  /// elastic law.
  double dissipated() const { return bending_.dissipated(); }
  double plastic_curvature() const { return bending_.largest_plastic_curvature(); }
  const HingeBending& bending() const { return bending_; }
  /// Distance between the closest non-neighbouring segments minus the section depth. O(n).
  std::optional<double> clearance(const paths::State& x) override;
  /// Records every accepted equilibrium (ring::PathPoint) at these hinges from now on.
  void record_path(std::vector<int> hinges) {
    record_ = std::move(hinges);
    recording_ = true;
  }
  /// The recorded path, rest first.
  const std::vector<ring::PathPoint>& path() const { return path_; }
  /// The path point of the hinge positions p (2 x n).
  ring::PathPoint path_point(double s, const Eigen::Matrix2Xd& p) const;

 protected:
  const Chain& chain_;
  const double depth_;
  const int gap_;
  HingeBending bending_;  ///< the hinges' law and committed states (changes in accept only)

 private:
  std::vector<int> record_;
  bool recording_ = false;
  std::vector<ring::PathPoint> path_;
};

}  // namespace detail

/// Static equilibrium under `statics.loads` at full load, or with the point of
/// `statics.displacement` driven to its value (file comment; `reaction` at every path point,
/// limit point and the end).
/// Returns the displacements of the recorded points (ring-centred frame, m), the
/// number of accepted load steps, the total Newton iterations, and every hinge's
/// deformed position. Cost: O(n^3) per Newton iteration on the dense path, O(n) on the
/// O(n) path (multibody.method = "sparse", or "auto" from kSparseStaticsCrossover); both
/// pass limit points. Requires the rigid motions held (ring::static_rigid_modes = 0: a pin
/// and a roller, or springs, a foundation, gravity below a single pin). Throws std::invalid_argument for inputs that can never work and
/// ring::NumericalError when the equilibrium path does not reach the full load (the ring
/// touches itself; no return past a limit point).
ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::StaticOptions& statics);

/// Frequencies under load (modes.preload = "static"): the `count` lowest modes about the
/// equilibrium of `statics` at its full load, on the dense path: the tangent T there (the
/// springs, the terms, the load stiffness and the constraints' multipliers: the prestress),
/// the mass M(q) of the deformed chain, both on the constraints' tangent space at q, solved
/// by the shifted inverse of modes.hpp; shapes are the hinges' displacements about the
/// deformed state at the common stations. Under a uniform pressure on the inextensible
/// chain the equilibrium is the circle and T = K_0 + s K_1 (buckling.hpp): each omega^2
/// falls to zero at its critical load. Cost: the statics, then O(n^3).
/// Throws std::invalid_argument (check_preloaded_modes) and ring::NumericalError when the
/// path does not reach the full load (a bifurcation, a limit point) or omega^2 <= 0.
ring::ModalResult compute_modes_under_load(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                           const ring::StaticOptions& statics, int count);

}  // namespace multibody
