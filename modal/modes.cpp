#include "modal/modes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "ring/errors.hpp"

namespace modal {

double bending_scale(const ring::RingSpec& spec) {
  const double R = spec.radius;
  return spec.EI() / (spec.rhoA() * R * R * R * R);
}

bool is_rigid(double omega2, double scale) { return omega2 < kRigidThreshold * scale; }

Selection select_modes(const std::string& solver, const Eigen::VectorXd& omega2, double scale, int count) {
  if (count < 1 || !(scale > 0.0))
    throw std::invalid_argument("modal: count (= " + std::to_string(count) + ") must be >= 1 and scale (= " +
                                std::to_string(scale) + ") > 0");
  if (!omega2.allFinite()) throw ring::NumericalError(solver + ": non-finite eigenvalue");
  std::vector<int> order(static_cast<std::size_t>(omega2.size()));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return omega2[a] < omega2[b]; });
  Selection s;
  for (int i : order) {
    if (is_rigid(omega2[i], scale)) {
      s.rigid.push_back(i);
      s.rigid_omega2.push_back(omega2[i]);
    } else if (static_cast<int>(s.elastic.size()) < count) {
      s.elastic.push_back(i);
    }
  }
  if (static_cast<int>(s.elastic.size()) < count)
    throw ring::NumericalError(solver + ": found only " + std::to_string(s.elastic.size()) + " of " +
                               std::to_string(count) + " elastic modes");
  return s;
}

double relative_residual(double r_norm, double ax_norm, double bx_norm, double lambda) {
  return r_norm / (ax_norm + std::abs(lambda) * bx_norm);
}

PairResidual pair_residual(double r_norm, double ax_norm, double bx_norm, double lambda, double x_norm,
                           double norm_a, double norm_b) {
  return {relative_residual(r_norm, ax_norm, bx_norm, lambda),
          r_norm / ((norm_a + std::abs(lambda) * norm_b) * x_norm)};
}

PairResidual pair_residual(const Eigen::Ref<const Eigen::VectorXd>& ax,
                           const Eigen::Ref<const Eigen::VectorXd>& bx, double lambda, double x_norm,
                           double norm_a, double norm_b) {
  return pair_residual((ax - lambda * bx).norm(), ax.norm(), bx.norm(), lambda, x_norm, norm_a, norm_b);
}

double norm_estimate(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& op, Eigen::Index dim,
                     int iterations) {
  Eigen::VectorXd v(dim);
  for (Eigen::Index i = 0; i < dim; ++i)
    v[i] = (i % 2 ? 1.0 : -1.0) * (1.0 + 0.25 * std::sin(1.0 + static_cast<double>(i)));
  double lam = 0.0;
  for (int it = 0; it < iterations; ++it) {
    v /= v.norm();
    Eigen::VectorXd y = op(v);
    lam = v.dot(y);
    v = std::move(y);
  }
  return lam;
}

void assemble(ring::ModalResult& result, const std::string& solver, const Eigen::VectorXd& omega2,
              const Selection& selection, const std::vector<double>& relative) {
  result.solver = solver;
  result.rigid_modes = static_cast<int>(selection.rigid.size());
  result.omega.clear();
  for (int i : selection.elastic) result.omega.push_back(std::sqrt(omega2[i]));
  double largest = 0.0;
  for (double r : relative) largest = worst(largest, r);
  result.max_residual = largest;
}

void require_eigenpairs(const ring::ModalResult& result) {
  // NaN fails (it is no answer), and so does a result that reports no residual.
  if (result.max_residual && *result.max_residual <= kAcceptedResidual) return;
  std::ostringstream m;
  m << result.solver << ": the computed pairs are not eigenpairs (largest relative residual ";
  if (result.max_residual) m << *result.max_residual;
  else m << "not computed";
  m << ", accepted " << kAcceptedResidual << ")";
  throw ring::NumericalError(m.str());
}

}  // namespace modal
