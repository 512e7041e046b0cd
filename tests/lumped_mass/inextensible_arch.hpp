// The exact natural frequencies and mode shapes of the inextensible circular arch (the
// chain's continuum limit: rigid links, Euler-Bernoulli hinges, no rotary inertia), written
// for tests/lumped_mass/arch_test.cpp independently of lumped_mass/.
//
// Theory (Euler-Bernoulli, thin, inextensible; u tangential counter-clockwise, w radial
// outward, theta in [0, alpha] along the arch, R the radius): the strain (u' + w) / R = 0
// gives w = -u', the change of curvature (w'' + w) / R^2 = -(u''' + u') / R^2 and the rotation
// of the tangent (u - w') / R = (u + u'') / R. With U = EI / (2 R^3) int (u''' + u')^2 and
// T = rho A R / 2 int (u_t^2 + u_t'^2), a mode u(theta) e^{i omega t} satisfies
//   -(u^(6) + 2 u^(4) + u'') = lambda (u - u''),   lambda = omega^2 rho A R^4 / EI,
// whose solutions are e^{s theta} with p = s^2 a root of p^3 + 2 p^2 + (1 - lambda) p + lambda = 0
// (on a closed ring u = sin k theta gives lambda = k^2 (k^2 - 1)^2 / (k^2 + 1), the ring's
// inextensible frequencies: a check of the operator). The end conditions, from the boundary
// terms of the variation of U - omega^2 T:
//   pinned: u = 0, w = 0 (u' = 0), moment 0 (u''' + u' = 0, so u''' = 0);
//   clamped: u = 0, u' = 0, the rotation 0 (u + u'' = 0, so u'' = 0);
//   free: moment 0 (u''' + u' = 0), shear 0 (u'''' + u'' = 0), and the tangential force 0
//         (u^(5) + 2 u''' + (1 - lambda) u' = 0).
// The frequencies are the lambda where the 6 x 6 matrix of the end conditions on the six
// exponentials is singular. They are located as the minima of its smallest singular value
// (relative to the largest, the columns normalized; the exponentials shifted to be at most 1
// on the arch) on a grid of omega, refined by golden-section search to 1e-14 relative. A
// minimum is a frequency when that ratio is below 1e-11 and the cubic's roots are apart
// (where two coincide, two columns are equal whatever the ends: ratio 3e-9 at such points,
// against 1e-16 at the frequencies, measured).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <vector>

