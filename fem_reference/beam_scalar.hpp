// Internal to fem_reference/: a scalar of four local variables with its gradient and
// Hessian, and the exact rotation measures of the geometrically exact beam (nonlinear.hpp),
// shared by the beam's energy (ring_beam.cpp) and its terms (beam_potential.cpp: the
// rotational springs). No deal.II here.
#pragma once

#include <array>
#include <cmath>

namespace fem::detail {

using Vec4 = std::array<double, 4>;
using Mat4 = std::array<std::array<double, 4>, 4>;

/// A scalar of g = (a_t, a_n, b_t, b_n) with its gradient and Hessian; a = dx/ds0 in the
/// rest frame (t0, n0) and b = da/dtheta.
struct Scalar {
  double value = 0.0;
  Vec4 d{};
  Mat4 dd{};
};

/// The rotation rate dphi/dtheta = (a_n b_t - a_t b_n) / |a|^2 of the tangent angle
/// phi = atan2(-a_n, a_t) (counter-clockwise from t0), exact for any rotation.
inline Scalar rotation_rate(const Vec4& g) {
  const double a[2] = {g[0], g[1]};
  const double mu = 1.0 / (a[0] * a[0] + a[1] * a[1]);
  const double c = g[1] * g[2] - g[0] * g[3];
  const double dmu[2] = {-2.0 * mu * mu * a[0], -2.0 * mu * mu * a[1]};
  const double dca[2] = {-g[3], g[2]};  // dc/da
  const double dcb[2] = {g[1], -g[0]};  // dc/db
  const double D[2][2] = {{0.0, -1.0}, {1.0, 0.0}};  // d2c/da db
  Scalar k;
  k.value = c * mu;
  k.d = {dca[0] * mu + c * dmu[0], dca[1] * mu + c * dmu[1], dcb[0] * mu, dcb[1] * mu};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double ddmu = -2.0 * mu * mu * (i == j) + 8.0 * mu * mu * mu * a[i] * a[j];
      k.dd[i][j] = c * ddmu + dca[i] * dmu[j] + dmu[i] * dca[j];
      k.dd[i][2 + j] = k.dd[2 + j][i] = mu * D[i][j] + dmu[i] * dcb[j];
    }
  return k;
}

/// The tangent angle phi(a) = atan2(-a_n, a_t) relative to t0: gradient and Hessian in a
/// (the value itself only enters through differences, see the vertex terms).
inline Scalar tangent_angle(const Vec4& g) {
  const double at = g[0], an = g[1], mu = 1.0 / (at * at + an * an);
  Scalar p;
  p.value = std::atan2(-an, at);
  p.d = {an * mu, -at * mu, 0.0, 0.0};
  p.dd[0][0] = -2.0 * mu * mu * at * an;
  p.dd[0][1] = p.dd[1][0] = mu - 2.0 * mu * mu * an * an;
  p.dd[1][1] = 2.0 * mu * mu * at * an;
  return p;
}

}  // namespace fem::detail
