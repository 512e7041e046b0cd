// The eigen-solve of the linear ring model: dense LAPACK or ARPACK shift-invert, then the
// extended-precision refinement of the pairs (ring_model.hpp).
#include <deal.II/base/parallel.h>

#include "fem_reference/ring_model.hpp"
#include "modal/modes.hpp"
#include "modal/subspace.hpp"

namespace fem::detail {

EigenPairs LinearModel::solve(unsigned int n_wanted, bool refine_pairs) const {
  const unsigned int N = n_free_;
  // A few guard pairs above the wanted ones keep the refinement's gap large.
  const unsigned int n_compute = std::min(n_wanted + kGuardModes, N - 1);
  // K - sigma M with sigma < 0 is positive definite even with rigid modes.
  SparseMatrix<double> shifted(sparsity_);
  shifted.copy_from(K_);
  shifted.add(-sigma_, M_);
  SparseDirectUMFPACK inverse;
  inverse.initialize(shifted);

  EigenPairs raw;
  if (N <= kDenseLimit) {
    LAPACKFullMatrix<double> Kd(N, N), Md(N, N);
    for (auto it = K_.begin(); it != K_.end(); ++it) Kd(it->row(), it->column()) = it->value();
    for (auto it = M_.begin(); it != M_.end(); ++it) Md(it->row(), it->column()) = it->value();
    std::vector<Vector<double>> vectors(n_compute, Vector<double>(N));
    Kd.compute_generalized_eigenvalues_symmetric(Md, vectors);
    for (unsigned int i = 0; i < n_compute; ++i) raw.lambda.push_back(Kd.eigenvalue(i).real());
    raw.q = std::move(vectors);
  } else {
    // Shift-invert Lanczos about sigma: the eigenvalues nearest sigma (the lowest)
    // converge first. The basis size is the project's one rule (modal/subspace.hpp); deal.II's
    // ArpackSolver asserts more than ARPACK itself needs (ncv > 2 nev + 1 and ncv < N, in
    // debug builds), so one vector more where the rule gives 2 nev + 1 (or N).
    const unsigned int rule = static_cast<unsigned int>(modal::subspace_size(int(n_compute), int(N)));
    const unsigned int ncv = std::min(N - 1, std::max(rule, 2 * n_compute + 2));
    SolverControl control(std::max(1000u, 10 * N), 1e-12);
    ArpackSolver::AdditionalData data(ncv, ArpackSolver::largest_magnitude, true);
    ArpackSolver arpack(control, data);
    arpack.set_shift(sigma_);
    // A fixed pseudo-random start: reproducible, and not orthogonal to any symmetry class.
    Vector<double> start(N);
    std::mt19937 gen(20261121);
    std::uniform_real_distribution<double> dist(-1.0, 1.0);
    for (auto& s : start) s = dist(gen);
    arpack.set_initial_vector(start);
    std::vector<std::complex<double>> lambda(n_compute);
    std::vector<Vector<double>> vectors(n_compute, Vector<double>(N));
    arpack.solve(K_, M_, inverse, lambda, vectors, n_compute);
    std::vector<unsigned int> order(n_compute);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) { return lambda[a].real() < lambda[b].real(); });
    for (const auto i : order) {
      raw.lambda.push_back(lambda[i].real());
      raw.q.push_back(vectors[i]);
    }
  }
  EigenPairs out = refine_pairs ? refine(std::move(raw), n_wanted, inverse) : std::move(raw);
  out.residual.resize(n_compute, std::numeric_limits<double>::quiet_NaN());
  out.lambda.resize(n_wanted);
  out.q.resize(n_wanted);
  out.residual.resize(n_wanted);
  return out;
}

