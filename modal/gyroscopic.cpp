#include "modal/gyroscopic.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ring/errors.hpp"
#include "ring/sampling.hpp"

namespace modal {

namespace {

/// The relative residual ||(K - w^2 M + i w G) x|| / (||K x|| + w^2 ||M x|| + w ||G x||).
double relative_residual(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, const Eigen::MatrixXd& G,
                         const Eigen::VectorXcd& x, double w) {
  const std::complex<double> i(0.0, 1.0);
  const Eigen::VectorXcd kx = K * x, mx = M * x, gx = G * x;
  const double r = (kx - w * w * mx + i * w * gx).norm();
  const double scale = kx.norm() + w * w * mx.norm() + w * gx.norm();
  return scale > 0.0 ? r / scale : r;
}

/// Stores mode k (frequency w, shape x normalized here) and raises out.max_residual by its
/// residual (a NaN residual sticks).
void store(GyroscopicModes& out, int k, double w, Eigen::VectorXcd x, const Eigen::MatrixXd& K,
           const Eigen::MatrixXd& M, const Eigen::MatrixXd& G) {
  x /= x.norm();
  out.omega(k) = w;
  out.vectors.col(k) = x;
  const double rel = relative_residual(K, M, G, x, w);
  out.max_residual = std::isnan(rel) || rel > out.max_residual ? rel : out.max_residual;
}

/// K not positive definite: past a divergence speed the Coriolis coupling may still hold the ring
/// (gyroscopic stabilization; Thomson–Tait: possible only where K has an even number of negative
/// eigenvalues). The Hermitian form needs A = diag(K, M) definite, so the general eigenproblem of
/// the first-order form x'' = -M^-1 (K x + G x') decides: stable when every eigenvalue lambda lies
/// on the imaginary axis to kImaginaryAxis of the largest |lambda| (the general QR leaves
/// round-off off the axis; a true growth rate above that is reported), the frequencies then
/// omega = Im lambda > 0. A ring::NumericalError names the fastest growth rate otherwise.
GyroscopicModes gyroscopically_stable_modes(const std::string& solver, const Eigen::MatrixXd& K,
                                            const Eigen::MatrixXd& M, const Eigen::MatrixXd& G, int count) {
  constexpr double kImaginaryAxis = 1e-7;
  const Eigen::Index n = K.rows();
  const Eigen::LDLT<Eigen::MatrixXd> m(M);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  C.topRightCorner(n, n).setIdentity();
  C.bottomLeftCorner(n, n) = -m.solve(K);
  C.bottomRightCorner(n, n) = -m.solve(G);
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(C);
  if (eig.info() != Eigen::Success) throw ring::NumericalError(solver + ": the gyroscopic eigensolve did not converge");
  const Eigen::VectorXcd& lambda = eig.eigenvalues();
  const double largest = lambda.cwiseAbs().maxCoeff();
  Eigen::Index fastest = 0;
  for (Eigen::Index j = 1; j < lambda.size(); ++j)
    if (lambda(j).real() > lambda(fastest).real()) fastest = j;
  if (lambda(fastest).real() > kImaginaryAxis * largest)
    throw ring::NumericalError(
        solver + ": the spinning ring is unstable at this speed (a divergence): the centrifugal softening has overcome "
                 "a mode's stiffness and the Coriolis coupling does not hold it (growth rate " +
        std::to_string(lambda(fastest).real()) + " 1/s)");
  std::vector<std::pair<double, Eigen::Index>> positive;
  for (Eigen::Index j = 0; j < lambda.size(); ++j)
    if (lambda(j).imag() > kImaginaryAxis * largest) positive.emplace_back(lambda(j).imag(), j);
  std::sort(positive.begin(), positive.end());
  if (static_cast<Eigen::Index>(positive.size()) < count)
    throw ring::NumericalError(solver + ": the gyroscopic eigenproblem gave " + std::to_string(positive.size()) +
                               " positive frequencies, fewer than the " + std::to_string(count) + " asked for");
  GyroscopicModes out;
  out.omega.resize(count);
  out.vectors.resize(n, count);
  for (int k = 0; k < count; ++k) store(out, k, positive[k].first, eig.eigenvectors().col(positive[k].second).head(n), K, M, G);
  return out;
}

}  // namespace

GyroscopicModes gyroscopic_modes(const std::string& solver, const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                 const Eigen::MatrixXd& G, int count) {
  const Eigen::Index n = K.rows();
  if (K.cols() != n || M.rows() != n || M.cols() != n || G.rows() != n || G.cols() != n)
    throw std::invalid_argument("gyroscopic_modes: K, M and G must be square and of one size");
  if (count < 1 || count > n)
    throw std::invalid_argument("gyroscopic_modes: count " + std::to_string(count) + " is not in [1, " +
                                std::to_string(n) + "]");
  if (n > kMaxGyroscopicUnknowns)
    throw std::invalid_argument(solver + ": the spinning ring's modes are dense and take at most " +
                                std::to_string(kMaxGyroscopicUnknowns) + " unknowns, this model has " +
                                std::to_string(n) + ": lower the model's size");
  if (!K.allFinite() || !M.allFinite() || !G.allFinite())
    throw ring::NumericalError(solver + ": the spinning ring's matrices are not finite");
  const Eigen::LLT<Eigen::MatrixXd> lk(K), lm(M);
  if (lm.info() != Eigen::Success) throw ring::NumericalError(solver + ": the mass matrix is not positive definite");
  if (lk.info() != Eigen::Success) return gyroscopically_stable_modes(solver, K, M, G, count);
  const Eigen::MatrixXd Lk = lk.matrixL(), Lm = lm.matrixL();
  // S12 = Lk^T Lm^-T, S22 = -Lm^-1 G Lm^-T.
  const Eigen::MatrixXd s12 = lm.matrixL().solve(Lk).transpose();
  Eigen::MatrixXd s22 = lm.matrixL().solve(lm.matrixL().solve(G).transpose()).transpose();
  s22 = -0.5 * (s22 - s22.transpose());  // skew to round-off: keep it exactly skew
  Eigen::MatrixXcd H = Eigen::MatrixXcd::Zero(2 * n, 2 * n);
  const std::complex<double> i(0.0, 1.0);
  H.topRightCorner(n, n) = i * s12.cast<std::complex<double>>();
  H.bottomLeftCorner(n, n) = -i * s12.transpose().cast<std::complex<double>>();
  H.bottomRightCorner(n, n) = i * s22.cast<std::complex<double>>();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> eig(H);
  if (eig.info() != Eigen::Success) throw ring::NumericalError(solver + ": the gyroscopic eigensolve did not converge");
  // Eigenvalues ascend: -omega for the positive frequencies come first, the largest omega
  // first; the lowest omega are the negative eigenvalues closest to zero.
  const Eigen::VectorXd& mu = eig.eigenvalues();
  Eigen::Index neg = 0;
  while (neg < 2 * n && mu(neg) < 0.0) ++neg;
  if (neg < count)
    throw ring::NumericalError(solver + ": the gyroscopic eigenproblem gave " + std::to_string(neg) +
                               " positive frequencies, fewer than the " + std::to_string(count) + " asked for");
  GyroscopicModes out;
  out.omega.resize(count);
  out.vectors.resize(n, count);
  for (int k = 0; k < count; ++k) {
    const Eigen::Index j = neg - 1 - k;
    const double w = -mu(j);
    const Eigen::VectorXcd top = eig.eigenvectors().col(j).head(n);
    Eigen::VectorXcd x(n);  // Lk^T x = top, real triangle, complex right-hand side
    x.real() = Lk.transpose().triangularView<Eigen::Upper>().solve(Eigen::VectorXd(top.real()));
    x.imag() = Lk.transpose().triangularView<Eigen::Upper>().solve(Eigen::VectorXd(top.imag()));
    store(out, k, w, x, K, M, G);
  }
  return out;
}

ring::Wave classify_wave(const Eigen::VectorXcd& radial, const Eigen::VectorXcd& tangential, double speed) {
  const int m = static_cast<int>(radial.size());
  const double pi = std::acos(-1.0);
  int best = 0;
  double best_power = -1.0, plus = 0.0, minus = 0.0;  // |c_k|^2 and |c_-k|^2 of both parts
  for (int k = 0; k <= m / 2; ++k) {
    double p_plus = 0.0, p_minus = 0.0;
    for (const Eigen::VectorXcd* part : {&radial, &tangential}) {
      std::complex<double> cp = 0.0, cm = 0.0;  // c_k and c_-k
      for (int s = 0; s < m; ++s) {
        const double a = 2.0 * pi * k * s / m;
        const std::complex<double> e(std::cos(a), -std::sin(a));
        cp += (*part)(s) * e;
        cm += (*part)(s) * std::conj(e);
      }
      p_plus += std::norm(cp), p_minus += std::norm(cm);
    }
    if (p_plus + p_minus > best_power * (1.0 + 1e-12)) best = k, best_power = p_plus + p_minus, plus = p_plus, minus = p_minus;
  }
  ring::Wave w;
  w.number = best;
  // Towards +theta (c_-k the larger) is with a positive spin; powers agree to 2e-6 for amplitudes to 1e-6.
  if (best == 0 || std::abs(minus - plus) <= 2e-6 * std::max(minus, plus)) return w;
  const int towards_plus = minus > plus ? 1 : -1;
  w.direction = speed >= 0.0 ? towards_plus : -towards_plus;
  return w;
}

std::pair<ring::ModeShape, ring::Wave> travelling_mode(const Eigen::VectorXcd& x_in,
                                                       const std::function<ring::ModeShape(const Eigen::VectorXd&)>& sample,
                                                       double speed) {
  Eigen::Index big = 0;
  x_in.cwiseAbs().maxCoeff(&big);
  const std::complex<double> phase = std::abs(x_in(big)) > 0.0 ? std::conj(x_in(big)) / std::abs(x_in(big)) : 1.0;
  const Eigen::VectorXcd x = x_in * phase;
  const Eigen::VectorXd a = x.real(), b = x.imag();
  ring::ModeShape shape = sample(a);
  ring::normalize(shape);
  const int m = static_cast<int>(shape.radial.size());
  Eigen::VectorXcd radial(m), tangential(m);
  auto as_vector = [](const std::vector<double>& v) { return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()); };
  if (b.norm() <= 1e-12 * a.norm()) {
    radial = as_vector(shape.radial).cast<std::complex<double>>();
    tangential = as_vector(shape.tangential).cast<std::complex<double>>();
  } else {
    // sample() = (linear sample) / unknown scale: ra = A / alpha, rb = B / beta, rc = (A + B) / gamma,
    // so rc = (alpha / gamma) ra + (beta / gamma) rb, least squares over every component.
    const ring::ModeShape sa = sample(a), sb = sample(b), sc = sample(a + b);
    Eigen::MatrixXd P(2 * m, 2);
    Eigen::VectorXd q(2 * m);
    P.col(0) << as_vector(sa.radial), as_vector(sa.tangential);
    P.col(1) << as_vector(sb.radial), as_vector(sb.tangential);
    q << as_vector(sc.radial), as_vector(sc.tangential);
    const Eigen::Vector2d ab = P.colPivHouseholderQr().solve(q);
    radial = (ab(0) * as_vector(sa.radial)).cast<std::complex<double>>() +
             std::complex<double>(0.0, 1.0) * (ab(1) * as_vector(sb.radial)).cast<std::complex<double>>();
    tangential = (ab(0) * as_vector(sa.tangential)).cast<std::complex<double>>() +
                 std::complex<double>(0.0, 1.0) * (ab(1) * as_vector(sb.tangential)).cast<std::complex<double>>();
  }
  return {shape, classify_wave(radial, tangential, speed)};
}

}  // namespace modal
