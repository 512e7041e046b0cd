#include "multibody/lanczos.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "ring/errors.hpp"

namespace multibody {

namespace {

/// w -= V h, V = the first k basis vectors. Eigen's column-major matrix-vector product
/// over all k columns at once was measured 3x (n = 10^6) to 9x (n = 10^5) slower than
/// the same product taken 8 columns at a time once k exceeds ~16 (k = 25, 2 cores shared:
/// 70 -> 29 ms at 10^6, 6.7 -> 0.70 ms at 10^5): streaming 8 columns plus w at a time
/// reaches the memory bandwidth that the transposed product V^T p reaches on its own.
/// The rounding is that of the same sums in another order. O(N k).
template <class Basis>
void subtract_basis(const Basis& V, const Vector& h, Vector& w) {
  constexpr Eigen::Index kGroup = 8;
  for (Eigen::Index j = 0; j < V.cols(); j += kGroup) {
    const Eigen::Index b = std::min(kGroup, V.cols() - j);
    w.noalias() -= V.middleCols(j, b) * h.segment(j, b);
  }
}

}  // namespace

SparsePairs hand_lanczos(const ShiftedSolve& sp, int nev) {
  const int N = sp.dofs(), r = sp.r();
  const int max_steps = std::min(r, 4 * nev + 60);
  // Residual estimate |beta y_last| <= 1e-8 theta: the Ritz values come from the exact
  // Rayleigh quotient V^T M V, so their error is quadratic in the residual (~1e-16 theta
  // for gaps ~theta). The estimate stagnates near 1e-9 (the solve's rounding in the S
  // norm; measured n = 2000 .. 2e5), so Spectra's 1e-13 would never be met here.
  constexpr double tol = 1e-8;
  Matrix V(N, max_steps + 1);
  std::mt19937_64 gen(20260421);  // fixed seed: reproducible runs
  std::uniform_real_distribution<double> uni(-0.5, 0.5);
  // One workspace and three vectors for the whole iteration: the products and solves
  // below write into them instead of allocating (at n = 10^6 fresh 8 MB vectors cost
  // page faults at every step).
  ShiftedSolve::Workspace ws;
  Vector p(N), w(N), q(N);
  for (int i = 0; i < N; ++i) p[i] = uni(gen);
  sp.solve_full(p, w, ws);  // a start vector in the null space of J
  sp.S_full(w, q, ws);
  w /= std::sqrt(w.dot(q));
  V.col(0) = w;
  Eigen::SelfAdjointEigenSolver<Matrix> es;
  int m = 0;  // Krylov dimension reached
  bool done = false;
  Matrix H = Matrix::Zero(max_steps, max_steps);  // V^T M V = V^T S T V, by columns
  for (int k = 0; k < max_steps && !done; ++k) {
    sp.m_times(V.col(k), p, ws);
    const auto Vk = V.leftCols(k + 1);
    // Column k of the Rayleigh quotient V^T M V: exact up to the dot products' rounding,
    // whatever the solve's error (which only slows convergence).
    const Vector h = Vk.transpose() * p;
    H.col(k).head(k + 1) = h;
    H.row(k).head(k + 1) = h.transpose();
    // Unrefined: the Ritz values come from the exact Rayleigh quotient, so the solve's
    // error only slows convergence, and measured it does not (45 steps at n = 10^5 and
    // 10^6 as with it; the oracle errors of docs/measured.md unchanged, n = 12 .. 10^5):
    // the refinement was a third of each step's O(n) work.
    sp.solve_full(p, w, ws, 0);
    const double b0 = std::sqrt(std::max(0.0, w.dot(p)));  // ||w||_S before orthogonalization
    // Gram-Schmidt with <w, v_j>_S = v_j^T (p - J^T lambda) = h_j, first the three-term
    // part (O(N)): it carries the cancellation, so one full pass with the true S w then
    // removes only rounding and the basis's loss of orthogonality. (Before, the full pass
    // with h came first and the cancellation sent 44 of 45 steps into a second one: four
    // reads of the basis per step where there are now three.)
    for (int j = std::max(0, k - 1); j <= k; ++j) w.noalias() -= h[j] * V.col(j);
    sp.S_full(w, q, ws);
    const double b1 = std::sqrt(std::max(0.0, w.dot(q)));
    const Vector g = Vk.transpose() * q;
    subtract_basis(Vk, g, w);
    // ||w - V g||_S^2 = b1^2 - |g|^2 for an S-orthonormal V: no S product when the pass
    // removed little (measured: rounding and lost orthogonality only, |g| <= 3e-7 b1 at
    // n = 2000 .. 10^6 on the paper ring, 45 steps; the DGKS branch below never ran).
    const double removed = g.squaredNorm();
    double b = std::sqrt(std::max(0.0, b1 * b1 - removed));
    if (!(b > 0.7 * b1)) {  // DGKS: the full pass cancelled too, so once more with the true S w
      sp.S_full(w, q, ws);
      subtract_basis(Vk, (Vk.transpose() * q).eval(), w);
      sp.S_full(w, q, ws);
      b = std::sqrt(std::max(0.0, w.dot(q)));
    }
    m = k + 1;
    if (!(b > 1e-10 * b0) && m < r) {
      // The Krylov space closed (a single start vector spans one copy of each multiple
      // eigenvalue: the free ring's three rigid modes and its cos/sin pairs): continue
      // with a fresh random direction in the null space, S-orthogonal to V. H stays the
      // exact Rayleigh quotient (its new column comes from the next step's dots).
      for (int i = 0; i < N; ++i) p[i] = uni(gen);
      sp.solve_full(p, w, ws);
      for (int pass = 0; pass < 2; ++pass) {
        sp.S_full(w, q, ws);
        subtract_basis(Vk, (Vk.transpose() * q).eval(), w);
      }
      sp.project(w);
      sp.S_full(w, q, ws);
      b = std::sqrt(std::max(0.0, w.dot(q)));
      V.col(k + 1) = w / b;
      continue;
    }
    const bool invariant = m == r;
    if (m >= nev) {
      es.compute(H.topLeftCorner(m, m));
      if (es.info() != Eigen::Success) throw ring::NumericalError("multibody: Ritz eigensolver failed");
      done = invariant;
      if (!done) {
        done = true;
        for (int i = 0; i < nev; ++i) {
          const int j = m - 1 - i;  // ascending order: the largest last
          const double theta = es.eigenvalues()[j];
          if (std::abs(b * es.eigenvectors()(m - 1, j)) > tol * std::abs(theta)) done = false;
        }
      }
    }
    if (!done) {
      sp.project(w);  // rounding (and, at invariance, noise) off the null space of J
      V.col(k + 1) = w / b;  // the projection moves w by rounding only (not invariant here)
    }
  }
  if (!done)
    throw ring::NumericalError("multibody: sparse Lanczos did not converge for " + std::to_string(nev) +
                               " modes of " + std::to_string(r) + " in " + std::to_string(max_steps) + " steps");
  // The nev largest mu, descending: omega^2 = 1 / mu - s.
  SparsePairs out;
  out.steps = m;
  out.omega2.resize(nev);
  Matrix Y(m, nev);
  for (int i = 0; i < nev; ++i) {
    const double mu = es.eigenvalues()[m - 1 - i];
    // M0 is positive definite by construction (M = Jr I + m l^2 G^T G, G of full column
    // rank) and never formed here: the check is that every Ritz value
    // mu = x^T M0 x / x^T S0 x comes out > 0.
    if (!(mu > 0.0))
      throw ring::NumericalError("multibody: non-positive Ritz value of S0^{-1} M0: M0 is not "
                                 "positive definite (r = " + std::to_string(r) + ")");
    out.omega2[i] = 1.0 / mu - sp.shift();
    Y.col(i) = es.eigenvectors().col(m - 1 - i);
  }
  // The Ritz vectors V Y overwrite the basis's first nev columns, a block of rows at a
  // time (row i of V Y needs only row i of V), and the basis shrinks to them: at
  // n = 10^6 a separate N x nev result was 208 MB of freshly faulted memory on top of
  // the basis.
  constexpr Eigen::Index kRows = 4096;
  Matrix block;
  for (Eigen::Index i = 0; i < N; i += kRows) {
    const Eigen::Index rows = std::min<Eigen::Index>(kRows, N - i);
    block.noalias() = V.block(i, 0, rows, m) * Y;
    V.block(i, 0, rows, nev) = block;
  }
  V.conservativeResize(N, nev);  // column-major, same rows: a realloc that keeps the front
  out.dq = std::move(V);
  return out;
}

}  // namespace multibody
