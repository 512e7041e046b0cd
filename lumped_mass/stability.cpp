#include "lumped_mass/stability.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "modal/buckling.hpp"
#include "modal/inertia.hpp"

namespace lumped {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

/// The constraint Jacobian G (links, then supports; rows x 2n), dense.
Eigen::MatrixXd dense_jacobian(const Chain& c, const Eigen::VectorXd& x) {
  Triplets g;
  jacobian(c, x, 0, 1.0, false, g);
  Sparse G(c.rows(), 2 * c.n);
  G.setFromTriplets(g.begin(), g.end());
  return Eigen::MatrixXd(G);
}

/// The tangent T (2n x 2n), dense.
Eigen::MatrixXd dense_tangent(const Triplets& hess, int n) {
  Sparse T(2 * n, 2 * n);
  T.setFromTriplets(hess.begin(), hess.end());
  return Eigen::MatrixXd(T);
}

bool takes_dense_route(const Chain& c, InertiaRoute route) {
  return route == InertiaRoute::dense || (route == InertiaRoute::automatic && 2 * c.n <= kDenseInertiaUnknowns);
}

std::optional<int> frontal_count(const Chain& c, const Triplets& tangent_hess, const Eigen::VectorXd& x, double scale) {
  const int n = c.n, N = 2 * n, R = c.rows();
  Triplets t = tangent_hess;
  jacobian(c, x, N, scale, true, t);
  jacobian(c, x, N, scale, false, t);
  Sparse K(N + R, N + R);
  K.setFromTriplets(t.begin(), t.end());
  // Hinge j with its link j (to hinge j + 1); the last two hinges close the ring onto the
  // first ones (the corners of the band), so they wait in the border with the supports.
  std::vector<std::vector<int>> groups;
  std::vector<int> border;
  // An arch (c.open) has no closing link: every node with its link (the last node alone) in
  // order, and only the supports, which join its two ends, in the border.
  const int links = c.links();
  for (int j = 0; j < n; ++j) {
    std::vector<int> g{2 * j, 2 * j + 1};
    if (j < links) g.push_back(N + j);
    if (c.open || j < n - 2) groups.push_back(g);
    else border.insert(border.end(), g.begin(), g.end());
  }
  for (int r = links; r < R; ++r) border.push_back(N + r);
  const std::optional<modal::Inertia> in = modal::frontal_inertia(K, groups, border);
  if (!in || in->zero != 0 || in->negative < R || in->positive < R) return std::nullopt;
  return static_cast<int>(in->negative - R);
}

}  // namespace

std::optional<int> unstable_directions(const Chain& c, const ChainLoads& loads, const Eigen::VectorXd& x,
                                       const Eigen::VectorXd& lambda, double s, double scale, InertiaRoute route) {
  if (route == InertiaRoute::automatic && c.n > kMaxInertiaHinges) return std::nullopt;
  const Springs sp = tangent(c, loads, x, lambda, s, 1.0);
  if (!takes_dense_route(c, route)) return frontal_count(c, sp.hess, x, scale);
  return modal::unstable_directions(dense_tangent(sp.hess, c.n), dense_jacobian(c, x));
}

std::optional<Eigen::VectorXd> least_stable_direction(const Chain& c, const ChainLoads& loads,
                                                      const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                                                      double s, InertiaRoute route) {
  if (!takes_dense_route(c, route)) return std::nullopt;
  const Springs sp = tangent(c, loads, x, lambda, s, 1.0);
  return modal::least_stable(dense_tangent(sp.hess, c.n), dense_jacobian(c, x)).direction;
}

}  // namespace lumped
