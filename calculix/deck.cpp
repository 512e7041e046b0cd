#include "calculix/deck.hpp"

#include <array>
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

namespace {

/// The equal pieces between nodes: elements (B31) or 2 elements (B32, B32R: a middle node).
int pieces(const ring::CalculixOptions& o) {
  return o.element == ring::CalculixOptions::Element::b31 ? o.elements : 2 * o.elements;
}

}  // namespace

int node_count(const ring::CalculixOptions& o) { return pieces(o); }

int node_count(const ring::RingSpec& spec, const ring::CalculixOptions& o) { return ring::node_count(spec, pieces(o)); }

namespace {

/// What the deck refuses whatever the nodes: see check_deck.
void check_refusals(const ring::RingSpec& spec, const ring::CalculixOptions& o, Inertia inertia) {
  // What ccx cannot express on an expanded beam (measured with ccx 2.20, calculix/README.md):
  // a rotational spring (a SPRING1 on degree of freedom 6 of a beam node is accepted and
  // silently does nothing: the node's rotation is no degree of freedom unless a knot is
  // made) and the rotary inertia of a point mass (ccx has *MASS, no *ROTARY INERTIA).
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i)
    if (spec.supports.springs[i].kr != 0.0)
      throw ring::InputError("", "supports.springs[" + std::to_string(i + 1) + "].kr",
                             "the calculix deck cannot write a rotational spring: ccx's spring elements act on the "
                             "displacements of the expanded beam's node, and a SPRING1 on its rotation (degree of "
                             "freedom 6) is silently ignored; give kr = 0 or leave calculix out");
  if (inertia == Inertia::matters)
    for (std::size_t i = 0; i < spec.masses.size(); ++i)
      if (spec.masses[i].inertia != 0.0)
        throw ring::InputError("", "masses[" + std::to_string(i + 1) + "].inertia",
                               "the calculix deck cannot write a point mass's rotary inertia: ccx 2.20 has *MASS "
                               "elements (translation only) and no *ROTARY INERTIA; give inertia = 0 or leave "
                               "calculix out of modes and responses (statics does not need it)");
  // The resultant law (moment against curvature) has no place on ccx's expanded beam, whose
  // material is a 3-D continuum: only a stress–strain law (*PLASTIC) could be written. Only
  // the statics take the law (a static deck ignores inertia); the modes at rest are elastic.
  if (inertia == Inertia::ignored && spec.plastic && spec.plastic->law == ring::Plastic::Law::resultant)
    throw ring::InputError("", "ring.plastic.moment",
                           "the calculix deck cannot write the resultant plastic law: ccx expands the beam into "
                           "bricks whose material takes a stress-strain law (*PLASTIC), not a moment against "
                           "curvature; leave calculix out of a plastic scene");
  if (o.section == ring::CalculixOptions::Section::as_given && spec.section.shape == ring::Section::Shape::general)
    throw ring::InputError("", "calculix.section",
                           "\"as-given\" needs a circle or a rectangle; a section given by {area, inertia} has no "
                           "shape for ccx to expand (use \"equivalent-rectangle\")");
}

/// Every point term on a node: a ring's nodes every 360/nodes degrees from spec.anchor(), an
/// arch's every span/pieces degrees from its `from` end to its `to` end.
void check_points(const ring::RingSpec& spec, const ring::CalculixOptions& o) {
  // Every point term on a node of the model (the scene reader checks this for every model;
  // the deck checks it again for callers without a scene).
  const double step = (spec.arc ? spec.arc->span() : 360.0) / pieces(o), anchor = spec.anchor();
  auto need_node = [&](double angle, const std::string& key) {
    if (spec.arc && !spec.arc->contains(angle))
      throw ring::InputError("", key,
                             "angle " + number(angle) + " lies outside the arch (ring.arc = [" +
                                 number(spec.arc->from) + ", " + number(spec.arc->to) + "])");
    if (!ring::on_node(spec, angle, pieces(o)))
      throw ring::InputError("", key,
                             "angle is not a node of the calculix model (calculix.elements = " +
                                 std::to_string(o.elements) + " puts nodes every " + number(step) + " degrees from " +
                                 (spec.arc ? "the arch's end " + number(anchor)
                                           : spec.supports.pin ? std::string("the pin") : number(anchor)) + ")");
  };
  if (spec.supports.roller) need_node(*spec.supports.roller, "supports.roller");
  if (spec.supports.clamp) need_node(*spec.supports.clamp, "supports.clamp");  // before pins, which hold it too
  for (double p : spec.supports.pins) need_node(p, "supports.pins");
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i)
    need_node(spec.supports.springs[i].angle, "supports.springs[" + std::to_string(i + 1) + "].at");
  for (std::size_t i = 0; i < spec.masses.size(); ++i)
    need_node(spec.masses[i].angle, "masses[" + std::to_string(i + 1) + "].at");
}

}  // namespace

void check_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, Inertia inertia) {
  ring::refuse_variations(spec, "the calculix column");
  check_refusals(spec, o, inertia);
  check_points(spec, o);
}

