#include "multibody/linear_model.hpp"

#include <algorithm>
#include <string>

#include "ring/errors.hpp"

namespace multibody {

namespace {

using Dependent = ring::MultibodyOptions::Dependent;

/// The paper's dependent angles: the last two, plus (with a roller at hinge r) segment
/// r-1, or n-3 when r-1 is already among the last two.
std::vector<int> paper_dependents(const Chain& c) {
  const int n = c.n();
  std::vector<int> p{n - 2, n - 1};
  if (c.roller_hinge()) {
    const int r = *c.roller_hinge();
    p.insert(p.begin(), r - 1 <= n - 3 ? r - 1 : n - 3);
  }
  return p;
}

/// D^T A D for D = rows I: identity, rows P: X (c x r), without forming A D. O(N^2 c).
Matrix condense(const Matrix& A, const std::vector<int>& I, const std::vector<int>& P,
                const Matrix& X) {
  const int r = static_cast<int>(I.size()), c = static_cast<int>(P.size());
  Matrix AII(r, r), AIP(r, c), APP(c, c);
  for (int j = 0; j < r; ++j)
    for (int i = 0; i < r; ++i) AII(i, j) = A(I[i], I[j]);
  for (int j = 0; j < c; ++j) {
    for (int i = 0; i < r; ++i) AIP(i, j) = A(I[i], P[j]);
    for (int i = 0; i < c; ++i) APP(i, j) = A(P[i], P[j]);
  }
  const Matrix t = AIP * X;  // r x r
  Matrix R = AII + t + t.transpose() + X.transpose() * (APP * X);
  return 0.5 * (R + R.transpose());
}

}  // namespace

int linear_unknowns(const Chain& chain, const detail::LinearTerms* terms, const Shear* shear) {
  return chain.dofs() + (shear ? chain.n() : 0) + (terms ? terms->hinge_dofs() : 0);
}

double j2_condition(const Matrix& J, int n) {
  if (J.rows() < 2) return 1.0;  // an arch without the far end's rows: no J_2
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(J.block(0, n - 2, 2, 2).eval());
  const auto sv = svd.singularValues();
  return sv[0] / sv[1];
}

namespace {

/// The unreduced K, M and J of the chain with its terms: on q (Euler-Bernoulli), or on
/// (q, gamma) with the bending and the rotation terms on psi = theta + gamma (Timoshenko), and
/// the hinge rotations that carry an inertia after them (linear_model.hpp). O(N^2).
void assemble(const Chain& chain, const detail::LinearTerms* terms, const Shear* shear, const LocalChain* local,
              Matrix& K, Matrix& M, Matrix& J) {
  const Vector q0 = chain.q0();
  const int n = chain.n(), dofs = chain.dofs(), hinge0 = dofs + (shear ? n : 0);
  const int N = linear_unknowns(chain, terms, shear);
  M = local ? local->rest_mass_matrix(chain) : chain.mass_matrix(q0);
  if (N > dofs) {
    Matrix full = Matrix::Zero(N, N);
    full.topLeftCorner(dofs, dofs) = M;
    M = std::move(full);
  }
  K = Matrix::Zero(N, N);
  if (terms) {
    K.topLeftCorner(dofs, dofs) += terms->K;
    M.topLeftCorner(dofs, dofs) += terms->M;
  }
  // T(i, j) += v on the rotations r_i, r_j of segments i, j: theta (+ gamma), P^T A P with
  // P = [I 0 | I]; index >= n: a hinge rotation of its own.
  auto add = [&](Matrix& T, int i, int j, double v) {
    const int a[2] = {i < n ? i : hinge0 + i - n, i < n && shear ? dofs + i : -1};
    const int b[2] = {j < n ? j : hinge0 + j - n, j < n && shear ? dofs + j : -1};
    for (int p : a)
      for (int q : b)
        if (p >= 0 && q >= 0) T(p, q) += v;
  };
  // A spring c (r_i - r_j)^2 / 2.
  auto spring = [&](int i, int j, double c) {
    add(K, i, i, c);
    add(K, j, j, c);
    add(K, i, j, -c);
    add(K, j, i, -c);
  };
  // The hinge springs: the chain's K, or a varying ring's local K_h (LocalChain).
  auto Kat = [&](int h) { return local ? local->spring[h % n] : chain.K(); };
  for (int h = chain.first_spring(); h < n; ++h) spring((h + n - 1) % n, h, Kat(h));
  if (terms) {
    for (const detail::HingeRotation& t : terms->rotations) {
      if (t.moves()) continue;
      // Condensed onto the mean rotation (attachments.hpp): c m^2 / 2, m = (r_a + r_b) / 2
      // (an arch's end: its one segment's rotation).
      const double c = detail::condensed_rotation_stiffness(t.kr, Kat(t.hinge), detail::is_end(chain, t.hinge));
      for (const auto& [i, wi] : detail::mean_rotation(chain, t.hinge))
        for (const auto& [j, wj] : detail::mean_rotation(chain, t.hinge)) add(K, i, j, c * wi * wj);
    }
    // The moving hinges: the spring split in two halves 2K to the hinge's rotation chi, which
    // carries the inertia and kr.
    detail::split_hinges(
        terms->rotations, n, Kat, spring, [&](int x, double kr) { add(K, x, x, kr); },
        [&](int x, double j) { add(M, x, x, j); });
  }
  if (shear)
    for (int i = 0; i < n; ++i) {
      add(M, i, i, shear->inertia);
      K(dofs + i, dofs + i) += shear->stiffness;
    }
  const Matrix J_chain = chain.constraint_jacobian(q0);
  const int c = static_cast<int>(J_chain.rows()) + (terms ? static_cast<int>(terms->J.rows()) : 0);
  J = Matrix::Zero(c, N);  // the constraints hold the centroid line: nothing on gamma or chi
  J.topLeftCorner(J_chain.rows(), dofs) = J_chain;
  if (terms) J.bottomLeftCorner(terms->J.rows(), dofs) = terms->J;
}

}  // namespace

LinearModel linearize(const Chain& chain, Dependent dependent, const detail::LinearTerms* terms, const Shear* shear,
                      const LocalChain* local) {
  Matrix K, M, J;
  assemble(chain, terms, shear, local, K, M, J);
  const int N = static_cast<int>(K.rows()), c = static_cast<int>(J.rows()), r = N - c;
  LinearModel lm;
  lm.j2_condition = j2_condition(J, chain.n());
  if (dependent == Dependent::paper) {
    const std::vector<int> P = paper_dependents(chain);
    std::vector<int> I;
    for (int i = 0; i < N; ++i)
      if (std::find(P.begin(), P.end(), i) == P.end()) I.push_back(i);
    Matrix JP(c, c), JI(c, r);
    for (int k = 0; k < c; ++k) JP.col(k) = J.col(P[k]);
    for (int k = 0; k < r; ++k) JI.col(k) = J.col(I[k]);
    Eigen::FullPivLU<Matrix> lu(JP);
    if (lu.rank() < c)
      throw ring::NumericalError("multibody: the paper's dependent block J_2 is singular (n = " +
                                 std::to_string(chain.n()) + ")");
    const Matrix X = -lu.solve(JI);  // c x r: the paper's -J_2^{-1} J_1
    lm.K0 = condense(K, I, P, X);
    lm.M0 = condense(M, I, P, X);
    lm.kind = Dependent::paper;
    lm.independent = I;
    lm.dependent = P;
    lm.X = X;
  } else {
    // Orthonormal null-space basis: the last r columns of Q in J^T = Q R. Q^T A Q is
    // applied as c Householder reflections from each side: O(N^2 c).
    lm.kind = Dependent::robust;
    lm.qr.compute(J.transpose());
    const auto Q = lm.qr.householderQ();
    auto reduce = [&](const Matrix& A) {
      const Matrix B = Q.transpose() * A;               // Q^T A
      const Matrix C = Q.transpose() * B.transpose();   // Q^T (A Q), A symmetric
      Matrix R = C.bottomRightCorner(r, r);
      return Matrix(0.5 * (R + R.transpose()));
    };
    // Each unreduced matrix freed once reduced: one N x N less at the peak.
    lm.K0 = reduce(K);
    K = Matrix();
    lm.M0 = reduce(M);
  }
  return lm;
}

LocalChain LocalChain::of(const Chain& chain, const ring::RingSpec& spec) {
  const int n = chain.n();
  const double l = chain.l();
  const std::vector<double>& a = chain.hinge_angles_deg();
  LocalChain lc{Vector(n), Vector(n), Vector(n)};
  for (int i = 0; i < n; ++i) {
    // Segment i runs from hinge i to hinge i + 1 (ring: 360 / n degrees on).
    lc.mass[i] = spec.rhoA_at(a[i] + 180.0 / n) * l;
    lc.rotary[i] = chain.Jr() > 0.0 ? lc.mass[i] * l * l / 12.0 : 0.0;
    lc.spring[i] = spec.EI_at(a[i]) / l;
  }
  return lc;
}

Matrix LocalChain::rest_mass_matrix(const Chain& chain) const {
  const int n = chain.n();
  const double l = chain.l();
  const Vector& c = chain.cos0();
  const Vector& s = chain.sin0();
  Vector after(n);  // S_j = sum_{i > j} m_i
  double acc = 0.0;
  for (int j = n - 1; j >= 0; --j) {
    after[j] = acc;
    acc += mass[j];
  }
  Matrix M = Matrix::Zero(chain.dofs(), chain.dofs());
  for (int k = 0; k < n; ++k) {
    for (int j = k + 1; j < n; ++j) {
      const double v = l * l * (after[j] + 0.5 * mass[j]) * (c[j] * c[k] + s[j] * s[k]);
      M(j, k) = v;
      M(k, j) = v;
    }
    M(k, k) = l * l * (after[k] + 0.25 * mass[k]) + rotary[k];
  }
  if (chain.free()) {
    for (int j = 0; j < n; ++j) {
      const double b = l * (after[j] + 0.5 * mass[j]);
      M(j, n) = M(n, j) = -b * s[j];
      M(j, n + 1) = M(n + 1, j) = b * c[j];
    }
    M.bottomRightCorner<2, 2>() = acc * Eigen::Matrix2d::Identity();
  }
  return M;
}

Matrix LinearModel::expand(const Matrix& x) const {
  if (kind == Dependent::paper) {
    const int N = static_cast<int>(independent.size() + dependent.size());
    Matrix dq(N, x.cols());
    for (std::size_t k = 0; k < independent.size(); ++k) dq.row(independent[k]) = x.row(k);
    const Matrix xd = X * x;
    for (std::size_t k = 0; k < dependent.size(); ++k) dq.row(dependent[k]) = xd.row(k);
    return dq;
  }
  const int N = static_cast<int>(qr.rows()), r = static_cast<int>(x.rows());
  Matrix dq = Matrix::Zero(N, x.cols());
  dq.bottomRows(r) = x;
  return qr.householderQ() * dq;
}

Matrix LinearModel::basis() const {
  return expand(Matrix::Identity(K0.rows(), K0.rows()));
}

}  // namespace multibody
