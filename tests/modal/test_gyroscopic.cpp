// modal/gyroscopic.hpp against closed forms: the spinning ring's wave pair reduced to its two
// coordinates (m z'' + 2 i g z' + k z = 0 for z = a + i b: omega = (sqrt(g^2 + m k) -+ g) / m),
// several such pairs hidden by an orthogonal change of coordinates, and synthetic travelling
// waves for the classification.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>
#include <complex>
#include <string>

#include "modal/gyroscopic.hpp"
#include "ring/errors.hpp"
#include "ring/results.hpp"

namespace {

// One wave pair: m a'' - 2 g b' + k a = 0, m b'' + 2 g a' + k b = 0.
struct Pair {
  double m, g, k;
  double lower() const { return (std::sqrt(g * g + m * k) - g) / m; }
  double upper() const { return (std::sqrt(g * g + m * k) + g) / m; }
};

void add(Eigen::MatrixXd& K, Eigen::MatrixXd& M, Eigen::MatrixXd& G, int at, const Pair& p) {
  M(at, at) = M(at + 1, at + 1) = p.m;
  K(at, at) = K(at + 1, at + 1) = p.k;
  G(at, at + 1) = -2.0 * p.g;
  G(at + 1, at) = 2.0 * p.g;
}

TEST(GyroscopicModes, OneWavePairSplitsByTwiceTheCoriolisCoefficientOverTheMass) {
  const Pair p{3.0, 0.7, 50.0};
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2, 2), M = K, G = K;
  add(K, M, G, 0, p);
  const modal::GyroscopicModes r = modal::gyroscopic_modes("test", K, M, G, 2);
  // Round-off of a 4 x 4 Hermitian eigensolve: ~1e-15 relative.
  EXPECT_NEAR(r.omega(0), p.lower(), 1e-13 * p.upper());
  EXPECT_NEAR(r.omega(1), p.upper(), 1e-13 * p.upper());
  EXPECT_LT(r.max_residual, 1e-14);
  // The lower mode is z = a + i b = e^{i omega t}: b lags a by a quarter period, x = (1, -i)/sqrt 2 up to phase.
  const std::complex<double> ratio = r.vectors(1, 0) / r.vectors(0, 0);
  EXPECT_NEAR(ratio.real(), 0.0, 1e-12);
  EXPECT_NEAR(ratio.imag(), -1.0, 1e-12);
}

TEST(GyroscopicModes, PairsSurviveAnOrthogonalChangeOfCoordinates) {
  const Pair pairs[] = {{1.0, 0.3, 4.0}, {2.0, 0.1, 90.0}, {0.5, 1.5, 7.0}};
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6), M = K, G = K;
  for (int j = 0; j < 3; ++j) add(K, M, G, 2 * j, pairs[j]);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(6, 6)).householderQ();
  const modal::GyroscopicModes r =
      modal::gyroscopic_modes("test", Q.transpose() * K * Q, Q.transpose() * M * Q, Q.transpose() * G * Q, 6);
  std::vector<double> expected;
  for (const Pair& p : pairs) expected.push_back(p.lower()), expected.push_back(p.upper());
  std::sort(expected.begin(), expected.end());
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(r.omega(j), expected[j], 1e-12 * expected.back()) << j;
  EXPECT_LT(r.max_residual, 1e-13);
}

TEST(GyroscopicModes, AtRestGivesTheSymmetricPencilsFrequencies) {
  Eigen::MatrixXd K(2, 2), M(2, 2);
  K << 2.0, -1.0, -1.0, 2.0;
  M << 1.0, 0.0, 0.0, 1.0;
  const modal::GyroscopicModes r = modal::gyroscopic_modes("test", K, M, Eigen::MatrixXd::Zero(2, 2), 2);
  EXPECT_NEAR(r.omega(0), 1.0, 1e-14);
  EXPECT_NEAR(r.omega(1), std::sqrt(3.0), 1e-14);
}

TEST(GyroscopicModes, AStiffnessThatIsNotPositiveDefiniteIsANumericalFailure) {
  // Softening past the stiffness: k - speed^2 m < 0.
  Eigen::MatrixXd K = -Eigen::MatrixXd::Identity(2, 2), M = Eigen::MatrixXd::Identity(2, 2), G = Eigen::MatrixXd::Zero(2, 2);
  EXPECT_THROW(modal::gyroscopic_modes("test", K, M, G, 1), ring::NumericalError);
  EXPECT_THROW(modal::gyroscopic_modes("test", M, M, G, 3), std::invalid_argument);
}