namespace {

/// The share of the ring's length at each node (m): B31 the element length L, B32/B32R
/// the quadratic element's consistent weights (an end node L/3, a middle node 2L/3). An
/// arch's two end nodes belong to one element only: half of that (B31 L/2, B32/B32R L/6).
std::vector<double> node_shares(const ring::RingSpec& spec, const ring::CalculixOptions& o) {
  const double L = spec.length() / o.elements;
  const bool quadratic = o.element != ring::CalculixOptions::Element::b31;
  std::vector<double> w(node_count(spec, o));
  for (std::size_t k = 0; k < w.size(); ++k) w[k] = quadratic ? (k % 2 ? 2.0 * L / 3.0 : L / 3.0) : L;
  if (spec.arc) {
    w.front() *= 0.5;
    w.back() *= 0.5;
  }
  return w;
}

/// The fibre law (ring.plastic.stress) as ccx's von Mises plasticity of the bricks: the
/// bilinear uniaxial law sigma = sigma_y + H eps_p, H = h E / (1 - h), as its table of the
/// yield stress against the equivalent plastic strain (two rows reaching a plastic strain of
/// 10, far past any ring's; one row, perfectly plastic, for h = 0). The rule: kinematic
/// (HARDENING=KINEMATIC, Prager's linear kinematic hardening) or isotropic (ccx's default).
std::string plastic_block(const ring::RingSpec& spec) {
  const ring::Plastic& p = *spec.plastic;
  const bool kinematic = p.rule == ring::Plastic::Rule::kinematic;
  const double H = p.hardening * spec.E / (1.0 - p.hardening), reach = 10.0;
  std::ostringstream s;
  s << "** The fibre law: von Mises plasticity, yield stress sigma_y = " << number(p.stress) << " Pa, "
    << (p.hardening == 0.0 ? std::string("perfectly plastic")
                           : "hardening modulus H = h E / (1 - h) = " + number(H) + " Pa (h = " + number(p.hardening) +
                                 ")")
    << ",\n** " << (kinematic ? "kinematic" : "isotropic")
    << " rule; rows: yield stress (Pa), equivalent plastic strain. The bricks integrate it at\n"
    << "** their points through the depth (B32R: 5, B31: 2, B32: 3), not over the section's fibres.\n"
    << (kinematic ? "*PLASTIC, HARDENING=KINEMATIC\n" : "*PLASTIC\n") << number(p.stress) << ", 0.0\n";
  if (p.hardening > 0.0) s << number(p.stress + H * reach) << ", " << number(reach) << "\n";
  return s.str();
}

/// Everything but the step: heading, nodes, elements, material, section, supports.
/// `dynamic`: the step has inertia (frequency, response), so the point masses are written
/// as MASS elements; a static deck leaves them out (their weight is a load).
/// `loads_on_nodes`: the step loads nodes beyond the paper's point loads (dead pressure,
/// the masses' weight).
Deck model_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const std::string& title,
                const std::string& analysis, bool dynamic, bool loads_on_nodes = false) {
  check_refusals(spec, o, dynamic ? Inertia::matters : Inertia::ignored);
  check_points(spec, o);
  using Element = ring::CalculixOptions::Element;
  Deck d;
  const bool fibre = !dynamic && spec.plastic && spec.plastic->law == ring::Plastic::Law::fibre;
  const bool wants_width_rigid = !spec.supports.springs.empty() || spec.foundation.any() ||
                                 (dynamic && !spec.masses.empty()) || loads_on_nodes;
  // ccx 2.20 stops a beam section whose material is orthotropic with *PLASTIC ("*ERROR
  // reading *BEAM SECTION: nonexistent material": it renames such a material for its
  // anisotropic plasticity; a *SOLID SECTION takes it): the fibre law keeps the isotropic
  // material, and the section's bending across its width with it (calculix/README.md).
  const bool width_rigid = wants_width_rigid && !fibre;
  const int nodes = node_count(spec, o);
  d.anchor = spec.anchor();
  d.node_angles = ring::node_angles(spec, pieces(o));
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
    << "** " << analysis << " of a circular " << (spec.arc ? "arch" : "ring") << ": " << o.elements << " " << type
    << " beam elements, which ccx\n"
    << "** expands into " << (o.element == Element::b31 ? "8" : "20") << "-node bricks of the section's shape.\n"
    << "** Units SI (m, kg, s, N, Pa); frequencies in the .dat file in rad/s and cycles/s.\n"
    << "*HEADING\n"
    << (title.empty() ? std::string("ringvib ring") : title.substr(0, 70)) << "\n";

  if (spec.arc)
    s << "** Nodes on the centroid circle, R = " << number(spec.radius) << " m: node k + 1 at polar angle\n"
      << "** " << number(spec.arc->from) << " + " << number(spec.arc->span()) << " k / " << pieces(o)
      << " degrees, k = 0.." << pieces(o) << ", counter-clockwise from +x: the arch from node 1 to node " << nodes
      << ".\n"
      << "*NODE, NSET=NALL\n";
  else
    s << "** Nodes on the centroid circle, R = " << number(spec.radius) << " m: node k + 1 at polar angle\n"
      << "** " << number(d.anchor) << " + 360 k / " << nodes << " degrees, counter-clockwise from +x"
      << (spec.supports.pin ? " (node 1 is the pin)" : "") << ".\n"
      << "*NODE, NSET=NALL\n";
  for (int k = 0; k < nodes; ++k) {
    const double a = d.node_angles[k] * kPi / 180.0;
    s << k + 1 << ", " << number(spec.radius * std::cos(a)) << ", " << number(spec.radius * std::sin(a)) << ", 0.0\n";
  }

  s << "** Elements: " << (o.element == Element::b31 ? "two nodes each" : "end, middle, end node")
    << (spec.arc ? ", an open line from end to end.\n" : ", closing the ring.\n")
    << "*ELEMENT, TYPE=" << type << ", ELSET=ERING\n";
  // Modulo nodes: the ring's last element closes on node 1; an arch has one node more than it
  // has pieces, so its last element ends on the last node.
  for (int e = 0; e < o.elements; ++e) {
    if (o.element == Element::b31)
      s << e + 1 << ", " << e + 1 << ", " << (e + 1) % nodes + 1 << "\n";
    else
      s << e + 1 << ", " << 2 * e + 1 << ", " << 2 * e + 2 << ", " << (2 * e + 2) % nodes + 1 << "\n";
  }

  s << "** Material: Poisson's ratio 0 (the ring has none; the section then keeps its shape, and the\n"
    << "** bricks act as a beam with shear modulus E/2 and the section's rotary inertia).\n"
    << "*MATERIAL, NAME=RING\n";
  if (width_rigid) {
    // Springs, masses and nodal loads act on a beam node, which ccx ties to the corners of
    // the expanded section; the section's midside nodes then carry their share through
    // the plate bending of the section across its width (z), which a beam has not: with an
    // isotropic material a tyre belt (width/height 19) on its foundation had its lowest
    // frequencies 0.3-0.6 % low at any element count. E_z = 1e4 E removes it (to 6e-6
    // against 1e3 E) and changes no in-plane stress: with Poisson's ratio 0 the in-plane
    // stresses never involve E_z (measured: the free ring's frequencies agree to 7 digits).
    s << "** The section made rigid across its width (E_z = 1e4 E): springs, masses and loads hang on\n"
      << "** the corners of the expanded section, and a beam's section does not bend across its width.\n"
      << "** E_x, E_y, E_z, nu_xy, nu_xz, nu_yz, G_xy, G_xz / G_yz.\n"
      << "*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
      << number(spec.E) << ", " << number(spec.E) << ", " << number(1e4 * spec.E) << ", 0.0, 0.0, 0.0, "
      << number(spec.E / 2.0) << ", " << number(spec.E / 2.0) << "\n"
      << number(spec.E / 2.0) << "\n";
  } else {
    if (wants_width_rigid)
      s << "** Isotropic although springs or loads hang on the section's corners: ccx 2.20 refuses a beam\n"
        << "** section of an orthotropic material with *PLASTIC (the section may bend across its width).\n";
    s << "*ELASTIC\n" << number(spec.E) << ", 0.0\n";
  }
  if (fibre) s << plastic_block(spec);
  s << "*DENSITY\n" << number(spec.rho) << "\n";

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

  // A MASS element on a node whose out-of-plane displacement is a *BOUNDARY stops ccx 2.20's
  // frequency step ("add_bo_st: coefficient should be 0": the mass couples the held degree
  // of freedom, for which the matrix has no place); a one-term *EQUATION holds it as well.
  std::vector<int> mass_nodes;
  if (dynamic)
    for (const auto& m : spec.masses) mass_nodes.push_back(node_at(d.node_angles, m.angle) + 1);
  if (mass_nodes.empty()) {
    s << "** In-plane motion only: the out-of-plane displacement of every beam node is held.\n"
      << "*BOUNDARY\nNALL, 3, 3\n";
  } else {
    s << "** In-plane motion only: the out-of-plane displacement of every beam node is held, by *BOUNDARY\n"
      << "** on NPLANE and, at the point masses' nodes, by one-term equations (a MASS element beside a\n"
      << "** held degree of freedom stops ccx 2.20's frequency step).\n"
      << "*NSET, NSET=NPLANE, GENERATE\n";
    std::vector<int> sorted = mass_nodes;
    std::sort(sorted.begin(), sorted.end());
    int first = 1;
    for (int k : sorted) {
      if (k > first) s << first << ", " << k - 1 << ", 1\n";
      first = std::max(first, k + 1);
    }
    if (first <= nodes) s << first << ", " << nodes << ", 1\n";
    s << "*BOUNDARY\nNPLANE, 3, 3\n";
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    for (int k : sorted) s << "*EQUATION\n1\n" << k << ", 3, 1.0\n";
  }
  // Held displacements first..last of node k: *BOUNDARY, or at a point mass's node one-term
  // *EQUATIONs.
  auto hold = [&](int k, int first, int last) {
    if (std::find(mass_nodes.begin(), mass_nodes.end(), k) == mass_nodes.end())
      s << "*BOUNDARY\n" << k << ", " << first << ", " << last << "\n";
    else
      for (int dof = first; dof <= last; ++dof) s << "*EQUATION\n1\n" << k << ", " << dof << ", 1.0\n";
  };
  const std::vector<double> pinned = spec.supports.pinned();
  for (std::size_t i = 0; i < pinned.size(); ++i) {
    const int k = node_at(d.node_angles, pinned[i]) + 1;
    s << "** Pin at " << number(pinned[i]) << " degrees: both displacements of node " << k << " held"
      << (spec.supports.clamp && node_at(d.node_angles, *spec.supports.clamp) + 1 == k ? "" : ", rotation free")
      << ".\n";
    hold(k, 1, 2);
  }
  if (spec.supports.clamp) {
    // The rotation about z of the beam node: ccx makes the node a knot (the expanded section
    // a rigid body turning with it) in a frequency or dynamic step, and a mean-rotation
    // constraint of the section in a static one. Checked against the FE reference for B31,
    // B32 and B32R (tests/calculix/calculix_terms_test.cpp).
    const int k = node_at(d.node_angles, *spec.supports.clamp) + 1;
    s << "** Clamp at " << number(*spec.supports.clamp) << " degrees: the rotation of node " << k
      << " (about z, degree of freedom 6) held too.\n*BOUNDARY\n" << k << ", 6, 6\n";
  }
  if (spec.supports.roller) {
    const int k = node_at(d.node_angles, *spec.supports.roller) + 1;
    const RollerLine n = roller_line(spec);
    s << "** Roller at " << number(*spec.supports.roller) << " degrees (node " << k
      << "): it stays on the line through the pin and itself,\n"
      << "** its displacement along the line's normal (" << number(n.nx) << ", " << number(n.ny) << ") held.\n";
    if (std::abs(n.nx) < 1e-12 || std::abs(n.ny) < 1e-12) {
      const int dof = std::abs(n.nx) < 1e-12 ? 2 : 1;
      hold(k, dof, dof);
    } else {
      // The first term is the dependent one: the larger coefficient.
      const bool x_first = std::abs(n.nx) >= std::abs(n.ny);
      s << "*EQUATION\n2\n"
        << k << ", " << (x_first ? 1 : 2) << ", " << number(x_first ? n.nx : n.ny) << ", " << k << ", "
        << (x_first ? 2 : 1) << ", " << number(x_first ? n.ny : n.nx) << "\n";
    }
  }

  int element = o.elements;  // the beam elements are 1..elements; springs and masses follow
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i) {
    const ring::Spring& k = spec.supports.springs[i];
    const int node = node_at(d.node_angles, k.angle) + 1;
    s << "** Elastic support " << i + 1 << " at " << number(k.angle) << " degrees (node " << node
      << "): springs to the ground in x and y (N/m), SPRING1 on the node's displacement.\n";
    for (int dof : {1, 2}) {
      const double stiffness = dof == 1 ? k.kx : k.ky;
      if (stiffness == 0.0) continue;
      const std::string set = "ESPRING" + std::to_string(i + 1) + (dof == 1 ? "X" : "Y");
      s << "*ELEMENT, TYPE=SPRING1, ELSET=" << set << "\n" << ++element << ", " << node << "\n"
        << "*SPRING, ELSET=" << set << "\n" << dof << "\n" << number(stiffness) << "\n";
    }
  }
  if (dynamic) {
    for (std::size_t i = 0; i < spec.masses.size(); ++i) {
      const ring::PointMass& m = spec.masses[i];
      const std::string set = "EMASS" + std::to_string(i + 1);
      s << "** Point mass " << i + 1 << " at " << number(m.angle) << " degrees (node " << mass_nodes[i]
        << "): " << number(m.mass) << " kg, no rotary inertia (ccx has none).\n"
        << "*ELEMENT, TYPE=MASS, ELSET=" << set << "\n" << ++element << ", " << mass_nodes[i] << "\n"
        << "*MASS, ELSET=" << set << "\n" << number(m.mass) << "\n";
    }
  }
  if (spec.foundation.any()) {
    // A spring at every node, its stiffness the modulus times the node's share of the ring:
    // B31 the element length L; B32/B32R the quadratic element's consistent weights L/6,
    // 2L/3, L/6 (an end node L/3, shared by two elements). The springs act in the cylindrical
    // system about the ring's axis, fixed radial and tangential directions of each node's
    // undeformed position (SPRING1 keeps its direction under NLGEOM).
    const double L = spec.length() / o.elements;
    const bool quadratic = o.element != Element::b31;
    const std::vector<double> shares = node_shares(spec, o);
    // An arch's two end nodes carry half an end node's share: a set of their own (TIP), the
    // END set then starts at the next element end (node index 1 for B31, 2 for B32/B32R) and
    // stops before the last node.
    const int step = quadratic ? 2 : 1;
    const int first = spec.arc ? step : 0, last = spec.arc ? nodes - 1 : nodes;
    s << "** Winkler foundation: radial " << number(spec.foundation.radial) << " and tangential "
      << number(spec.foundation.tangential) << " N/m per metre of ring, a spring at every node\n"
      << "** times its share of the ring (" << (quadratic ? "end nodes L/3, middle nodes 2L/3" : "L")
      << (spec.arc ? ", the arch's two ends half an end node's" : "") << ", L = " << number(L) << " m), in the\n"
      << "** cylindrical system about z: degree of freedom 1 radial, 2 tangential, of the undeformed node.\n"
      << "*ORIENTATION, NAME=CYLINDER, SYSTEM=CYLINDRICAL\n0.0, 0.0, 0.0, 0.0, 0.0, 1.0\n";
    for (int dof : {1, 2}) {
      const double modulus = dof == 1 ? spec.foundation.radial : spec.foundation.tangential;
      if (modulus == 0.0) continue;
      for (int middle : quadratic ? std::vector<int>{0, 1} : std::vector<int>{0}) {
        const std::string set = std::string("EFOUND") + (dof == 1 ? "R" : "T") + (middle ? "MID" : "END");
        const int from = middle ? 1 : first;
        if (from >= last) continue;  // an arch of one element has no inner end node
        s << "*ELEMENT, TYPE=SPRING1, ELSET=" << set << "\n";
        for (int k = from; k < last; k += step) s << ++element << ", " << k + 1 << "\n";
        s << "*SPRING, ELSET=" << set << ", ORIENTATION=CYLINDER\n" << dof << "\n"
          << number(modulus * shares[from]) << "\n";
      }
      if (spec.arc) {
        const std::string set = std::string("EFOUND") + (dof == 1 ? "R" : "T") + "TIP";
        s << "*ELEMENT, TYPE=SPRING1, ELSET=" << set << "\n"
          << ++element << ", 1\n" << ++element << ", " << nodes << "\n"
          << "*SPRING, ELSET=" << set << ", ORIENTATION=CYLINDER\n" << dof << "\n"
          << number(modulus * shares.front()) << "\n";
      }
    }
  }

  d.text = s.str();
  d.last_element = element;
  return d;
}

}  // namespace

