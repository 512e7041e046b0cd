// The arch oracles of tests/support/arch.hpp against routes that share none of their code:
// the free ring's Fourier modes (Love; Soedel's 2 x 2 extensible ring), the straight beam's
// characteristic equations (the shallow arch's limit), the clamped ring's modal-series
// receptance (tests/support/ring_receptance.hpp), the unit-load method for the deep arch's
// linear stiffness, DaDeppo & Schmidt's published limit load, and the exact special cases of
// Timoshenko & Gere's arch buckling equations.
#include <gtest/gtest.h>

#include <complex>
#include <cstdio>
#include <vector>

#include "support/arch.hpp"
#include "support/close.hpp"
#include "support/convergence.hpp"
#include "support/ring_receptance.hpp"

namespace {

using archtest::Arch;
using archtest::End;
using ringtest::IsClose;

/// The root of f in (a, b) by bisection (f(a), f(b) of opposite signs).
template <class F>
double bisect(F f, double a, double b) {
  const bool fa = f(a) < 0;
  for (int it = 0; it < 200 && b - a > 4e-16 * b; ++it) {
    const double m = 0.5 * (a + b);
    ((f(m) < 0) == fa ? a : b) = m;
  }
  return 0.5 * (a + b);
}

/// sigma_min / sigma_max of A(Omega) - i k I: zero when the Fourier mode e^{i k theta} solves
/// y' = A y, i.e. when Omega is a frequency of the free ring with k waves.
double fourier_residual(double W2, double e, int k) {
  const Eigen::Matrix<std::complex<double>, 6, 6> B =
      archtest::detail::system_matrix(W2, e, 0.0).cast<std::complex<double>>() -
      std::complex<double>(0.0, k) * Eigen::Matrix<std::complex<double>, 6, 6>::Identity();
  const auto s = B.jacobiSvd().singularValues();
  return s(5) / s(0);
}

// Oracle: the free ring's modes are Fourier modes; their frequencies are Love's inextensible
// Omega_k^2 = k^2 (k^2 - 1)^2 / (k^2 + 1) (Love, sec. 294) and, with e = EI/(EA R^2), the two
// eigenvalues of Soedel's K = (1/e) [1 k; k k^2] + [k^4 k^3; k^3 k^2] (Soedel, sec. 6.6; the
// same kinematics as ring::closed_form::free_ring_extensible, written here again). The arch's
// system matrix must carry e^{i k theta} there (residual at round-off) and not 1 % away.
TEST(ArchOracle, SystemMatrixCarriesTheFreeRingsFourierModes) {
  for (int k = 2; k <= 6; ++k) {
    const double kk = k * k, W2 = kk * (kk - 1) * (kk - 1) / (kk + 1);
    EXPECT_LT(fourier_residual(W2, 0.0, k), 1e-13) << "inextensible, k = " << k;  // round-off of a 6 x 6 SVD
    EXPECT_GT(fourier_residual(1.0201 * W2, 0.0, k), 1e-9) << "k = " << k;        // measured >= 4e-7
    const double e = 1e-3, a = 1.0 / e;
    const double k11 = a + kk * kk, k12 = a * k + kk * k, k22 = a * kk + kk;
    const double tr = k11 + k22, det = k11 * k22 - k12 * k12, disc = std::sqrt(tr * tr - 4 * det);
    for (double lam : {det / (0.5 * (tr + disc)), 0.5 * (tr + disc)})
      EXPECT_LT(fourier_residual(lam, e, k), 1e-12) << "extensible, k = " << k << ", Omega^2 = " << lam;
    // With a Winkler foundation: K + diag(fr, ft) (ring::closed_form::free_ring_extensible's
    // foundation term, per unit EI/R^4).
    const double fr = 300.0, ft = 50.0, f11 = k11 + fr, f22 = k22 + ft;
    const double ftr = f11 + f22, fdet = f11 * f22 - k12 * k12, fdisc = std::sqrt(ftr * ftr - 4 * fdet);
    for (double lam : {fdet / (0.5 * (ftr + fdisc)), 0.5 * (ftr + fdisc)}) {
      const Eigen::Matrix<std::complex<double>, 6, 6> B =
          archtest::detail::system_matrix(lam, e, 0.0, 0.0, fr, ft).cast<std::complex<double>>() -
          std::complex<double>(0.0, k) * Eigen::Matrix<std::complex<double>, 6, 6>::Identity();
      const auto sv = B.jacobiSvd().singularValues();
      EXPECT_LT(sv(5) / sv(0), 1e-12) << "foundation, k = " << k << ", Omega^2 = " << lam;
    }
  }
}

// Oracle: the free Timoshenko ring's Fourier modes (u = U sin k theta, w = W cos k theta,
// R psi = P sin k theta): the three eigenvalues of K - Omega^2 M with, in units R = EI = rhoA = 1,
// K = a a^T / e + b b^T / g + k^2 e3 e3^T, M = diag(1, 1, j), a = (k, 1, 0), b = (-1, -k, 1)
// (Seidel & Erdelyi 1964, Kirkhope 1976; the matrices of ring::closed_form::free_ring_timoshenko,
// written here again). The arch's system matrix with shear and rotary inertia must carry
// e^{i k theta} at each of them.
TEST(ArchOracle, SystemMatrixCarriesTheTimoshenkoRingsFourierModes) {
  const double e = 1e-3, g = 2.5e-3, j = 1e-3;
  for (int k = 1; k <= 5; ++k) {
    const Eigen::Vector3d a(k, 1, 0), b(-1, -k, 1);
    Eigen::Matrix3d K = a * a.transpose() / e + b * b.transpose() / g;
    K(2, 2) += double(k) * k;
    const Eigen::Vector3d m(1, 1, j);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> es(K, m.asDiagonal().toDenseMatrix());
    for (int r = 0; r < 3; ++r) {
      const double lam = es.eigenvalues()(r);
      if (k == 1 && r == 0) continue;  // the rigid translation, Omega = 0
      const Eigen::Matrix<std::complex<double>, 6, 6> B =
          archtest::detail::system_matrix(lam, e, j, g).cast<std::complex<double>>() -
          std::complex<double>(0.0, k) * Eigen::Matrix<std::complex<double>, 6, 6>::Identity();
      const auto sv = B.jacobiSvd().singularValues();
      EXPECT_LT(sv(5) / sv(0), 1e-12) << "k = " << k << ", branch " << r;  // round-off of the SVD
      if (k > 1 && r == 0) {
        // The shear term matters on the flexural branch: without it (or with its sign turned)
        // the mode is no solution (measured residuals 3e-5..3e-4).
        for (double other : {0.0, -g}) {
          const Eigen::Matrix<std::complex<double>, 6, 6> C =
              archtest::detail::system_matrix(lam, e, j, other).cast<std::complex<double>>() -
              std::complex<double>(0.0, k) * Eigen::Matrix<std::complex<double>, 6, 6>::Identity();
          const auto sc = C.jacobiSvd().singularValues();
          EXPECT_GT(sc(5) / sc(0), 1e-6) << "k = " << k << ", g = " << other;
        }
      }
    }
  }
}

// Oracle: a shallow arch (opening alpha -> 0 at a fixed slenderness L/r = 100, so the rise over
// r falls like alpha) tends to the straight beam of length L = R alpha, Omega = (beta_m/alpha)^2
// with beta_m the roots of the beam's characteristic equation (pinned-pinned sin = 0;
// clamped-clamped and free-free cos cosh = 1; clamped-pinned tan = tanh; clamped-free
// cos cosh = -1), solved here by bisection. The curvature's terms are O(alpha^2) (the ring's
// K^2 (K^2 - 1)^2 / (K^2 + 1) at K = m pi / alpha against K^4) and so is the arch effect
// (rise / r)^2; fitted order 2 +- 0.1 (three halvings, measured 2.00), finest errors below
// 1e-3 (measured at most 1.7e-4, the pinned arch's first, symmetric mode). The axial modes sit
// above the third bending one (pi L/r / beta_3^2 = 2.6), free ends' rigid motions are skipped.
TEST(ArchOracle, ShallowArchTendsToTheStraightBeam) {
  struct Case {
    const char* name;
    End start, end;
    double (*f)(double);
    double centre0, step, half;  // root m in (centre0 + m step -+ half)
  };
  const Case cases[] = {
      {"pinned-pinned", End::pinned, End::pinned, [](double x) { return std::sin(x); }, M_PI, M_PI, 0.5},
      {"clamped-clamped", End::clamped, End::clamped, [](double x) { return std::cos(x) - 1 / std::cosh(x); },
       1.5 * M_PI, M_PI, 0.3},
      {"clamped-pinned", End::clamped, End::pinned, [](double x) { return std::sin(x) - std::cos(x) * std::tanh(x); },
       1.25 * M_PI, M_PI, 0.3},
      {"clamped-free", End::clamped, End::free, [](double x) { return std::cos(x) + 1 / std::cosh(x); }, 0.5 * M_PI,
       M_PI, 0.4},
      {"free-free", End::free, End::free, [](double x) { return std::cos(x) - 1 / std::cosh(x); }, 1.5 * M_PI, M_PI,
       0.3},
  };
  const std::vector<double> alphas{0.008, 0.004, 0.002};
  for (const Case& c : cases) {
    std::vector<double> beta;
    for (int m = 0; m < 3; ++m)
      beta.push_back(bisect(c.f, c.centre0 + m * c.step - c.half, c.centre0 + m * c.step + c.half));
    std::vector<std::vector<double>> err(3);
    for (double alpha : alphas) {
      Arch a;
      a.alpha = alpha;
      a.EA = 1e4 / (alpha * alpha);  // (L/r)^2 EI / L^2 with L = R alpha, R = 1
      a.start = c.start;
      a.end = c.end;
      const auto w = archtest::arch_omegas(a, 3);
      for (int m = 0; m < 3; ++m) err[m].push_back(ringtest::rel(w[m], beta[m] * beta[m] / (alpha * alpha)));
    }
    for (int m = 0; m < 3; ++m)
      EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(alphas, err[m]), 2.0, 0.1, 1e-3)) << c.name << ", mode " << m + 1;
  }
}

