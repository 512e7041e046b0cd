#include "multibody/spin.hpp"

#include <cmath>
#include <vector>

namespace multibody::detail {

TranslationProducts translation_products(const Chain& chain, const Attachments* terms, const Vector& q) {
  const int n = chain.n(), dofs = chain.dofs();
  const double m = chain.m(), l = chain.l();
  // after[a] = the point masses at hinges >= a (hinge h moves with the angles j < h).
  std::vector<double> after(static_cast<std::size_t>(n) + 2, 0.0);
  if (terms)
    for (int h = n - 1; h >= 0; --h) after[h] = after[h + 1] + terms->hinge_mass(h);
  const Vector c = q.head(n).array().cos(), s = q.head(n).array().sin();
  TranslationProducts out{Matrix::Zero(dofs, dofs), Matrix::Zero(dofs, dofs)};
  // W_jk: a segment's centroid moves with the angles before it (weight 1) and its own (1/2):
  // sum over the segments m ((n - 1 - max(j, k)) + 1/2), or + 1/4 on the diagonal; the point
  // masses add those at hinges > max(j, k).
  for (int k = 0; k < n; ++k)
    for (int j = k; j < n; ++j) {
      const double W = m * (n - 1 - j + (j == k ? 0.25 : 0.5)) + after[j + 1];
      const double cjk = c[j] * c[k] + s[j] * s[k], sjk = s[j] * c[k] - c[j] * s[k];  // cos, sin (phi_j - phi_k)
      out.mass(j, k) = out.mass(k, j) = l * l * W * cjk;
      out.coriolis(j, k) = l * l * W * sjk;
      out.coriolis(k, j) = -out.coriolis(j, k);
    }
  if (chain.free()) {
    // The identity on (x_0, y_0) in every J_s: b_j = sum_s m_s w_sj, total = sum_s m_s.
    const int X = n, Y = n + 1;
    for (int j = 0; j < n; ++j) {
      const double b = m * (n - 1 - j + 0.5) + after[j + 1];
      out.mass(j, X) = out.mass(X, j) = -l * b * s[j];  // l b e'(phi_j)
      out.mass(j, Y) = out.mass(Y, j) = l * b * c[j];
      out.coriolis(j, X) = l * b * c[j];  // l b e'(phi_j)^T S = l b e(phi_j)^T
      out.coriolis(j, Y) = l * b * s[j];
      out.coriolis(X, j) = -out.coriolis(j, X);
      out.coriolis(Y, j) = -out.coriolis(j, Y);
    }
    const double total = n * m + after[0];
    out.mass(X, X) = out.mass(Y, Y) = total;
    out.coriolis(X, Y) = -total;  // S = [[0, -1], [1, 0]]
    out.coriolis(Y, X) = total;
  }
  return out;
}

}  // namespace multibody::detail
