#include "multibody/dynamics_sparse.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace multibody::detail {
namespace {
inline Eigen::Vector2d e(double a) { return {std::cos(a), std::sin(a)}; }
inline Eigen::Vector2d eprime(double a) { return {-std::sin(a), std::cos(a)}; }
inline double A_diag(Eigen::Index n, Eigen::Index j) { return double(n - 1 - j) + 0.25; }
}  // namespace

Eigen::Matrix2Xd apply_A(const Eigen::Matrix2Xd& w) {
  const Eigen::Index n = w.cols();
  Eigen::Matrix2Xd y(2, n), z(2, n);
  Eigen::Vector2d acc = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {  // y = L w
    y.col(i) = acc + 0.5 * w.col(i);
    acc += w.col(i);
  }
  acc.setZero();
  for (Eigen::Index j = n - 1; j >= 0; --j) {  // z = L^T y
    z.col(j) = acc + 0.5 * y.col(j);
    acc += y.col(j);
  }
  return z;
}

Vector StructuredMatrix::times(const Vector& x) const {
  const Eigen::Index n = size();
  Vector y = diag.cwiseProduct(x);
  if (cyclic != 0.0)
    for (Eigen::Index k = 0; k < n; ++k)
      y[k] += cyclic * (2.0 * x[k] - x[(k + n - 1) % n] - x[(k + 1) % n]);
  for (const LowRankTerm& t : terms) {
    Eigen::Matrix2Xd w(2, n);
    for (Eigen::Index j = 0; j < n; ++j) w.col(j) = t.right.col(j) * x[j];
    const Eigen::Matrix2Xd z = apply_A(w);
    for (Eigen::Index j = 0; j < n; ++j) y[j] += t.coef * t.left.col(j).dot(z.col(j));
  }
  return y;
}

Vector StructuredMatrix::diagonal() const {
  const Eigen::Index n = size();
  Vector d = diag.array() + 2.0 * cyclic;
  for (const LowRankTerm& t : terms)
    for (Eigen::Index j = 0; j < n; ++j) d[j] += t.coef * A_diag(n, j) * t.left.col(j).dot(t.right.col(j));
  return d;
}

Matrix StructuredMatrix::dense() const {
  const Eigen::Index n = size();
  Matrix M(n, n);
  for (Eigen::Index j = 0; j < n; ++j) M.col(j) = times(Vector::Unit(n, j));
  return M;
}

// Derivation (angles only; the pinned chain). With midpoint accelerations
//   a_i = l sum_k L_ik (e'_k qdd_k - e_k v_k^2),  e_k = e(phi_k), e'_k = e'(phi_k),
// the inertia force is f = J^T m a + Jr qdd with J_ik = l L_ik e'_k, i.e.
//   f_j = m l^2 e'_j . Y_j + Jr qdd_j,   Y = (I_2 (x) A) h,  h_k = e'_k qdd_k - e_k v_k^2
// (this is M qdd + xi of chain.hpp: xi_j = m l^2 sum_k A_jk sin(phi_j - phi_k) v_k^2).
// d f_j / d(phi_k, v_k) through h_k (with qdd = cm dq, v = cv dq along the integrator):
//   m l^2 A_jk e'_j . (cm e'_k - e_k qdd_k - e'_k v_k^2 - 2 cv e_k v_k)  =: U^T A W,
// and through e'_j itself (diagonal): -m l^2 e_j . Y_j, plus Jr cm. The k = j entry of
// U^T A W is m l^2 A_jj (cm - v_j^2), and together with the diagonal this is the dense
// tangent's cm M_jj + d f_j/d phi_j (checked entry by entry in test_dynamics_sparse.cpp).
void inertia_terms_structured(const Chain& chain, const Vector& q, const Vector& v,
                              const Vector& qdd, double cm, double cv, Vector& r,
                              StructuredMatrix* T) {
  if (chain.free()) throw std::logic_error("inertia_terms_structured: pinned chains only");
  const Eigen::Index n = chain.n();
  const double ml2 = chain.m() * chain.l() * chain.l(), jr = chain.Jr();
  Eigen::Matrix2Xd E(2, n), Ep(2, n), h(2, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    E.col(k) = e(q[k]);
    Ep.col(k) = eprime(q[k]);
    h.col(k) = Ep.col(k) * qdd[k] - E.col(k) * (v[k] * v[k]);
  }
  const Eigen::Matrix2Xd Y = apply_A(h);
  r.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) r[j] = ml2 * Ep.col(j).dot(Y.col(j)) + jr * qdd[j];
  if (!T) return;
  if (T->diag.size() != n) {
    T->diag = Vector::Zero(n);
  }
  LowRankTerm t;
  t.coef = ml2;
  t.left = Ep;
  t.right.resize(2, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    t.right.col(k) = (cm - v[k] * v[k]) * Ep.col(k) - (qdd[k] + 2.0 * cv * v[k]) * E.col(k);
    T->diag[k] += jr * cm - ml2 * E.col(k).dot(Y.col(k));
  }
  T->terms.push_back(std::move(t));
}