// Oracle: an arch of 360 degrees clamped at both ends is the ring clamped at one point (the
// clamp takes any force and moment, so the two sides do not interact): the receptance oracle's
// roots (modal series of the free ring, tests/support/ring_receptance.hpp), another algorithm
// on another representation. Inextensible on both sides. The series is cut at kmax = 3000 to keep
// the test fast: tolerance 5e-10 (measured differences at most 1.0e-10 at kmax = 3000, 5.3e-13 at
// the default 20000, so the series' truncation, not the transfer matrix).
TEST(ArchOracle, FullTurnClampedArchIsTheClampedRing) {
  receptance::Ring ring{1.0, 1.0, 1.0};
  ring.kmax = 3000;
  const auto expected = receptance::clamped_omegas(ring, 6);
  Arch a;
  a.alpha = 2 * M_PI;
  a.start = a.end = End::clamped;
  const auto got = archtest::arch_omegas(a, 6);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(IsClose(got[i], expected[i], 5e-10)) << "mode " << i + 1;
}

// Oracle: the frequencies scale as sqrt(EI / (rhoA R^4)) (dimensional analysis at a fixed
// EI/(EA R^2)); the reversed arch (ends swapped) has the same spectrum (the mirror image).
TEST(ArchOracle, ScalingAndMirror) {
  Arch a;
  a.alpha = 2.0;
  a.EA = 1e4;
  a.start = End::clamped;
  a.end = End::pinned;
  const auto w = archtest::arch_omegas(a, 5);
  Arch b = a;
  b.R = 2.0, b.EI = 3.0, b.rhoA = 5.0, b.EA = 1e4 * 3.0 / 4.0;
  b.start = End::pinned;
  b.end = End::clamped;
  const auto v = archtest::arch_omegas(b, 5);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(IsClose(v[i], w[i] * std::sqrt(3.0 / (5.0 * 16.0)), 1e-12)) << i;
}

