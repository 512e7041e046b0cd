#include "lumped_mass/eigen.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "modal/lanczos.hpp"
#include "modal/modes.hpp"
#include "ring/errors.hpp"

namespace lumped {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// Orthonormal selection T (N x Nr) with S T = 0: free translations and rotations
/// keep their unit columns; a node with one blocked direction d keeps the column
/// along d rotated by +90 deg; a node with two blocked directions loses both; a clamped
/// frame node loses its rotation; the chain's hinge rotations after the node DOFs (model.hpp)
/// keep theirs. Each row of S acts on one node's (ux, uy) or on its rotation alone (model.hpp).
/// O(N).
struct Reduction {
  SpMat T;
  std::vector<char> massless;  // per reduced DOF
};

Reduction support_reduction(const Model& m) {
  const int N = static_cast<int>(m.K.rows()), dpn = m.dofs_per_node;
  std::vector<std::vector<std::array<double, 2>>> blocked(m.n);
  std::vector<char> rotation_blocked(m.n, 0);
  const SpMat St = m.S.transpose();  // column r of St = row r of S
  for (int r = 0; r < St.cols(); ++r) {
    int node = -1;
    bool rotation = false;
    std::array<double, 2> d{0.0, 0.0};
    for (SpMat::InnerIterator it(St, r); it; ++it) {
      node = static_cast<int>(it.row()) / dpn;
      if (it.row() % dpn >= 2)
        rotation = true;
      else
        d[it.row() % dpn] = it.value();
    }
    if (rotation)
      rotation_blocked[node] = 1;
    else
      blocked[node].push_back(d);
  }
  Reduction red;
  Triplets t;
  int col = 0;
  for (int k = 0; k < m.n; ++k) {
    if (blocked[k].empty()) {
      t.emplace_back(dpn * k, col++, 1.0);
      t.emplace_back(dpn * k + 1, col++, 1.0);
      red.massless.push_back(m.massless[dpn * k]);
      red.massless.push_back(m.massless[dpn * k + 1]);
    } else if (blocked[k].size() == 1) {
      const auto& d = blocked[k][0];
      t.emplace_back(dpn * k, col, -d[1]);
      t.emplace_back(dpn * k + 1, col++, d[0]);
      red.massless.push_back(m.massless[dpn * k]);
    }  // two blocked directions: pinned, no column
    for (int r = 2; r < dpn; ++r) {
      if (rotation_blocked[k]) continue;
      t.emplace_back(dpn * k + r, col++, 1.0);
      red.massless.push_back(m.massless[dpn * k + r]);
    }
  }
  for (int i = m.node_dofs(); i < N; ++i) {
    t.emplace_back(i, col++, 1.0);
    red.massless.push_back(m.massless[i]);
  }
  red.T.resize(N, col);
  red.T.setFromTriplets(t.begin(), t.end());
  return red;
}

/// Selection E (Nr x Na) of the inertial (not massless) reduced DOFs.
SpMat inertial_selection(const std::vector<char>& massless) {
  Triplets t;
  int col = 0;
  for (std::size_t i = 0; i < massless.size(); ++i)
    if (!massless[i]) t.emplace_back(static_cast<int>(i), col++, 1.0);
  SpMat E(static_cast<int>(massless.size()), col);
  E.setFromTriplets(t.begin(), t.end());
  return E;
}

// ---------------------------------------------------------------- dense path

/// Dense path (eigen.hpp): the eigenvalues are the squared singular values of
/// F = D^1/2 B Y L^-T, where Y spans the admissible DOFs (supports and links
/// eliminated, massless DOFs condensed) and Y^T M Y = L L^T. Small singular values of F
/// carry absolute error eps ||F||, so a low lambda has relative error eps sqrt(lambda_max /
/// lambda) instead of the eps lambda_max / lambda of a symmetric eigensolver on Y^T K Y.
Eigenpairs solve_dense(const Model& m, const Reduction& red, int count) {
  const MatrixXd T = MatrixXd(red.T);
  MatrixXd A = m.D.cwiseSqrt().asDiagonal() * (MatrixXd(m.B) * T);  // strains x Nr
  const MatrixXd Mt = T.transpose() * MatrixXd(m.M) * T;
  const MatrixXd Ct = MatrixXd(m.C) * T;
  const int Nr = static_cast<int>(T.cols());
  MatrixXd Md, lift;  // lift: reduced-problem vector -> model DOFs (N x Nd)
  if (Ct.rows() > 0) {
    Eigen::ColPivHouseholderQR<MatrixXd> qr(Ct.transpose());
    if (qr.rank() != Ct.rows())
      throw ring::NumericalError("lumped: link constraints are dependent (rank " +
                                 std::to_string(qr.rank()) + " of " + std::to_string(Ct.rows()) + ")");
    const MatrixXd Q = qr.householderQ();
    const MatrixXd Z = Q.rightCols(Nr - Ct.rows());
    A = A * Z;
    Md = Z.transpose() * Mt * Z;
    lift = T * Z;
  } else if (std::count(red.massless.begin(), red.massless.end(), 1) > 0) {
    // Static condensation in factored form: min over x_b of |A_a x_a + A_b x_b|^2 gives
    // x_b = -R_b^-1 Q_b^T A_a x_a and the residual (I - Q_b Q_b^T) A_a x_a.
    std::vector<int> a, b;
    for (int i = 0; i < Nr; ++i) (red.massless[i] ? b : a).push_back(i);
    const MatrixXd Aa = A(Eigen::all, a), Ab = A(Eigen::all, b);
    Eigen::HouseholderQR<MatrixXd> qr(Ab);
    const MatrixXd Qb = qr.householderQ() * MatrixXd::Identity(Ab.rows(), Ab.cols());
    const MatrixXd Rb = qr.matrixQR().topRows(Ab.cols()).triangularView<Eigen::Upper>();
    const MatrixXd QtAa = Qb.transpose() * Aa;
    const MatrixXd G = -Rb.triangularView<Eigen::Upper>().solve(QtAa);  // x_b = G x_a
    A = Aa - Qb * QtAa;
    Md = Mt(a, a);
    MatrixXd L = MatrixXd::Zero(Nr, a.size());
    for (std::size_t i = 0; i < a.size(); ++i) L(a[i], i) = 1.0;
    for (std::size_t i = 0; i < b.size(); ++i) L.row(b[i]) = G.row(i);
    lift = T * L;
  } else {
    Md = Mt;
    lift = T;
  }
  // Jacobi scaling by diag(Md)^-1/2 (translations and rotations differ in mass by
  // orders of magnitude), then the Cholesky factor of the scaled mass.
  const VectorXd dscale = Md.diagonal().cwiseSqrt().cwiseInverse();
  A = A * dscale.asDiagonal();
  Md = dscale.asDiagonal() * Md * dscale.asDiagonal();
  lift = lift * dscale.asDiagonal();
  Eigen::LLT<MatrixXd> llt(Md);
  if (llt.info() != Eigen::Success) throw ring::NumericalError("lumped: reduced mass matrix not positive definite");
  const int Nd = static_cast<int>(Md.rows());
  if (A.rows() < Nd) A.conservativeResizeLike(MatrixXd::Zero(Nd, Nd));  // zero rows keep the zero modes
  const MatrixXd F = llt.matrixL().solve(A.transpose()).transpose();     // A L^-T
  Eigen::BDCSVD<MatrixXd> svd(F, Eigen::ComputeThinV);
  if (svd.info() != Eigen::Success) throw ring::NumericalError("lumped: dense SVD failed");
  Eigenpairs p;
  p.method = Method::dense;
  p.unknowns = Nd;
  const int take = std::min(Nd, count + m.expected_rigid);
  p.X.resize(m.K.rows(), take);
  for (int c = 0; c < take; ++c) {
    const int i = Nd - 1 - c;  // singular values come in descending order
    p.lambda.push_back(svd.singularValues()[i] * svd.singularValues()[i]);
    const VectorXd w = llt.matrixU().solve(VectorXd(svd.matrixV().col(i)));  // L^-T v
    const VectorXd x = lift * w;
    p.X.col(c) = x / std::sqrt(x.dot(m.M * x));
  }
  return p;
}

// ---------------------------------------------------------------- sparse path

/// y = (A - sigma B)^-1 x in the inertial DOFs through the factorized mixed system
///   [ -sigma Mt   b Bt^T   g Ct^T ] [y]   [E x]
///   [ b Bt      -b^2 D^-1   0     ] [s] = [ 0 ]      (s = D Bt y / b: scaled stresses)
///   [ g Ct        0         0     ] [mu]  [ 0 ]
/// whose Schur complement on y is Kt - sigma Mt restricted to C y = 0. The stiffness
/// never appears assembled (eigen.hpp, model.hpp). b_i = sqrt(|sigma| m D_i) and g
/// balance the blocks for pivoting. SparseLU (COLAMD), O(n) fill for the ring's
/// cyclic-banded pattern.
class ShiftInvertOp {
 public:
  using Scalar = double;
  using Factor = Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>>;
  ShiftInvertOp(const SpMat& Bt, const VectorXd& D, const SpMat& Mt, const SpMat& Ct, const SpMat& E,
                double mass_scale)
      : Bt_(Bt), D_(D), Mt_(Mt), Ct_(Ct), E_(E), mass_(mass_scale),
        size_(Mt.rows() + Bt.rows() + Ct.rows()) {}
  Eigen::Index rows() const { return E_.cols(); }
  Eigen::Index cols() const { return E_.cols(); }

