#include "multibody/modes.hpp"

#include "multibody/checks.hpp"

#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <stdexcept>
#include <string>

#include "modal/lanczos.hpp"
#include "modal/modes.hpp"
#include "multibody/lanczos.hpp"
#include "multibody/shifted_solve.hpp"
#include "ring/errors.hpp"
#include "ring/sampling.hpp"

namespace multibody {

namespace {

using Dependent = ring::MultibodyOptions::Dependent;

/// y = G^{-1} M0 G^{-T} x with S = G G^T: the operator whose largest eigenvalues are
/// 1 / (omega^2 + s). O(r^2) per product.
class InverseOp {
 public:
  using Scalar = double;
  InverseOp(const Eigen::LLT<Matrix>& llt, const Matrix& M0) : llt_(llt), M0_(M0) {}
  Eigen::Index rows() const { return M0_.rows(); }
  Eigen::Index cols() const { return M0_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Vector> x(x_in, rows());
    Eigen::Map<Vector> y(y_out, rows());
    Vector t = llt_.matrixU().solve(x);
    y = M0_ * t;
    llt_.matrixL().solveInPlace(y);
  }

 private:
  const Eigen::LLT<Matrix>& llt_;
  const Matrix& M0_;
};

/// Dense path (modes.hpp): the nev (or, for small r, all) largest mu of S0^{-1} M0 with
/// their reduced vectors, converted to omega^2 = 1 / mu - s (ascending) as long as
/// mu > 0 (M0 is positive definite: the rest of the spectrum is rounding).
void dense_pairs(const LinearModel& lm, double s, int nev, Vector& omega2, Matrix& x) {
  const Matrix& K0 = lm.K0;
  const Matrix& M0 = lm.M0;
  const int r = static_cast<int>(K0.rows());
  // M0 is positive definite in exact arithmetic (M = Jr I + m l^2 G^T G with G of full
  // column rank, D of full column rank); this guards against rounding at extreme n.
  if (Eigen::LLT<Matrix>(M0).info() != Eigen::Success)
    throw ring::NumericalError("multibody: reduced mass matrix M0 is not positive definite (r = " +
                               std::to_string(r) + ")");
  const Eigen::LLT<Matrix> llt(K0 + s * M0);
  if (llt.info() != Eigen::Success)
    throw ring::NumericalError("multibody: K0 + s M0 is not positive definite (r = " + std::to_string(r) + ")");
  Vector mu;
  Matrix y;
  if (r <= 300 || 3 * nev > r) {
    Matrix T = llt.matrixL().solve(M0);             // G^{-1} M0
    Matrix C = llt.matrixL().solve(T.transpose());  // G^{-1} M0 G^{-T}
    C = 0.5 * (C + C.transpose());
    Eigen::SelfAdjointEigenSolver<Matrix> es(C);
    if (es.info() != Eigen::Success) throw ring::NumericalError("multibody: dense eigensolver did not converge");
    mu = es.eigenvalues().reverse();
    y = es.eigenvectors().rowwise().reverse();
  } else {
    // A standard symmetric problem (the transformed operator is symmetric in the
    // Euclidean product), so Spectra's SymEigsSolver with the layer's subspace rule.
    InverseOp op(llt, M0);
    Spectra::SymEigsSolver<InverseOp> eigs(op, nev, modal::subspace_size(nev, r));
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestAlge, 1000, 1e-13);
    if (eigs.info() != Spectra::CompInfo::Successful)
      throw ring::NumericalError("multibody: Lanczos (Spectra) did not converge for " + std::to_string(nev) +
                                 " modes of " + std::to_string(r));
    mu = eigs.eigenvalues();
    y = eigs.eigenvectors();
  }
  Eigen::Index k = 0;
  while (k < mu.size() && mu[k] > 0.0) ++k;
  omega2 = mu.head(k).cwiseInverse().array() - s;
  x = llt.matrixU().solve(y.leftCols(k));  // x = G^{-T} y
}

/// Sparse path through the eigen layer: Spectra's shift-invert Lanczos with the O(n)
/// constrained solve as the operator and M(q0) as B, in chain coordinates.
SparsePairs library_pairs(ShiftedSolve& sp, int nev) {
  MassProduct mass(sp);
  modal::LanczosOptions opt;
  opt.tol = kLibraryLanczosTol;
  modal::ShiftInvertLanczos<ShiftedSolve, MassProduct> eigs(sp, mass, nev, -sp.shift(), opt);
  eigs.compute();
  SparsePairs out;
  out.omega2 = eigs.eigenvalues();  // throws ring::NumericalError unless Successful
  out.dq = eigs.eigenvectors();
  out.steps = eigs.operations();
  return out;
}

/// One of the two eigen-solution paths of solve_modes (modes.hpp), chosen once: the
/// computed pairs, their M-normalized vectors, the operator norms of the backward error,
/// the reduced products K0 x and M0 x of the residuals, and the chain-coordinate shapes.
class ModesPath {
 public:
  virtual ~ModesPath() = default;
  /// omega^2 ascending and their vectors (any scale): reduced x (dense) or chain dq
  /// (sparse); `model` gets the linear model behind them (dense: K0, M0 and D; sparse: D).
  virtual void pairs(int nev, Vector& omega2, Matrix& vecs, LinearModel& model) = 0;
  /// Fills sol.x (x^T M0 x = 1; sparse also sol.dq) from the selected columns of vecs.
  virtual void normalize(Matrix& vecs, const std::vector<int>& columns, ModalSolution& sol) = 0;
  /// ||K|| and ||M|| of the backward error (dense: K0, M0; sparse: the unreduced K, M).
  virtual std::pair<double, double> norms(const ModalSolution& sol) = 0;
  /// K0 x and M0 x for the columns k0 .. k0 + nb - 1 of sol.x.
  virtual void products(const ModalSolution& sol, int k0, int nb, Matrix& KX, Matrix& MX) = 0;
  /// Sets sol.dq = D x where normalize() did not.
  virtual void shapes(ModalSolution& sol) = 0;
  virtual const char* name() const = 0;
};

/// The dense path: K0, M0 and D formed (O(n^2) memory, O(n^3) time).
class DensePath final : public ModesPath {
 public:
  DensePath(const Chain& chain, Dependent dependent, double s, const detail::LinearTerms* terms,
            std::optional<Shear> shear)
      : chain_(chain), dependent_(dependent), s_(s), terms_(terms), shear_(shear) {}
  void pairs(int nev, Vector& omega2, Matrix& vecs, LinearModel& model) override {
    model = linearize(chain_, dependent_, terms_, shear_ ? &*shear_ : nullptr);
    dense_pairs(model, s_, nev, omega2, vecs);
  }
  void normalize(Matrix& vecs, const std::vector<int>& columns, ModalSolution& sol) override {
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const Vector x = vecs.col(columns[k]);
      sol.x.col(static_cast<Eigen::Index>(k)) = x / std::sqrt(x.dot(sol.model.M0 * x));
    }
  }
  std::pair<double, double> norms(const ModalSolution& sol) override {
    const int r = static_cast<int>(sol.model.K0.rows());
    return {modal::norm_estimate([&](const Vector& v) { return Vector(sol.model.K0 * v); }, r),
            modal::norm_estimate([&](const Vector& v) { return Vector(sol.model.M0 * v); }, r)};
  }
  void products(const ModalSolution& sol, int k0, int nb, Matrix& KX, Matrix& MX) override {
    KX = sol.model.K0 * sol.x.middleCols(k0, nb);
    MX = sol.model.M0 * sol.x.middleCols(k0, nb);
  }
  // The chain's coordinates q; the Timoshenko chain's shear angles (the rows below) do not move it.
  void shapes(ModalSolution& sol) override { sol.dq = sol.model.expand(sol.x).topRows(chain_.dofs()); }
  const char* name() const override { return "dense"; }

