// Oracle of the linear in-plane modes of a closed thin ring whose radial depth and density vary
// around the circumference as harmonics (issue 49, item 2: ring.variations). Written from the
// mechanics, independent of every solver's code.
//
// ## The ring
// Depth factor s(theta) = 1 + sum_i e_i cos(K_i (theta - phi_i)), density factor
// d(theta) = 1 + sum_i d_i cos(K_i (theta - phi_i)) (as ring::RingSpec::depth_factor and
// density_factor; phases in degrees). A rectangle keeps its width: A = A0 s, I = I0 s^3; a circle
// scales its diameter: A = A0 s^2, I = I0 s^4. Mass per length rho d(theta) A(theta). Optional
// Winkler foundation kr (radial), kt (tangential), N/m^2.
//
// ## Kinematics (tests/support/arch.hpp, spinning_ring.hpp)
// w radial (outward), v tangential (counter-clockwise), ' = d/dtheta. Strain eps = (v' + w)/R,
// tangent rotation phi = (v - w')/R, change of curvature phi'/R = (v' - w'')/R^2.
//   U = 1/2 int [EA eps^2 + EI (phi'/R)^2 + kr w^2 + kt v^2] R dtheta,
//   T = 1/2 int rho A (w_t^2 + v_t^2) R dtheta.
// Extensible (Euler-Bernoulli): fields e = v' + w (R times the strain) and v, so w = e - v' and
// phi'/R = (v' + v''' - e'')/R^2: the membrane stiffness acts on e alone, which keeps the
// stiffness matrix well scaled however thin the ring (EA/R^2 vs EI/R^4). Inextensible: e = 0,
// one field v (w = -v').
//
// ## Hill's method (Fourier-Galerkin)
// Each field is a real trigonometric polynomial of degree N: 1, cos k theta, sin k theta,
// k = 1..N (2N+1 coefficients per field). The stiffness and mass matrices are the quadratic
// forms above, integrated on Q = 2N + 4 Kmax + 8 uniform points: every integrand is a
// trigonometric polynomial of degree <= 2N + 4 Kmax (s^4 of the circle's I), and the uniform
// rule with Q points integrates every degree < Q exactly. So the only error is the truncation N:
// Galerkin with a complete smooth basis, the eigenvector's Fourier coefficients decay
// geometrically (each harmonic K couples k to k +- K with a factor ~ amplitude), so the
// eigenvalues converge spectrally (tests/ring/test_variations_oracle.cpp: N = 32 -> 64 changes
// nothing beyond 1e-12 for amplitudes up to 0.2).
// Eigenproblem: the rigid modes make K singular, and the modes of interest are the smallest of
// a spectrum spanning (N^3 / 2^3)^2 and more, so instead of K x = lambda M x the oracle solves
// M x = mu (K + sigma M) x (sigma = EI0/(rho A0 R^4), the flexural scale), after the symmetric
// diagonal scaling that gives K + sigma M a unit diagonal: then mu = 1/(lambda + sigma) are the
// largest eigenvalues for the lowest modes, computed to round-off relative to themselves
// (absolute error eps * max mu), lambda = 1/mu - sigma.
// Rigid modes (excluded, by count, from the bottom of the ascending spectrum): the kernel of K is
// v in span{1, cos theta, sin theta}, e = 0 (the rotation and the two translations) whatever the
// variations: 3 without a foundation (kr = kt = 0), 1 (the rotation) with kr > 0 and kt = 0,
// none with kt > 0. omegas() checks they are ~0 (|lambda| < 1e-8 sigma) and throws if not.
//
// ## Pairs, split, orientation
// A mode's wave number is the k maximising its kinetic content at k (W_ck^2 + W_sk^2 + V_ck^2 +
// V_sk^2, W the radial coefficients). pair_split(ring, k) takes the two lowest elastic modes of
// wave number k: lower, upper omega, and the orientation of the lower one: the angle of its
// radial k-th harmonic's antinode, W_ck cos k theta + W_sk sin k theta = C cos k (theta - o),
// o in [0, 180/k) degrees.
//
// ## First-order split of the inextensible ring (derived here; degenerate perturbation)
// Uniform pair k >= 2: v = cos k (theta - t), w = -v'. Then phi'/R = (v' + v''')/R^2 is
// proportional to sin k (theta - t), and v^2 + v'^2 = (1 + k^2)/2 + (1 - k^2)/2 cos 2k(theta - t).
// A harmonic of EI/EI0 = 1 + beta cos K (theta - phi) and rhoA/rhoA0 = 1 + mu cos K (theta - phi)
// (to first order: rectangle beta = 3e, mu = d + e; circle beta = 4e, mu = d + 2e) changes
//   int EI (phi'/R)^2  by the factor (1 - beta/2 c), int rhoA (v^2 + v'^2) by (1 - mu (k^2-1)/(2(k^2+1)) c),
// c = cos 2k (t - phi), and ONLY when K = 2k (otherwise the product integrates to zero: no
// first-order effect). The 2 x 2 perturbation is diagonal in t = phi, phi + 90/k deg, so
//   lambda(t) = lambda0 (1 - delta c),  delta = f_b beta/2 - mu (k^2-1)/(2(k^2+1)),
// f_b = EI0 k^2 (k^2-1)^2 / R^4 / (EI0 k^2 (k^2-1)^2 / R^4 + kr k^2 + kt) (the bending share of the
// stiffness; 1 without foundation). omega splits by (omega_hi - omega_lo)/omega0 = |delta| + O(a^3)
// (the split is odd in the amplitude a: -a is the same ring turned by 180/K degrees, which swaps
// the branches, so there is no a^2 term; the mean of the pair moves at O(a^2)):
// density alone d (k^2-1)/(2(k^2+1)) (0.3 d for k = 2); thickness alone (rectangle) 3e/2 -
// e (k^2-1)/(2(k^2+1)). Several K = 2k harmonics add as Z = sum delta_i e^{i 2k phi_i}: split |Z|,
// the lower mode v = cos k(theta - t), t = arg Z / (2k), radial antinode (w = k sin k(theta - t))
// at t + 90/k deg (mod 180/k). E.g. heavier at phi (d > 0): the lower mode's radial antinodes are
// at the heavy spots; thicker at phi: they are at the thin spots.
// Symmetry rule (any order; checked with Hill in the self-test): a single harmonic K couples the
// waves e^{+ik theta} and e^{-ik theta} only through n steps of +-K with n K = 2k, so it splits
// pair k iff K divides 2k, at order 2k/K in the amplitude (K = 2k: first order; K = k: second
// order); otherwise the pair stays exactly double (the ring's rotation by 360/K degrees turns
// e^{ik theta} by different phases than e^{-ik theta}: two-dimensional representation of D_K).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