  void set_shift(double sigma) {
    const Eigen::Index nr = Mt_.rows(), ns = Bt_.rows();
    const VectorXd beta = (std::abs(sigma) * mass_ * D_).cwiseSqrt();
    double gamma = 0.0;
    Triplets t;
    t.reserve(Mt_.nonZeros() + 2 * Bt_.nonZeros() + ns + 2 * Ct_.nonZeros());
    for (int j = 0; j < Mt_.outerSize(); ++j)
      for (SpMat::InnerIterator it(Mt_, j); it; ++it) t.emplace_back(it.row(), it.col(), -sigma * it.value());
    for (int j = 0; j < Bt_.outerSize(); ++j)
      for (SpMat::InnerIterator it(Bt_, j); it; ++it) {
        const double v = beta[it.row()] * it.value();
        gamma = std::max(gamma, std::abs(v));
        t.emplace_back(nr + it.row(), it.col(), v);
        t.emplace_back(it.col(), nr + it.row(), v);
      }
    for (Eigen::Index i = 0; i < ns; ++i) t.emplace_back(nr + i, nr + i, -beta[i] * beta[i] / D_[i]);
    for (int j = 0; j < Ct_.outerSize(); ++j)
      for (SpMat::InnerIterator it(Ct_, j); it; ++it) {
        t.emplace_back(nr + ns + it.row(), it.col(), gamma * it.value());
        t.emplace_back(it.col(), nr + ns + it.row(), gamma * it.value());
      }
    SpMat A(size_, size_);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    factor_.compute(A);
    if (factor_.info() != Eigen::Success)
      throw ring::NumericalError("lumped: sparse factorization of the shifted system failed (sigma = " +
                                 std::to_string(sigma) + "): " + factor_.lastErrorMessage());
  }
  /// Reduced-DOF part of the solution for a right-hand side in the reduced DOFs.
  VectorXd solve_reduced(const VectorXd& rhs) const {
    VectorXd b = VectorXd::Zero(size_);
    b.head(rhs.size()) = rhs;
    const VectorXd z = factor_.solve(b);
    return z.head(rhs.size());
  }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const VectorXd> x(x_in, E_.cols());
    Eigen::Map<VectorXd> y(y_out, E_.cols());
    y = E_.transpose() * solve_reduced(E_ * x);
  }
  long long factor_nonzeros() const { return factor_.nnzL() + factor_.nnzU(); }
  Eigen::Index size() const { return size_; }