 private:
  const Chain& chain_;
  Dependent dependent_;
  double s_;
  const detail::LinearTerms* terms_;
  std::optional<Shear> shear_;
};

/// The O(n) path: the shifted constrained solve as the operator, K and M as products,
/// D applied only to the final vectors.
class SparsePath final : public ModesPath {
 public:
  SparsePath(const Chain& chain, double s, SparseEigensolver eigensolver)
      : chain_(chain), sp_(chain), eigensolver_(eigensolver) {
    sp_.set_shift(-s);
  }
  void pairs(int nev, Vector& omega2, Matrix& vecs, LinearModel& model) override {
    SparsePairs p = eigensolver_ == SparseEigensolver::library ? library_pairs(sp_, nev) : hand_lanczos(sp_, nev);
    omega2 = std::move(p.omega2);
    vecs = std::move(p.dq);
    model.kind = Dependent::robust;
    model.qr = sp_.qr();
    model.j2_condition = j2_condition(chain_.constraint_jacobian(chain_.q0()), chain_.n());
  }
  // dq with dq^T M dq = 1, then x = D^T dq in one blocked Householder application.
  void normalize(Matrix& vecs, const std::vector<int>& columns, ModalSolution& sol) override {
    const Eigen::Index N = vecs.rows();
    sol.dq.resize(N, static_cast<Eigen::Index>(columns.size()));
    ShiftedSolve::Workspace ws;
    Vector md(N);
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const auto d = vecs.col(columns[k]);
      sp_.m_times(d, md, ws);
      sol.dq.col(static_cast<Eigen::Index>(k)) = d / std::sqrt(d.dot(md));
    }
    vecs.resize(0, 0);
    sol.x = sp_.reduce_cols(sol.dq);
  }
  // The unreduced K and M (N = r + c: the c constrained directions barely move the
  // largest eigenvalue), O(n) per product.
  std::pair<double, double> norms(const ModalSolution&) override {
    const int N = chain_.dofs();
    ShiftedSolve::Workspace ws;
    return {modal::norm_estimate([&](const Vector& v) { Vector y(N); sp_.k_times(v, y); return y; }, N),
            modal::norm_estimate([&](const Vector& v) { Vector y(N); sp_.m_times(v, y, ws); return y; }, N)};
  }
  // D^T K dq, D^T M dq with dq = D x, a block of columns per Householder application.
  void products(const ModalSolution& sol, int k0, int nb, Matrix& KX, Matrix& MX) override {
    const int N = chain_.dofs();
    Matrix Kd(N, nb), Md(N, nb);
    ShiftedSolve::Workspace ws;
    for (int j = 0; j < nb; ++j) {
      sp_.k_times(sol.dq.col(k0 + j), Kd.col(j));
      sp_.m_times(sol.dq.col(k0 + j), Md.col(j), ws);
    }
    KX = sp_.reduce_cols(Kd);
    MX = sp_.reduce_cols(Md);
  }
  void shapes(ModalSolution&) override {}
  const char* name() const override { return "sparse"; }

 private:
  const Chain& chain_;
  ShiftedSolve sp_;
  SparseEigensolver eigensolver_;
};

}  // namespace

ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options, int count,
                          SparseEigensolver eigensolver) {
  const auto start = std::chrono::steady_clock::now();
  check_modes(spec, options);
  const Chain chain(spec, options);
  const bool sparse = backend(options, spec, count) == Backend::banded;
  std::optional<detail::LinearTerms> terms;
  if (!spec.paper_terms_only()) terms = detail::linear_terms(chain, spec);
  std::optional<Shear> shear;  // the Timoshenko chain (linear_model.hpp), dense only (checks.cpp)
  if (spec.theory == ring::Theory::timoshenko) shear = Shear::of(spec, chain.l());
  const int N = chain.dofs() + (shear ? chain.n() : 0) + (terms ? terms->hinge_dofs() : 0);
  const int r = N - chain.constraint_count() - (terms ? static_cast<int>(terms->J.rows()) : 0);
  const int expected_rigid = spec.rigid_modes();
  if (count < 1 || count > r - expected_rigid)
    throw std::invalid_argument("multibody: count = " + std::to_string(count) +
                                " must satisfy 1 <= count <= " + std::to_string(r - expected_rigid) +
                                " (elastic modes of the n = " + std::to_string(chain.n()) + " chain)");
  const double s = modal::bending_scale(spec);
  const int nev = std::min(r, count + expected_rigid + 2);
  std::unique_ptr<ModesPath> path;
  if (sparse)
    path = std::make_unique<SparsePath>(chain, s, eigensolver);
  else
    path = std::make_unique<DensePath>(chain, options.dependent, s, terms ? &*terms : nullptr, shear);

  ModalSolution sol;
  Vector omega2;  // computed eigenvalues, ascending
  Matrix vecs;
  path->pairs(nev, omega2, vecs, sol.model);
  const modal::Selection sel = modal::select_modes("multibody", omega2, s, count);
  sol.rigid_omega2 = Eigen::Map<const Vector>(sel.rigid_omega2.data(),
                                              static_cast<Eigen::Index>(sel.rigid_omega2.size()));
  sol.x.resize(r, count);
  path->normalize(vecs, sel.elastic, sol);
  const auto [normK, normM] = path->norms(sol);
  // Residuals of the reduced pairs, in blocks of columns (on the sparse path one blocked
  // Householder application per block instead of one per vector: 2.4 s -> ~0.5 s at
  // n = 10^6), the extra memory bounded by 4 N kBlock doubles.
  constexpr int kBlock = 6;
  std::vector<double> relative;
  for (int k0 = 0; k0 < count; k0 += kBlock) {
    const int nb = std::min(kBlock, count - k0);
    Matrix KX(r, nb), MX(r, nb);
    path->products(sol, k0, nb, KX, MX);
    for (int j = 0; j < nb; ++j) {
      const int k = k0 + j;
      const modal::PairResidual pr = modal::pair_residual(KX.col(j), MX.col(j), omega2[sel.elastic[k]],
                                                          sol.x.col(k).norm(), normK, normM);
      relative.push_back(pr.relative);
      sol.backward_error = std::max(sol.backward_error, pr.backward);
    }
  }
  ring::ModalResult& res = sol.result;
  modal::assemble(res, "multibody", omega2, sel, relative);
  modal::require_eigenpairs(res);
  res.model["n"] = static_cast<long long>(chain.n());
  res.model["rotary_inertia"] = options.rotary_inertia;
  res.model["theory"] = ring::to_string(spec.theory);
  res.model["dependent"] = ring::to_string(options.dependent);
  res.model["method"] = std::string(path->name());
  res.unknowns = r;
  path->shapes(sol);
  // Solver time: everything up to the chain-coordinate shapes; the sampling at the
  // common stations below is output formatting (ring::sample_polygon, ~10 us per mode).
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const int n = chain.n();
  sol.hinge_ux.resize(n, count);
  sol.hinge_uy.resize(n, count);
  for (int k = 0; k < count; ++k) {
    const Vector dq = sol.dq.col(k);
    const Eigen::Matrix2Xd u = chain.rest_displacements(dq);
    sol.hinge_ux.col(k) = u.row(0).transpose();
    sol.hinge_uy.col(k) = u.row(1).transpose();
    res.shapes.push_back(chain.rest_shape(dq));
  }
  return sol;
}

ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options, int count) {
  return solve_modes(spec, options, count, kDefaultSparseEigensolver);
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                int count) {
  return solve_modes(spec, options, count).result;
}

}  // namespace multibody
