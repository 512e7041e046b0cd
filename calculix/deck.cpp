#include "calculix/deck.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <sstream>

#include "ring/errors.hpp"

namespace calculix {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The roller's condition: the displacement of its node along `normal` is zero, where
/// `normal` is normal to the line through the pin and the roller.
struct RollerLine {
  double nx = 0.0, ny = 0.0;
};

RollerLine roller_line(const ring::RingSpec& spec) {
  const double p = *spec.supports.pin * kPi / 180.0, q = *spec.supports.roller * kPi / 180.0;
  const double dx = std::cos(q) - std::cos(p), dy = std::sin(q) - std::sin(p);
  const double len = std::hypot(dx, dy);
  return {-dy / len, dx / len};
}

/// The node (0-based) at `angle`, or -1.
int node_at(const std::vector<double>& angles, double angle) {
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double d = ring::wrap_degrees(angles[k] - angle);
    if (std::min(d, 360.0 - d) < 1e-9) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

std::string number(double x) {
  if (x == 0.0) return "0.0";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.13e", x);  // "-1.2345678901234e-15": 20 characters
  if (std::strlen(buf) > 20) std::snprintf(buf, sizeof buf, "%.12e", x);  // a three-digit exponent
  return buf;
}

int node_count(const ring::CalculixOptions& o) {
  return o.element == ring::CalculixOptions::Element::b31 ? o.elements : 2 * o.elements;
}

void check_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o) {
  // Further pins, a clamp (a rotation condition: see deck.hpp), springs, point masses and
  // the foundation are not written yet: refused by name, not left out.
  const std::vector<std::string> terms = spec.terms_beyond_paper();
  if (!terms.empty()) {
    std::string list;
    for (std::size_t i = 0; i < terms.size(); ++i) list += (i ? ", " : "") + terms[i];
    throw ring::InputError("", terms.front(), "the calculix deck does not write " + list + " yet (pin and roller only)");
  }
  if (o.section == ring::CalculixOptions::Section::as_given && spec.section.shape == ring::Section::Shape::general)
    throw ring::InputError("", "calculix.section",
                           "\"as-given\" needs a circle or a rectangle; a section given by {area, inertia} has no "
                           "shape for ccx to expand (use \"equivalent-rectangle\")");
  if (spec.supports.roller) {
    const double step = 360.0 / node_count(o);
    const double off = ring::wrap_degrees(*spec.supports.roller - *spec.supports.pin) / step;
    if (std::abs(off - std::round(off)) > 1e-9)
      throw ring::InputError("", "supports.roller",
                             "angle is not a node of the calculix model (calculix.elements = " +
                                 std::to_string(o.elements) + " puts nodes every " + number(step) +
                                 " degrees from the pin)");
  }
}

namespace {

/// Everything but the step: heading, nodes, elements, material, section, supports.
Deck model_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const std::string& title,
                const std::string& analysis) {
  check_deck(spec, o);
  using Element = ring::CalculixOptions::Element;
  Deck d;
  const int nodes = node_count(o);
  d.anchor = spec.supports.pin.value_or(0.0);
  d.node_angles = ring::node_angles(spec, nodes, 0.0);
  const bool circle = o.section == ring::CalculixOptions::Section::as_given &&
                      spec.section.shape == ring::Section::Shape::circle;
  if (o.section == ring::CalculixOptions::Section::equivalent_rectangle) {
    d.height = std::sqrt(12.0 * spec.I() / spec.A());
    d.width = spec.A() / d.height;
  } else if (circle) {
    d.width = d.height = spec.section.diameter;
  } else {
    d.width = spec.section.width;
    d.height = spec.section.height;
  }
  const std::string type = ring::to_string(o.element);

  std::ostringstream s;
  s << "** CalculiX deck written by ringvib (calculix/deck.cpp)" << (title.empty() ? "" : ": " + title) << "\n"
    << "** " << analysis << " of a circular ring: " << o.elements << " " << type << " beam elements, which ccx\n"
    << "** expands into " << (o.element == Element::b31 ? "8" : "20") << "-node bricks of the section's shape.\n"
    << "** Units SI (m, kg, s, N, Pa); frequencies in the .dat file in rad/s and cycles/s.\n"
    << "*HEADING\n"
    << (title.empty() ? std::string("ringvib ring") : title.substr(0, 70)) << "\n";

  s << "** Nodes on the centroid circle, R = " << number(spec.radius) << " m: node k + 1 at polar angle\n"
    << "** " << number(d.anchor) << " + 360 k / " << nodes << " degrees, counter-clockwise from +x"
    << (spec.supports.pin ? " (node 1 is the pin)" : "") << ".\n"
    << "*NODE, NSET=NALL\n";
  for (int k = 0; k < nodes; ++k) {
    const double a = d.node_angles[k] * kPi / 180.0;
    s << k + 1 << ", " << number(spec.radius * std::cos(a)) << ", " << number(spec.radius * std::sin(a)) << ", 0.0\n";
  }

  s << "** Elements: " << (o.element == Element::b31 ? "two nodes each" : "end, middle, end node")
    << ", closing the ring.\n"
    << "*ELEMENT, TYPE=" << type << ", ELSET=ERING\n";
  for (int e = 0; e < o.elements; ++e) {
    if (o.element == Element::b31)
      s << e + 1 << ", " << e + 1 << ", " << (e + 1) % nodes + 1 << "\n";
    else
      s << e + 1 << ", " << 2 * e + 1 << ", " << 2 * e + 2 << ", " << (2 * e + 2) % nodes + 1 << "\n";
  }

  s << "** Material: Poisson's ratio 0 (the ring has none; the section then keeps its shape, and the\n"
    << "** bricks act as a beam with shear modulus E/2 and the section's rotary inertia).\n"
    << "*MATERIAL, NAME=RING\n*ELASTIC\n"
    << number(spec.E) << ", 0.0\n*DENSITY\n" << number(spec.rho) << "\n";

  s << "** Section: the 1-direction is normal to the ring's plane (0, 0, 1), so the 2-direction is\n"
    << "** radial and in-plane bending uses the radial height.\n";
  if (circle) {
    s << "** As given: the circle, diameter " << number(d.width) << " m (ccx's expansion of a circle is not exact).\n"
      << "*BEAM SECTION, ELSET=ERING, MATERIAL=RING, SECTION=CIRC\n"
      << number(d.width) << ", " << number(d.width) << "\n";
  } else {
    if (o.section == ring::CalculixOptions::Section::equivalent_rectangle)
      s << "** Equivalent rectangle: A = " << number(spec.A()) << " m^2 and I = " << number(spec.I())
        << " m^4 of the ring's section;\n** width A/h, radial height h = sqrt(12 I/A).\n";
    else
      s << "** As given: the rectangle, width (normal to the plane) x height (radial).\n";
    s << "*BEAM SECTION, ELSET=ERING, MATERIAL=RING, SECTION=RECT\n"
      << number(d.width) << ", " << number(d.height) << "\n";
  }
  s << "0.0, 0.0, 1.0\n";

  s << "** In-plane motion only: the out-of-plane displacement of every beam node is held.\n"
    << "*BOUNDARY\nNALL, 3, 3\n";
  if (spec.supports.pin) {
    s << "** Pin at " << number(*spec.supports.pin) << " degrees: both displacements of node 1 held, rotation free.\n"
      << "*BOUNDARY\n1, 1, 2\n";
  }
  if (spec.supports.roller) {
    const int k = node_at(d.node_angles, *spec.supports.roller) + 1;
    const RollerLine n = roller_line(spec);
    s << "** Roller at " << number(*spec.supports.roller) << " degrees (node " << k
      << "): it stays on the line through the pin and itself,\n"
      << "** its displacement along the line's normal (" << number(n.nx) << ", " << number(n.ny) << ") held.\n";
    if (std::abs(n.nx) < 1e-12 || std::abs(n.ny) < 1e-12) {
      s << "*BOUNDARY\n" << k << ", " << (std::abs(n.nx) < 1e-12 ? 2 : 1) << ", " << (std::abs(n.nx) < 1e-12 ? 2 : 1)
        << "\n";
    } else {
      // The first term is the dependent one: the larger coefficient.
      const bool x_first = std::abs(n.nx) >= std::abs(n.ny);
      s << "*EQUATION\n2\n"
        << k << ", " << (x_first ? 1 : 2) << ", " << number(x_first ? n.nx : n.ny) << ", " << k << ", "
        << (x_first ? 2 : 1) << ", " << number(x_first ? n.ny : n.nx) << "\n";
    }
  }

  d.text = s.str();
  return d;
}

}  // namespace