Deck frequency_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const FrequencyStep& step,
                    const std::string& title) {
  Deck d = model_deck(spec, o, title, "In-plane vibration", true);
  std::ostringstream s;
  s << "** Step: the " << step.eigenvalues << " lowest eigenvalues (in-plane, rigid and out-of-plane modes\n"
    << "** together; ringvib keeps the in-plane ones). Displacements of the beam nodes go to the\n"
    << "** .dat file (NODE PRINT), those of the expanded bricks to the .frd file (for cgx).\n"
    << "*STEP\n*FREQUENCY\n" << step.eigenvalues << "\n"
    << "*NODE PRINT, NSET=NALL\nU\n*NODE FILE\nU\n*END STEP\n";
  d.text += s.str();
  return d;
}

void check_spin(const ring::RingSpec& spec, const ring::CalculixOptions& o) {
  ring::refuse_variations(spec, "the calculix column");
  if (!spec.rotation.spinning()) return;
  if (o.element != ring::CalculixOptions::Element::b32r)
    throw ring::InputError("", "calculix.element",
                           "the calculix deck of a spinning ring takes B32R only: with ccx 2.20, B31 (C3D8I bricks) "
                           "on a foundation gives the spinning ring's k = 1 pair 33 % low already in the real step, "
                           "and B32 gives a Coriolis split 5 % low at any element count (measured, calculix/README.md)");
  if (spec.arc)
    throw ring::InputError("", "ring.arc", "the calculix deck of a spinning ring takes a closed ring, not an arch");
  if (spec.rigid_modes() > 0)
    throw ring::InputError("", "rotation.speed",
                           "a spinning ring with rigid modes: the centrifugal softening makes its free motions "
                           "unstable; hold the ring by supports, springs or a foundation");
  if (o.section == ring::CalculixOptions::Section::as_given && spec.section.shape == ring::Section::Shape::circle)
    throw ring::InputError("", "calculix.section",
                           "the calculix deck of a spinning ring writes its bricks with a rectangular section: use "
                           "\"equivalent-rectangle\" for a circle");
  auto need_end = [&](double angle, const std::string& key) {
    if (!ring::on_node(spec, angle, o.elements))
      throw ring::InputError("", key,
                             "the calculix deck of a spinning ring puts a point term on an element's end (every " +
                                 number(360.0 / o.elements) + " degrees from " + number(spec.anchor()) +
                                 "): its bricks have no node on the centroid line at an element's middle");
  };
  for (double p : spec.supports.pinned())
    need_end(p, spec.supports.clamp && *spec.supports.clamp == p ? "supports.clamp"
                : spec.supports.pin && *spec.supports.pin == p   ? "supports.pin"
                                                                  : "supports.pins");
  if (spec.supports.roller) {
    need_end(*spec.supports.roller, "supports.roller");
    const RollerLine n = roller_line(spec);
    if (!(std::abs(n.nx) < 1e-12 || std::abs(n.ny) < 1e-12))
      throw ring::InputError("", "supports.roller",
                             "the calculix deck of a spinning ring holds a roller by a boundary condition, so its line "
                             "through the pin must lie along x or y (an oblique one needs an *EQUATION, an MPC, under "
                             "which ccx 2.20's Coriolis matrix is wrong)");
  }
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i)
    need_end(spec.supports.springs[i].angle, "supports.springs[" + std::to_string(i + 1) + "].at");
  if (!spec.masses.empty())
    throw ring::InputError("", "masses",
                           "the calculix deck of a spinning ring cannot carry point masses: ccx 2.20 assembles the "
                           "Coriolis matrix (mafillcorio) of solid elements only, so a MASS element would get neither "
                           "the Coriolis term nor the centrifugal softening; leave calculix out or the masses");
}