StructuredMatrix mass_structured(const Chain& chain, const Vector& q) {
  const Eigen::Index n = chain.n();
  StructuredMatrix M;
  M.diag = Vector::Constant(n, chain.Jr());
  LowRankTerm t;
  t.coef = chain.m() * chain.l() * chain.l();
  t.left.resize(2, n);
  for (Eigen::Index k = 0; k < n; ++k) t.left.col(k) = eprime(q[k]);
  t.right = t.left;
  M.terms.push_back(std::move(t));
  return M;
}

// ---- banded LU with partial pivoting: LAPACK's dgbtrf/dgbtrs ----
// A(i, j) is stored at ab[j * ldab + kv + i - j], kv = kl + ku, ldab = 2 kl + ku + 1 (LAPACK's
// band storage: the kl extra rows hold the fill of the row interchanges). O(N kl (kl + ku))
// to factor, O(N (2 kl + ku)) to solve.
extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab, const int* ldab, int* ipiv,
             int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs, const double* ab,
             const int* ldab, const int* ipiv, double* b, const int* ldb, int* info, std::size_t trans_len);
}

void BandLU::resize(Eigen::Index N, int kl, int ku) {
  N_ = N;
  kl_ = kl;
  ku_ = ku;
  ldab_ = 2 * kl + ku + 1;
  ab_.assign(size_t(N) * ldab_, 0.0);
  ipiv_.assign(N, 0);
}

bool BandLU::factor() {
  for (double x : ab_)
    if (!std::isfinite(x)) return false;
  const int n = static_cast<int>(N_);
  int info = 0;
  dgbtrf_(&n, &n, &kl_, &ku_, ab_.data(), &ldab_, ipiv_.data(), &info);
  return info == 0;  // info > 0: an exactly zero pivot
}

void BandLU::solve_many(double* b, Eigen::Index ld, Eigen::Index k) const {
  const int n = static_cast<int>(N_), nrhs = static_cast<int>(k), ldb = static_cast<int>(ld);
  int info = 0;
  dgbtrs_("N", &n, &kl_, &ku_, &nrhs, ab_.data(), &ldab_, ipiv_.data(), b, &ldb, &info, 1);
}

void BandLU::solve(double* b) const { solve_many(b, N_, 1); }

void BandLU::solve_rows(double* b, int k) const {
  const Eigen::Index kv = kl_ + ku_;
  // L: dgbtrs's row interchanges and multipliers (rows kv + 1 .. kv + kl of column j).
  for (Eigen::Index j = 0; j + 1 < N_; ++j) {
    double* bj = b + j * k;
    const Eigen::Index p = ipiv_[j] - 1, lm = std::min<Eigen::Index>(kl_, N_ - 1 - j);
    if (p != j) std::swap_ranges(bj, bj + k, b + p * k);
    const double* l = &ab_[size_t(j) * ldab_ + kv + 1];
    for (Eigen::Index i = 0; i < lm; ++i)
      for (int q = 0; q < k; ++q) bj[(i + 1) * k + q] -= l[i] * bj[q];
  }
  // U, upper bandwidth kv, column by column from the last (dtbsv's order).
  for (Eigen::Index j = N_ - 1; j >= 0; --j) {
    double* bj = b + j * k;
    const double* u = &ab_[size_t(j) * ldab_ + kv - j];  // u[i] = U(i, j), j - kv <= i <= j
    for (int q = 0; q < k; ++q) bj[q] /= u[j];
    for (Eigen::Index i = j - 1; i >= std::max<Eigen::Index>(0, j - kv); --i)
      for (int q = 0; q < k; ++q) b[i * k + q] -= bj[q] * u[i];
  }
}