Deck frequency_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const FrequencyStep& step,
                    const std::string& title) {
  Deck d = model_deck(spec, o, title, "In-plane vibration");
  std::ostringstream s;
  s << "** Step: the " << step.eigenvalues << " lowest eigenvalues (in-plane, rigid and out-of-plane modes\n"
    << "** together; ringvib keeps the in-plane ones). Displacements of the beam nodes go to the\n"
    << "** .dat file (NODE PRINT), those of the expanded bricks to the .frd file (for cgx).\n"
    << "*STEP\n*FREQUENCY\n" << step.eigenvalues << "\n"
    << "*NODE PRINT, NSET=NALL\nU\n*NODE FILE\nU\n*END STEP\n";
  d.text += s.str();
  return d;
}

namespace {

/// The *CLOAD blocks of the point loads (`keyword`: "*CLOAD" or "*CLOAD, AMPLITUDE=LOAD"),
/// each at its node, in N; pressure and gravity are refused (the deck writes no distributed load
/// yet). Throws InputError naming `section`'s key.
std::string point_loads(const Deck& d, const ring::Loads& loads, const std::string& section, const char* keyword) {
  const char* why = "the calculix deck writes point loads only (no distributed load yet)";
  if (loads.pressure.any()) throw ring::InputError("", section + ".pressure", why);
  if (loads.has_gravity()) throw ring::InputError("", section + ".gravity", why);
  std::ostringstream s;
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const ring::PointLoad& p = loads.points[i];
    const int node = node_at(d.node_angles, p.angle);
    const std::string key = loads.points.size() == 1 ? section + ".at" : section + ".loads[" + std::to_string(i + 1) + "].at";
    if (node < 0) throw ring::InputError("", key, "angle " + number(p.angle) + " is not a node of the calculix model");
    s << "** The load at " << number(p.angle) << " degrees (node " << node + 1 << "): (Fx, Fy) in N.\n" << keyword << "\n";
    if (p.force[0] != 0.0) s << node + 1 << ", 1, " << number(p.force[0]) << "\n";
    if (p.force[1] != 0.0) s << node + 1 << ", 2, " << number(p.force[1]) << "\n";
    if (p.force[0] == 0.0 && p.force[1] == 0.0) s << node + 1 << ", 1, 0.0\n";
  }
  return s.str();
}

}  // namespace