 private:
  const SpMat& Bt_;
  const VectorXd& D_;
  const SpMat &Mt_, &Ct_, &E_;
  double mass_;
  Eigen::Index size_;
  Factor factor_;
};

/// y = B x with B = Maa + mass_scale * Ca^T Ca (eigen.hpp). O(n).
class MassOp {
 public:
  using Scalar = double;
  MassOp(const SpMat& Maa, const SpMat& Ca, double mass_scale) : Maa_(Maa), Ca_(Ca), c_(mass_scale) {}
  Eigen::Index rows() const { return Maa_.rows(); }
  Eigen::Index cols() const { return Maa_.rows(); }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const VectorXd> x(x_in, Maa_.rows());
    Eigen::Map<VectorXd> y(y_out, Maa_.rows());
    y = Maa_ * x;
    if (Ca_.rows() > 0) y += c_ * (Ca_.transpose() * (Ca_ * x));
  }

 private:
  const SpMat &Maa_, &Ca_;
  double c_;
};

Eigenpairs solve_sparse(const Model& m, const Reduction& red, int count) {
  const SpMat Bt = SpMat(m.B * red.T);
  const SpMat Mt = SpMat(red.T.transpose() * m.M * red.T);
  const SpMat Ct = SpMat(m.C * red.T);
  const SpMat E = inertial_selection(red.massless);
  const SpMat Maa = SpMat(E.transpose() * Mt * E);
  const SpMat Ca = SpMat(Ct * E);
  const int Na = static_cast<int>(E.cols());
  const int nev = count + m.expected_rigid;
  if (nev >= Na)
    throw std::invalid_argument("lumped: sparse path needs count + rigid modes (=" + std::to_string(nev) +
                                ") < " + std::to_string(Na) + " inertial DOFs; use the dense path");
  // Typical mass of one inertial DOF, to make Ct^T Ct commensurate with Mt.
  const double mass_scale = Maa.diagonal().mean();
  const double sigma = -m.lambda_scale;

  ShiftInvertOp op(Bt, m.D, Mt, Ct, E, mass_scale);
  MassOp bop(Maa, Ca, mass_scale);
  // The eigen layer starts in the admissible space (the operator's range, v0 = op(B r)).
  // tol is Spectra's relative Ritz-residual bound on nu = 1/(lambda - sigma).
  modal::LanczosOptions opt;
  opt.tol = 1e-13;
  opt.max_restarts = 2000;
  modal::ShiftInvertLanczos<ShiftInvertOp, MassOp> eigs(op, bop, nev, sigma, opt);
  eigs.compute();
  const VectorXd& lam = eigs.eigenvalues();  // ascending; ring::NumericalError unless converged
  const MatrixXd& V = eigs.eigenvectors();

  Eigenpairs p;
  p.method = Method::sparse;
  p.system_order = op.size();
  p.factor_nonzeros = op.factor_nonzeros();
  p.X.resize(m.K.rows(), nev);
  for (int i = 0; i < nev; ++i) {
    p.lambda.push_back(lam[i]);
    // Lift to all reduced DOFs: (Kt - sigma Mt) x = (lambda - sigma) Mt x (eigen.hpp).
    const VectorXd xa = V.col(i);
    const VectorXd xr = (lam[i] - sigma) * op.solve_reduced(E * (Maa * xa));
    const VectorXd x = red.T * xr;
    p.X.col(i) = x / std::sqrt(x.dot(m.M * x));
  }
  return p;
}

}  // namespace

