// The thin ring pinched by two opposite point loads P with the FIBRE law (ring.plastic.stress:
// a uniaxial bilinear stress–strain law, yield sigma_y, tangent h E past it, integrated over
// the section's depth), at small displacement: the oracle of the fibre law in the solvers.
//
// The section's moment–curvature law under monotonic bending, in closed form. With b(y) the
// section's width at the depth y, c its half-depth, F1(y) = int_0^y b t dt and
// F2(y) = int_0^y b t^2 dt, and the elastic core's half-depth y_e = min(c, eps_y / kappa):
//   M(kappa) = 2 [E kappa F2(y_e) + sigma_y (F1(c) - F1(y_e))
//                 + h E (kappa (F2(c) - F2(y_e)) - eps_y (F1(c) - F1(y_e)))],
// (the elastic core, the yielded fibres' sigma_y and their hardening), with
//   rectangle b x h:    F1 = b y^2 / 2, F2 = b y^3 / 3;
//   circle of radius a: F1 = (2/3)(a^3 - (a^2 - y^2)^(3/2)),
//                       F2 = (y/4)(2 y^2 - a^2) sqrt(a^2 - y^2) + (a^4/4) asin(y/a).
// Elastic, M = E I kappa (I = 2 F2(c)); first yield My = sigma_y I / c; with h = 0 the moment
// tends to Mp = 2 sigma_y F1(c) (b h^2 / 4 sigma_y, d^3 / 6 sigma_y): the shape factors 1.5 and
// 16 / (3 pi). (For h = 0 these are Lubliner's, "Plasticity Theory", 2008, sec. 4.4.)
//
// The ring: a quarter from a load (theta = 0) to the other diameter carries
// M(theta) = M0 - (P R / 2) sin(theta) (statics); its end sections keep their directions
// (symmetry), so int_0^{pi/2} kappa(M(theta)) dtheta = 0 fixes M0 (compatibility), kappa(M)
// the inverse of the law above. Under proportional loading no point of the pinched ring
// unloads (the moment at each point grows with P: |dM0/dP| stays below R/2), so the monotonic
// law is the path-dependent law's answer. The closing of the load points by the unit-load
// theorem with the virtual moment -(R/2) sin(theta) of a unit pinch:
//   delta = -2 R^2 int_0^{pi/2} kappa(M(theta)) sin(theta) dtheta
// (elastic: (pi/4 - 2/pi) P R^3 / EI, Roark's case 1). The first yield under the loads is at
// P_y = pi My / R; the four-hinge collapse at P_c = 4 Mp / R (limit analysis: plastic_ring.hpp).
// Geometrically exact models deviate from these by O(delta / R).
//
// The integrals are exact to round-off but for the quadrature: each is split where |M| = My
// (the law's kinks) and integrated by Gauss–Legendre on panels; kappa(M) by bisection. The
// law may also be passed as a function with the moments where its slope jumps (for example
// a solver's own fibre quadrature, or the resultant law with a little hardening), so that a
// structural discretization is measured apart from the section's.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "ring/spec.hpp"

namespace ringtest {

class FibrePinchedRing {
 public:
  /// The ring of `spec` (its radius, E and section; spec.plastic the fibre law).
  explicit FibrePinchedRing(const ring::RingSpec& spec)
      : R_(spec.radius), E_(spec.E), sy_(spec.plastic->stress), h_(spec.plastic->hardening), section_(spec.section) {
    if (section_.shape == ring::Section::Shape::general) throw std::invalid_argument("fibre law: a shaped section");
    c_ = section_.shape == ring::Section::Shape::rectangle ? section_.height / 2 : section_.diameter / 2;
    I_ = 2.0 * F2(c_);
    law_ = [this](double kappa) { return closed_form_moment(kappa); };
    kinks_ = {first_yield_moment()};
  }
  /// The same ring with another monotonic moment–curvature law M(kappa) (odd in kappa, N m),
  /// whose slope jumps at the moments `kinks` (N m).
  FibrePinchedRing(const ring::RingSpec& spec, std::function<double(double)> law, std::vector<double> kinks)
      : FibrePinchedRing(spec) {
    law_ = std::move(law);
    kinks_ = std::move(kinks);
  }

  double first_yield_moment() const { return sy_ * I_ / c_; }         ///< My, N m
  double plastic_moment() const { return 2.0 * sy_ * F1(c_); }        ///< Mp (h = 0), N m
  double first_yield() const { return M_PI * first_yield_moment() / R_; }  ///< P_y, N
  double collapse() const { return 4.0 * plastic_moment() / R_; }          ///< P_c (h = 0), N
  double EI() const { return E_ * I_; }