Deck response_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const ring::ResponseOptions& rs,
                   const std::string& title) {
  check_response_deck(rs);
  Deck d = model_deck(spec, o, title, "Forced nonlinear response");
  const std::string cloads = point_loads(d, rs.loads, "response", "*CLOAD, AMPLITUDE=LOAD");
  std::vector<int> record;
  for (double a : rs.record) {
    const int k = node_at(d.node_angles, a);
    if (k < 0) throw ring::InputError("", "response.record", "angle " + number(a) + " is not a node of the calculix model");
    record.push_back(k);
  }
  std::ostringstream s;
  s << "** The recorded points (response.record), printed after every increment.\n*NSET, NSET=NREC\n";
  for (std::size_t i = 0; i < record.size(); ++i) s << record[i] + 1 << (i + 1 < record.size() ? ", " : "\n");
  // The load factor in time: exact for step and ramp (piecewise linear), sampled at every
  // time step for the half-sine and the harmonic (ccx interpolates linearly in between).
  s << "** Load factor in time (response.history = " << ring::to_string(rs.history.kind) << ", period "
    << number(rs.history.period) << " s): time, factor.\n*AMPLITUDE, NAME=LOAD\n";
  const auto& h = rs.history;
  const long steps = std::lround(std::ceil(rs.t_end / rs.dt - 1e-9));
  if (h.kind == ring::LoadHistory::Kind::step) {
    s << "0.0, 1.0\n" << number(rs.t_end * 2.0) << ", 1.0\n";
  } else if (h.kind == ring::LoadHistory::Kind::ramp) {
    s << "0.0, 0.0\n" << number(h.period) << ", 1.0\n" << number(std::max(rs.t_end, h.period) * 2.0) << ", 1.0\n";
  } else {
    for (long k = 0; k <= steps; ++k) {
      const double t = std::min(k * rs.dt, rs.t_end);
      s << number(t) << ", " << number(h.factor(t)) << "\n";
    }
  }
  s << "** Step: geometrically nonlinear dynamics (NLGEOM) from rest, fixed time step dt = " << number(rs.dt)
    << " s\n** to t_end = " << number(rs.t_end) << " s; ALPHA = 0: Newmark's average acceleration.\n"
    << "*STEP, NLGEOM, INC=" << steps + 10 << "\n*DYNAMIC, DIRECT, ALPHA=0.0\n"
    << number(rs.dt) << ", " << number(rs.t_end) << "\n"
    << "** The loads, times the factor LOAD.\n" << cloads;
  s << "*NODE PRINT, NSET=NREC\nU\n*END STEP\n";
  d.text += s.str();
  return d;
}

void check_response_deck(const ring::ResponseOptions& rs) {
  if (rs.integrator != ring::ResponseOptions::Integrator::newmark)
    throw ring::InputError("", "response.integrator",
                           "the calculix deck writes Newmark's average acceleration (ccx's *DYNAMIC with ALPHA = 0): "
                           "\"newmark\" only");
  if (rs.rayleigh_mass != 0.0 || rs.rayleigh_stiffness != 0.0)
    throw ring::InputError("", rs.rayleigh_mass != 0.0 ? "response.rayleigh_mass" : "response.rayleigh_stiffness",
                           "the calculix deck writes no damping");
  if (rs.hinge_damping != 0.0)
    throw ring::InputError("", "response.hinge_damping", "the calculix deck writes no damping");
}

Deck static_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const ring::StaticOptions& st,
                 const std::string& title) {
  Deck d = model_deck(spec, o, title, "Nonlinear statics");
  const std::string cloads = point_loads(d, st.loads, "static", "*CLOAD");
  const double inc = 1.0 / st.steps;
  std::ostringstream s;
  s << "** Step: geometrically nonlinear statics (NLGEOM) under the dead point loads, in load\n"
    << "** increments of 1/" << st.steps << " (static.steps; ccx may cut them, down to 1e-5 of that).\n"
    << "*STEP, NLGEOM, INC=" << std::max(1000, 20 * st.steps) << "\n*STATIC\n"
    << number(inc) << ", 1.0, " << number(1e-5 * inc) << ", " << number(inc) << "\n"
    << cloads;
  s << "** Displacements of the beam nodes after every increment, to the .dat file.\n"
    << "*NODE PRINT, NSET=NALL\nU\n*END STEP\n";
  d.text += s.str();
  return d;
}

}  // namespace calculix