namespace vartest {

/// One harmonic of the variations (the fields of ring::Variation).
struct Harm {
  int harmonic = 1;        ///< K >= 1
  double thickness = 0.0;  ///< e: relative amplitude of the radial depth
  double density = 0.0;    ///< d: relative amplitude of the density
  double phase = 0.0;      ///< phi, degrees
};

struct Ring {
  double R = 10.0;     ///< m, centroid radius
  double E = 2.1e11;   ///< Pa
  double rho = 7.8e3;  ///< kg/m^3
  double A0 = 0.0;     ///< m^2, uniform section's area
  double I0 = 0.0;     ///< m^4, uniform section's inertia
  bool circle = true;  ///< circle (A ~ s^2, I ~ s^4) or rectangle (A ~ s, I ~ s^3)
  std::vector<Harm> harmonics;
  double kr = 0.0, kt = 0.0;  ///< Winkler foundation, N/m^2
  bool extensible = true;     ///< false: inextensible limit (w = -v')
};

struct Mode {
  double omega = 0.0;    ///< rad/s
  int wave = 0;          ///< dominant wave number (file comment)
  double orientation = 0.0;  ///< degrees in [0, 180/wave): radial antinode of the wave-th harmonic (0 for wave 0)
};

struct Split {
  double lower = 0.0, upper = 0.0;  ///< rad/s
  double orientation_deg = 0.0;     ///< lower mode's radial antinode, [0, 180/k)
};

namespace detail {

inline double pi() { return std::acos(-1.0); }

inline double depth(const Ring& r, double th) {
  double s = 1.0;
  for (const auto& h : r.harmonics) s += h.thickness * std::cos(h.harmonic * (th - h.phase * pi() / 180.0));
  return s;
}
inline double dens(const Ring& r, double th) {
  double d = 1.0;
  for (const auto& h : r.harmonics) d += h.density * std::cos(h.harmonic * (th - h.phase * pi() / 180.0));
  return d;
}

/// Number of rigid modes (file comment).
inline int rigid_count(const Ring& r) { return r.kt > 0.0 ? 0 : (r.kr > 0.0 ? 1 : 3); }

/// Value of the j-th real basis function's p-th derivative at theta: j = 0: 1; j = 2k-1: cos k;
/// j = 2k: sin k.
inline double basis(int j, int p, double th) {
  if (j == 0) return p == 0 ? 1.0 : 0.0;
  const int k = (j + 1) / 2;
  const bool c = (j % 2) == 1;
  const double kp = std::pow(double(k), p);
  // d^p cos = k^p cos(x + p pi/2), d^p sin = k^p sin(x + p pi/2)
  const double x = k * th + p * pi() / 2.0;
  return kp * (c ? std::cos(x) : std::sin(x));
}

struct Solved {
  std::vector<Mode> modes;  ///< elastic modes, ascending
};

inline Solved solve(const Ring& r, int N) {
  if (N < 4) throw std::invalid_argument("vartest: N >= 4");
  int Kmax = 0;
  for (const auto& h : r.harmonics) Kmax = std::max(Kmax, h.harmonic);
  const int nb = 2 * N + 1, nf = r.extensible ? 2 : 1, n = nf * nb;
  const int Q = 2 * N + 4 * Kmax + 8;
  const double R = r.R, EI0 = r.E * r.I0, EA0 = r.E * r.A0, rA0 = r.rho * r.A0;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
  // Per point: rows of the linear maps coefficients -> (e, kappa R^2, w, v).
  Eigen::VectorXd le(n), lk(n), lw(n), lv(n);
  for (int q = 0; q < Q; ++q) {
    const double th = 2.0 * pi() * q / Q, wq = 2.0 * pi() / Q * R;
    const double s = depth(r, th), d = dens(r, th);
    const double A = r.circle ? s * s : s, I = r.circle ? s * s * s * s : s * s * s;
    le.setZero();
    lk.setZero();
    lw.setZero();
    lv.setZero();
    for (int j = 0; j < nb; ++j) {
      const double b0 = basis(j, 0, th), b1 = basis(j, 1, th), b2 = basis(j, 2, th), b3 = basis(j, 3, th);
      // v coefficients at [0, nb): v = b0, v' = b1; w = e - v'; kappa R^2 = v' + v''' - e''
      lv(j) = b0;
      lw(j) = -b1;
      lk(j) = b1 + b3;
      if (r.extensible) {
        le(nb + j) = b0;
        lw(nb + j) += b0;
        lk(nb + j) = -b2;
      }
    }
    K.noalias() += wq * (EA0 * A / (R * R)) * le * le.transpose();
    K.noalias() += wq * (EI0 * I / std::pow(R, 4)) * lk * lk.transpose();
    if (r.kr != 0.0) K.noalias() += wq * r.kr * lw * lw.transpose();
    if (r.kt != 0.0) K.noalias() += wq * r.kt * lv * lv.transpose();
    M.noalias() += wq * rA0 * d * A * (lw * lw.transpose() + lv * lv.transpose());
  }
  const double sigma = EI0 / (rA0 * std::pow(R, 4));
  Eigen::MatrixXd B = K + sigma * M;
  Eigen::VectorXd D = B.diagonal().cwiseSqrt().cwiseInverse();
  B = D.asDiagonal() * B * D.asDiagonal();
  Eigen::MatrixXd Ms = D.asDiagonal() * M * D.asDiagonal();
  B = 0.5 * (B + B.transpose());
  Ms = 0.5 * (Ms + Ms.transpose());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Ms, B);
  if (es.info() != Eigen::Success) throw std::runtime_error("vartest: eigensolver failed");
  // ascending mu -> descending lambda: walk from the end
  const int rigid = rigid_count(r);
  Solved out;
  for (int i = n - 1; i >= 0; --i) {
    const double lambda = 1.0 / es.eigenvalues()(i) - sigma;
    const int rank = n - 1 - i;
    if (rank < rigid) {
      if (std::abs(lambda) > 1e-8 * sigma) throw std::runtime_error("vartest: rigid mode not at zero");
      continue;
    }
    if (!(lambda > 0.0)) throw std::runtime_error("vartest: non-positive elastic eigenvalue");
    const Eigen::VectorXd x = D.asDiagonal() * es.eigenvectors().col(i);
    // radial and tangential Fourier coefficients
    auto V = [&](int j) { return x(j); };
    auto Ec = [&](int j) { return r.extensible ? x(nb + j) : 0.0; };
    Mode m;
    m.omega = std::sqrt(lambda);
    double best = -1.0, wc = 0.0, ws = 0.0;
    for (int k = 0; k <= N; ++k) {
      double c = 0.0;
      double Wc = 0.0, Ws = 0.0;
      if (k == 0) {
        Wc = Ec(0);
        c = Wc * Wc + V(0) * V(0);
      } else {
        const double Vc = V(2 * k - 1), Vs = V(2 * k);
        // v = Vc cos + Vs sin: v' = -k Vc sin + k Vs cos; w = e - v'
        Wc = Ec(2 * k - 1) - k * Vs;
        Ws = Ec(2 * k) + k * Vc;
        c = Wc * Wc + Ws * Ws + Vc * Vc + Vs * Vs;
      }
      if (c > best) {
        best = c;
        m.wave = k;
        wc = Wc;
        ws = Ws;
      }
    }
    if (m.wave > 0) {
      const double per = 180.0 / m.wave;
      double o = std::atan2(ws, wc) / m.wave * 180.0 / pi();
      o = std::fmod(o, per);
      if (o < 0.0) o += per;
      if (o >= per) o -= per;
      m.orientation = o;
    }
    out.modes.push_back(m);
  }
  return out;
}

}  // namespace detail