namespace {

/// The three steps of a spinning ring's modes (spinning_deck's file comment), printing `print`.
std::string spin_steps(const ring::RingSpec& spec, const SpinStep& step, const std::string& print) {
  const double speed = spec.rotation.speed;
  const bool tension = spec.rotation.tension == ring::Rotation::Tension::spin;
  std::ostringstream centrif;
  centrif << "*DLOAD\nERING, CENTRIF, " << number(speed * speed) << ", 0.0, 0.0, 0.0, 0.0, 0.0, "
          << (speed > 0.0 ? "1.0" : "-1.0") << "\n";
  std::ostringstream s;
  s << "** The ring spins at " << number(speed) << " rad/s about z (rotation.speed): the frame turns with it.\n"
    << "** Step 1: the equilibrium under the centrifugal body force (CENTRIF, speed^2, a point on the axis,\n"
    << "** the axis' direction: the sign of the speed)"
    << (tension ? ", NLGEOM: its hoop tension (rotation.tension = \"spin\").\n"
                : ";\n** rotation.tension = \"none\": without the load, so that the next steps perturb the unstressed\n"
                  "** ring (ccx adds the centrifugal softening in a perturbation step only).\n")
    << "*STEP, NLGEOM\n*STATIC\n" << (tension ? centrif.str() : "") << "*END STEP\n"
    << "** Step 2: " << step.eigenvalues << " real modes of the tangent (prestress, softening -speed^2 M), stored\n"
    << "** for step 3.\n"
    << "*STEP, PERTURBATION\n*FREQUENCY, STORAGE=YES\n" << step.eigenvalues << "\n"
    << (tension ? "" : centrif.str()) << "*END STEP\n"
    << "** Step 3: the " << step.complex << " lowest modes with the Coriolis term, in the basis of step 2's modes;\n"
    << "** the real and imaginary parts of " << print << " to the .dat file.\n"
    << "*STEP, PERTURBATION\n*COMPLEX FREQUENCY, CORIOLIS\n" << step.complex << "\n"
    << "*NODE PRINT, NSET=NALL\nU\n*END STEP\n";
  return s.str();
}

}  // namespace

