// modal::frontal_inertia against inertias known in closed form, not computed by the code
// under test:
// - the periodic second difference A = circulant(-1, 2, -1) (n x n) shifted by sigma has
//   eigenvalues 2 - 2 cos(2 pi k / n) - sigma, k = 0 .. n-1 (the discrete Fourier
//   transform diagonalizes it), so its negative count is the number of k below the shift;
// - the KKT matrix [A - sigma I, g; g^T, 0] with g = (1, ..., 1) (the constraint sum u = 0,
//   which removes the k = 0 eigenvector, the constant): by Sylvester (Gould 1985) its
//   inertia is that of A - sigma I on the constraint's kernel (the k >= 1 eigenvalues) plus
//   one positive and one negative.
// The dense eigenvalue count of a random banded matrix is the third oracle (fixed seed).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <random>
#include <vector>

#include "modal/inertia.hpp"

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;
constexpr double kPi = 3.14159265358979323846;

Triplets periodic_laplacian(int n, double sigma) {
  Triplets t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 - sigma);
    t.emplace_back(i, (i + 1) % n, -1.0);
    t.emplace_back((i + 1) % n, i, -1.0);
  }
  return t;
}

/// Groups of one unknown in order except the last `tail` ones, which form the border.
void split(int n, int tail, std::vector<std::vector<int>>& groups, std::vector<int>& border) {
  for (int i = 0; i < n - tail; ++i) groups.push_back({i});
  for (int i = n - tail; i < n; ++i) border.push_back(i);
}

long below(int n, double sigma, int from) {
  long c = 0;
  for (int k = from; k < n; ++k) c += 2.0 - 2.0 * std::cos(2.0 * kPi * k / n) < sigma ? 1 : 0;
  return c;
}

// Shifts between the eigenvalues (never on one: sigma = 2 - 2 cos(2 pi (k + 1/2) / n)),
// n = 1000 and 10^5, the closing corner in the border.
TEST(FrontalInertia, ShiftedPeriodicLaplacianCountsTheFourierEigenvaluesBelowTheShift) {
  for (int n : {1000, 100000})
    for (double k : {0.5, 3.5, 40.5}) {
      const double sigma = 2.0 - 2.0 * std::cos(2.0 * kPi * k / n);
      const Triplets t = periodic_laplacian(n, sigma);
      Sparse A(n, n);
      A.setFromTriplets(t.begin(), t.end());
      std::vector<std::vector<int>> groups;
      std::vector<int> border;
      split(n, 1, groups, border);
      const auto in = modal::frontal_inertia(A, groups, border);
      ASSERT_TRUE(in.has_value()) << n;
      EXPECT_EQ(in->negative, below(n, sigma, 0)) << "n = " << n << ", k = " << k;
      EXPECT_EQ(in->zero, 0);
      EXPECT_EQ(in->negative + in->positive, n);
    }
}

// The KKT form, with the multiplier in the border: its zero diagonal is never a pivot.
TEST(FrontalInertia, KktMatrixHasTheInertiaOnTheKernelPlusOneOfEachSign) {
  const int n = 2000;
  for (double k : {0.5, 1.5, 7.5}) {
    const double sigma = 2.0 - 2.0 * std::cos(2.0 * kPi * k / n);
    Triplets t = periodic_laplacian(n, sigma);
    for (int i = 0; i < n; ++i) {
      t.emplace_back(i, n, 1.0);
      t.emplace_back(n, i, 1.0);
    }
    Sparse K(n + 1, n + 1);
    K.setFromTriplets(t.begin(), t.end());
    std::vector<std::vector<int>> groups;
    std::vector<int> border;
    split(n, 1, groups, border);
    border.push_back(n);
    const auto in = modal::frontal_inertia(K, groups, border);
    ASSERT_TRUE(in.has_value());
    EXPECT_EQ(in->negative, below(n, sigma, 1) + 1) << "k = " << k;
    EXPECT_EQ(in->positive, n - 1 - below(n, sigma, 1) + 1) << "k = " << k;
  }
}

// A random symmetric band (half-width 3, fixed seed) with a zero diagonal on every third
// unknown (pivots that must be delayed or paired): the dense eigenvalue count.
TEST(FrontalInertia, RandomIndefiniteBandAgreesWithTheDenseEigenvalues) {
  std::mt19937 gen(20260101);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 300;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = i; j < std::min(n, i + 4); ++j) D(i, j) = D(j, i) = (i == j && i % 3 == 0) ? 0.0 : u(gen);
    const Sparse K = D.sparseView();
    std::vector<std::vector<int>> groups;
    std::vector<int> border;
    split(n, 0, groups, border);
    const auto in = modal::frontal_inertia(K, groups, border);
    ASSERT_TRUE(in.has_value());
    const Eigen::VectorXd e = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(D, Eigen::EigenvaluesOnly).eigenvalues();
    EXPECT_EQ(in->negative, (e.array() < 0.0).count()) << "trial " << trial;
    EXPECT_EQ(in->positive, (e.array() > 0.0).count()) << "trial " << trial;
  }
}

}  // namespace