// Unknowns, segment by segment: dq_j, then per term (y_x, y_y, s_x, s_y)_j. Rows in the
// same order: the equation of dq_j, the y and s relations. The term's coefficient goes
// into its W rows (y carries force units), so the equation rows of dq_j hold the unit
// vectors U_j. This core is banded (lower bandwidth 2 stride - 1, upper stride). The two
// cyclic corner entries of the springs and the constraint rows/columns form a border of
// k = 2 + c unknowns (z0 = dq_{n-1}, z1 = dq_0, the multipliers), eliminated by the
// Schur complement S = D - C core^{-1} B (k x k) of the bordered system.
bool SparseSaddle::factor(const StructuredMatrix& T, const Matrix& G, double sc) {
  const Eigen::Index n = T.size(), c = G.rows();
  const int nt = static_cast<int>(T.terms.size());
  stride_ = 1 + 4 * nt;
  order_ = n * stride_;
  T_ = T;
  G_ = G;
  sc_ = sc;
  // Within a segment's block: the y of every term, dq_j, then the s of every term. This
  // order gives the narrowest band (one term: lower 5, upper 5).
  std::vector<Eigen::Triplet<double>> tr;
  tr.reserve(size_t(n) * (3 + 14 * nt));
  auto put = [&](Eigen::Index i, Eigen::Index j, double v) { tr.emplace_back(i, j, v); };
  auto dq = [&](Eigen::Index j) { return j * stride_ + 2 * nt; };
  auto yv = [&](Eigen::Index j, int t, int comp) { return j * stride_ + 2 * t + comp; };
  auto sv = [&](Eigen::Index j, int t, int comp) { return j * stride_ + 2 * nt + 1 + 2 * t + comp; };
  dq0_ = 2 * nt;
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Index row = dq(j);
    put(row, dq(j), T.diag[j] + 2.0 * T.cyclic);
    if (T.cyclic != 0.0) {
      if (j > 0) put(row, dq(j - 1), -T.cyclic);
      if (j + 1 < n) put(row, dq(j + 1), -T.cyclic);
    }
    for (int t = 0; t < nt; ++t) {
      const LowRankTerm& term = T.terms[t];
      for (int a = 0; a < 2; ++a) {
        put(row, sv(j, t, a), term.left(a, j));
        // y_j - y_{j-1} - (coef/2) (W_j dq_j + W_{j-1} dq_{j-1}) = 0
        const Eigen::Index ry = yv(j, t, a);
        put(ry, yv(j, t, a), 1.0);
        put(ry, dq(j), -0.5 * term.coef * term.right(a, j));
        if (j > 0) {
          put(ry, yv(j - 1, t, a), -1.0);
          put(ry, dq(j - 1), -0.5 * term.coef * term.right(a, j - 1));
        }
        // s_j - s_{j+1} - (y_j + y_{j+1}) / 2 = 0
        const Eigen::Index rs = sv(j, t, a);
        put(rs, sv(j, t, a), 1.0);
        put(rs, yv(j, t, a), -0.5);
        if (j + 1 < n) {
          put(rs, sv(j + 1, t, a), -1.0);
          put(rs, yv(j + 1, t, a), -0.5);
        }
      }
    }
  }
  int kl = 0, ku = 0;
  for (const auto& e : tr) {
    kl = std::max<int>(kl, int(e.row() - e.col()));
    ku = std::max<int>(ku, int(e.col() - e.row()));
  }
  band_.resize(order_, kl, ku);
  for (const auto& e : tr) band_.at(e.row(), e.col()) += e.value();
  nnz_ = static_cast<long>(tr.size());
  if (!band_.factor()) return false;
  // Border: B (order x k), C (k x order), D (k x k).
  const Eigen::Index k = 2 + c;
  X_ = RowMatrix::Zero(order_, k);  // B, then core^{-1} B in place
  C_ = Matrix::Zero(k, order_);
  Matrix D = Matrix::Zero(k, k);
  X_(dq(0), 0) = -T.cyclic;
  X_(dq(n - 1), 1) = -T.cyclic;
  C_(0, dq(n - 1)) = -1.0;
  C_(1, dq(0)) = -1.0;
  D(0, 0) = D(1, 1) = 1.0;
  for (Eigen::Index i = 0; i < c; ++i)
    for (Eigen::Index j = 0; j < n; ++j) X_(dq(j), 2 + i) = C_(2 + i, dq(j)) = sc * G(i, j);
  nnz_ += 2 + 2 * n * c;
  band_.solve_rows(X_.data(), static_cast<int>(k));
  schur_.compute(D - C_ * X_);
  return std::isfinite(schur_.rcond()) && schur_.rcond() > 1e-300;
}