BrickRing spinning_brick_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const SpinStep& step,
                              const std::string& title) {
  check_refusals(spec, o, Inertia::matters);
  BrickRing b;
  Deck& d = b.deck;
  const int turns = 2 * o.elements;  // stations: element ends (even) and middles (odd)
  d.anchor = spec.anchor();
  d.node_angles = ring::node_angles(spec, turns);
  if (o.section == ring::CalculixOptions::Section::equivalent_rectangle) {
    d.height = std::sqrt(12.0 * spec.I() / spec.A());
    d.width = spec.A() / d.height;
  } else {
    d.width = spec.section.width;
    d.height = spec.section.height;
  }
  const double R = spec.radius;
  std::vector<int> id(static_cast<std::size_t>(turns) * 9, 0);
  auto at = [&](int i, int j, int l) -> int& { return id[(static_cast<std::size_t>(i % turns) * 3 + j) * 3 + l]; };
  std::ostringstream s;
  s << "** CalculiX deck written by ringvib (calculix/deck.cpp)" << (title.empty() ? "" : ": " + title) << "\n"
    << "** In-plane vibration of the spinning ring: " << o.elements << " x 1 x 1 C3D20R bricks written by the deck\n"
    << "** (not expanded from beams: no MPC, under which ccx 2.20's Coriolis matrix is wrong).\n"
    << "** Units SI (m, kg, s, N, Pa); frequencies in the .dat file in rad/s and cycles/s.\n"
    << "*HEADING\n" << (title.empty() ? std::string("ringvib ring") : title.substr(0, 70)) << "\n"
    << "** Nodes: station i (polar angle " << number(d.anchor) << " + 360 i / " << turns
    << " degrees), radius R + (j - 1) h/2, z = (l - 1) b/2,\n** j, l = 0..2, at most one of i, j, l odd; R = "
    << number(R) << " m, h = " << number(d.height) << " m (radial), b = " << number(d.width) << " m.\n"
    << "*NODE, NSET=NALL\n";
  int n = 0;
  for (int i = 0; i < turns; ++i)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l) {
        if (i % 2 + j % 2 + l % 2 > 1) continue;
        at(i, j, l) = ++n;
        const double a = d.node_angles[i] * kPi / 180.0, r = R + (j - 1) * d.height / 2.0;
        s << n << ", " << number(r * std::cos(a)) << ", " << number(r * std::sin(a)) << ", "
          << number((l - 1) * d.width / 2.0) << "\n";
      }
  b.nodes = n;
  for (int i = 0; i < turns; ++i)
    b.stations.push_back(i % 2 == 0 ? std::vector<int>{at(i, 1, 0), at(i, 1, 2)}
                                    : std::vector<int>{at(i, 0, 0), at(i, 0, 2), at(i, 2, 0), at(i, 2, 2)});
  // Local xi radial, eta around the ring, zeta across the width (right-handed): the C3D20
  // corners, then the midside nodes of the edges.
  static const int corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  static const int middle[12][3] = {{0, -1, -1}, {1, 0, -1}, {0, 1, -1}, {-1, 0, -1}, {0, -1, 1},  {1, 0, 1},
                                    {0, 1, 1},   {-1, 0, 1}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},   {-1, 1, 0}};
  s << "** Elements: element e spans stations 2e .. 2e + 2 (the last closes the ring).\n"
    << "*ELEMENT, TYPE=C3D20R, ELSET=ERING\n";
  for (int e = 0; e < o.elements; ++e) {
    s << e + 1;
    for (int c = 0; c < 20; ++c) {
      const int* x = c < 8 ? corner[c] : middle[c - 8];
      s << (c == 15 ? ",\n" : ", ") << at(2 * e + 1 + x[1], 1 + x[0], 1 + x[2]);
    }
    s << "\n";
  }
  s << "** Material: Poisson's ratio 0, as the beam deck's.\n*MATERIAL, NAME=RING\n*ELASTIC\n" << number(spec.E)
    << ", 0.0\n*DENSITY\n" << number(spec.rho) << "\n*SOLID SECTION, ELSET=ERING, MATERIAL=RING\n"
    << "** In-plane motion only: the out-of-plane displacement of every node held.\n*BOUNDARY\nNALL, 3, 3\n";
  auto station = [&](double angle) { return ring::node_index(spec, angle, o.elements) * 2; };
  for (double p : spec.supports.pinned()) {
    const int i = station(p);
    const bool clamp = spec.supports.clamp && *spec.supports.clamp == p;
    s << "** " << (clamp ? "Clamp" : "Pin") << " at " << number(p) << " degrees (station " << i << "): "
      << (clamp ? "both displacements of the section's eight nodes held.\n"
                : "both displacements of its two centroid nodes held.\n")
      << "*BOUNDARY\n";
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l)
        if ((j % 2 + l % 2 <= 1) && (clamp ? !(j == 1 && l == 1) : (j == 1 && l != 1)))
          s << at(i, j, l) << ", 1, 2\n";
  }
  if (spec.supports.roller) {
    const int i = station(*spec.supports.roller);
    const RollerLine nl = roller_line(spec);
    const int dof = std::abs(nl.nx) < 1e-12 ? 2 : 1;
    s << "** Roller at " << number(*spec.supports.roller) << " degrees (station " << i
      << "): its two centroid nodes held across the line through the pin.\n*BOUNDARY\n"
      << at(i, 1, 0) << ", " << dof << ", " << dof << "\n" << at(i, 1, 2) << ", " << dof << ", " << dof << "\n";
  }
  int element = o.elements;
  for (std::size_t k = 0; k < spec.supports.springs.size(); ++k) {
    const ring::Spring& sp = spec.supports.springs[k];
    const int i = station(sp.angle);
    s << "** Elastic support " << k + 1 << " at " << number(sp.angle) << " degrees (station " << i
      << "): half of kx and ky on each of its two centroid nodes.\n";
    for (int dof : {1, 2}) {
      const double stiffness = dof == 1 ? sp.kx : sp.ky;
      if (stiffness == 0.0) continue;
      const std::string set = "ESPRING" + std::to_string(k + 1) + (dof == 1 ? "X" : "Y");
      s << "*ELEMENT, TYPE=SPRING1, ELSET=" << set << "\n"
        << ++element << ", " << at(i, 1, 0) << "\n" << ++element << ", " << at(i, 1, 2) << "\n"
        << "*SPRING, ELSET=" << set << "\n" << dof << "\n" << number(stiffness / 2.0) << "\n";
    }
  }
  if (spec.foundation.any()) {
    const double L = spec.length() / o.elements;
    s << "** Winkler foundation: radial " << number(spec.foundation.radial) << " and tangential "
      << number(spec.foundation.tangential) << " N/m per metre of ring: SPRING1 on every station's\n"
      << "** nodes (an end section's two centroid nodes share L/3, a middle's four corners 2L/3: L/6 each,\n"
      << "** L = " << number(L) << " m) in the cylindrical system about z.\n"
      << "*ORIENTATION, NAME=CYLINDER, SYSTEM=CYLINDRICAL\n0.0, 0.0, 0.0, 0.0, 0.0, 1.0\n";
    for (int dof : {1, 2}) {
      const double modulus = dof == 1 ? spec.foundation.radial : spec.foundation.tangential;
      if (modulus == 0.0) continue;
      const std::string set = std::string("EFOUND") + (dof == 1 ? "R" : "T");
      s << "*ELEMENT, TYPE=SPRING1, ELSET=" << set << "\n";
      for (const auto& nodes : b.stations)
        for (int node : nodes) s << ++element << ", " << node << "\n";
      s << "*SPRING, ELSET=" << set << ", ORIENTATION=CYLINDER\n" << dof << "\n" << number(modulus * L / 6.0) << "\n";
    }
  }
  d.text = s.str() + spin_steps(spec, step, "every node");
  return b;
}

