#include "ring/spec.hpp"
#include "ring/analysis.hpp"

#include <cmath>

namespace ring {

double Section::area() const {
  switch (shape) {
    case Shape::circle: return M_PI * diameter * diameter / 4.0;
    case Shape::rectangle: return width * height;
    case Shape::general: return area_;
  }
  return 0.0;
}

double Section::inertia() const {
  switch (shape) {
    case Shape::circle: return M_PI * std::pow(diameter, 4) / 64.0;
    case Shape::rectangle: return width * std::pow(height, 3) / 12.0;
    case Shape::general: return inertia_;
  }
  return 0.0;
}

double Section::depth() const {
  switch (shape) {
    case Shape::circle: return diameter;
    case Shape::rectangle: return height;
    case Shape::general: return 2.0 * std::sqrt(3.0 * inertia_ / area_);
  }
  return 0.0;
}

double LoadHistory::factor(double t) const {
  if (t < 0.0) return 0.0;
  switch (kind) {
    case Kind::step: return 1.0;
    case Kind::ramp: return std::min(t / period, 1.0);
    case Kind::half_sine: return t < period ? std::sin(M_PI * t / period) : 0.0;
    case Kind::harmonic: return std::sin(2.0 * M_PI * t / period);
  }
  return 0.0;
}

double RingSpec::bending_frequency_scale() const {
  return std::sqrt(EI() / (rhoA() * std::pow(radius, 4)));
}

double RingSpec::slenderness() const { return radius / std::sqrt(I() / A()); }

double wrap_degrees(double a) {
  double r = std::fmod(a, 360.0);
  if (r < 0.0) r += 360.0;
  return r;
}

std::vector<double> node_angles(const RingSpec& spec, int n, double fallback) {
  const double anchor = spec.supports.pin.value_or(fallback);
  std::vector<double> a(n);
  for (int k = 0; k < n; ++k) a[k] = wrap_degrees(anchor + 360.0 * k / n);
  return a;
}

bool on_node(double angle, double anchor, int n) {
  const double steps = wrap_degrees(angle - anchor) * n / 360.0;
  // Angles come from decimal input: accept a node to 1e-9 of a step.
  const double frac = std::abs(steps - std::round(steps));
  return frac < 1e-9 * std::max(1.0, steps);
}

std::string to_string(MultibodyOptions::Dependent d) {
  return d == MultibodyOptions::Dependent::paper ? "paper" : "robust";
}
std::string to_string(LumpedOptions::Variant v) {
  switch (v) {
    case LumpedOptions::Variant::chain: return "chain";
    case LumpedOptions::Variant::frame: return "frame";
    case LumpedOptions::Variant::frame_consistent: return "frame-consistent";
  }
  return "";
}
std::string to_string(FemOptions::Geometry g) {
  return g == FemOptions::Geometry::polygon ? "polygon" : "curved";
}
std::string to_string(LoadHistory::Kind k) {
  switch (k) {
    case LoadHistory::Kind::step: return "step";
    case LoadHistory::Kind::ramp: return "ramp";
    case LoadHistory::Kind::half_sine: return "half-sine";
    case LoadHistory::Kind::harmonic: return "harmonic";
  }
  return "";
}

std::string to_string(ResponseOptions::Integrator i) {
  switch (i) {
    case ResponseOptions::Integrator::newmark: return "newmark";
    case ResponseOptions::Integrator::generalized_alpha: return "generalized-alpha";
    case ResponseOptions::Integrator::energy_momentum: return "energy-momentum";
    case ResponseOptions::Integrator::midpoint: return "midpoint";
  }
  return "";
}

}  // namespace ring