EigenPairs LinearModel::refine(EigenPairs raw, unsigned int wanted, const SparseDirectUMFPACK& shifted_inverse) const {
  const unsigned int m = raw.q.size(), N = n_free_;
  std::vector<Vector<double>>& X = raw.q;
  std::vector<std::vector<Real>> KX(m), MX(m);
  auto to_double = [N](const std::vector<Real>& a) {
    Vector<double> v(N);
    for (unsigned int i = 0; i < N; ++i) v[i] = static_cast<double>(a[i]);
    return v;
  };
  // The pairs' applies and solves are independent (apply() and the factorization's solve
  // are const): on the cores deal.II's thread pool has (at most 30 % of a paper-ring
  // reference, where the extended-precision apply() dominates the refinement).
  auto for_each_pair = [m](const auto& f) {
    parallel::apply_to_subranges(
        0u, m, [&](unsigned int begin, unsigned int end) { for (unsigned int k = begin; k < end; ++k) f(k); }, 1);
  };
  auto apply_all = [&]() { for_each_pair([&](unsigned int k) { apply(X[k], KX[k], MX[k]); }); };
  // Rayleigh-Ritz on span(X) with Gram matrices X^T K X, X^T M X from apply().
  auto ritz = [&]() {
    apply_all();
    LAPACKFullMatrix<double> A(m, m), B(m, m);
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int l = 0; l < m; ++l) {
        Real a = 0, b = 0;
        for (unsigned int i = 0; i < N; ++i) {
          a += X[k][i] * KX[l][i];
          b += X[k][i] * MX[l][i];
        }
        A(k, l) = static_cast<double>(a);
        B(k, l) = static_cast<double>(b);
      }
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int l = 0; l < k; ++l) {
        A(k, l) = A(l, k) = 0.5 * (A(k, l) + A(l, k));
        B(k, l) = B(l, k) = 0.5 * (B(k, l) + B(l, k));
      }
    std::vector<Vector<double>> Y(m, Vector<double>(m));
    A.compute_generalized_eigenvalues_symmetric(B, Y);
    std::vector<Vector<double>> next(m, Vector<double>(N));
    for (unsigned int k = 0; k < m; ++k) {
      raw.lambda[k] = A.eigenvalue(k).real();
      for (unsigned int j = 0; j < m; ++j) next[k].add(Y[k][j], X[j]);
    }
    X = std::move(next);
    apply_all();
  };
  auto residual_vector = [&](unsigned int k) {
    std::vector<Real> r(N);
    for (unsigned int i = 0; i < N; ++i) r[i] = KX[k][i] - static_cast<Real>(raw.lambda[k]) * MX[k][i];
    return to_double(r);
  };
  // Denominator of the relative residual: for an eigenpair K q = lambda M q and
  // (K - sigma M)^{-1} M q = q / (lambda - sigma), so ||K q||_* + lambda ||M q||_* =
  // 2 lambda sqrt(q^T M q / (lambda - sigma)) up to O(residual); this saves two solves per pair.
  auto denominator = [&](unsigned int k) {
    Real qmq = 0;
    for (unsigned int i = 0; i < N; ++i) qmq += X[k][i] * MX[k][i];
    const double lambda = std::abs(raw.lambda[k]);
    return 2.0 * lambda * std::sqrt(static_cast<double>(qmq) / (lambda - sigma_));
  };
  // Every pair's residual r, z = (K - sigma M)^{-1} r and the relative dual norm
  // sqrt(r^T z) / denominator (infinite if r^T z < 0: the solve is garbage); the worst
  // of the wanted elastic pairs.
  raw.residual.assign(m, 0.0);
  const unsigned int rigid = static_cast<unsigned int>(spec_.rigid_modes());
  std::vector<Vector<double>> Z(m, Vector<double>(N));
  auto residuals = [&]() {
    for_each_pair([&](unsigned int k) {
      const Vector<double> r = residual_vector(k);
      shifted_inverse.vmult(Z[k], r);
      const double rz = r * Z[k];
      raw.residual[k] = rz >= 0 ? std::sqrt(rz) / denominator(k) : std::numeric_limits<double>::infinity();
    });
    // The stopping rule looks at the wanted elastic pairs: a rigid one's relative
    // residual divides by lambda ~ 0 (the lowest `rigid` pairs: kRigidSeparation), the
    // guard pairs converge last.
    double worst = 0.0;
    for (unsigned int k = rigid; k < std::min(wanted, m); ++k) worst = modal::worst(worst, raw.residual[k]);
    return worst;
  };
  ritz();
  double worst = residuals();
  // Subspace (inverse) iteration q -= (K - sigma M)^{-1} r damps the error along mode j
  // by (lambda - sigma) / (lambda_j - sigma); Ritz then removes the error inside the span.
  // Until refined, or until a correction no longer halves the worst residual (round-off).
  for (unsigned int round = 0; round < kMaxRefinementRounds && worst > kRefinedResidual; ++round) {
    for (unsigned int k = 0; k < m; ++k) X[k] -= Z[k];
    ritz();
    const double next = residuals();
    const bool halved = next < 0.5 * worst;
    worst = next;
    if (!halved) break;
  }
  return raw;
}

}  // namespace fem::detail