/// The `count` lowest elastic modes (ascending; rigid modes excluded by count, file comment).
inline std::vector<Mode> modes(const Ring& r, int count, int N = 64) {
  auto s = detail::solve(r, N);
  if (int(s.modes.size()) < count) throw std::invalid_argument("vartest: count > modes of the truncation");
  s.modes.resize(count);
  return s.modes;
}

/// The `count` lowest elastic frequencies, rad/s, ascending.
inline std::vector<double> omegas(const Ring& r, int count, int N = 64) {
  std::vector<double> w;
  for (const auto& m : modes(r, count, N)) w.push_back(m.omega);
  return w;
}

/// Pair k (k >= 2 free; >= 0 on a foundation): the two lowest elastic modes of wave number k.
inline Split pair_split(const Ring& r, int k, int N = 64) {
  const auto s = detail::solve(r, N);
  std::vector<Mode> found;
  for (const auto& m : s.modes)
    if (m.wave == k && found.size() < 2) found.push_back(m);
  if (found.size() < 2) throw std::runtime_error("vartest: pair " + std::to_string(k) + " not found");
  return {found[0].omega, found[1].omega, found[0].orientation};
}

/// First-order split of the inextensible ring's pair k >= 2 (file comment): relative split
/// (omega_hi - omega_lo)/omega0 = |Z| and the lower mode's radial antinode (degrees, [0, 180/k)),
/// from the harmonics with K = 2k (others have no first-order effect). orientation is
/// meaningless when relative == 0.
struct FirstOrder {
  double relative = 0.0;
  double orientation_deg = 0.0;
};

inline FirstOrder first_order_inextensible(const Ring& r, int k) {
  const double pi = detail::pi(), k2 = double(k) * k, R = r.R;
  const double bend = r.E * r.I0 * k2 * (k2 - 1.0) * (k2 - 1.0) / std::pow(R, 4);
  const double fb = bend / (bend + r.kr * k2 + r.kt);
  std::complex<double> Z = 0.0;
  for (const auto& h : r.harmonics) {
    if (h.harmonic != 2 * k) continue;
    const double beta = (r.circle ? 4.0 : 3.0) * h.thickness;
    const double mu = h.density + (r.circle ? 2.0 : 1.0) * h.thickness;
    const double delta = fb * beta / 2.0 - mu * (k2 - 1.0) / (2.0 * (k2 + 1.0));
    Z += delta * std::polar(1.0, 2.0 * k * h.phase * pi / 180.0);
  }
  FirstOrder f;
  f.relative = std::abs(Z);
  const double per = 180.0 / k;
  double o = std::arg(Z) / (2.0 * k) * 180.0 / pi + 90.0 / k;
  o = std::fmod(o, per);
  if (o < 0.0) o += per;
  if (o >= per) o -= per;
  f.orientation_deg = o;
  return f;
}

}  // namespace vartest
