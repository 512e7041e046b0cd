#include "ring/spec.hpp"
#include "ring/analysis.hpp"
#include "ring/errors.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <stdexcept>

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

double RingSpec::bending_frequency_scale() const { return std::sqrt(EI() / (rhoA() * std::pow(radius, 4))); }

double RingSpec::slenderness() const { return radius / std::sqrt(I() / A()); }

std::vector<double> Supports::pinned() const {
  std::vector<double> all;
  if (pin) all.push_back(*pin);
  all.insert(all.end(), pins.begin(), pins.end());
  return all;
}

double RingSpec::opening() const { return arc ? arc->span() * M_PI / 180.0 : 2.0 * M_PI; }

int RingSpec::rigid_modes() const {
  // Rows on the rigid motion (tx, ty, w) of the ring: the displacement of the point at polar
  // angle a is (tx - w R sin a, ty + w R cos a). A constraint or a positive spring along a
  // direction d there removes the motion d . u(a); the foundation removes what has radial
  // or tangential displacement somewhere (radial: both translations; tangential: all three).
  std::vector<Eigen::RowVector3d> rows;
  auto along = [&](double deg, double dx, double dy) {
    const double a = deg * M_PI / 180.0;
    rows.emplace_back(dx, dy, radius * (-dx * std::sin(a) + dy * std::cos(a)));
  };
  for (double p : supports.pinned()) {
    along(p, 1.0, 0.0);
    along(p, 0.0, 1.0);
  }
  if (supports.clamp) rows.emplace_back(0.0, 0.0, 1.0);
  if (supports.roller && supports.pin) {
    const double a = *supports.roller * M_PI / 180.0, a0 = *supports.pin * M_PI / 180.0;
    const double dx = std::cos(a) - std::cos(a0), dy = std::sin(a) - std::sin(a0);
    along(*supports.roller, -dy, dx);  // the line's normal
  }
  for (const Spring& s : supports.springs) {
    if (s.kx > 0.0) along(s.angle, 1.0, 0.0);
    if (s.ky > 0.0) along(s.angle, 0.0, 1.0);
    if (s.kr > 0.0) rows.emplace_back(0.0, 0.0, 1.0);
  }
  if (foundation.radial > 0.0) {
    rows.emplace_back(1.0, 0.0, 0.0);
    rows.emplace_back(0.0, 1.0, 0.0);
  }
  if (foundation.tangential > 0.0) {
    rows.emplace_back(1.0, 0.0, 0.0);
    rows.emplace_back(0.0, 1.0, 0.0);
    rows.emplace_back(0.0, 0.0, 1.0);
  }
  if (rows.empty()) return 3;
  Eigen::MatrixXd A(rows.size(), 3);
  for (std::size_t i = 0; i < rows.size(); ++i) A.row(i) = rows[i] / std::max(1.0, rows[i].norm());
  Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  lu.setThreshold(1e-9);
  return 3 - static_cast<int>(lu.rank());
}

namespace {

/// Throws std::invalid_argument "`who` does not take KEY, KEY yet (see docs/solvers.md ...)" for a
/// non-empty list of scene keys.
void refuse_keys(const std::vector<std::string>& keys, const std::string& who) {
  if (keys.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < keys.size(); ++i) list += (i ? ", " : "") + keys[i];
  throw std::invalid_argument(who + " does not take " + list +
                              " yet (see docs/solvers.md, \"Beyond the paper's ring\", for what each solver takes)");
}

}  // namespace

void refuse_timoshenko(const RingSpec& spec, const std::string& who) {
  if (spec.theory == Theory::timoshenko)
    throw std::invalid_argument(who +
                                " has no Timoshenko model yet (the model's theory is \"timoshenko\": ring.theory, or the "
                                "solver's own multibody.theory or fem.theory where given; see docs/solvers.md, "
                                "\"Thick rings\", for what each solver takes)");
}

void refuse_terms_beyond_paper(const RingSpec& spec, const std::string& who) {
  refuse_keys(spec.terms_beyond_paper(), who);
}


