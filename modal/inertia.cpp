#include "modal/inertia.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace modal {

namespace {

enum class State : unsigned char { waiting, front, gone };

/// The dense front: global indices and their matrix, with the Schur complement updates of
/// every accepted pivot so far.
class Front {
 public:
  Front(const Eigen::SparseMatrix<double>& K, std::vector<State>& state, const std::vector<bool>& border)
      : K_(K), state_(state), border_(border), pos_(K.rows(), -1) {}

  /// Brings the indices `add` (all waiting) into the front with their entries of K against
  /// the front. An entry against an eliminated index is a pattern that the ordering does
  /// not allow: false.
  bool enter(const std::vector<int>& add) {
    const Eigen::Index old = static_cast<Eigen::Index>(idx_.size());
    for (int i : add) {
      pos_[i] = static_cast<int>(idx_.size());
      idx_.push_back(i);
      state_[i] = State::front;
    }
    const Eigen::Index size = static_cast<Eigen::Index>(idx_.size());
    F_.conservativeResize(size, size);
    F_.bottomRows(size - old).setZero();
    F_.rightCols(size - old).setZero();
    for (int i : add)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K_, i); it; ++it) {
        const int k = static_cast<int>(it.row());
        if (state_[k] == State::gone) return false;
        if (state_[k] != State::front) continue;
        F_(pos_[k], pos_[i]) = it.value();
        if (pos_[k] < old) F_(pos_[i], pos_[k]) = it.value();
      }
    return true;
  }

  /// Eliminates the front indices `P` if their pivot passes the threshold test; adds the
  /// pivot's inertia to `out`. False (nothing changed) when the pivot is rejected.
  bool eliminate(const std::vector<int>& P, double threshold, double zero, Inertia& out) {
    const Eigen::Index p = static_cast<Eigen::Index>(P.size());
    std::vector<int> rest;
    std::vector<bool> in_p(idx_.size(), false);
    for (int i : P) in_p[pos_[i]] = true;
    for (std::size_t a = 0; a < idx_.size(); ++a)
      if (!in_p[a]) rest.push_back(static_cast<int>(a));
    const Eigen::Index r = static_cast<Eigen::Index>(rest.size());
    Eigen::MatrixXd D(p, p), B(r, p);
    for (Eigen::Index a = 0; a < p; ++a) {
      for (Eigen::Index b = 0; b < p; ++b) D(a, b) = F_(pos_[P[a]], pos_[P[b]]);
      for (Eigen::Index b = 0; b < r; ++b) B(b, a) = F_(rest[b], pos_[P[a]]);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (D + D.transpose()));
    const Eigen::VectorXd& e = eig.eigenvalues();
    if (e.cwiseAbs().minCoeff() <= zero) return false;
    const Eigen::MatrixXd L = B * eig.eigenvectors() * e.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
    // The threshold on the rows that will be pivots; the border's rows only collect (they
    // are counted last, and what they hold is not used to eliminate anything).
    for (Eigen::Index b = 0; b < r; ++b)
      if (!border_[idx_[rest[b]]] && !(L.row(b).cwiseAbs().maxCoeff() <= 1.0 / threshold)) return false;
    if (!L.allFinite()) return false;
    for (Eigen::Index a = 0; a < p; ++a) (e[a] < 0.0 ? out.negative : out.positive) += 1;
    Eigen::MatrixXd S(r, r);
    for (Eigen::Index a = 0; a < r; ++a)
      for (Eigen::Index b = 0; b < r; ++b) S(a, b) = F_(rest[a], rest[b]);
    S.noalias() -= L * B.transpose();
    std::vector<int> kept;
    for (int a : rest) kept.push_back(idx_[a]);
    for (int i : P) {
      state_[i] = State::gone;
      pos_[i] = -1;
    }
    idx_ = kept;
    for (std::size_t a = 0; a < idx_.size(); ++a) pos_[idx_[a]] = static_cast<int>(a);
    F_ = S;
    return true;
  }

  /// The inertia of what is left, by a dense eigen-solve.
  void count_rest(double zero, Inertia& out) const {
    if (F_.rows() == 0) return;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (F_ + F_.transpose()), Eigen::EigenvaluesOnly);
    for (Eigen::Index a = 0; a < F_.rows(); ++a) {
      const double v = eig.eigenvalues()[a];
      (std::abs(v) <= zero ? out.zero : v < 0.0 ? out.negative : out.positive) += 1;
    }
  }

  Eigen::Index size() const { return static_cast<Eigen::Index>(idx_.size()); }

 private:
  const Eigen::SparseMatrix<double>& K_;
  std::vector<State>& state_;
  const std::vector<bool>& border_;
  std::vector<int> pos_;  ///< index -> place in the front (-1: not there)
  std::vector<int> idx_;  ///< place in the front -> index
  Eigen::MatrixXd F_;
};

}  // namespace

std::optional<Inertia> frontal_inertia(const Eigen::SparseMatrix<double>& K, const std::vector<std::vector<int>>& groups,
                                       const std::vector<int>& border, int max_front, double threshold) {
  const Eigen::Index N = K.rows();
  if (K.cols() != N) throw std::invalid_argument("frontal_inertia: K is " + std::to_string(N) + " x " +
                                                 std::to_string(K.cols()) + ", not square");
  std::vector<int> group_of(N, -2);
  auto claim = [&](int i, int g) {
    if (i < 0 || i >= N || group_of[i] != -2)
      throw std::invalid_argument("frontal_inertia: index " + std::to_string(i) + " is out of range (0 .. " +
                                  std::to_string(N - 1) + ") or listed twice");
    group_of[i] = g;
  };
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (int i : groups[g]) claim(i, static_cast<int>(g));
  for (int i : border) claim(i, -1);
  for (Eigen::Index i = 0; i < N; ++i)
    if (group_of[i] == -2)
      throw std::invalid_argument("frontal_inertia: index " + std::to_string(i) + " is in no group");

  double largest = 0.0;
  for (Eigen::Index k = 0; k < K.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, k); it; ++it) largest = std::max(largest, std::abs(it.value()));
  const double zero = 1e-15 * largest;

  std::vector<State> state(N, State::waiting);
  std::vector<bool> in_border(N, false);
  for (int i : border) in_border[i] = true;
  Front front(K, state, in_border);
  Inertia out;
  if (!front.enter(border)) return std::nullopt;
  std::vector<int> pivot;  // the group about to go and any delayed before it
  for (std::size_t g = 0; g < groups.size(); ++g) {
    std::vector<int> add;
    for (int i : groups[g])
      if (state[i] == State::waiting) add.push_back(i);
    if (!front.enter(add)) return std::nullopt;
    pivot.insert(pivot.end(), groups[g].begin(), groups[g].end());
    // Every unknown coupled to the pivot enters, with its whole group.
    for (int i : pivot)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, i); it; ++it) {
        const int k = static_cast<int>(it.row());
        if (state[k] != State::waiting) continue;
        add.clear();
        for (int j : groups[group_of[k]])
          if (state[j] == State::waiting) add.push_back(j);
        if (!front.enter(add)) return std::nullopt;
      }
    if (front.size() > max_front) return std::nullopt;
    if (front.eliminate(pivot, threshold, zero, out)) pivot.clear();
  }
  front.count_rest(zero, out);
  return out;
}

}  // namespace modal
