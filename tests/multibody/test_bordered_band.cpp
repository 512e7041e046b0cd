// The band kernel and the bordered band factorization of every O(n) Newton matrix
// (multibody/bordered_band.hpp). Oracles: LAPACK's own band solve (dgbtrs) and a dense
// LU with partial pivoting (Eigen) of the same matrix, formed entry by entry.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "multibody/bordered_band.hpp"

namespace {

using Matrix = Eigen::MatrixXd;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using multibody::detail::BandLU;
using multibody::detail::BorderedBand;

// BandLU::solve_rows (all right-hand sides in one pass over the factors) does dgbtrs's
// operations in its order: the same solution bit for bit as solve_many (LAPACK), with a
// backward-stable residual, on random band matrices with pivoting (weak diagonals).
TEST(MultibodyBorderedBand, BandSolveRowsEqualsLapack) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int kl : {0, 1, 3, 7})
    for (int ku : {0, 2, 7})
      for (int k : {1, 2, 5}) {
        const int N = 60;
        Matrix A = Matrix::Zero(N, N);
        for (int j = 0; j < N; ++j)
          for (int i = std::max(0, j - ku); i <= std::min(N - 1, j + kl); ++i) A(i, j) = u(gen) + (i == j ? 0.1 : 0.0);
        BandLU lu;
        lu.resize(N, kl, ku);
        for (int j = 0; j < N; ++j)
          for (int i = std::max(0, j - ku); i <= std::min(N - 1, j + kl); ++i) lu.at(i, j) = A(i, j);
        ASSERT_TRUE(lu.factor());
        const Matrix R = Matrix::Random(N, k);
        Matrix byc = R;  // column-major, for dgbtrs
        lu.solve_many(byc.data(), N, k);
        RowMatrix byr = R;
        lu.solve_rows(byr.data(), k);
        const std::string tag = "kl " + std::to_string(kl) + " ku " + std::to_string(ku) + " k " + std::to_string(k);
        EXPECT_EQ(Matrix(byr), byc) << tag;
        // Backward stable: residual ~ eps ||A|| ||x|| (bound 1e-12; random band matrices
        // may be ill-conditioned, so the solution itself is not compared).
        EXPECT_LE((A * byc - R).norm(), 1e-12 * A.norm() * byc.norm()) << tag;
      }
}

/// A bordered band matrix with a sparse border, as the O(n) paths have: core m, widths
/// (3, 2), border 4. Border columns 0 and 2 have entries in the band (0 on every band
/// row, 2 on the last six), 1 and 3 only in D; border row 0 reaches band columns 0 and 1,
/// row 1 none, row 2 the last four, row 3 every other one; D full. The band's diagonal
/// is weak (random entries + 0.1), so the band LU pivots.
struct Bordered {
  static constexpr int m = 40, kl = 3, ku = 2, b = 4;
  std::vector<std::pair<int, int>> pattern;
  Matrix dense = Matrix::Zero(m + b, m + b);

  explicit Bordered(unsigned seed) {
    for (int j = 0; j < m; ++j)
      for (int i = std::max(0, j - ku); i <= std::min(m - 1, j + kl); ++i) pattern.emplace_back(i, j);
    for (int i = 0; i < m; ++i) pattern.emplace_back(i, m);
    for (int i = m - 6; i < m; ++i) pattern.emplace_back(i, m + 2);
    for (int j : {0, 1}) pattern.emplace_back(m, j);
    for (int j = m - 4; j < m; ++j) pattern.emplace_back(m + 2, j);
    for (int j = 0; j < m; j += 2) pattern.emplace_back(m + 3, j);
    for (int i = m; i < m + b; ++i)
      for (int j = m; j < m + b; ++j) pattern.emplace_back(i, j);
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (auto [i, j] : pattern) dense(i, j) = u(gen) + (i == j ? 0.1 : 0.0);
  }
  /// The structure from the pattern and the values of `dense`, assembled through add().
  BorderedBand assembled() const {
    BorderedBand A(m, b, [&](auto mark) {
      for (auto [i, j] : pattern) mark(i, j);
    });
    for (auto [i, j] : pattern) A.add(i, j, dense(i, j));
    return A;
  }
};

// The bordered band solve equals a dense LU of the same matrix, for one right-hand side
// (dgbtrs) and for three (solve_rows). Tolerance: both are backward stable (residual
// ~ N eps ||A|| ||z||), so they differ by at most ~kappa(A) N eps ||z|| in the solution;
// bound 10 N eps kappa with kappa = 1 / (Eigen's rcond estimate), checked <= 1e6 so that
// the bound stays meaningful. A second assembly after clear() gives the same solution.
TEST(MultibodyBorderedBand, SolvesAsADenseLUOfTheSameMatrix) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    const Bordered M(seed);
    const int N = M.m + M.b;
    const Eigen::PartialPivLU<Matrix> ref(M.dense);
    const double kappa = 1.0 / ref.rcond();
    ASSERT_LE(kappa, 1e6) << "seed " << seed;
    const double tol = 10.0 * N * std::numeric_limits<double>::epsilon() * kappa;
    BorderedBand A = M.assembled();
    ASSERT_TRUE(A.factor()) << "seed " << seed;
    for (int k : {1, 3}) {
      const Matrix f = Matrix::Random(N, k);
      const Matrix z_ref = ref.solve(f);
      RowMatrix z = f;
      A.solve(z.data(), k);
      EXPECT_LE((Matrix(z) - z_ref).norm(), tol * z_ref.norm()) << "seed " << seed << ", k " << k;
    }
    // Reassembled into the same structure: the same factorization.
    const Eigen::VectorXd f = Eigen::VectorXd::Random(N);
    Eigen::VectorXd z1 = f, z2 = f;
    A.solve(z1.data());
    A.clear();
    for (auto [i, j] : M.pattern) A.add(i, j, M.dense(i, j));
    ASSERT_TRUE(A.factor());
    A.solve(z2.data());
    EXPECT_EQ(z1, z2) << "seed " << seed;
  }
}

// The one singularity test: a non-finite entry, an exactly zero pivot of the band, a
// singular Schur complement.
TEST(MultibodyBorderedBand, RefusesSingularAndNonFiniteMatrices) {
  const Bordered M(1);
  {  // border unknown 1 has no band entries: a zero row and column of D make S singular
    BorderedBand A(M.m, M.b, [&](auto mark) {
      for (auto [i, j] : M.pattern) mark(i, j);
    });
    for (auto [i, j] : M.pattern)
      if (i != M.m + 1 && j != M.m + 1) A.add(i, j, M.dense(i, j));
    EXPECT_FALSE(A.factor());
  }
  {  // a zero band column: an exactly zero pivot
    BorderedBand A = M.assembled();
    for (int i = 0; i < M.m; ++i)
      if (i <= 5 + M.kl && i >= 5 - M.ku) A.add(i, 5, -M.dense(i, 5));
    EXPECT_FALSE(A.factor());
  }
  for (auto [i, j] : {std::pair{3, 4}, std::pair{10, M.m}, std::pair{M.m + 3, 6}, std::pair{M.m + 1, M.m + 2}}) {
    BorderedBand A = M.assembled();  // NaN in the band, in B, in C, in D
    A.add(i, j, std::nan(""));
    EXPECT_FALSE(A.factor()) << i << ", " << j;
  }
}

}  // namespace