Deck spinning_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const SpinStep& step,
                   const std::string& title) {
  Deck d = model_deck(spec, o, title, "In-plane vibration of the spinning ring", true);
  d.text += spin_steps(spec, step, "the beam nodes");
  return d;
}

namespace {

/// True when `loads` put forces on nodes beyond the paper's point loads: the consistent
/// nodal forces of a dead pressure, the point masses' weight.
bool nodal_loads(const ring::RingSpec& spec, const ring::Loads& loads) {
  return (loads.pressure.any() && loads.pressure.kind == ring::Pressure::Kind::dead) ||
         (loads.has_gravity() && !spec.masses.empty());
}

/// The load blocks of a step (`amplitude`: every load times the amplitude LOAD), each with a
/// comment: point loads and the point masses' weight as *CLOAD at their nodes, a follower
/// pressure as ccx's beam pressure P2, a dead pressure as the consistent nodal forces of the
/// undeformed ring, gravity as *DLOAD GRAV. Throws InputError naming `section`'s key for a
/// point off the nodes and for what ccx cannot express (a central pressure).
std::string load_blocks(const ring::RingSpec& spec, const ring::CalculixOptions& o, const Deck& d,
                        const ring::Loads& loads, const std::string& section, bool amplitude) {
  const std::string cload = amplitude ? "*CLOAD, AMPLITUDE=LOAD" : "*CLOAD";
  const std::string dload = amplitude ? "*DLOAD, AMPLITUDE=LOAD" : "*DLOAD";
  std::ostringstream s;
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const ring::PointLoad& p = loads.points[i];
    const int node = node_at(d.node_angles, p.angle);
    const std::string key = loads.points.size() == 1 ? section + ".at" : section + ".loads[" + std::to_string(i + 1) + "].at";
    if (node < 0) throw ring::InputError("", key, "angle " + number(p.angle) + " is not a node of the calculix model");
    s << "** The load at " << number(p.angle) << " degrees (node " << node + 1 << "): (Fx, Fy) in N.\n" << cload << "\n";
    if (p.force[0] != 0.0) s << node + 1 << ", 1, " << number(p.force[0]) << "\n";
    if (p.force[1] != 0.0) s << node + 1 << ", 2, " << number(p.force[1]) << "\n";
    if (p.force[0] == 0.0 && p.force[1] == 0.0) s << node + 1 << ", 1, 0.0\n";
  }
  const ring::Pressure& pr = loads.pressure;
  if (pr.any()) {
    switch (pr.kind) {
      case ring::Pressure::Kind::follower: {
        if (o.section == ring::CalculixOptions::Section::as_given && spec.section.shape == ring::Section::Shape::circle)
          throw ring::InputError("", section + ".pressure",
                                 "the calculix deck writes a follower pressure as a pressure on the expanded beam's "
                                 "face, whose width it knows for a rectangle only, not for ccx's expansion of a circle "
                                 "(use calculix.section = \"equivalent-rectangle\")");
        // ccx's beam pressure P2 acts on the face of the expanded section at R - h/2 (the
        // -2 side), positive in +2 (outward), and follows that face under NLGEOM (its force
        // is the pressure times the deformed face's area). p per unit length of the
        // centroid line, positive inward: P2 = -p / (width (1 - h/(2R))), measured: a
        // pinned ring shrinks by the hoop strain p R/EA (tests/calculix).
        const double face = -pr.value / (d.width * (1.0 - d.height / (2.0 * spec.radius)));
        s << "** Follower pressure " << number(pr.value) << " N/m per metre of centroid line, inward: ccx's beam\n"
          << "** pressure P2 on the inner face of the expanded section (R - h/2), which follows the deformed\n"
          << "** face under NLGEOM; P2 = -p / (width (1 - h/(2R))) Pa.\n"
          << dload << "\nERING, P2, " << number(face) << "\n";
        break;
      }
      case ring::Pressure::Kind::dead: {
        const std::vector<double> w = node_shares(spec, o);
        s << "** Dead pressure " << number(pr.value) << " N/m per metre of centroid line: the consistent nodal\n"
          << "** forces of the undeformed ring, p times the node's share of the ring (see the foundation)\n"
          << "** along the inward normal of the undeformed node; *CLOAD keeps direction and magnitude.\n"
          << cload << "\n";
        for (std::size_t k = 0; k < w.size(); ++k) {
          const double a = d.node_angles[k] * kPi / 180.0;
          s << k + 1 << ", 1, " << number(-pr.value * w[k] * std::cos(a)) << "\n"
            << k + 1 << ", 2, " << number(-pr.value * w[k] * std::sin(a)) << "\n";
        }
        break;
      }
      case ring::Pressure::Kind::central:
        throw ring::InputError("", section + ".pressure.kind",
                               "the calculix deck cannot write a central pressure: ccx has no load that points from "
                               "the deformed point at a fixed centre (its *CLOAD keeps its direction, its face "
                               "pressure follows the deformed face); use \"follower\" or \"dead\", or leave calculix "
                               "out");
    }
  }
  if (loads.has_gravity()) {
    const double g = std::hypot(loads.gravity[0], loads.gravity[1]);
    s << "** Gravity (" << number(loads.gravity[0]) << ", " << number(loads.gravity[1])
      << ") m/s^2 on the ring's density: GRAV, |g|, direction.\n"
      << dload << "\nERING, GRAV, " << number(g) << ", " << number(loads.gravity[0] / g) << ", "
      << number(loads.gravity[1] / g) << ", 0.0\n";
    for (std::size_t i = 0; i < spec.masses.size(); ++i) {
      const ring::PointMass& m = spec.masses[i];
      const int node = node_at(d.node_angles, m.angle) + 1;
      s << "** The weight of point mass " << i + 1 << " (" << number(m.mass) << " kg) at node " << node << ".\n"
        << cload << "\n"
        << node << ", 1, " << number(m.mass * loads.gravity[0]) << "\n"
        << node << ", 2, " << number(m.mass * loads.gravity[1]) << "\n";
    }
  }
  return s.str();
}

}  // namespace