int elastic_dofs(const Model& m) {
  const Reduction red = support_reduction(m);
  const long long inertial = std::count(red.massless.begin(), red.massless.end(), 0);
  return static_cast<int>(inertial - m.C.rows()) - m.expected_rigid;
}

Eigenpairs solve(const Model& m, int count, Method method) {
  const int avail = elastic_dofs(m);
  if (count < 1 || count > avail)
    throw std::invalid_argument("lumped: count (=" + std::to_string(count) + ") must be in [1, " +
                                std::to_string(avail) + "] for n = " + std::to_string(m.n));
  const Reduction red = support_reduction(m);
  const int nev = count + m.expected_rigid;
  if (method == Method::automatic)
    method = (m.n <= 24 || 3 * nev > avail) ? Method::dense : Method::sparse;
  Eigenpairs p;
  if (method == Method::dense)
    p = solve_dense(m, red, count);
  else
    p = solve_sparse(m, red, count);

  p.unknowns = avail + m.expected_rigid;
  p.rigid = 0;
  for (double l : p.lambda) {
    if (!std::isfinite(l)) throw ring::NumericalError("lumped: non-finite eigenvalue");
    if (modal::is_rigid(l, m.lambda_scale)) ++p.rigid;
  }
  if (p.rigid != m.expected_rigid)
    throw ring::NumericalError("lumped: found " + std::to_string(p.rigid) + " modes with omega^2 < " +
                               std::to_string(modal::kRigidThreshold) + " EI/(rho A R^4), the supports leave " +
                               std::to_string(m.expected_rigid));
  const std::vector<double> res = residuals(m, p);
  for (std::size_t i = p.rigid; i < res.size(); ++i) p.max_residual = modal::worst(p.max_residual, res[i]);
  return p;
}

std::vector<double> residuals(const Model& m, const Eigenpairs& p) {
  const Reduction red = support_reduction(m);
  const SpMat Ct = SpMat(m.C * red.T);
  Eigen::SimplicialLDLT<SpMat> cct;
  if (Ct.rows() > 0) {
    cct.compute(SpMat(Ct * Ct.transpose()));
    if (cct.info() != Eigen::Success) throw ring::NumericalError("lumped: C C^T not positive definite");
  }
  std::vector<double> out;
  for (int c = 0; c < p.X.cols(); ++c) {
    const VectorXd x = p.X.col(c);
    // K x through the factored form (model.hpp): the assembled K would add a roundoff
    // floor of eps ||K|| ||x|| to a residual that is meant to measure the solver.
    const VectorXd bx = m.B * x;
    const VectorXd kx = m.B.transpose() * VectorXd(m.D.cwiseProduct(bx)), mx = m.M * x;
    VectorXd r = red.T.transpose() * (kx - p.lambda[c] * mx);
    if (Ct.rows() > 0) r -= Ct.transpose() * cct.solve(Ct * r);
    out.push_back(modal::relative_residual(r.norm(), kx.norm(), mx.norm(), p.lambda[c]));
  }
  return out;
}

}  // namespace lumped
