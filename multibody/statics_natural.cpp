// Nonlinear statics on the O(n) path: the chain in hinge positions (natural.hpp), load
// stepping with full Newton on the equilibrium ∇V(x) + G(x)^T lambda = s F, c(x) = 0.

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "multibody/natural.hpp"
#include "ring/errors.hpp"

namespace multibody::natural {
namespace {

constexpr int kMaxNewton = 25;
/// Smallest load increment tried, relative to one load step.
constexpr double kSmallestIncrement = 1e-6;

/// Newton at load factor s from (x, lambda); both updated. Iterations, or -1 on failure.
int newton(const Natural& c, double s, Vec& x, Vec& lambda, BandedKkt& kkt) {
  const int N = 2 * c.n, S = c.size();
  const double kappa = c.K / (c.l * c.l);  // the springs' stiffness scale: balances the KKT matrix
  NewtonStop stop(c.radius());
  for (int it = 1; it <= kMaxNewton; ++it) {
    kkt.clear();
    Vec rx = Vec::Zero(N);
    rx.segment<2>(2 * c.load) -= s * c.F;
    for (int k = 0; k < c.n; ++k) {
      const Turn tk = turn(local(c, x, k));
      const double d = tk.theta - c.theta0;
      const Vec6 g = c.K * d * tk.d;
      const Mat6 H = c.K * (tk.d * tk.d.transpose() + d * tk.dd);
      add_spring(c, k, g, H, rx, kkt);
    }
    add_constraint_curvature(c, lambda, 1.0, kkt);
    add_constraint_jacobian(c, x, N, true, kappa, kkt, &lambda, &rx);
    add_constraint_jacobian(c, x, N, false, kappa, kkt, nullptr, nullptr);
    Vec rhs(S);
    rhs << -rx, -kappa * constraints(c, x);
    if (!kkt.factor()) return -1;
    const Vec dz = kkt.solve(rhs);
    if (!dz.allFinite()) return -1;
    const double step = dz.head(N).cwiseAbs().maxCoeff();
    if (turns_a_link_by(c, dz.head(N)) > detail::kBasin) return -1;  // left the basin
    x += dz.head(N);
    lambda += kappa * dz.tail(c.rows());
    if (stop.converged(step, constraints(c, x).cwiseAbs().maxCoeff())) return it;
  }
  return -1;
}

}  // namespace

ring::StaticResult solve_static(const Chain& chain, const ring::RingSpec& spec, const ring::StaticOptions& st) {
  const Natural c = make_natural(chain, st.load.angle, Eigen::Vector2d(st.load.force[0], st.load.force[1]));
  const int gap = detail::contact_gap(chain, spec.section.depth());
  const double depth = spec.section.depth();
  Vec x = rest(chain), lambda = Vec::Zero(c.rows());
  BandedKkt kkt(c);
  ring::StaticResult res;
  res.solver = "multibody";
  res.unknowns = c.size();
  const double ds0 = 1.0 / st.steps;
  double s = 0.0, ds = ds0;
  while (s < 1.0 - 1e-14) {
    const double s1 = std::min(1.0, s + ds);
    Vec x1 = x, l1 = lambda;
    const int it = newton(c, s1, x1, l1, kkt);
    if (it < 0) {
      ds *= 0.5;
      if (ds < kSmallestIncrement * ds0) {
        std::ostringstream m;
        m << "multibody::solve_static (O(n) path): no equilibrium beyond load factor " << s
          << " (a limit point: this path has no arc-length continuation; multibody.method = \"dense\" has)";
        throw ring::NumericalError(m.str());
      }
      continue;
    }
    res.newton_iterations += it;
    x = std::move(x1);
    lambda = std::move(l1);
    s = s1;
    ++res.steps;
    ds = std::min(ds0, 2.0 * ds);
    Eigen::Matrix2Xd hp(2, c.n);
    for (int j = 0; j < c.n; ++j) hp.col(j) = hinge(x, j);
    const auto cp = detail::closest_nonadjacent_grid(hp, c.l, gap, depth);
    if (cp.distance < depth) {
      std::ostringstream m;
      m << "multibody::solve_static: the ring touches itself at load factor " << s << ": "
        << detail::describe_contact(cp) << " (section depth " << depth << " m); the chain model does not include contact";
      throw ring::NumericalError(m.str());
    }
  }
  for (double a : st.record) {
    const int k = chain.hinge_at(a);
    const Eigen::Vector2d u = hinge(x, k) - chain.hinge_rest(k);
    res.displacements.push_back({a, u.x(), u.y()});
  }
  for (int j = 0; j < c.n; ++j) {
    res.node_x.push_back(x(2 * j));
    res.node_y.push_back(x(2 * j + 1));
  }
  return res;
}

}  // namespace multibody::natural