Deck response_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const ring::ResponseOptions& rs,
                   const std::string& title) {
  check_response_deck(rs);
  Deck d = model_deck(spec, o, title, "Forced nonlinear response", true, nodal_loads(spec, rs.loads));
  const std::string cloads = load_blocks(spec, o, d, rs.loads, "response", true);
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

void check_plates(const ring::RingSpec& spec, const ring::CalculixOptions& o, const ring::StaticOptions& st) {
  if (!st.plates) return;
  if (spec.arc)
    throw ring::InputError("", "plates", "crush a closed ring: an arch (ring.arc) between plates is not implemented");
  if (!st.loads.points.empty() || st.loads.pressure.any() || st.loads.has_gravity() || st.displacement)
    throw ring::InputError("", "plates",
                           "[plates] drive the path: no loads (static.*) and no static.displacement beside them");
  if (spec.supports.pin || spec.supports.roller || spec.supports.clamp || !spec.supports.pins.empty())
    throw ring::InputError("", "plates",
                           "the plates hold the ring themselves: no pin, roller, pins or clamp beside them");
  if (o.element != ring::CalculixOptions::Element::b32r)
    throw ring::InputError("", "calculix.element",
                           "[plates] are validated with B32R only (calculix/README.md, \"Rigid plates\"); B31 and B32 "
                           "differ in their plastic section laws and B32 locks: use calculix.element = \"B32R\"");
  // A leg that draws the plates back: ccx evaluates the first iteration of an increment with
  // the plates already moved, so their touching springs are open (any retreat exceeds the
  // penalty's sinking), the ring springs back elastically in the next iteration deep into the
  // plates, and Newton alternates until "too many cutbacks" (measured: a tube crushed to
  // c = 0.03 m and drawn back by a tenth fails in the return's first increment, where the same
  // deck continued forward converges in 2-3 iterations per increment; calculix/README.md).
  for (std::size_t k = 0; k < st.history.size(); ++k)
    if (st.history[k] < (k == 0 ? 0.0 : st.history[k - 1]))
      throw ring::InputError("", "static.history",
                             "leg " + std::to_string(k + 1) + " draws the plates back (" + number(st.history[k]) +
                                 " after " + number(k == 0 ? 0.0 : st.history[k - 1]) +
                                 "): the calculix column's plates ([plates]) take a rising history only (ccx's "
                                 "first iteration of a return finds the springs open, and its Newton alternates "
                                 "between open and deep contact; calculix/README.md, \"Rigid plates\")");
  const std::vector<double> angles = ring::node_angles(spec, pieces(o));
  for (double a : {st.plates->axis, st.plates->axis + 180.0})
    if (node_at(angles, a) < 0)
      throw ring::InputError("", "plates.axis",
                             "angle " + number(ring::wrap_degrees(a)) + " is not a node of the calculix model (" +
                                 std::to_string(pieces(o)) + " nodes from " + number(spec.anchor()) + " degrees)");
}

std::string plates_block(const ring::RingSpec& spec, const ring::CalculixOptions& o, const ring::StaticOptions& st,
                         Deck& d) {
  check_plates(spec, o, st);
  const ring::PlatePair pair(spec, *st.plates);
  const double axis = st.plates->axis, R = spec.radius;
  const std::array<double, 2> dv = pair.d, ev{-pair.d[1], pair.d[0]};
  const double length = kPlateSpringLength * R, window = kPlateWindow * R, range = 4.0 * R;
  const std::vector<double> shares = node_shares(spec, o);
  const int nodes = static_cast<int>(d.node_angles.size());
  const int first = node_at(d.node_angles, axis), opposite = node_at(d.node_angles, axis + 180.0);
  std::ostringstream s, springs, ties;
  s << "** Rigid frictionless plates ([plates]): normal d_0 = (" << number(dv[0]) << ", " << number(dv[1])
    << "), travel " << number(st.plates->travel) << " m at load factor 1,\n"
    << "** penalty k = " << number(pair.k) << " N/m^2 per metre of ring (ring::PlatePair). Every beam node facing "
    << "plate p has\n** a plate node " << number(length)
    << " m beyond the plate's line along d_p (d_1 = -d_0) and a SPRINGA to it whose force is\n"
    << "** 0 while the gap g is open and k w g beyond (w the node's share of the ring: L/3 end, 2L/3 middle).\n"
    << "** The plate nodes' local axes (*TRANSFORM): 1 = e = (" << number(ev[0]) << ", " << number(ev[1])
    << ") along the plates, 2 = d_0.\n";
  int plate_node = nodes, element = d.last_element;
  std::array<std::ostringstream, 2> sets;
  for (int k = 0; k < nodes; ++k) {
    const double t = d.node_angles[k] * kPi / 180.0, facing = std::cos((d.node_angles[k] - axis) * kPi / 180.0);
    if (std::abs(facing) < 1e-9) continue;  // at axis +- 90: can touch neither plate
    const int p = facing > 0.0 ? 0 : 1;
    const double sign = p == 0 ? 1.0 : -1.0;
    const double x = R * std::cos(t), y = R * std::sin(t);
    const double g0 = pair.gap(p, x, y, 0.0);  // R (1 - |cos(theta - axis)|)
    const double beyond = g0 + length;          // along d_p from the beam node to the plate node
    const int node = ++plate_node;
    sets[p] << node << ", " << number(x + sign * beyond * dv[0]) << ", " << number(y + sign * beyond * dv[1]) << ", 0.0\n";
    const double kw = pair.k * shares[k];
    const std::string set = "EPLATE" + std::to_string(k + 1);
    springs << "*ELEMENT, TYPE=SPRINGA, ELSET=" << set << "\n" << ++element << ", " << k + 1 << ", " << node << "\n"
            << "*SPRING, ELSET=" << set << ", NONLINEAR\n\n";
    // Rows (force, elongation), elongation = g - g0: the penalty below the kink at g = 0, 0 above.
    springs << number(-kw * range) << ", " << number(-g0 - range) << "\n";
    if (k == first || k == opposite)
      springs << "0.0, 0.0\n" << number(kw * window) << ", " << number(window) << "\n0.0, " << number(2.0 * window)
              << "\n";
    else
      springs << "0.0, " << number(-g0) << "\n";
    springs << "0.0, " << number(range) << "\n";
    if (k == first || k == opposite)
      ties << "*BOUNDARY\n" << node << ", 1, 1\n";
    else {
      ties << "*EQUATION\n" << (1 + (std::abs(ev[0]) > 1e-12) + (std::abs(ev[1]) > 1e-12)) << "\n" << node << ", 1, 1.0";
      if (std::abs(ev[0]) > 1e-12) ties << ", " << k + 1 << ", 1, " << number(-ev[0]);
      if (std::abs(ev[1]) > 1e-12) ties << ", " << k + 1 << ", 2, " << number(-ev[1]);
      ties << "\n";
    }
  }
  for (int p = 0; p < 2; ++p) s << "*NODE, NSET=NPLATE" << p << "\n" << sets[p].str();
  s << "*NSET, NSET=NPLATES\nNPLATE0, NPLATE1\n*TRANSFORM, NSET=NPLATES, TYPE=R\n"
    << number(ev[0]) << ", " << number(ev[1]) << ", 0.0, " << number(dv[0]) << ", " << number(dv[1]) << ", 0.0\n"
    << "** The plate nodes stay in the plane.\n*BOUNDARY\nNPLATES, 3, 3\n"
    << "** Each plate node follows its beam node along e (e . u of the beam node; the two nodes of first\n"
    << "** contact hold e . u = 0 themselves), so that its spring stays along d_p: no friction.\n"
    << ties.str()
    << "** The springs: rows force (N), elongation (m) = g - g_0 (g_0 the node's gap at rest).\n" << springs.str();
  // The two points of first contact keep their place along the plates: e . u = 0.
  s << "** No slide: the beam nodes at " << number(axis) << " and " << number(ring::wrap_degrees(axis + 180.0))
    << " degrees (" << first + 1 << ", " << opposite + 1 << ") do not move along e.\n";
  for (int k : {first, opposite}) {
    if (std::abs(ev[0]) < 1e-12 || std::abs(ev[1]) < 1e-12) {
      const int dof = std::abs(ev[0]) < 1e-12 ? 2 : 1;
      s << "*BOUNDARY\n" << k + 1 << ", " << dof << ", " << dof << "\n";
    } else {
      const bool x_first = std::abs(ev[0]) >= std::abs(ev[1]);
      s << "*EQUATION\n2\n" << k + 1 << ", " << (x_first ? 1 : 2) << ", " << number(x_first ? ev[0] : ev[1]) << ", "
        << k + 1 << ", " << (x_first ? 2 : 1) << ", " << number(x_first ? ev[1] : ev[0]) << "\n";
    }
  }
  d.last_element = element;
  return s.str();
}

Deck static_deck(const ring::RingSpec& spec, const ring::CalculixOptions& o, const ring::StaticOptions& st,
                 const std::string& title) {
  // Plates hang springs on the beam nodes as the elastic supports do: the section made rigid
  // across its width as for them (model_deck).
  Deck d = model_deck(spec, o, title, "Nonlinear statics", false, nodal_loads(spec, st.loads) || st.plates.has_value());
  if (st.plates) d.text += plates_block(spec, o, st, d);
  // A history: one *STEP per leg, every load (and the driven displacement) times the amplitude
  // LOAD in total time (leg k runs from total time k - 1 to k, from the factor s_{k-1} to s_k),
  // so that a factor of 0 unloads (a load merely left out of a later step would stay on).
  const bool history = !st.history.empty();
  const std::vector<double> legs = history ? st.history : std::vector<double>{1.0};
  const std::string cloads = load_blocks(spec, o, d, st.loads, "static", history);
  const double inc = 1.0 / st.steps;
  std::ostringstream s;
  int driven = -1;
  if (st.displacement) {
    driven = node_at(d.node_angles, st.displacement->at);
    if (driven < 0)
      throw ring::InputError("", "static.displacement.at",
                             "angle " + number(st.displacement->at) + " is not a node of the calculix model");
    s << "** The driven point (static.displacement) at " << number(st.displacement->at) << " degrees: node "
      << driven + 1 << ", its reaction force printed.\n*NSET, NSET=NDRIVE\n" << driven + 1 << "\n";
  }
  if (history) {
    s << "** The load factor against total time: leg k of static.history from s_{k-1} at k - 1 to s_k at k.\n"
      << "*AMPLITUDE, NAME=LOAD, TIME=TOTAL TIME\n0.0, 0.0\n";
    for (std::size_t k = 0; k < legs.size(); ++k) s << k + 1 << ".0, " << number(legs[k]) << "\n";
  }
  for (std::size_t k = 0; k < legs.size(); ++k) {
    s << "** Step " << k + 1 << ": geometrically nonlinear statics (NLGEOM) "
      << (history ? "to the load factor " + number(legs[k]) + " (static.history)" : std::string("under the loads"))
      << ",\n** in increments of 1/" << st.steps << " (static.steps; ccx may cut them, down to 1e-5 of that).\n"
      << "*STEP, NLGEOM, INC=" << std::max(1000, 20 * st.steps) << "\n*STATIC\n"
      << number(inc) << ", 1.0, " << number(1e-5 * inc) << ", " << number(inc) << "\n"
      << cloads;
    if (st.displacement) {
      // ccx ties the expanded section's nodes to the beam node by MPCs whose mean displacement
      // is the node's; the boundary on the beam node holds that mean, and the node's RF is the
      // force through those MPCs, the whole force on the section (checked: the driven pinch's
      // reaction against the closed form, tests/calculix/calculix_driven_test.cpp).
      const auto& v = st.displacement->value;
      s << "** The driven node held at s (" << number(v[0]) << ", " << number(v[1]) << ") m, s the load factor"
        << (history ? " (amplitude LOAD).\n*BOUNDARY, AMPLITUDE=LOAD\n" : " (ramped over the step).\n*BOUNDARY\n")
        << driven + 1 << ", 1, 1, " << number(v[0]) << "\n" << driven + 1 << ", 2, 2, " << number(v[1]) << "\n";
    }
    if (st.plates) {
      // The plate nodes' local 2 is d_0: plate 0 moves by -s travel / 2 along it, plate 1 by +.
      const double half = 0.5 * st.plates->travel;
      s << "** The plates move towards the centre by s travel / 2 each, s the load factor"
        << (history ? " (amplitude LOAD).\n*BOUNDARY, AMPLITUDE=LOAD\n" : " (ramped over the step).\n*BOUNDARY\n")
        << "NPLATE0, 2, 2, " << number(-half) << "\nNPLATE1, 2, 2, " << number(half) << "\n";
    }
    s << "** Displacements of the beam nodes after every increment, to the .dat file"
      << (st.displacement ? "; the driven node's reaction after them.\n"
                          : st.plates ? "; the plates' total forces after them\n** (the force each plate's springs "
                                        "put on the ring).\n"
                                      : ".\n")
      << "*NODE PRINT, NSET=NALL\nU\n";
    if (st.displacement) s << "*NODE PRINT, NSET=NDRIVE\nRF\n";
    if (st.plates) s << "*NODE PRINT, NSET=NPLATE0, TOTALS=ONLY\nRF\n*NODE PRINT, NSET=NPLATE1, TOTALS=ONLY\nRF\n";
    s << "*END STEP\n";
  }
  d.text += s.str();
  return d;
}

}  // namespace calculix
