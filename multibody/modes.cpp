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
#include "multibody/attachments.hpp"
#include "multibody/lanczos.hpp"
#include "multibody/position_modes.hpp"
#include "multibody/shifted_solve.hpp"
#include "multibody/spin.hpp"
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
/// the products of the residuals (K0 x and M0 x, or vectors with their norms), and the
/// chain-coordinate shapes.
class ModesPath {
 public:
  virtual ~ModesPath() = default;
  /// omega^2 ascending and their vectors (any scale): reduced x (dense) or chain dq
  /// (sparse); `model` gets the linear model behind them (dense: K0, M0 and D; sparse: D).
  virtual void pairs(int nev, Vector& omega2, Matrix& vecs, LinearModel& model) = 0;
  /// Fills sol.x (dense) or sol.dq (sparse), x^T M0 x = 1, from the selected columns of vecs.
  virtual void normalize(Matrix& vecs, const std::vector<int>& columns, ModalSolution& sol) = 0;
  /// ||K|| and ||M|| of the backward error (dense: K0, M0; sparse: the unreduced K, M).
  virtual std::pair<double, double> norms(const ModalSolution& sol) = 0;
  /// For mode k: kx, mx with the norms of every combination kx - w mx equal to those of
  /// K0 x - w M0 x (K0 x and M0 x themselves, or their images under an isometry); returns ||x||.
  virtual double products(const ModalSolution& sol, int k, Vector& kx, Vector& mx) = 0;
  /// Sets sol.dq = D x where normalize() did not.
  virtual void shapes(ModalSolution& sol) = 0;
  virtual const char* name() const = 0;
};

/// The dense path: K0, M0 and D formed (O(n^2) memory, O(n^3) time).
class DensePath final : public ModesPath {
 public:
  DensePath(const Chain& chain, Dependent dependent, double s, const detail::LinearTerms* terms,
            std::optional<Shear> shear, std::optional<LocalChain> local = std::nullopt)
      : chain_(chain), dependent_(dependent), s_(s), terms_(terms), shear_(shear), local_(std::move(local)) {}
  void pairs(int nev, Vector& omega2, Matrix& vecs, LinearModel& model) override {
    model = linearize(chain_, dependent_, terms_, shear_ ? &*shear_ : nullptr, local_ ? &*local_ : nullptr);
    dense_pairs(model, s_, nev, omega2, vecs);
  }
  void normalize(Matrix& vecs, const std::vector<int>& columns, ModalSolution& sol) override {
    sol.x.resize(vecs.rows(), static_cast<Eigen::Index>(columns.size()));
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
  double products(const ModalSolution& sol, int k, Vector& kx, Vector& mx) override {
    kx.noalias() = sol.model.K0 * sol.x.col(k);
    mx.noalias() = sol.model.M0 * sol.x.col(k);
    return sol.x.col(k).norm();
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
  std::optional<LocalChain> local_;  ///< ring.variations' local masses and springs (linear_model.hpp)
};

/// The O(n) paths' side in chain coordinates: the shapes dq, their M-normalization, the
/// norms and the residuals' products, through the O(n) products of K and M and the
/// projection onto the null space of the constraint rows that each path supplies.
class ChainPath : public ModesPath {
 public:
  // dq with dq^T M dq = 1, in vecs's own columns (the selected columns ascend, so column
  // k is written only after it is read: no second N x count matrix, whose fresh pages were
  // 184 MB of page faults at n = 10^6). x = D^T dq is not formed (modes.hpp).
  void normalize(Matrix& vecs, const std::vector<int>& columns, ModalSolution& sol) override {
    const Eigen::Index N = vecs.rows(), count = static_cast<Eigen::Index>(columns.size());
    Vector md(N);
    for (Eigen::Index k = 0; k < count; ++k) {
      const Eigen::Index from = columns[static_cast<std::size_t>(k)];
      m_times(vecs.col(from), md);
      vecs.col(k) = vecs.col(from) / std::sqrt(vecs.col(from).dot(md));
    }
    vecs.conservativeResize(N, count);  // column-major, same rows: keeps the front
    sol.dq = std::move(vecs);
  }
  // The unreduced K and M (N = r + c: the c constrained directions barely move the
  // largest eigenvalue), O(n) per product.
  std::pair<double, double> norms(const ModalSolution&) override {
    const int N = chain_.dofs();
    return {modal::norm_estimate([&](const Vector& v) { Vector y(N); k_times(v, y); return y; }, N),
            modal::norm_estimate([&](const Vector& v) { Vector y(N); m_times(v, y); return y; }, N)};
  }
  // P K dq and P M dq, P = D D^T the projection onto the null space of J: with dq = D x
  // and D's orthonormal columns, ||P v|| = ||D^T v||, so every norm of the residual is
  // that of D^T (K - w M) dq = K0 x - w M0 x, in O(n c) per product instead of a
  // Householder application (and without N x block temporaries: 1.1 GB of page faults
  // at n = 10^6).
  double products(const ModalSolution& sol, int k, Vector& kx, Vector& mx) override {
    kx.resize(chain_.dofs());
    mx.resize(chain_.dofs());
    k_times(sol.dq.col(k), kx);
    m_times(sol.dq.col(k), mx);
    project(kx);
    project(mx);
    return sol.dq.col(k).norm();  // ||D x|| = ||x||
  }
  void shapes(ModalSolution&) override {}

 protected:
  explicit ChainPath(const Chain& chain) : chain_(chain) {}
  /// y = K v and y = M v (y has dofs() entries), and v = P v.
  virtual void k_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y) = 0;
  virtual void m_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y) = 0;
  virtual void project(Vector& v) const = 0;