// Past a divergence (k < 0) a wave pair is held by its Coriolis coupling when g^2 + m k >= 0:
// both roots (g -+ sqrt(g^2 + m k)) / m are then real and positive (Thomson–Tait gyroscopic
// stabilization); below that they are complex and the motion grows. One held pair beside an
// ordinary one, hidden by an orthogonal change of coordinates so that K is indefinite and full.
// Tolerance 1e-9: the general eigensolver's round-off on a 4 x 4 of entries O(10).
TEST(GyroscopicModes, ACoriolisCouplingThatHoldsADivergedPairGivesItsRealFrequencies) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(4, 4), M = K, G = K;
  const Pair held{2.0, 3.0, -4.0}, plain{1.0, 0.5, 9.0};
  add(K, M, G, 0, held);
  add(K, M, G, 2, plain);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(4, 4)).householderQ();
  const Eigen::MatrixXd Kq = Q.transpose() * K * Q, Mq = Q.transpose() * M * Q, Gq = Q.transpose() * G * Q;
  EXPECT_NE(Eigen::LLT<Eigen::MatrixXd>(Kq).info(), Eigen::Success);  // indefinite: the Hermitian form cannot
  const modal::GyroscopicModes r = modal::gyroscopic_modes("test", Kq, Mq, Gq, 4);
  const double s = std::sqrt(held.g * held.g + held.m * held.k);
  EXPECT_NEAR(r.omega(0), (held.g - s) / held.m, 1e-9);
  EXPECT_NEAR(r.omega(1), (held.g + s) / held.m, 1e-9);
  EXPECT_NEAR(r.omega(2), plain.lower(), 1e-9);
  EXPECT_NEAR(r.omega(3), plain.upper(), 1e-9);
  EXPECT_LT(r.max_residual, 1e-12);
  // g^2 + m k < 0: the same pair no longer held.
  Eigen::MatrixXd K2 = Eigen::MatrixXd::Zero(2, 2), M2 = K2, G2 = K2;
  add(K2, M2, G2, 0, Pair{2.0, 2.0, -4.0});
  try {
    modal::gyroscopic_modes("test", K2, M2, G2, 1);
    ADD_FAILURE() << "an unstable spinning pair gave frequencies";
  } catch (const ring::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("growth rate"), std::string::npos) << e.what();
  }
}

Eigen::VectorXcd wave(int k, int towards) {  // e^{-i towards k theta} travels towards +theta for towards = +1
  Eigen::VectorXcd w(ring::kStations);
  const double pi = std::acos(-1.0);
  for (int s = 0; s < ring::kStations; ++s) w(s) = std::polar(1.0, -towards * k * 2.0 * pi * s / ring::kStations);
  return w;
}

TEST(ClassifyWave, NamesTheWaveNumberAndTheSenseAgainstTheSpin) {
  ring::Wave w = modal::classify_wave(wave(3, +1), wave(3, +1) * 0.5, 2.0);
  EXPECT_EQ(w.number, 3);
  EXPECT_EQ(w.direction, 1);
  w = modal::classify_wave(wave(3, +1), wave(3, +1) * 0.5, -2.0);  // the same wave on a ring spinning the other way
  EXPECT_EQ(w.direction, -1);
  w = modal::classify_wave(wave(2, -1) + 0.3 * wave(2, +1), Eigen::VectorXcd::Zero(ring::kStations), 1.0);  // mostly backward, a little forward
  EXPECT_EQ(w.number, 2);
  EXPECT_EQ(w.direction, -1);
  w = modal::classify_wave(wave(2, -1) + wave(2, +1), Eigen::VectorXcd::Zero(ring::kStations), 1.0);  // standing: cos 2 theta
  EXPECT_EQ(w.direction, 0);
  // The ring turning on a tangential foundation: no radial motion but a small polygon ripple
  // (wave 40 at 1e-3), all of it tangential and uniform: wave 0.
  w = modal::classify_wave(1e-3 * wave(40, +1), Eigen::VectorXcd::Ones(ring::kStations), 1.0);
  EXPECT_EQ(w.number, 0);
  EXPECT_EQ(w.direction, 0);
}

TEST(TravellingMode, RestoresTheRelativeScaleThatANormalizingSamplerLoses) {
  // A "model" whose coordinates are the radial displacement at the stations itself.
  const Eigen::VectorXcd x = wave(2, +1) * std::complex<double>(0.6, 0.8);
  auto sample = [](const Eigen::VectorXd& v) {
    ring::ModeShape s;
    s.radial.assign(v.data(), v.data() + v.size());
    s.tangential.assign(v.size(), 0.0);
    double big = 0.0;
    for (double r : s.radial) big = std::max(big, std::abs(r));
    for (double& r : s.radial) r /= -big;  // normalized, and with a sign flip
    return s;
  };
  const auto [shape, w] = modal::travelling_mode(x, sample, 5.0);
  EXPECT_EQ(w.number, 2);
  EXPECT_EQ(w.direction, 1);
  EXPECT_EQ(static_cast<int>(shape.radial.size()), ring::kStations);
}

}  // namespace