// The deep arch's linear limit by the unit-load method (an independent route: the statically
// indeterminate arch by compatibility, no ODE): the primary structure is the cantilever from
// the clamp; the pin's reaction (X1, X2) makes its displacement vanish,
// int (m0 + X1 m1 + X2 m2) m_i ds = 0; the apex displacements are int M m_v ds (reduction
// theorem). Moments of a force F at r_F on [0, s]: (r_F - r(s)) x F. Simpson's rule in theta
// on each side of the apex (smooth integrands: error far below 1e-12 at 2000 intervals).
// Returns {P / d, dx / d} for a unit downward load, d the apex's descent.
std::array<double, 2> deep_arch_linear() {
  const double half = 107.5 * M_PI / 180.0, tc = 0.5 * M_PI - half, tp = 0.5 * M_PI + half;
  const double xp = std::cos(tp), yp = std::sin(tp);
  // Integrand vectors: m0 (unit apex load, before the apex only), m1, m2 (unit forces at the pin).
  double d11 = 0, d12 = 0, d22 = 0, d01 = 0, d02 = 0, v00 = 0, v01 = 0, v02 = 0, h00 = 0, h01 = 0, h02 = 0;
  for (int side = 0; side < 2; ++side) {
    const double a = side == 0 ? tc : 0.5 * M_PI, b = side == 0 ? 0.5 * M_PI : tp;
    const int n = 2000;
    for (int i = 0; i <= n; ++i) {
      const double t = a + (b - a) * i / n, wgt = (b - a) / n / 3.0 * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
      const double x = std::cos(t), y = std::sin(t);
      const double m0 = side == 0 ? x : 0.0;           // (r_a - r) x (0, -1), r_a = (0, 1)
      const double mh = side == 0 ? -(1.0 - y) : 0.0;  // (r_a - r) x (1, 0)
      const double m1 = -(yp - y), m2 = xp - x;        // (r_p - r) x (1, 0), (r_p - r) x (0, 1)
      d11 += wgt * m1 * m1, d12 += wgt * m1 * m2, d22 += wgt * m2 * m2;
      d01 += wgt * m0 * m1, d02 += wgt * m0 * m2;
      v00 += wgt * m0 * m0, v01 += wgt * m0 * m1, v02 += wgt * m0 * m2;
      h00 += wgt * mh * m0, h01 += wgt * mh * m1, h02 += wgt * mh * m2;
    }
  }
  const double det = d11 * d22 - d12 * d12;
  const double X1 = (-d01 * d22 + d02 * d12) / det, X2 = (-d02 * d11 + d01 * d12) / det;
  const double down = v00 + X1 * v01 + X2 * v02, dx = h00 + X1 * h01 + X2 * h02;
  return {1.0 / down, dx / down};
}