  /// The closed-form moment at the curvature kappa (1/m) under monotonic bending, N m.
  double closed_form_moment(double kappa) const {
    const double k = std::abs(kappa), ey = sy_ / E_;
    const double ye = k * c_ <= ey ? c_ : ey / k;
    const double m = 2.0 * (E_ * k * F2(ye) + sy_ * (F1(c_) - F1(ye)) +
                            h_ * E_ * (k * (F2(c_) - F2(ye)) - ey * (F1(c_) - F1(ye))));
    return std::copysign(m, kappa);
  }

  /// The moment under the loads, M0 (N m), at the load P (N) below the collapse.
  double moment_under_load(double P) const {
    // int kappa(M0 - P R sin / 2) grows with M0: bisect between the bounds where the moment
    // stays inside the law's range (|M| < Mp for h = 0) at both ends of the quarter.
    const double top = law_(1e9 * sy_ / (E_ * c_));  // the law's range: Mp for h = 0
    double lo = std::max(0.0, P * R_ / 2 - top), hi = std::min(top, P * R_ / 2 + top);
    const double shrink = 1e-14 * top;
    lo += shrink;
    hi -= shrink;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * top; ++it) {
      const double mid = 0.5 * (lo + hi);
      (quarter([&](double t) { return curvature(mid - P * R_ / 2 * std::sin(t)); }, mid, P) > 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }

  /// The closing of the two load points at P (N), m.
  double closing(double P) const {
    const double M0 = moment_under_load(P);
    return -2.0 * R_ * R_ *
           quarter([&](double t) { return curvature(M0 - P * R_ / 2 * std::sin(t)) * std::sin(t); }, M0, P);
  }

  /// kappa(M): the inverse of the law (1/m), by bisection.
  double curvature(double M) const {
    const double a = std::abs(M), ky = sy_ / (E_ * c_);
    double lo = 0.0, hi = ky;
    while (law_(hi) < a) {
      lo = hi;
      hi *= 2.0;
      if (hi > 1e12 * ky) throw std::domain_error("FibrePinchedRing: a moment beyond the section's");
    }
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      (law_(mid) < a ? lo : hi) = mid;
    }
    return std::copysign(0.5 * (lo + hi), M);
  }

 private:
  double F1(double y) const {
    if (section_.shape == ring::Section::Shape::rectangle) return section_.width * y * y / 2;
    const double a = c_;
    return 2.0 / 3.0 * (a * a * a - std::pow(std::max(0.0, a * a - y * y), 1.5));
  }
  double F2(double y) const {
    if (section_.shape == ring::Section::Shape::rectangle) return section_.width * y * y * y / 3;
    const double a = c_;
    return (y / 4) * (2 * y * y - a * a) * std::sqrt(std::max(0.0, a * a - y * y)) +
           std::pow(a, 4) / 4 * std::asin(std::min(1.0, y / a));
  }

  /// int_0^{pi/2} f, split where |M0 - P R sin(t) / 2| meets a kink of the law, each piece
  /// by 16 panels of 10-point Gauss–Legendre.
  template <class F>
  double quarter(F f, double M0, double P) const {
    std::vector<double> cuts{0.0, M_PI / 2};
    const double q = P * R_ / 2;
    for (const double kink : kinks_)
      for (const double edge : {M0 - kink, M0 + kink})
        if (q > 0 && edge > 0 && edge < q) cuts.push_back(std::asin(edge / q));
    std::sort(cuts.begin(), cuts.end());
    static const double x[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                                0.9739065285171717};
    static const double w[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                0.0666713443086881};
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const int panels = 16;
      const double d = (cuts[i + 1] - cuts[i]) / panels;
      for (int p = 0; p < panels; ++p) {
        const double mid = cuts[i] + (p + 0.5) * d;
        for (int j = 0; j < 5; ++j) sum += 0.5 * d * w[j] * (f(mid - 0.5 * d * x[j]) + f(mid + 0.5 * d * x[j]));
      }
    }
    return sum;
  }

  double R_, E_, sy_, h_;
  ring::Section section_;
  double c_ = 0.0, I_ = 0.0;
  std::function<double(double)> law_;
  std::vector<double> kinks_;
};

}  // namespace ringtest