std::optional<ScaleViolation> scale_violation(const RingSpec& spec) {
  auto text = [](double x) {
    std::ostringstream s;
    s << x;
    return s.str();
  };
  const std::string window = "[" + text(kMinScale) + ", " + text(kMaxScale) + "]";
  // `!(x <= hi)`: a NaN scale is outside too.
  auto outside = [](double x, double lo) { return !(x >= lo && x <= kMaxScale); };
  const double R = spec.radius, rhoA_ = spec.rhoA();
  const std::string ring_keys = "ring.E, ring.rho, ring.section, ring.radius";
  const std::pair<const char*, double> own[] = {{"EI/R^4 (N/m^2)", spec.EI() / std::pow(R, 4)},
                                                {"EA/R^2 (N/m^2)", spec.EA() / (R * R)},
                                                {"rho A (kg/m)", rhoA_},
                                                {"EI/(rho A R^4) (1/s^2)", spec.EI() / (rhoA_ * std::pow(R, 4))}};
  for (const auto& [name, x] : own)
    if (outside(x, kMinScale))
      return ScaleViolation{ring_keys, std::string("the ring's ") + name + " = " + text(x) + " is outside " + window +
                                           ", the magnitudes the solvers' arithmetic holds (products of the model "
                                           "overflow or underflow); give the ring in SI units of ordinary size"};
  // A term: at most kMaxScale per metre of ring, and over the ring's mass per metre.
  auto term = [&](const std::string& key, const char* formula, double per_metre, bool stiffness) {
    const char* unit = stiffness ? "N/m^2" : "kg/m";
    std::optional<ScaleViolation> v;
    if (outside(per_metre, 0.0))
      v = ScaleViolation{key, "per metre of ring (" + std::string(formula) + ") it is " + text(per_metre) + " " + unit +
                                  ", above " + text(kMaxScale) + ", the largest scale the solvers' arithmetic holds"};
    else if (stiffness && outside(per_metre / rhoA_, 0.0))
      v = ScaleViolation{key, "its frequency scale over the ring's mass (" + std::string(formula) + ")/(rho A) is " +
                                  text(per_metre / rhoA_) + " 1/s^2, above " + text(kMaxScale) +
                                  ", the largest scale the solvers' arithmetic holds"};
    return v;
  };
  std::optional<ScaleViolation> v;
  if ((v = term("foundation.radial", "k", spec.foundation.radial, true))) return v;
  if ((v = term("foundation.tangential", "k", spec.foundation.tangential, true))) return v;
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i) {
    const Spring& s = spec.supports.springs[i];
    const std::string key = "supports.springs[" + std::to_string(i + 1) + "]";
    if ((v = term(key + ".kx", "kx/R", s.kx / R, true)) || (v = term(key + ".ky", "ky/R", s.ky / R, true)) ||
        (v = term(key + ".kr", "kr/R^3", s.kr / (R * R * R), true)))
      return v;
  }
  for (std::size_t i = 0; i < spec.masses.size(); ++i) {
    const PointMass& m = spec.masses[i];
    const std::string key = "masses[" + std::to_string(i + 1) + "]";
    if ((v = term(key + ".mass", "mass/R", m.mass / R, false)) ||
        (v = term(key + ".inertia", "inertia/R^3", m.inertia / (R * R * R), false)))
      return v;
  }
  return std::nullopt;
}

int static_rigid_modes(const RingSpec& spec, const Loads& loads) {
  const int rigid = spec.rigid_modes();
  if (rigid != 1 || !spec.supports.pin || !loads.has_gravity()) return rigid;
  // With a pin, the one motion left is the rotation about it; it is held when the centroid of
  // the centre line (the ring's centre; an arch's at R sin(h) / h along its bisector, h half
  // its opening) lies below the pin.
  const double a = *spec.supports.pin * M_PI / 180.0;
  double cx = 0.0, cy = 0.0;
  if (spec.arc) {
    const double h = spec.arc->span() * M_PI / 360.0, mid = (spec.arc->from + spec.arc->to) * M_PI / 360.0;
    cx = spec.radius * std::sin(h) / h * std::cos(mid);
    cy = spec.radius * std::sin(h) / h * std::sin(mid);
  }
  const double below = loads.gravity[0] * (cx - spec.radius * std::cos(a)) + loads.gravity[1] * (cy - spec.radius * std::sin(a));
  return below > 0.0 ? 0 : 1;
}