// Oracle: the elastica's path leaves the unloaded arch along the linear solution: P/d and
// dx/d tend to the unit-load method's values with an error O(d) (the first geometric term);
// fitted order 1 +- 0.1 over d = 1e-4, 1e-5, 1e-6 (measured 1.00), finest below 1e-5 relative
// (measured 4e-6).
TEST(ArchOracle, DeepArchLeavesAlongTheLinearSolution) {
  const auto lin = deep_arch_linear();
  const std::vector<double> ds{1e-4, 1e-5, 1e-6};
  std::vector<double> ep, ex;
  for (double d : ds) {
    const auto p = archtest::deep_arch_at(d);
    EXPECT_DOUBLE_EQ(p.apex_dy, -d);
    ep.push_back(ringtest::rel(p.load / d, lin[0]));
    ex.push_back(ringtest::rel(p.apex_dx / d, lin[1]));
  }
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(ds, ep), 1.0, 0.1, 1e-5)) << "P / d against " << lin[0];
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_h(ds, ex), 1.0, 0.1, 1e-5)) << "dx / d against " << lin[1];
}

// Oracle: DaDeppo & Schmidt (J. Appl. Mech. 42, 1975) print P R^2/EI = 8.97 at the limit of
// the inextensible elastica (3 digits: |P - 8.97| <= 0.005). The shooting's RK4 error is
// O(h^4): the differences of successive halvings fall with a fitted order 4 +- 0.2 (measured
// 4.0), the last below 1e-7. The limit is a maximum along the path: deep_arch_at a little before
// and after it carries a smaller load; at it, the same load (1e-12: Newton's tolerance).
TEST(ArchOracle, DeepArchLimitLoadMatchesDaDeppoSchmidt) {
  const std::vector<int> ns{128, 256, 512, 1024};
  std::vector<archtest::DeepArchPoint> lim;
  for (int n : ns) lim.push_back(archtest::deep_arch_limit(n));
  std::vector<double> dp, dx, dy;
  for (std::size_t i = 0; i + 1 < lim.size(); ++i) {
    dp.push_back(std::abs(lim[i].load - lim[i + 1].load));
    dx.push_back(std::abs(lim[i].apex_dx - lim[i + 1].apex_dx));
    dy.push_back(std::abs(lim[i].apex_dy - lim[i + 1].apex_dy));
  }
  const std::vector<int> n3(ns.begin(), ns.end() - 1);
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(n3, dp), 4.0, 0.2, 1e-7)) << "load";
  EXPECT_TRUE(ringtest::OrderNear(ringtest::in_n(n3, dy), 4.0, 0.3, 1e-7)) << "apex dy";
  const auto& best = lim.back();
  EXPECT_NEAR(best.load, 8.97, 0.005);
  std::printf("deep arch limit (n = 1024): P R^2/EI = %.10f, apex dx/R = %.10f, dy/R = %.10f\n", best.load,
              best.apex_dx, best.apex_dy);
  const double d = -best.apex_dy;
  EXPECT_TRUE(IsClose(archtest::deep_arch_at(d, 1024).load, best.load, 1e-12));
  EXPECT_LT(archtest::deep_arch_at(d - 0.05, 1024).load, best.load);
  EXPECT_LT(archtest::deep_arch_at(d + 0.05, 1024).load, best.load);
}

