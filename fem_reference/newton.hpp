// Internal to fem_reference/: full Newton on the geometrically exact beam's equations and the
// LU of its matrix, shared by the statics (static_path.cpp) and the response (nonlinear.cpp).
#pragma once

#include "fem_reference/ring_model.hpp"
#include "paths/newton.hpp"

namespace fem::detail {

/// Up to this many unknowns the Newton matrix is factored dense (LAPACK getrf, O(N^3)):
/// UMFPACK's fixed cost per factorization (ordering, symbolic analysis, sorted copies of
/// the arrays) outweighs it there. Measured on the half-sine response (degree 4, dt = 0.01 s,
/// 600 factorizations; docs/measured.md, "The Newton matrix's LU"): dense ~20 % faster at 96
/// nodal values (8 elements), even at 144 (12), sparse ahead from 192 (16).
constexpr unsigned int kDenseNewtonLimit = 120;

/// The LU of a Newton matrix: dense up to kDenseNewtonLimit unknowns, UMFPACK above. Throws
/// on a singular matrix as SparseDirectUMFPACK does.
class NewtonLu {
 public:
  void initialize(const SparseMatrix<double>& S) {
    dense_ = S.m() <= kDenseNewtonLimit;
    if (!dense_) {
      sparse_.initialize(S);
      return;
    }
    lu_.reinit(S.m());
    lu_ = S;
    lu_.compute_lu_factorization();
  }
  void solve(Vector<double>& x) const {
    if (dense_)
      lu_.solve(x);
    else
      sparse_.solve(x);
  }

 private:
  bool dense_ = false;
  SparseDirectUMFPACK sparse_;
  LAPACKFullMatrix<double> lu_;
};

/// Newton on grad V(q) - rhs(q) = 0 with the tangent `tangent(q) + extra`; q updated in
/// place, through the one Newton (paths/newton.hpp: full Newton, its cap). Returns the
/// iterations, or -1 when it did not converge (q then unusable).
/// Converged: the correction is below 1e-12 of the ring radius (quadratic convergence
/// takes the residual to round-off one iteration later). With `max_move`, an iterate
/// that moves any value of q by more than that from the start counts as not converged:
/// near a limit point Newton can otherwise land on a distant branch of equilibria.
/// Corrections and moves are lengths: max_i |dq_i| lengths_i (BeamModel::lengths, a section
/// rotation psi counts as R psi; all ones when `lengths` is null).
template <class Residual>
int newton(Vector<double>& q, double radius, Residual&& residual_and_tangent,
           double max_move = std::numeric_limits<double>::infinity(), const std::vector<double>* lengths = nullptr) {
  auto length = [&](const Vector<double>& v) {
    if (!lengths) return v.linfty_norm();
    double m = 0.0;
    for (unsigned int i = 0; i < v.size(); ++i) m = std::max(m, std::abs(v[i]) * (*lengths)[i]);
    return m;
  };
  NewtonLu lu;
  Vector<double> r, dq, moved;
  const Vector<double> start = q;
  paths::NewtonFunctions system;
  system.linearize_at = [&](bool) {
    SparseMatrix<double>& S = residual_and_tangent(q, r);
    if (!std::isfinite(r.l2_norm())) return false;
    try {
      lu.initialize(S);
    } catch (const std::exception&) {
      return false;
    }
    return true;
  };
  system.solve_for = [&](paths::Correction& c) {
    dq = r;
    lu.solve(dq);
    if (!std::isfinite(dq.l2_norm())) return false;
    c.size = length(dq);
    c.move = 0.0;
    if (max_move < std::numeric_limits<double>::infinity()) {
      moved = q;
      moved.add(-1.0, dq);
      moved -= start;
      c.move = length(moved) / max_move;
    }
    return true;
  };
  system.apply_correction = [&] { q.add(-1.0, dq); };
  paths::Rule rule;
  rule.tolerance = 1e-12 * radius;
  const paths::NewtonResult result = paths::newton(system, rule);
  return result.converged ? result.iterations : -1;
}

}  // namespace fem::detail