double load_scale(const RingSpec& spec, const Loads& loads) {
  double f = 0.0;
  for (const auto& p : loads.points) f += std::hypot(p.force[0], p.force[1]);
  const double L = spec.length();
  double mass = spec.rhoA() * L;
  for (const auto& m : spec.masses) mass += m.mass;
  return f + std::abs(loads.pressure.value) * L + mass * std::hypot(loads.gravity[0], loads.gravity[1]);
}

std::vector<std::string> RingSpec::terms_beyond_paper() const {
  std::vector<std::string> keys;
  if (!supports.pins.empty()) keys.push_back("supports.pins");
  if (supports.clamp) keys.push_back("supports.clamp");
  if (!supports.springs.empty()) keys.push_back("supports.springs");
  if (!masses.empty()) keys.push_back("masses");
  if (foundation.any()) keys.push_back("foundation");
  return keys;
}

double wrap_degrees(double a) {
  double r = std::fmod(a, 360.0);
  if (r < 0.0) r += 360.0;
  return r;
}

std::vector<double> node_angles(const RingSpec& spec, int n) {
  const double anchor = spec.anchor();
  const double step = spec.arc ? spec.arc->span() / n : 360.0 / n;
  std::vector<double> a(node_count(spec, n));
  for (std::size_t k = 0; k < a.size(); ++k) a[k] = wrap_degrees(anchor + step * static_cast<double>(k));
  return a;
}

int node_index(const RingSpec& spec, double angle, int n) {
  const double span = spec.arc ? spec.arc->span() : 360.0;
  const double rel = spec.arc ? spec.arc->offset(angle) : wrap_degrees(angle - spec.anchor());
  const double steps = rel * n / span;
  // Angles come from decimal input: accept a node to 1e-9 of a step.
  const double k = std::round(steps);
  if (std::abs(steps - k) >= 1e-9 * std::max(1.0, steps)) return -1;
  if (!spec.arc) return static_cast<int>(k) % n;
  return k <= n ? static_cast<int>(k) : -1;
}

bool Arc::contains(double deg) const { return offset(deg) <= span() + 1e-9; }

double Arc::offset(double deg) const {
  const double rel = wrap_degrees(deg - from);
  // A point a hair before `from` is the `from` end, not a full turn on.
  return rel > 360.0 - 1e-9 ? 0.0 : rel;
}

void refuse_arch(const RingSpec& spec, const std::string& who) {
  if (spec.arc) throw std::invalid_argument(who + " does not take an arch (ring.arc) yet");
}

void refuse_variations(const RingSpec& spec, const std::string& who) {
  if (spec.varies()) throw std::invalid_argument(who + " does not take ring.variations yet");
}

double RingSpec::depth_factor(double deg) const {
  double f = 1.0;
  for (const auto& v : variations) f += v.thickness * std::cos(v.harmonic * (deg - v.phase) * M_PI / 180.0);
  return f;
}

double RingSpec::density_factor(double deg) const {
  double f = 1.0;
  for (const auto& v : variations) f += v.density * std::cos(v.harmonic * (deg - v.phase) * M_PI / 180.0);
  return f;
}

double RingSpec::A_at(double deg) const {
  if (variations.empty()) return A();
  const double s = depth_factor(deg);
  return A() * (section.shape == Section::Shape::circle ? s * s : s);
}

double RingSpec::I_at(double deg) const {
  if (variations.empty()) return I();
  const double s = depth_factor(deg);
  return I() * (section.shape == Section::Shape::circle ? s * s * s * s : s * s * s);
}

void refuse_displacement(const StaticOptions& statics, const std::string& who) {
  if (statics.displacement)
    throw InputError("", "static.displacement",
                     who + " has no displacement control (static.displacement) yet: drive the path by loads");
}

int static_rigid_modes(const RingSpec& spec, const StaticOptions& statics) {
  if (statics.plates) return 0;
  if (!statics.displacement) return static_rigid_modes(spec, statics.loads);
  RingSpec held = spec;
  if (held.supports.pin) held.supports.pins.push_back(statics.displacement->at);
  else held.supports.pin = statics.displacement->at;
  return static_rigid_modes(held, statics.loads);
}

void refuse_plates(const StaticOptions& statics, const std::string& who) {
  if (statics.plates) throw InputError("", "plates", who + " has no rigid plates ([plates]) yet: drive the path by static.displacement");
}