// Oracle: deep_arch_under inverts deep_arch_at on the rising branch (the load it is given
// comes back from the descent it returns, to Newton's tolerance 1e-12) and refuses a load past
// the limit.
TEST(ArchOracle, DeepArchUnderALoadInvertsTheDescent) {
  for (double P : {1.0, 5.0, 8.5}) {
    const auto p = archtest::deep_arch_under(P, 512);
    EXPECT_TRUE(IsClose(p.load, P, 1e-12));
    const auto q = archtest::deep_arch_at(-p.apex_dy, 512);
    EXPECT_TRUE(IsClose(q.load, P, 1e-12)) << "P = " << P;
    EXPECT_TRUE(IsClose(q.apex_dx, p.apex_dx, 1e-10)) << "P = " << P;
  }
  EXPECT_THROW(archtest::deep_arch_under(9.0, 512), std::invalid_argument);
}

// Oracle: Timoshenko & Gere sec. 7.5's exact cases. Pinned: the semicircle (alpha = pi/2)
// carries q R^3/EI = 3, the ring's value. Clamped: at alpha = pi/2, tan(alpha) is infinite and
// the equation reads cos(k pi/2) = 0, k = 3, q R^3/EI = 8; as alpha -> pi it tends to the ring
// clamped at one point (k = 2, 3); as alpha -> 0 both tend to the columns' antisymmetric
// buckling (N = q R on a length 2 alpha R): alpha^2 q R^3/EI -> pi^2 (pinned) and -> x^2 with
// x the first positive root of tan x = x (clamped-clamped, x = 4.4934), with a relative
// difference O(alpha^2) (the -1 of k^2 - 1). And the root satisfies the printed equation.
TEST(ArchOracle, FollowerPressureBucklingOfArches) {
  EXPECT_TRUE(IsClose(archtest::pinned_follower_pressure(M_PI / 2), 3.0, 1e-15));
  EXPECT_TRUE(IsClose(archtest::clamped_follower_pressure(M_PI / 2), 8.0, 1e-14));
  EXPECT_TRUE(IsClose(archtest::clamped_follower_pressure(M_PI - 1e-9), 3.0, 1e-8));
  const double x = bisect([](double t) { return std::sin(t) - t * std::cos(t); }, M_PI, 1.5 * M_PI);
  for (double a : {1e-2, 1e-3}) {
    EXPECT_TRUE(IsClose(a * a * archtest::pinned_follower_pressure(a), M_PI * M_PI, 2 * a * a));
    EXPECT_TRUE(IsClose(a * a * archtest::clamped_follower_pressure(a), x * x, 2 * a * a));
  }
  for (double a : {0.2, 0.7, 1.2, 2.0, 2.8}) {
    const double k = std::sqrt(1.0 + archtest::clamped_follower_pressure(a));
    EXPECT_NEAR(k * std::tan(a) / std::tan(k * a), 1.0, 1e-11) << "alpha = " << a;
  }
}

}  // namespace