  const Chain& chain_;
};

/// The O(n) path of the paper's ring: the shifted constrained solve in segment angles as
/// the operator, K and M as products, D applied only to the final vectors.
class SparsePath final : public ChainPath {
 public:
  SparsePath(const Chain& chain, double s, SparseEigensolver eigensolver)
      : ChainPath(chain), sp_(chain), eigensolver_(eigensolver) {
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
  const char* name() const override { return "sparse"; }

 private:
  void k_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y) override { sp_.k_times(v, y); }
  void m_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y) override { sp_.m_times(v, y, ws_); }
  void project(Vector& v) const override { sp_.project(v); }

  ShiftedSolve sp_;
  SparseEigensolver eigensolver_;
  ShiftedSolve::Workspace ws_;
};

/// The O(n) path of the ring with its terms (attachments.hpp) in hinge positions
/// (position_modes.hpp): the eigen layer's shift-invert Lanczos on one bordered-band solve
/// per step, its vectors converted to chain coordinates, where the residuals are those of
/// the dense path's pencil (the chain's K and M with the terms', the constraint rows with
/// the further pins').
class PositionPath final : public ChainPath {
 public:
  PositionPath(const Chain& chain, const ring::RingSpec& spec, double s)
      : ChainPath(chain), terms_(chain, spec), chain_products_(chain), s_(s) {
    Jt_ = terms_.constraints(chain.q0()).G.transpose();
    jjt_.compute(Jt_.transpose() * Jt_);
  }
  /// r: the chain's unknowns less the constraint rows (closure, roller, further pins).
  int unknowns() const { return chain_.dofs() - static_cast<int>(Jt_.cols()); }
  void pairs(int nev, Vector& omega2, Matrix& vecs, LinearModel& model) override {
    natural::ShiftedKkt op(chain_, terms_);
    natural::PositionMass mass(op.model(), terms_);
    modal::LanczosOptions opt;
    opt.tol = kLibraryLanczosTol;
    opt.ncv = modal::subspace_size(nev, unknowns());  // the Krylov space lives in G u = 0
    modal::ShiftInvertLanczos<natural::ShiftedKkt, natural::PositionMass> eigs(op, mass, nev, -s_, opt);
    eigs.compute();
    omega2 = eigs.eigenvalues();  // throws ring::NumericalError unless Successful
    vecs = natural::chain_coordinates(chain_, eigs.eigenvectors());
    model.kind = Dependent::robust;
    model.qr.compute(Jt_);
    model.j2_condition = j2_condition(Jt_.transpose(), chain_.n());
  }
  const char* name() const override { return "sparse"; }