namespace inextensible {

enum class End { pinned, clamped, free };

struct Arch {
  double alpha = M_PI;  ///< opening angle, rad
  End a = End::pinned, b = End::pinned;  ///< the ends at theta = 0 and theta = alpha
};

namespace detail {

using C = std::complex<double>;
using Matrix6 = Eigen::Matrix<C, 6, 6>;

/// The six exponents s (s^2 the cubic's roots) at lambda, and the least distance between roots.
inline std::vector<C> exponents(double lambda, double* separation = nullptr) {
  Eigen::Matrix3d companion = Eigen::Matrix3d::Zero();
  companion(0, 0) = -2.0;
  companion(0, 1) = -(1.0 - lambda);
  companion(0, 2) = -lambda;
  companion(1, 0) = 1.0;
  companion(2, 1) = 1.0;
  const Eigen::Vector3cd p = Eigen::EigenSolver<Eigen::Matrix3d>(companion).eigenvalues();
  if (separation)
    *separation = std::min({std::abs(p[0] - p[1]), std::abs(p[1] - p[2]), std::abs(p[0] - p[2])}) /
                  std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  std::vector<C> s;
  for (int i = 0; i < 3; ++i) {
    const C r = std::sqrt(p[i]);
    s.push_back(r);
    s.push_back(-r);
  }
  return s;
}

/// The end condition rows: coefficients of s^0..s^5 for each of the three conditions.
inline std::array<std::array<double, 6>, 3> conditions(End e, double lambda) {
  switch (e) {
    case End::pinned: return {{{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 0, 1, 0, 0}}};
    case End::clamped: return {{{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0}}};
    case End::free: return {{{0, 1, 0, 1, 0, 0}, {0, 0, 1, 0, 1, 0}, {0, 1.0 - lambda, 0, 2, 0, 1}}};
  }
  return {};
}

/// The shift of exponential j: e^{s (theta - shift)} is at most 1 on [0, alpha].
inline double shift(const C& s, double alpha) { return s.real() > 0.0 ? alpha : 0.0; }

/// The end conditions on the six shifted exponentials (columns), rows: three at each end.
inline Matrix6 raw_matrix(const Arch& arch, double lambda) {
  const std::vector<C> s = exponents(lambda);
  Matrix6 M;
  for (int j = 0; j < 6; ++j)
    for (int end = 0; end < 2; ++end) {
      const double th = end == 0 ? 0.0 : arch.alpha;
      const C f = std::exp(s[j] * (th - shift(s[j], arch.alpha)));
      const auto rows = conditions(end == 0 ? arch.a : arch.b, lambda);
      for (int r = 0; r < 3; ++r) {
        C v = 0.0;
        for (int k = 0; k < 6; ++k) v += rows[r][k] * std::pow(s[j], k);
        M(3 * end + r, j) = v * f;
      }
    }
  return M;
}

/// raw_matrix with its columns normalized.
inline Matrix6 end_matrix(const Arch& arch, double lambda) {
  Matrix6 M = raw_matrix(arch, lambda);
  for (int j = 0; j < 6; ++j) M.col(j) /= M.col(j).norm();
  return M;
}

inline double singularity(const Arch& arch, double omega) {
  Eigen::JacobiSVD<Matrix6> svd(end_matrix(arch, omega * omega));
  return svd.singularValues()[5] / svd.singularValues()[0];
}

}  // namespace detail

/// The lowest `count` frequencies omega / sqrt(EI / (rho A R^4)), ascending (zero excluded).
inline std::vector<double> frequencies(const Arch& arch, int count) {
  std::vector<double> out;
  const double h = 0.005;
  double f2 = INFINITY, f1 = INFINITY;
  for (double w = h; static_cast<int>(out.size()) < count && w < 200.0; w += h) {
    const double f = detail::singularity(arch, w);
    if (w > 3.0 * h && f1 < f2 && f1 < f) {
      const double g = (std::sqrt(5.0) - 1.0) / 2.0;
      double a = w - 2.0 * h, b = w, c = b - g * (b - a), d = a + g * (b - a);
      double fc = detail::singularity(arch, c), fd = detail::singularity(arch, d);
      for (int it = 0; it < 200 && b - a > 1e-14 * b; ++it) {
        if (fc < fd) {
          b = d, d = c, fd = fc, c = b - g * (b - a), fc = detail::singularity(arch, c);
        } else {
          a = c, c = d, fc = fd, d = a + g * (b - a), fd = detail::singularity(arch, d);
        }
      }
      const double m = 0.5 * (a + b);
      double separation = 0.0;
      detail::exponents(m * m, &separation);
      if (detail::singularity(arch, m) < 1e-11 && separation > 1e-6) out.push_back(m);
    }
    f2 = f1;
    f1 = f;
  }
  return out;
}

/// The mode at frequency omega (scaled as frequencies()): (u, w) at the arch angles theta
/// (rad, from the end a), up to a factor.
inline void shape(const Arch& arch, double omega, const std::vector<double>& theta, std::vector<double>& u,
                  std::vector<double>& w) {
  using detail::C;
  const double lambda = omega * omega;
  const detail::Matrix6 raw = detail::raw_matrix(arch, lambda);
  Eigen::Matrix<double, 6, 1> norms;
  for (int j = 0; j < 6; ++j) norms[j] = raw.col(j).norm();
  detail::Matrix6 M = raw;
  for (int j = 0; j < 6; ++j) M.col(j) /= norms[j];
  Eigen::JacobiSVD<detail::Matrix6> svd(M, Eigen::ComputeFullV);
  const Eigen::Matrix<C, 6, 1> c = svd.matrixV().col(5);  // the null vector of the normalized columns
  const std::vector<C> s = detail::exponents(lambda);
  std::vector<C> uc(theta.size(), 0.0), wc(theta.size(), 0.0);
  u.assign(theta.size(), 0.0);
  w.assign(theta.size(), 0.0);
  for (std::size_t i = 0; i < theta.size(); ++i)
    for (int j = 0; j < 6; ++j) {
      const C e = c[j] / norms[j] * std::exp(s[j] * (theta[i] - detail::shift(s[j], arch.alpha)));
      uc[i] += e;
      wc[i] -= s[j] * e;  // w = -u'
    }
  // The mode is real up to a complex factor: take the phase of its largest value off.
  std::size_t big = 0;
  for (std::size_t i = 0; i < theta.size(); ++i)
    if (std::abs(uc[i]) > std::abs(uc[big])) big = i;
  const C phase = std::abs(uc[big]) > 0.0 ? std::conj(uc[big]) / std::abs(uc[big]) : C(1.0);
  for (std::size_t i = 0; i < theta.size(); ++i) {
    u[i] = (uc[i] * phase).real();
    w[i] = (wc[i] * phase).real();
  }
}

}  // namespace inextensible
