// Internal to multibody/: the linear algebra of one run of the nonlinear response
// (dynamics.hpp), behind one interface with two backends chosen once per run:
//  - dense: the n x n tangent, damping and mass matrices, an LU of the saddle-point
//    matrix; O(n^2) per residual and solve, O(n^3) per factorization;
//  - structured: the tangent as diag + cyclic springs + low-rank mass terms
//    (dynamics_sparse.hpp), a banded LU with a border; O(n) for everything.
// Both give the same residuals and Newton corrections to round-off (tests at n = 40,
// 160, 1280 in tests/multibody/test_dynamics_sparse.cpp).
//
// The Timoshenko chain (sections.hpp, dense only): the unknowns are (phi, gamma), 2n; the
// residual and the tangent are the chain's on phi bordered by the sections' constant
// blocks (stiffness [A, A; A, A + S] and mass [J, J; J, J]); the constraints' columns on
// gamma are zero. Damping: Rayleigh a times that full mass at rest, and the cyclic dampers
// (Rayleigh b K and the hinge dampers) between neighbouring sections, as the hinge springs.
//
// Point inertias (attachments.hpp, HingeInertias, dense only): the unknowns are (phi, chi),
// the residual and tangent bordered by the constant H and the mass J on chi, the same way;
// the dampers follow the split hinge springs. Point masses add to the chain's inertia
// constants (their mass has its structure); further pins add constraint rows.
//
// ring.plastic (both backends, Euler–Bernoulli chain without point inertias: checks.cpp):
// the hinge springs follow the hinges' law (bending.hpp) at every iterate, from the states
// committed at the last accepted step: their moments in the residual, their tangents in T in
// place of the constant K (the structured T: StructuredMatrix::hinge, per hinge). The caller
// commits the states when it accepts a step.
//
// The Newton matrix is the scaled saddle-point system
//   [T G^T; G 0] [dq; dl] = [-r; -g],
// rows of g and columns of lambda multiplied by s = max|T_jj| / l so that both blocks
// have the size of T (Bottasso, Bauchau & Cardona 2007). A factorization is kept across
// iterations and steps until the integrator refreshes it (modified Newton).
#pragma once

#include <memory>

#include "multibody/bending.hpp"
#include "multibody/chain.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/attachments.hpp"
#include "multibody/loading.hpp"
#include "multibody/sections.hpp"

namespace multibody::detail {

/// Damping C = mass M(q0) + cyclic (2, -1, -1 at every hinge; Timoshenko: on the sections'
/// rotations), constant.
struct Damping {
  double mass = 0.0;    ///< Rayleigh a (1/s)
  double cyclic = 0.0;  ///< N m s / rad: Rayleigh b times the spring K, plus hinge dampers
  bool any() const { return mass > 0.0 || cyclic > 0.0; }
};

class NewtonBackend {
 public:
  virtual ~NewtonBackend() = default;
  /// C v.
  virtual Vector damping_times(const Vector& v) const = 0;
  /// Consistent accelerations and multipliers at (q, v) under load factor f: the index-1
  /// problem [M G^T; G 0] [qdd; lambda] = [f Phi - xi - C v - K theta; -Gdot v].
  /// False if it cannot be solved.
  virtual bool initial_acceleration(const Vector& q, const Vector& v, double f, Vector& qdd,
                                    Vector& lambda) const = 0;
  /// Residual r (without G^T lambda) of the equations of motion at (q, v, qdd) for load
  /// factor f; with `tangent`, also the tangent T along the integrator's formulas
  /// dqdd/dq = cm, dv/dq = cv (without the constraint curvature), kept for factor().
  virtual void residual(const Vector& q, const Vector& v, const Vector& qdd, double f, double cm, double cv,
                        Vector& r, bool tangent) = 0;
  /// Adds a diagonal (the constraint curvature sum_i lambda_i Hess g_i) to the tangent.
  virtual void add_to_tangent_diagonal(const Vector& d) = 0;
  /// The dense backend's tangent of the last residual(..., tangent = true); null for the
  /// structured one (for tests).
  virtual const Matrix* dense_tangent() const { return nullptr; }
  /// Factors the scaled saddle-point matrix of the tangent and G for steps of size h.
  /// False if the factorization fails.
  virtual bool factor(const Matrix& G, double l, double h) = 0;
  /// The Newton correction with the kept factorization. False on a non-finite result.
  virtual bool solve(const Vector& r, const Vector& g, Vector& dq, Vector& dl) const = 0;
  /// solve() for the columns of R with g = 0, all at once. False on a non-finite result.
  virtual bool solve_columns(const Matrix& R, Matrix& DQ, Matrix& DL) const = 0;

  /// A factorization for steps of size h is kept.
  bool usable(double h) const { return valid_ && h == h_; }
  void invalidate() { valid_ = false; }

 protected:
  NewtonBackend(const Chain& chain, const DeadLoad& load, const Damping& damping, const Loading* loading = nullptr,
                const Attachments* terms = nullptr, const Sections* sections = nullptr,
                const HingeInertias* hinges = nullptr, const HingeBending* bending = nullptr)
      : chain_(chain), load_(load), damping_(damping), loading_(loading), terms_(terms), sections_(sections),
        hinges_(hinges), bending_(bending) {}
  /// The loads' generalized forces at q (the dead point load, or `loading`'s), and, if
  /// `tangent` is not null, f times their stiffness added to it.
  Vector load_forces_at(const Vector& q, double f, Eigen::Ref<Matrix>* tangent) const;
  const Chain& chain_;
  DeadLoad load_;
  Damping damping_;
  const Loading* loading_;
  const Attachments* terms_;
  const Sections* sections_;
  const HingeInertias* hinges_;
  const HingeBending* bending_;  ///< ring.plastic's hinges (their committed states), or null: K
  bool valid_ = false;
  double h_ = 0.0;
  double sc_ = 1.0;  ///< the constraint rows' scale of the last factorization
};

/// The dense or the structured backend for this chain, load and damping; `loading` (loads
/// beyond one point load: on the structured one without a shape-dependent part), `terms`
/// (foundation, springs, clamp, point masses, further pins), `sections` (the Timoshenko
/// chain: the unknowns become (phi, gamma)) and `hinges` (point inertias: the unknowns
/// become (phi, [gamma,] chi)) on the dense one only; `bending` (ring.plastic: the hinges'
/// law, read at every residual) on both.
std::unique_ptr<NewtonBackend> make_newton_backend(const Chain& chain, const DeadLoad& load, const Damping& damping,
                                                   bool structured, const Loading* loading = nullptr,
                                                   const Attachments* terms = nullptr,
                                                   const Sections* sections = nullptr,
                                                   const HingeInertias* hinges = nullptr,
                                                   const HingeBending* bending = nullptr);

}  // namespace multibody::detail
