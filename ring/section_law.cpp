#include "ring/section_law.hpp"

#include <cmath>
#include <stdexcept>

#include "ring/spec.hpp"

namespace ring {

namespace {

/// Gauss–Legendre nodes and weights on [-1, 1]: the roots of P_n by Newton's method from
/// Tricomi's estimate cos(pi (i + 3/4) / (n + 1/2)), the weights 2 / ((1 - x^2) P_n'(x)^2)
/// (Abramowitz & Stegun 25.4.29). Converged to round-off in a few iterations for n <= 100.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;  // P_0, P_1, then the three-term recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

}  // namespace

SectionLaw::SectionLaw(const RingSpec& spec, int fibres)
    : EI_(spec.EI()),
      law_(spec.plastic->law == Plastic::Law::resultant
               ? BilinearLaw(spec.EI(), spec.plastic->moment, spec.plastic->hardening, spec.plastic->rule)
               : BilinearLaw(spec.E, spec.plastic->stress, spec.plastic->hardening, spec.plastic->rule)) {
  const Plastic& p = *spec.plastic;
  if (p.law == Plastic::Law::resultant) {
    yield_ = p.moment;
    return;
  }
  yield_ = p.stress;
  const Section& s = spec.section;
  if (s.shape == Section::Shape::general || fibres < 2 || fibres % 2)
    throw std::invalid_argument("ring.plastic.stress: the fibre law needs a section with a shape and an even fibre count");
  // Each half of the depth on its own Gauss points: the stress's kink at the centroid (where a
  // fully plastic section's stress changes sign) falls between them.
  std::vector<double> x, w;
  gauss_legendre(fibres / 2, x, w);
  double I = 0.0;
  for (const double half : {-1.0, 1.0})
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double wu = 0.5 * w[i];  // the weight on a half of (-1, 1)
      const double v = half < 0 ? 0.5 * (x[i] - 1.0) : 0.5 * (x[i] + 1.0);
      Fibre f;
      if (s.shape == Section::Shape::rectangle) {
        f.y = 0.5 * s.height * v;
        f.area = s.width * 0.5 * s.height * wu;
      } else {
        // y = r sin t over t in [-pi/2, pi/2]: the strip's width 2 r cos t times dy = r cos t dt.
        const double r = 0.5 * s.diameter, t = 0.5 * M_PI * v;
        f.y = r * std::sin(t);
        f.area = 2.0 * r * r * std::cos(t) * std::cos(t) * 0.5 * M_PI * wu;
      }
      I += f.y * f.y * f.area;
      fibres_.push_back(f);
    }
  for (Fibre& f : fibres_) f.area *= s.inertia() / I;
}

BilinearLaw::Point SectionLaw::at(const PlasticState* s, double kappa) const {
  if (fibres_.empty()) return law_.at(*s, kappa);
  BilinearLaw::Point m;
  m.force = m.tangent = m.potential = 0.0;
  for (std::size_t i = 0; i < fibres_.size(); ++i) {
    const Fibre& f = fibres_[i];
    const BilinearLaw::Point p = law_.at(s[i], f.y * kappa);
    m.force += f.y * f.area * p.force;
    m.tangent += f.y * f.y * f.area * p.tangent;
    m.potential += f.area * p.potential;
    m.yielding = m.yielding || p.yielding;
  }
  return m;
}

void SectionLaw::commit(PlasticState* s, double kappa) const {
  if (fibres_.empty()) {
    *s = law_.commit(*s, kappa);
    return;
  }
  for (std::size_t i = 0; i < fibres_.size(); ++i) s[i] = law_.commit(s[i], fibres_[i].y * kappa);
}

double SectionLaw::dissipated(const PlasticState* s, double kappa) const {
  if (fibres_.empty()) return law_.dissipated(*s, kappa);
  double d = 0.0;
  for (std::size_t i = 0; i < fibres_.size(); ++i) d += fibres_[i].area * law_.dissipated(s[i], fibres_[i].y * kappa);
  return d;
}

double SectionLaw::plastic_curvature(const PlasticState* s, double kappa) const {
  return kappa - at(s, kappa).force / EI_;
}

double SectionLaw::stored(const PlasticState* s, double kappa) const {
  if (fibres_.empty()) return law_.stored(*s, kappa);
  double e = 0.0;
  for (std::size_t i = 0; i < fibres_.size(); ++i) e += fibres_[i].area * law_.stored(s[i], fibres_[i].y * kappa);
  return e;
}

double SectionLaw::plastic_moment() const {
  if (fibres_.empty()) return yield_;
  double z = 0.0;
  for (const Fibre& f : fibres_) z += std::abs(f.y) * f.area;
  return yield_ * z;
}

}  // namespace ring
