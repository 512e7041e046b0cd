// The band LU and the bordered band factorization (bordered_band.hpp).
#include "multibody/bordered_band.hpp"

#include <cmath>

namespace multibody::detail {

// ---- banded LU with partial pivoting: LAPACK's dgbtrf/dgbtrs ----
// A(i, j) is stored at ab[j * ldab + kv + i - j], kv = kl + ku, ldab = 2 kl + ku + 1 (LAPACK's
// band storage: the kl extra rows hold the fill of the row interchanges).
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

// ---- the bordered band ----

void BorderedBand::number() {
  auto columns = [](std::vector<int>& mark, std::vector<int>& of) {
    of.clear();
    for (size_t k = 0; k < mark.size(); ++k)
      if (mark[k] >= 0) {
        mark[k] = static_cast<int>(of.size());
        of.push_back(static_cast<int>(k));
      }
  };
  columns(solved_, border_of_);
  columns(reached_, band_of_);
}

void BorderedBand::clear() {
  band_.resize(core_, kl_, ku_);
  X_.setZero(core_, static_cast<Eigen::Index>(border_of_.size()));
  C_.setZero(border_, static_cast<Eigen::Index>(band_of_.size()));
  D_.setZero(border_, border_);
}

long BorderedBand::stored() const { return band_.stored() + long(X_.size() + C_.size() + D_.size()); }

bool BorderedBand::factor() {
  if (!band_.factor()) return false;
  if (border_ == 0) return true;
  band_.solve_rows(X_.data(), static_cast<int>(X_.cols()));
  // S = D - C P^-1 B, over the band rows that C reaches and the border columns B has.
  Eigen::MatrixXd Xr(band_of_.size(), X_.cols());
  for (size_t q = 0; q < band_of_.size(); ++q) Xr.row(q) = X_.row(band_of_[q]);
  const Eigen::MatrixXd CX = C_ * Xr;
  for (size_t q = 0; q < border_of_.size(); ++q) D_.col(border_of_[q]) -= CX.col(q);
  if (!D_.allFinite()) return false;
  schur_.compute(D_);
  const auto pivots = schur_.matrixLU().diagonal().cwiseAbs();
  return pivots.allFinite() && pivots.minCoeff() > 0.0;
}

void BorderedBand::solve(double* z, int k) const {
  if (k == 1) band_.solve_many(z, core_, 1);  // u = P^-1 f_P (dgbtrs; the same result as solve_rows)
  else band_.solve_rows(z, k);
  if (border_ == 0) return;
  Eigen::Map<RowMatrix> u(z, core_, k), w(z + core_ * k, border_, k);
  Eigen::MatrixXd ur(band_of_.size(), k);  // u on the band rows that C reaches
  for (size_t q = 0; q < band_of_.size(); ++q) ur.row(q) = u.row(band_of_[q]);
  const Eigen::MatrixXd g = w - C_ * ur;
  w = schur_.solve(g);
  Eigen::MatrixXd ws(border_of_.size(), k);  // w on the solved border columns
  for (size_t q = 0; q < border_of_.size(); ++q) ws.row(q) = w.row(border_of_[q]);
  u.noalias() -= X_ * ws;
}

}  // namespace multibody::detail
