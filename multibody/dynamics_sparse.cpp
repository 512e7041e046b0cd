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
  if (hinge.size())
    for (Eigen::Index k = 0; k < n; ++k)
      y[k] += hinge_at(k) * (x[k] - x[(k + n - 1) % n]) - hinge_at(k + 1) * (x[(k + 1) % n] - x[k]);
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
  if (hinge.size())
    for (Eigen::Index j = 0; j < n; ++j) d[j] += hinge_at(j) + hinge_at(j + 1);
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
  if (T->diag.size() != n) T->diag = Vector::Zero(n);
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

// Unknowns, segment by segment: per term (y_x, y_y), dq_j, per term (s_x, s_y) (the order
// with the narrowest band; one term: lower 5, upper 5). Rows in the same order: the y
// relations, the equation of dq_j, the s relations. The term's coefficient goes into its
// W rows (y carries force units), so the equation rows of dq_j hold the unit vectors
// U_j. The border: z0 = dq_{n-1} and z1 = dq_0 (the springs' cyclic corner entries move
// to them: row dq_0 holds -k z0, row z0 says z0 - dq_{n-1} = 0), then the multipliers.
namespace {
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
int stride(int terms) { return 1 + 4 * terms; }
Eigen::Index dq_index(Eigen::Index j, int terms) { return j * stride(terms) + 2 * terms; }

/// Calls put(i, j, v) for every entry of the bordered saddle-point matrix, the springs'
/// entries also when T.cyclic = 0: the pattern depends on n, the terms and c only.
template <class Put>
void saddle_entries(const StructuredMatrix& T, const Matrix& G, double sc, Put put) {
  const Eigen::Index n = T.size(), c = G.rows();
  const int nt = static_cast<int>(T.terms.size());
  const Eigen::Index core = n * stride(nt);
  auto dq = [&](Eigen::Index j) { return dq_index(j, nt); };
  auto yv = [&](Eigen::Index j, int t, int a) { return j * stride(nt) + 2 * t + a; };
  auto sv = [&](Eigen::Index j, int t, int a) { return dq(j) + 1 + 2 * t + a; };
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Index row = dq(j);
    put(row, row, T.diag[j] + 2.0 * T.cyclic + T.hinge_at(j) + T.hinge_at(j + 1));
    if (j > 0) put(row, dq(j - 1), -T.cyclic - T.hinge_at(j));
    if (j + 1 < n) put(row, dq(j + 1), -T.cyclic - T.hinge_at(j + 1));
    for (int t = 0; t < nt; ++t) {
      const LowRankTerm& term = T.terms[t];
      for (int a = 0; a < 2; ++a) {
        put(row, sv(j, t, a), term.left(a, j));
        // y_j - y_{j-1} - (coef/2) (W_j dq_j + W_{j-1} dq_{j-1}) = 0
        const Eigen::Index ry = yv(j, t, a);
        put(ry, ry, 1.0);
        put(ry, row, -0.5 * term.coef * term.right(a, j));
        if (j > 0) {
          put(ry, yv(j - 1, t, a), -1.0);
          put(ry, dq(j - 1), -0.5 * term.coef * term.right(a, j - 1));
        }
        // s_j - s_{j+1} - (y_j + y_{j+1}) / 2 = 0
        const Eigen::Index rs = sv(j, t, a);
        put(rs, rs, 1.0);
        put(rs, ry, -0.5);
        if (j + 1 < n) {
          put(rs, sv(j + 1, t, a), -1.0);
          put(rs, yv(j + 1, t, a), -0.5);
        }
      }
    }
  }
  put(dq(0), core, -T.cyclic - T.hinge_at(0));  // hinge 0 joins q_0 and q_{n-1}
  put(dq(n - 1), core + 1, -T.cyclic - T.hinge_at(0));
  put(core, dq(n - 1), -1.0);
  put(core + 1, dq(0), -1.0);
  put(core, core, 1.0);
  put(core + 1, core + 1, 1.0);
  for (Eigen::Index i = 0; i < c; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      put(dq(j), core + 2 + i, sc * G(i, j));
      put(core + 2 + i, dq(j), sc * G(i, j));
    }
}
}  // namespace

bool SparseSaddle::factor(const StructuredMatrix& T, const Matrix& G, double sc) {
  const int nt = static_cast<int>(T.terms.size());
  if (T.size() != T_.size() || nt != static_cast<int>(T_.terms.size()) || G.rows() != G_.rows())
    band_ = BorderedBand(T.size() * stride(nt), 2 + G.rows(), [&](auto mark) {
      saddle_entries(T, G, sc, [&](Eigen::Index i, Eigen::Index j, double) { mark(i, j); });
    });
  else
    band_.clear();
  T_ = T;
  G_ = G;
  sc_ = sc;
  saddle_entries(T, G, sc, [&](Eigen::Index i, Eigen::Index j, double v) { band_.add(i, j, v); });
  return band_.factor();
}

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
  const int nt = static_cast<int>(T_.terms.size());
  RowMatrix z = RowMatrix::Zero(band_.order(), k);  // by rows, as BorderedBand::solve takes them
  for (Eigen::Index j = 0; j < n; ++j) z.row(dq_index(j, nt)) = B.row(j);
  z.bottomRows(c) = D;
  if (!z.allFinite()) return false;
  band_.solve(z.data(), static_cast<int>(k));
  X.resize(n, k);
  for (Eigen::Index j = 0; j < n; ++j) X.row(j) = z.row(dq_index(j, nt));
  Y = z.bottomRows(c);
  return X.allFinite() && Y.allFinite();
}

ClosestPair closest_contact(const Eigen::Matrix2Xd& hinges, double l, int min_gap, double reach, bool closed) {
  if (!closed) return closest_nonadjacent(hinges, min_gap, reach, false);
  return hinges.cols() >= kGridContact ? closest_nonadjacent_grid(hinges, l, min_gap, reach)
                                       : closest_nonadjacent(hinges, min_gap, reach);
}

ClosestPair closest_nonadjacent_grid(const Eigen::Matrix2Xd& p, double l, int min_gap,
                                     double reach) {
  const int n = static_cast<int>(p.cols());
  ClosestPair best{reach, -1, -1};
  const double cell = l + reach;
  // Shifted as unsigned: a cell left of or below the origin has a negative index, and a
  // negative left shift is undefined behaviour (UBSan, a free ring's statics).
  auto key = [](long long ix, long long iy) {
    return static_cast<long long>((static_cast<unsigned long long>(ix) << 32) ^ (static_cast<unsigned long long>(iy) & 0xffffffffULL));
  };
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
