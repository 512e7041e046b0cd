#include "multibody/buckling.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <chrono>
#include <stdexcept>

#include "modal/buckling.hpp"
#include "multibody/checks.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"

namespace multibody {

void check_buckling(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                    const ring::BucklingOptions& buckling) {
  check_arch_buckling(spec, options, buckling.loads);  // an arch: the statics' loads (checks.hpp)
  ring::refuse_rotation(spec, "multibody linear buckling");
  ring::refuse_variations(spec, "multibody linear buckling");
  if (spec.plastic)
    throw ring::InputError("", "ring.plastic",
                           "multibody linear buckling is about the undeformed, elastic ring and would ignore the "
                           "plastic law: follow the nonlinear statics ([static]) instead, or remove ring.plastic");
  if (options.method == ring::MultibodyOptions::Method::sparse)
    throw std::invalid_argument("multibody.method = \"sparse\": linear buckling is computed on the dense path (segment "
                                "angles) only; use \"dense\" or \"auto\"");
  if (const int rigid = ring::static_rigid_modes(spec, buckling.loads); rigid > 0)
    throw std::invalid_argument("multibody buckling: the ring has " + std::to_string(rigid) +
                                " rigid modes the loads do not restrain; add a support (supports.roller, a pin, "
                                "springs or a foundation)");
}

ring::BucklingResult compute_buckling(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                      const ring::BucklingOptions& buckling) {
  check_buckling(spec, options, buckling);
  const auto start = std::chrono::steady_clock::now();
  const ring::Loads& loads = buckling.loads;
  const std::optional<double> loaded =
      loads.points.empty() ? std::nullopt : std::optional<double>(loads.points.front().angle);
  const Chain chain(spec, options, loaded);
  const detail::DenseTangent tangent(chain, spec, loads, "buckling");
  const Eigen::Index n = tangent.dofs(), c = tangent.rows();
  const Vector q0 = chain.q0();
  const Chain::ConstraintKinematics ck = tangent.constraints(q0);
  Matrix T0 = Matrix::Zero(n, n);
  tangent.add_tangent(q0, Vector::Zero(c), 0.0, ck, T0);

  // The linear prebuckling state; the constraint rows scaled by K / l as in the statics.
  const double sc = chain.K() / chain.l();
  Matrix A = Matrix::Zero(n + c, n + c);
  A.topLeftCorner(n, n) = T0;
  A.topRightCorner(n, c) = sc * ck.G.transpose();
  A.bottomLeftCorner(c, n) = sc * ck.G;
  Vector rhs = Vector::Zero(n + c);
  rhs.head(n) = tangent.loads().forces(q0);
  const Vector rate = Eigen::FullPivLU<Matrix>(A).solve(rhs);
  if (!rate.allFinite()) throw std::runtime_error("multibody buckling: the linear prebuckling state is not finite");
  const Vector dq = rate.head(n), dlambda = sc * rate.tail(c);

  Matrix K1 = Matrix::Zero(n, n);
  tangent.loads().add_stiffness(q0, 1.0, K1);
  K1.diagonal() += ck.hess.transpose() * dlambda;
  if (const double most = dq.cwiseAbs().maxCoeff(); most > 0.0 && !spec.paper_terms_only()) {
    const double h = 1e-6 / most;
    Matrix plus = Matrix::Zero(n, n), minus = Matrix::Zero(n, n);
    tangent.add_terms(q0 + h * dq, plus);
    tangent.add_terms(q0 - h * dq, minus);
    K1 += (plus - minus) / (2.0 * h);
  }

  // An orthonormal basis of ker G: the trailing columns of Q in G^T = Q R.
  const Eigen::ColPivHouseholderQR<Matrix> qr(ck.G.transpose());
  const Eigen::Index rank = qr.rank();
  const Matrix Z = Matrix(qr.householderQ()).rightCols(n - rank);
  const modal::CriticalFactors cf =
      modal::critical_factors(Z.transpose() * T0 * Z, Z.transpose() * K1 * Z, buckling.count, "multibody");

  ring::BucklingResult res;
  res.solver = "multibody";
  res.model["n"] = static_cast<long long>(chain.n());
  res.model["method"] = std::string("dense");
  res.unknowns = n - rank;
  res.factors.assign(cf.factors.data(), cf.factors.data() + cf.factors.size());
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (Eigen::Index i = 0; i < cf.vectors.cols(); ++i) res.shapes.push_back(chain.rest_shape(Z * cf.vectors.col(i)));
  return res;
}

}  // namespace multibody