PlatePair::PlatePair(const RingSpec& spec, const StaticOptions::Plates& plates)
    : R(spec.radius), travel(plates.travel), k(plates.stiffness),
      d{std::cos(plates.axis * M_PI / 180.0), std::sin(plates.axis * M_PI / 180.0)} {}

std::array<double, 2> PlatePair::contact_lengths(const std::vector<double>& x, const std::vector<double>& y, double s) const {
  const int n = static_cast<int>(x.size());
  if (n < 4 || static_cast<int>(y.size()) != n) throw std::invalid_argument("PlatePair::contact_lengths: needs at least 4 points, x and y alike");
  std::array<double, 2> lengths{0.0, 0.0};
  const auto at = [n](int i) { return ((i % n) + n) % n; };
  const auto chord = [&](int i, int j) { return std::hypot(x[at(j)] - x[at(i)], y[at(j)] - y[at(i)]); };
  for (int p = 0; p < 2; ++p) {
    const double sign = p == 0 ? 1.0 : -1.0;
    const auto facing = [&](int i) { return sign * (d[0] * x[at(i)] + d[1] * y[at(i)]); };
    const auto g = [&](int i) { return gap(p, x[at(i)], y[at(i)], s); };
    int c = 0;
    for (int i = 1; i < n; ++i)
      if (facing(i) > facing(c)) c = i;
    if (g(c) > 0.0) continue;
    // The furthest point in contact on each side of c within the facing half, and the part
    // of the next chord up to the gap's zero.
    double length = 0.0;
    for (int dir : {1, -1}) {
      int last = c;
      for (int step = 1; step < n / 2 && facing(c + dir * step) > 0.0; ++step)
        if (g(c + dir * step) <= 0.0) last = c + dir * step;
      for (int i = c; i != last; i += dir) length += chord(i, i + dir);
      const double g0 = g(last), g1 = g(last + dir);
      if (g1 > 0.0) length += chord(last, last + dir) * (-g0 / (g1 - g0));
    }
    lengths[p] = length;
  }
  return lengths;
}

void refuse_rotation(const RingSpec& spec, const std::string& who) {
  if (spec.rotation.spinning()) throw std::invalid_argument(who + " does not take a spinning ring (rotation.speed) yet");
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
    case LumpedOptions::Variant::timoshenko_frame: return "timoshenko-frame";
  }
  return "";
}
std::string to_string(FemOptions::Geometry g) { return g == FemOptions::Geometry::polygon ? "polygon" : "curved"; }
std::string to_string(LoadHistory::Kind k) {
  switch (k) {
    case LoadHistory::Kind::step: return "step";
    case LoadHistory::Kind::ramp: return "ramp";
    case LoadHistory::Kind::half_sine: return "half-sine";
    case LoadHistory::Kind::harmonic: return "harmonic";
  }
  return "";
}

std::string to_string(Pressure::Kind k) {
  switch (k) {
    case Pressure::Kind::follower: return "follower";
    case Pressure::Kind::dead: return "dead";
    case Pressure::Kind::central: return "central";
  }
  return "";
}

std::string to_string(Theory t) { return t == Theory::timoshenko ? "timoshenko" : "euler-bernoulli"; }

double RingSpec::kappa() const {
  if (shear_coefficient > 0.0) return shear_coefficient;
  switch (section.shape) {
    case Section::Shape::rectangle: return 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
    case Section::Shape::circle: return 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    case Section::Shape::general: return 0.0;
  }
  return 0.0;
}

std::vector<std::string> Loads::beyond_one_point(const std::string& section) const {
  std::vector<std::string> keys;
  if (points.size() > 1) keys.push_back(section + ".loads");
  if (pressure.any()) keys.push_back(section + ".pressure");
  if (has_gravity()) keys.push_back(section + ".gravity");
  return keys;
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

std::string to_string(CalculixOptions::Element e) {
  switch (e) {
    case CalculixOptions::Element::b31: return "B31";
    case CalculixOptions::Element::b32r: return "B32R";
    case CalculixOptions::Element::b32: return "B32";
  }
  return "";
}
std::string to_string(CalculixOptions::Section s) {
  return s == CalculixOptions::Section::as_given ? "as-given" : "equivalent-rectangle";
}

}  // namespace ring