 private:
  void k_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y) override {
    chain_products_.k_times(v, y);
    add_terms(v, y, true);
  }
  void m_times(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y) override {
    chain_products_.m_times(v, y, ws_);
    add_terms(v, y, false);
  }
  void project(Vector& v) const override { v.noalias() -= Jt_ * jjt_.solve(Jt_.transpose() * v); }
  /// y += the terms' K v (`stiffness`) or M v.
  void add_terms(const Eigen::Ref<const Vector>& v, Eigen::Ref<Vector> y, bool stiffness) const {
    Vector t = Vector::Zero(y.size());
    terms_.add_rest_products(v, stiffness ? &t : nullptr, stiffness ? nullptr : &t);
    y += t;
  }

  const detail::Attachments terms_;
  ShiftedSolve chain_products_;  ///< the chain's own K and M(q0) products (never factored)
  double s_;
  Matrix Jt_;                    ///< the constraint rows at rest, transposed: N x c
  Eigen::LLT<Matrix> jjt_;       ///< J J^T
  ShiftedSolve::Workspace ws_;
};

}  // namespace

ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options, int count,
                          SparseEigensolver eigensolver) {
  const auto start = std::chrono::steady_clock::now();
  check_modes(spec, options);
  // The spinning ring's modes are complex (spin.hpp): compute_modes has them.
  ring::refuse_rotation(spec, "multibody::solve_modes (the modes at rest; compute_modes has the spinning ring's)");
  const Chain chain(spec, options);
  const bool sparse = backend(options, spec, count) == Backend::banded;
  const double s = modal::bending_scale(spec);
  // The paths (modes.hpp): the paper's ring on the O(n) path in segment angles, its terms
  // (attachments.hpp) in hinge positions; the dense path with the terms' n x n matrices.
  std::optional<detail::LinearTerms> terms;
  std::optional<Shear> shear;  // the Timoshenko chain (linear_model.hpp), dense only (checks.cpp)
  std::unique_ptr<ModesPath> path;
  int r = 0;
  if (sparse && spec.paper_terms_only()) {
    path = std::make_unique<SparsePath>(chain, s, eigensolver);
    r = chain.dofs() - chain.constraint_count();
  } else if (sparse) {
    auto on_positions = std::make_unique<PositionPath>(chain, spec, s);
    r = on_positions->unknowns();
    path = std::move(on_positions);
  } else {
    if (!spec.paper_terms_only()) terms = detail::linear_terms(chain, spec);
    if (spec.theory == ring::Theory::timoshenko) shear = Shear::of(spec, chain.l());
    const int N = linear_unknowns(chain, terms ? &*terms : nullptr, shear ? &*shear : nullptr);
    r = N - chain.constraint_count() - (terms ? static_cast<int>(terms->J.rows()) : 0);
    // ring.variations: the local segment masses and hinge springs (linear_model.hpp, LocalChain),
    // on this path only (checks.cpp refuses the others by the key).
    std::optional<LocalChain> local;
    if (spec.varies()) local = LocalChain::of(chain, spec);
    path = std::make_unique<DensePath>(chain, options.dependent, s, terms ? &*terms : nullptr, shear, std::move(local));
  }
  const int expected_rigid = spec.rigid_modes();
  if (count < 1 || count > r - expected_rigid)
    throw std::invalid_argument("multibody: count = " + std::to_string(count) +
                                " must satisfy 1 <= count <= " + std::to_string(r - expected_rigid) +
                                " (elastic modes of the n = " + std::to_string(chain.n()) + " chain)");
  const int nev = std::min(r, count + expected_rigid + 2);

  ModalSolution sol;
  Vector omega2;  // computed eigenvalues, ascending
  Matrix vecs;
  path->pairs(nev, omega2, vecs, sol.model);
  const modal::Selection sel = modal::select_modes("multibody", omega2, s, count);
  sol.rigid_omega2 = Eigen::Map<const Vector>(sel.rigid_omega2.data(),
                                              static_cast<Eigen::Index>(sel.rigid_omega2.size()));
  path->normalize(vecs, sel.elastic, sol);
  const auto [normK, normM] = path->norms(sol);
  std::vector<double> relative;
  Vector kx, mx;
  for (int k = 0; k < count; ++k) {
    const double x_norm = path->products(sol, k, kx, mx);
    const modal::PairResidual pr = modal::pair_residual(kx, mx, omega2[sel.elastic[k]], x_norm, normK, normM);
    relative.push_back(pr.relative);
    sol.backward_error = modal::worst(sol.backward_error, pr.backward);
  }
  ring::ModalResult& res = sol.result;
  modal::assemble(res, "multibody", omega2, sel, relative);
  // A pair is an answer when its relative residual is at most modal::kAcceptedResidual,
  // or, in orthonormal (robust) coordinates, when its normwise backward error is at most
  // kAcceptedBackward: there the relative residual's rounding floor grows like n^2 (2.2e-8,
  // 2.2e-6, 2.9e-4, 7.5e-3 at n = 10^4, 10^5, 10^6, 7 10^6, backward errors <= 1e-12 and
  // frequencies within 2e-12 of the oracle) and would pass 1e-2 near n = 8 10^6, inside
  // the cost guard's budget. The failed Lanczos of a free thick ring (relative residual 1.0)
  // has a backward error of 5e-3. The paper's dependent angles are not orthonormal: their
  // wrong pairs at n = 2000 have relative residual 1.0 but backward error 1.6e-16 (the
  // inflated ||K0||), so there only the relative residual decides.
  constexpr double kAcceptedBackward = 1e-10;
  if (!(options.dependent == Dependent::robust && sol.backward_error <= kAcceptedBackward))
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

  res.shapes = chain.rest_shapes(sol.dq);
  return sol;
}

ModalSolution solve_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options, int count) {
  return solve_modes(spec, options, count, kDefaultSparseEigensolver);
}

ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                int count) {
  if (spec.rotation.spinning()) return compute_spinning_modes(spec, options, count);
  return solve_modes(spec, options, count).result;
}

}  // namespace multibody