long SparseSaddle::factor_nonzeros() const { return band_.stored(); }

bool SparseSaddle::solve(const Vector& b, const Vector& d, Vector& x, Vector& y,
                         int refinements) const {
  x = Vector::Zero(T_.size());
  y = Vector::Zero(G_.rows());
  Vector rb = b, rd = d;
  Matrix dx, dy;
  for (int pass = 0; pass <= refinements; ++pass) {
    if (!solve_columns(rb, rd, dx, dy)) return false;
    x += dx.col(0);
    y += dy.col(0);
    if (pass == refinements) break;
    // Residual of the saddle-point system with the exact O(n) product.
    rb = b - T_.times(x) - sc_ * (G_.transpose() * y);
    rd = d - sc_ * (G_ * x);
  }
  return x.allFinite() && y.allFinite();
}

bool SparseSaddle::solve_columns(const Matrix& B, const Matrix& D, Matrix& X, Matrix& Y) const {
  const Eigen::Index n = T_.size(), c = G_.rows(), k = B.cols();
  RowMatrix u = RowMatrix::Zero(order_, k);
  Matrix e = Matrix::Zero(2 + c, k);
  for (Eigen::Index j = 0; j < n; ++j) u.row(j * stride_ + dq0_) = B.row(j);
  e.bottomRows(c) = D;
  if (!u.allFinite() || !e.allFinite()) return false;
  band_.solve_rows(u.data(), static_cast<int>(k));
  const Matrix w = schur_.solve(e - C_ * u);
  u.noalias() -= X_ * w;
  X.resize(n, k);
  for (Eigen::Index j = 0; j < n; ++j) X.row(j) = u.row(j * stride_ + dq0_);
  Y = w.bottomRows(c);
  return X.allFinite() && Y.allFinite();
}

ClosestPair closest_contact(const Eigen::Matrix2Xd& hinges, double l, int min_gap, double reach) {
  return hinges.cols() >= kGridContact ? closest_nonadjacent_grid(hinges, l, min_gap, reach)
                                       : closest_nonadjacent(hinges, min_gap, reach);
}

ClosestPair closest_nonadjacent_grid(const Eigen::Matrix2Xd& p, double l, int min_gap,
                                     double reach) {
  const int n = static_cast<int>(p.cols());
  ClosestPair best{reach, -1, -1};
  const double cell = l + reach;
  auto key = [](long long ix, long long iy) { return (ix << 32) ^ (iy & 0xffffffffLL); };
  std::unordered_map<long long, std::vector<int>> grid;
  grid.reserve(size_t(n) * 2);
  std::vector<long long> cx(n), cy(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d mid = 0.5 * (p.col(i) + p.col((i + 1) % n));
    cx[i] = static_cast<long long>(std::floor(mid.x() / cell));
    cy[i] = static_cast<long long>(std::floor(mid.y() / cell));
    grid[key(cx[i], cy[i])].push_back(i);
  }
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = p.col(i), b = p.col((i + 1) % n);
    const Eigen::Vector2d lo_i = a.cwiseMin(b), hi_i = a.cwiseMax(b);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = grid.find(key(cx[i] + dx, cy[i] + dy));
        if (it == grid.end()) continue;
        for (int j : it->second) {
          // The same pair filter as closest_nonadjacent: j > i, cyclic gap >= min_gap.
          if (j < i + min_gap || n - (j - i) < min_gap) continue;
          const Eigen::Vector2d c = p.col(j), d = p.col((j + 1) % n);
          const Eigen::Vector2d lo_j = c.cwiseMin(d), hi_j = c.cwiseMax(d);
          if (lo_j.x() > hi_i.x() + reach || lo_i.x() > hi_j.x() + reach ||
              lo_j.y() > hi_i.y() + reach || lo_i.y() > hi_j.y() + reach)
            continue;
          const double dist = segment_distance(a, b, c, d);
          // Ties go to the lexicographically first pair, as in the O(n^2) loop.
          if (dist < best.distance ||
              (dist == best.distance && best.i >= 0 && (i < best.i || (i == best.i && j < best.j))))
            best = {dist, i, j};
        }
      }
  }
  return best;
}

}  // namespace multibody::detail
