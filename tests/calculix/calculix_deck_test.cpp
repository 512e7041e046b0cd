// The CalculiX deck parsed back: nodes on the circle, the section's A and I, the supports
// as *BOUNDARY lines or an *EQUATION at the right nodes (oracle: the ring's geometry), what
// the deck refuses; and the .dat reader on a small file in ccx's layout.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "calculix/dat.hpp"
#include "calculix/deck.hpp"
#include "ring/errors.hpp"

namespace {

/// What a test reads back from a deck: the keyword blocks' data lines.
struct Parsed {
  std::map<int, std::array<double, 3>> nodes;
  std::vector<std::vector<int>> elements;
  std::string element_type;
  std::vector<std::string> boundary;   ///< data lines of every *BOUNDARY block
  std::vector<std::string> equations;  ///< data lines of every *EQUATION block
  std::vector<double> section;         ///< the *BEAM SECTION's first data line
  std::string section_kind;
  int frequencies = 0;
};

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream s(line);
  for (std::string x; std::getline(s, x, ',');) {
    x.erase(0, x.find_first_not_of(' '));
    f.push_back(x);
  }
  return f;
}

Parsed parse(const std::string& deck) {
  Parsed p;
  std::istringstream in(deck);
  std::string block;
  int line_in_block = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("**", 0) == 0) continue;  // a comment
    if (line.rfind("*", 0) == 0) {
      block = fields(line)[0];
      line_in_block = 0;
      if (block == "*ELEMENT") p.element_type = line.substr(line.find("TYPE=") + 5, line.find(',', line.find("TYPE=")) - line.find("TYPE=") - 5);
      if (block == "*BEAM SECTION") p.section_kind = line.substr(line.find("SECTION=") + 8);
      continue;
    }
    const auto f = fields(line);
    ++line_in_block;
    if (block == "*NODE") p.nodes[std::stoi(f[0])] = {std::stod(f[1]), std::stod(f[2]), std::stod(f[3])};
    if (block == "*ELEMENT") {
      std::vector<int> e;
      for (std::size_t i = 1; i < f.size(); ++i) e.push_back(std::stoi(f[i]));
      p.elements.push_back(e);
    }
    if (block == "*BOUNDARY") p.boundary.push_back(line);
    if (block == "*EQUATION") p.equations.push_back(line);
    if (block == "*BEAM SECTION" && line_in_block == 1)
      for (const auto& x : f) p.section.push_back(std::stod(x));
    if (block == "*FREQUENCY") p.frequencies = std::stoi(f[0]);
  }
  return p;
}

ring::RingSpec paper_ring() {
  ring::RingSpec r;
  r.radius = 10.0;
  r.section.diameter = 0.12;
  return r;
}

/// The node of the deck at (x, y), or 0.
int node_near(const Parsed& p, double x, double y) {
  for (const auto& [k, c] : p.nodes)
    if (std::hypot(c[0] - x, c[1] - y) < 1e-9) return k;
  return 0;
}

TEST(CalculixDeck, NodesOnTheCircleAndElementsCloseTheRing) {
  for (auto element : {ring::CalculixOptions::Element::b31, ring::CalculixOptions::Element::b32r,
                       ring::CalculixOptions::Element::b32}) {
    ring::CalculixOptions o;
    o.elements = 12;
    o.element = element;
    const Parsed p = parse(calculix::frequency_deck(paper_ring(), o, {30}).text);
    const int nodes = element == ring::CalculixOptions::Element::b31 ? 12 : 24;
    ASSERT_EQ(static_cast<int>(p.nodes.size()), nodes);
    for (const auto& [k, c] : p.nodes) {
      EXPECT_NEAR(std::hypot(c[0], c[1]), 10.0, 1e-12) << "node " << k;
      EXPECT_EQ(c[2], 0.0);
      // Node k at 360 (k - 1) / nodes degrees from +x (a free ring's anchor is 0).
      EXPECT_NEAR(std::atan2(c[1], c[0]), std::remainder(2 * M_PI * (k - 1) / nodes, 2 * M_PI), 1e-12);
    }
    ASSERT_EQ(p.elements.size(), 12u);
    EXPECT_EQ(p.element_type, ring::to_string(element));
    // Consecutive elements share their end node, and the last closes on node 1.
    for (std::size_t e = 0; e < p.elements.size(); ++e)
      EXPECT_EQ(p.elements[e].back(), p.elements[(e + 1) % p.elements.size()].front());
    EXPECT_EQ(p.frequencies, 30);
  }
}

TEST(CalculixDeck, EquivalentRectangleHasTheRingsAreaAndInertia) {
  const ring::RingSpec r = paper_ring();
  const Parsed p = parse(calculix::frequency_deck(r, {}, {10}).text);
  EXPECT_EQ(p.section_kind, "RECT");
  ASSERT_EQ(p.section.size(), 2u);
  const double w = p.section[0], h = p.section[1];  // normal to the plane, radial
  // The deck writes 14 significant digits: w h^3 carries 4 roundings of 5e-14.
  EXPECT_NEAR(w * h, r.A(), 1e-12 * r.A());
  EXPECT_NEAR(w * h * h * h / 12.0, r.I(), 1e-12 * r.I());
}

TEST(CalculixDeck, AsGivenWritesTheCircleOrTheRectangle) {
  ring::CalculixOptions o;
  o.section = ring::CalculixOptions::Section::as_given;
  Parsed p = parse(calculix::frequency_deck(paper_ring(), o, {10}).text);
  EXPECT_EQ(p.section_kind, "CIRC");
  EXPECT_EQ(p.section, (std::vector<double>{0.12, 0.12}));
  ring::RingSpec r = paper_ring();
  r.section.shape = ring::Section::Shape::rectangle;
  r.section.width = 0.05;
  r.section.height = 0.1;
  p = parse(calculix::frequency_deck(r, o, {10}).text);
  EXPECT_EQ(p.section_kind, "RECT");
  EXPECT_EQ(p.section, (std::vector<double>{0.05, 0.1}));
}

TEST(CalculixDeck, FreeRingHoldsOnlyTheOutOfPlaneDisplacement) {
  const Parsed p = parse(calculix::frequency_deck(paper_ring(), {}, {10}).text);
  EXPECT_EQ(p.boundary, (std::vector<std::string>{"NALL, 3, 3"}));
  EXPECT_TRUE(p.equations.empty());
}

TEST(CalculixDeck, PinAndRollerOnAnAxisAreBoundaryLinesAtTheirNodes) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 180.0;
  r.supports.roller = 0.0;
  const Parsed p = parse(calculix::frequency_deck(r, {}, {10}).text);
  const int pin = node_near(p, -10.0, 0.0), roller = node_near(p, 10.0, 0.0);
  ASSERT_GT(pin, 0);
  ASSERT_GT(roller, 0);
  // The pin holds ux and uy; the roller on the x axis through the pin holds uy only.
  EXPECT_EQ(p.boundary, (std::vector<std::string>{"NALL, 3, 3", std::to_string(pin) + ", 1, 2",
                                                  std::to_string(roller) + ", 2, 2"}));
  EXPECT_TRUE(p.equations.empty());
}

TEST(CalculixDeck, RollerOffTheAxesIsAnEquationNormalToTheLineThroughThePin) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 180.0;
  r.supports.roller = 60.0;
  ring::CalculixOptions o;
  o.elements = 12;  // nodes every 15 degrees
  const Parsed p = parse(calculix::frequency_deck(r, o, {10}).text);
  const int roller = node_near(p, 10.0 * std::cos(M_PI / 3), 10.0 * std::sin(M_PI / 3));
  ASSERT_GT(roller, 0);
  ASSERT_EQ(p.equations.size(), 2u);
  EXPECT_EQ(p.equations[0], "2");
  const auto f = fields(p.equations[1]);
  ASSERT_EQ(f.size(), 6u);
  EXPECT_EQ(std::stoi(f[0]), roller);
  EXPECT_EQ(std::stoi(f[3]), roller);
  std::array<double, 3> c{};
  c[std::stoi(f[1])] = std::stod(f[2]);
  c[std::stoi(f[4])] = std::stod(f[5]);
  // The held direction is normal to the line from the pin (-10, 0) to the roller.
  const double dx = 10.0 * std::cos(M_PI / 3) + 10.0, dy = 10.0 * std::sin(M_PI / 3);
  EXPECT_NEAR(c[1] * dx + c[2] * dy, 0.0, 1e-12);
  EXPECT_NEAR(std::hypot(c[1], c[2]), 1.0, 1e-12);
}

TEST(CalculixDeck, StaticStepLoadsTheNodeAtTheLoadsAngle) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 180.0;
  r.supports.roller = 0.0;
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, 0.0}}};
  st.loads.points.at(0).force = {0.0, -2e4};
  st.steps = 8;
  const std::string deck = calculix::static_deck(r, {}, st).text;
  const Parsed p = parse(deck);
  EXPECT_NE(deck.find("*STEP, NLGEOM"), std::string::npos);
  // The *CLOAD line: the node at (0, 10), direction 2, the force.
  const auto at = deck.find("*CLOAD\n");
  ASSERT_NE(at, std::string::npos);
  const auto f = fields(deck.substr(at + 7, deck.find('\n', at + 7) - at - 7));
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(std::stoi(f[0]), node_near(p, 0.0, 10.0));
  EXPECT_EQ(f[1], "2");
  EXPECT_EQ(std::stod(f[2]), -2e4);
  // Increments of 1/8 of the load, the step ending at 1.
  const auto inc = fields(deck.substr(deck.find("*STATIC\n") + 8, 80).substr(0, deck.substr(deck.find("*STATIC\n") + 8).find('\n')));
  EXPECT_EQ(std::stod(inc[0]), 0.125);
  EXPECT_EQ(std::stod(inc[1]), 1.0);
  st.loads.points = {{91.0, {0.0, -2e4}}};  // not a node
  EXPECT_THROW(calculix::static_deck(r, {}, st), ring::InputError);
}

// Displacement control: the driven node in a set of its own, its two displacements a
// *BOUNDARY with the values at load factor 1 inside the step (ramped by ccx's *STATIC), its
// RF printed after the displacements; no load. A history: one *STEP per leg, the boundary
// times the amplitude LOAD in total time, whose rows are the legs' factors.
TEST(CalculixDeck, ADrivenNodeIsABoundaryWithItsValueAndPrintsItsReaction) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 270.0;
  ring::StaticOptions st;
  st.displacement = ring::StaticOptions::Displacement{90.0, {0.25, -2e-3}};
  st.steps = 4;
  std::string deck = calculix::static_deck(r, {}, st).text;
  const Parsed p = parse(deck);
  const int node = node_near(p, 0.0, 10.0);
  EXPECT_NE(deck.find("*NSET, NSET=NDRIVE\n" + std::to_string(node) + "\n"), std::string::npos);
  const auto step = deck.find("*STEP");
  const auto at = deck.find("*BOUNDARY\n" + std::to_string(node) + ", 1, 1, ", step);
  ASSERT_NE(at, std::string::npos) << deck.substr(step);
  std::istringstream in(deck.substr(at + 10));
  std::string x, y;
  std::getline(in, x);
  std::getline(in, y);
  EXPECT_EQ(std::stod(fields(x).at(3)), 0.25);
  EXPECT_EQ(std::stod(fields(y).at(3)), -2e-3);
  EXPECT_EQ(fields(y).at(1), "2");
  EXPECT_LT(deck.find("*NODE PRINT, NSET=NALL\nU\n"), deck.find("*NODE PRINT, NSET=NDRIVE\nRF\n"));
  EXPECT_EQ(deck.find("*CLOAD"), std::string::npos);
  EXPECT_EQ(deck.find("AMPLITUDE"), std::string::npos);

  st.history = {1.0, 0.0, -0.5};
  deck = calculix::static_deck(r, {}, st).text;
  std::size_t steps = 0;
  for (auto k = deck.find("*STEP"); k != std::string::npos; k = deck.find("*STEP", k + 1)) ++steps;
  EXPECT_EQ(steps, 3u);
  const auto amp = deck.find("*AMPLITUDE, NAME=LOAD, TIME=TOTAL TIME\n");
  ASSERT_NE(amp, std::string::npos);
  std::istringstream rows(deck.substr(amp + 39));
  const std::vector<std::array<double, 2>> expected = {{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}, {3.0, -0.5}};
  for (const auto& e : expected) {
    std::string row;
    std::getline(rows, row);
    const auto f = fields(row);
    ASSERT_EQ(f.size(), 2u) << row;
    EXPECT_EQ(std::stod(f[0]), e[0]) << row;
    EXPECT_EQ(std::stod(f[1]), e[1]) << row;
  }
  EXPECT_NE(deck.find("*BOUNDARY, AMPLITUDE=LOAD\n" + std::to_string(node) + ", 1, 1, "), std::string::npos);

  st.displacement->at = 91.0;  // not a node
  try {
    calculix::static_deck(r, {}, st);
    ADD_FAILURE() << "no refusal";
  } catch (const ring::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("static.displacement.at"), std::string::npos) << e.what();
  }
}

// The fibre law in a static deck: *PLASTIC after the *ELASTIC of the material, the bilinear
// law's table sigma_y + H eps_p (H = h E / (1 - h)) in two rows, or one row when perfectly
// plastic; HARDENING=KINEMATIC for the kinematic rule, none (ccx's isotropic default) for the
// isotropic one. The frequency deck stays elastic (the modes at rest).
TEST(CalculixDeck, FibreLawIsAPlasticTableAfterTheElasticMaterial) {
  ring::RingSpec r = paper_ring();
  r.section.shape = ring::Section::Shape::rectangle;
  r.section.width = 0.1;
  r.section.height = 0.12;
  r.supports.pin = 180.0;
  r.supports.roller = 0.0;
  ring::Plastic p;
  p.law = ring::Plastic::Law::fibre;
  p.stress = 2.5e8;
  p.hardening = 0.2;
  r.plastic = p;
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -2e4}}};
  auto rows = [](const std::string& deck, const std::string& keyword) {
    std::vector<std::vector<double>> v;
    const auto at = deck.find(keyword + "\n");
    if (at == std::string::npos) return v;
    std::istringstream in(deck.substr(at + keyword.size() + 1));
    for (std::string line; std::getline(in, line) && line[0] != '*';) {
      std::vector<double> row;
      for (const auto& f : fields(line)) row.push_back(std::stod(f));
      v.push_back(row);
    }
    return v;
  };
  std::string deck = calculix::static_deck(r, {}, st).text;
  EXPECT_LT(deck.find("*ELASTIC\n"), deck.find("*PLASTIC, HARDENING=KINEMATIC\n"));
  auto t = rows(deck, "*PLASTIC, HARDENING=KINEMATIC");
  ASSERT_EQ(t.size(), 2u);
  const double H = 0.2 * r.E / 0.8;
  EXPECT_EQ(t[0][0], 2.5e8);
  EXPECT_EQ(t[0][1], 0.0);
  EXPECT_NEAR((t[1][0] - t[0][0]) / (t[1][1] - t[0][1]), H, 1e-12 * H);  // the table's slope: H
  r.plastic->rule = ring::Plastic::Rule::isotropic;
  r.plastic->hardening = 0.0;
  deck = calculix::static_deck(r, {}, st).text;
  EXPECT_EQ(deck.find("HARDENING="), std::string::npos);
  t = rows(deck, "*PLASTIC");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0][0], 2.5e8);
  // With a spring the elastic deck's material is orthotropic (the section rigid across its
  // width); ccx 2.20 refuses that with *PLASTIC on a beam section, so the plastic deck keeps
  // the isotropic material.
  r.supports.springs = {{45.0, 1e3, 1e3, 0.0}};
  deck = calculix::static_deck(r, {}, st).text;
  EXPECT_EQ(deck.find("ENGINEERING CONSTANTS"), std::string::npos);
  EXPECT_LT(deck.find("*ELASTIC\n"), deck.find("*PLASTIC\n"));
  // The modes at rest are elastic: no *PLASTIC in a frequency deck.
  EXPECT_EQ(calculix::frequency_deck(r, {}, calculix::FrequencyStep{12}).text.find("*PLASTIC"), std::string::npos);
}

TEST(CalculixDeck, ResponseStepIsNewmarkWithTheLoadsHistory) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 180.0;
  ring::ResponseOptions rs;
  rs.loads.points = {{0.0, {0.0, 0.0}}};
  rs.loads.points.at(0).force = {-2e4, 0.0};
  rs.history.kind = ring::LoadHistory::Kind::half_sine;
  rs.history.period = 0.5;
  rs.dt = 0.1;
  rs.t_end = 1.0;
  rs.record = {0.0, 90.0};
  const std::string deck = calculix::response_deck(r, {}, rs).text;
  EXPECT_NE(deck.find("*STEP, NLGEOM"), std::string::npos);
  EXPECT_NE(deck.find("*DYNAMIC, DIRECT, ALPHA=0.0\n1.0000000000000e-01, 1.0000000000000e+00\n"), std::string::npos);
  EXPECT_NE(deck.find("*CLOAD, AMPLITUDE=LOAD\n"), std::string::npos);
  // The amplitude: (t, sin(pi t / T)) up to T, then 0 (LoadHistory::factor), every dt.
  std::istringstream in(deck.substr(deck.find("*AMPLITUDE, NAME=LOAD\n") + 22));
  int rows = 0;
  for (std::string line; std::getline(in, line) && line[0] != '*';) {
    if (line.rfind("**", 0) == 0) continue;
    const auto f = fields(line);
    const double t = std::stod(f[0]);
    EXPECT_NEAR(std::stod(f[1]), t < 0.5 ? std::sin(M_PI * t / 0.5) : 0.0, 1e-12) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 11);
  rs.integrator = ring::ResponseOptions::Integrator::energy_momentum;
  try {
    calculix::check_response_deck(rs);
    FAIL();
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "response.integrator");
  }
}

TEST(CalculixDeck, RefusesWhatItCannotExpressNamingTheKey) {
  ring::RingSpec r = paper_ring();
  r.section.shape = ring::Section::Shape::general;
  r.section.area_ = 0.01;
  r.section.inertia_ = 1e-5;
  ring::CalculixOptions o;
  o.section = ring::CalculixOptions::Section::as_given;
  try {
    calculix::check_deck(r, o);
    FAIL() << "a general section as given was accepted";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "calculix.section");
  }
  // Terms beyond the paper's ring that ccx cannot express: refused by name, with the reason.
  ring::RingSpec m = paper_ring();
  m.supports.pin = 0.0;
  m.masses.push_back({90.0, 10.0, 0.0});
  EXPECT_NO_THROW(calculix::check_deck(m, {}));  // a point mass without rotary inertia is written
  m.masses.push_back({180.0, 10.0, 2.0});
  try {
    calculix::check_deck(m, {});
    FAIL() << "a point mass's rotary inertia was accepted";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "masses[2].inertia");
    EXPECT_NE(std::string(e.what()).find("ROTARY INERTIA"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(calculix::check_deck(m, {}, calculix::Inertia::ignored));  // statics needs none
  ring::RingSpec k = paper_ring();
  k.supports.pin = 0.0;
  k.supports.springs.push_back({90.0, 1e3, 0.0, 5e4});
  try {
    calculix::check_deck(k, {});
    FAIL() << "a rotational spring was accepted";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "supports.springs[1].kr");
  }
  ring::StaticOptions central;
  central.loads.pressure = {1000.0, ring::Pressure::Kind::central};
  ring::RingSpec pr = paper_ring();
  pr.supports.pin = 180.0;
  pr.supports.roller = 0.0;
  try {
    calculix::static_deck(pr, {}, central);
    FAIL() << "a central pressure was accepted";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "static.pressure.kind");
  }
  ring::RingSpec s = paper_ring();
  s.supports.pin = 0.0;
  s.supports.roller = 100.0;  // 12 B31 nodes every 30 degrees: not a node
  o = {};
  o.elements = 12;
  o.element = ring::CalculixOptions::Element::b31;
  try {
    calculix::check_deck(s, o);
    FAIL() << "a roller between nodes was accepted";
  } catch (const ring::InputError& e) {
    EXPECT_EQ(e.key(), "supports.roller");
  }
}

/// The data lines that follow the first line starting with `keyword` (up to the next keyword).
std::vector<std::vector<std::string>> block(const std::string& deck, const std::string& keyword) {
  std::vector<std::vector<std::string>> rows;
  const auto at = deck.find("\n" + keyword);
  if (at == std::string::npos) return rows;
  std::istringstream in(deck.substr(deck.find('\n', at + 1) + 1));
  for (std::string line; std::getline(in, line) && line[0] != '*';) rows.push_back(fields(line));
  return rows;
}

TEST(CalculixDeck, PinsAndAClampAreBoundaryLinesAtTheirNodes) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 180.0;
  r.supports.pins = {0.0, 90.0};
  r.supports.clamp = 90.0;
  ring::CalculixOptions o;
  o.elements = 12;
  const Parsed p = parse(calculix::frequency_deck(r, o, {10}).text);
  const int a = node_near(p, -10.0, 0.0), b = node_near(p, 10.0, 0.0), c = node_near(p, 0.0, 10.0);
  ASSERT_GT(a * b * c, 0);
  // Every pin holds ux and uy; the clamp (at the pin at 90 degrees) its rotation about z too.
  EXPECT_EQ(p.boundary, (std::vector<std::string>{"NALL, 3, 3", std::to_string(a) + ", 1, 2", std::to_string(b) + ", 1, 2",
                                                  std::to_string(c) + ", 1, 2", std::to_string(c) + ", 6, 6"}));
}

TEST(CalculixDeck, SpringsMassesAndTheFoundationAreElementsOnTheNodes) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 180.0;
  r.supports.springs = {{0.0, 1e3, 2e3, 0.0}};
  r.masses = {{90.0, 50.0, 0.0}};
  r.foundation = {4e3, 1e3};
  for (auto element : {ring::CalculixOptions::Element::b31, ring::CalculixOptions::Element::b32r}) {
    ring::CalculixOptions o;
    o.elements = 12;
    o.element = element;
    const std::string deck = calculix::frequency_deck(r, o, {10}).text;
    const Parsed p = parse(deck);
    const int spring = node_near(p, 10.0, 0.0), mass = node_near(p, 0.0, 10.0);
    // The support: SPRING1 on degree of freedom 1 (kx) and 2 (ky) of its node.
    EXPECT_EQ(std::stoi(block(deck, "*ELEMENT, TYPE=SPRING1, ELSET=ESPRING1X")[0][1]), spring);
    EXPECT_EQ(block(deck, "*SPRING, ELSET=ESPRING1X")[0][0], "1");
    EXPECT_EQ(std::stod(block(deck, "*SPRING, ELSET=ESPRING1X")[1][0]), 1e3);
    EXPECT_EQ(block(deck, "*SPRING, ELSET=ESPRING1Y")[0][0], "2");
    EXPECT_EQ(std::stod(block(deck, "*SPRING, ELSET=ESPRING1Y")[1][0]), 2e3);
    // The mass: a MASS element on its node, whose out-of-plane displacement is an equation.
    EXPECT_EQ(std::stoi(block(deck, "*ELEMENT, TYPE=MASS")[0][1]), mass);
    EXPECT_EQ(std::stod(block(deck, "*MASS, ELSET=EMASS1")[0][0]), 50.0);
    EXPECT_NE(deck.find("*EQUATION\n1\n" + std::to_string(mass) + ", 3, 1.0\n"), std::string::npos);
    EXPECT_EQ(deck.find("NALL, 3, 3"), std::string::npos);
    // The foundation: every node has a radial and a tangential spring in the cylindrical
    // system, and their stiffnesses add up to the modulus times the circumference.
    for (const std::string dir : {"R", "T"}) {
      double total = 0.0;
      int springs = 0;
      for (const std::string where : {"END", "MID"}) {
        const auto elements = block(deck, "*ELEMENT, TYPE=SPRING1, ELSET=EFOUND" + dir + where);
        const auto spring_card = block(deck, "*SPRING, ELSET=EFOUND" + dir + where + ", ORIENTATION=CYLINDER");
        if (elements.empty()) continue;
        EXPECT_EQ(spring_card[0][0], dir == "R" ? "1" : "2");
        total += elements.size() * std::stod(spring_card[1][0]);
        springs += static_cast<int>(elements.size());
      }
      EXPECT_EQ(springs, static_cast<int>(p.nodes.size()));
      // 14 digits in each stiffness: a few 1e-14 of round-off.
      EXPECT_NEAR(total, (dir == "R" ? 4e3 : 1e3) * 2 * M_PI * 10.0, 1e-12 * 4e3 * 2 * M_PI * 10.0) << dir;
    }
    EXPECT_NE(deck.find("*ORIENTATION, NAME=CYLINDER, SYSTEM=CYLINDRICAL\n0.0, 0.0, 0.0, 0.0, 0.0, 1.0\n"),
              std::string::npos);
    EXPECT_NE(deck.find("*ELASTIC, TYPE=ENGINEERING CONSTANTS"), std::string::npos);
  }
  // A static deck writes no mass (statics has no inertia) and keeps the plain z boundary.
  ring::StaticOptions st;
  st.loads.points = {{0.0, {1.0, 0.0}}};
  const std::string deck = calculix::static_deck(r, {}, st).text;
  EXPECT_EQ(deck.find("TYPE=MASS"), std::string::npos);
  EXPECT_NE(deck.find("NALL, 3, 3"), std::string::npos);
}

TEST(CalculixDeck, AFreeRingsDecksHaveTheirFirstNodeAtTheSpecsAnchor) {
  // A free ring held by its foundation: every solver puts node 0 at RingSpec::anchor(),
  // which the scene reader sets to the first point load (ring/spec.hpp free_anchor).
  ring::RingSpec r = paper_ring();
  r.foundation = {1e4, 1e4};
  r.masses = {{62.0, 10.0, 0.0}};  // 2 + 60: a node from the load's anchor
  r.free_anchor = 2.0;
  ring::CalculixOptions o;
  o.elements = 12;
  ring::StaticOptions st;
  st.loads.points = {{2.0, {0.0, -1e3}}};
  st.loads.gravity = {0.0, -9.81};
  const calculix::Deck d = calculix::static_deck(r, o, st);
  EXPECT_EQ(d.anchor, 2.0);
  EXPECT_EQ(d.node_angles.at(1), 17.0);
  const Parsed p = parse(d.text);
  EXPECT_NEAR(p.nodes.at(1)[0], 10.0 * std::cos(2.0 * M_PI / 180.0), 1e-12);
  EXPECT_NE(d.text.find("*CLOAD\n1, 2, " + calculix::number(-1e3)), std::string::npos);
  // The frequency deck of the same ring counts from the same anchor: the mass is a node.
  EXPECT_EQ(calculix::frequency_deck(r, o, {10}).anchor, 2.0);
  // Anchored at 0, neither the mass nor the load is a node.
  r.free_anchor = 0.0;
  EXPECT_THROW(calculix::static_deck(r, o, st), ring::InputError);
  EXPECT_THROW(calculix::frequency_deck(r, o, {10}), ring::InputError);
}

TEST(CalculixDeck, PressureAndGravityLoads) {
  ring::RingSpec r = paper_ring();
  r.supports.pin = 180.0;
  r.supports.roller = 0.0;
  r.masses = {{90.0, 50.0, 0.0}};
  ring::CalculixOptions o;
  o.elements = 12;
  ring::StaticOptions st;
  st.loads.pressure = {1000.0, ring::Pressure::Kind::follower};
  st.loads.gravity = {0.0, -9.81};
  calculix::Deck d = calculix::static_deck(r, o, st);
  // Follower: the beam pressure P2 on the inner face, -p / (width (1 - h/(2R))).
  const auto p2_line = d.text.substr(d.text.find("ERING, P2, ") + 11);
  EXPECT_NEAR(std::stod(p2_line), -1000.0 / (d.width * (1.0 - d.height / 20.0)), 1e-12 * 1000.0 / d.width);
  // Gravity: GRAV with |g| and its direction; the mass's weight at its node.
  EXPECT_NE(d.text.find("ERING, GRAV, 9.8100000000000e+00, 0.0, -1.0000000000000e+00, 0.0\n"), std::string::npos);
  const Parsed p = parse(d.text);
  const int mass = node_near(p, 0.0, 10.0);
  EXPECT_NE(d.text.find(std::to_string(mass) + ", 2, " + calculix::number(-50.0 * 9.81)), std::string::npos);
  // Dead: consistent nodal forces that add up to no net force and to p times the circumference
  // along the inward normals.
  st.loads.pressure.kind = ring::Pressure::Kind::dead;
  st.loads.gravity = {0.0, 0.0};
  d = calculix::static_deck(r, o, st);
  const auto f = block(d.text, "*CLOAD");
  ASSERT_EQ(f.size(), 2 * p.nodes.size());
  double fx = 0.0, fy = 0.0, inward = 0.0;
  for (const auto& row : f) {
    const auto c = p.nodes.at(std::stoi(row[0]));
    const double v = std::stod(row[2]);
    (row[1] == "1" ? fx : fy) += v;
    inward -= v * (row[1] == "1" ? c[0] : c[1]) / 10.0;
  }
  EXPECT_NEAR(fx, 0.0, 1e-9);
  EXPECT_NEAR(fy, 0.0, 1e-9);
  EXPECT_NEAR(inward, 1000.0 * 2 * M_PI * 10.0, 1e-9);
}

TEST(CalculixDeck, NumbersFitCcxsTwentyCharacterFields) {
  for (double x : {-1.2246467991473533e-15, 1e300, -1e-300, 10.0, -9.9999999999999e-5})
    EXPECT_LE(calculix::number(x).size(), 20u) << x;
  EXPECT_NEAR(std::stod(calculix::number(-1.2246467991473533e-15)), -1.2246467991473533e-15, 1e-28);
}

// A .dat in ccx's layout (CalculiX 2.20), two nodes and two modes.
const char* kDat = R"(
     E I G E N V A L U E   O U T P U T

 MODE NO    EIGENVALUE                       FREQUENCY
                                     REAL PART            IMAGINARY PART
                           (RAD/TIME)      (CYCLES/TIME     (RAD/TIME)

      1  -0.2220049E-06   0.0000000E+00   0.0000000E+00   0.4711740E-03
      2   0.1745906E+02   0.4178405E+01   0.6650137E+00   0.0000000E+00

     P A R T I C I P A T I O N   F A C T O R S

                    E I G E N V A L U E    N U M B E R     1


 displacements (vx,vy,vz) for set NALL and time  0.1000000E+01

         1  1.000000E-02  0.000000E+00  0.000000E+00
         2  1.000000E-02  0.000000E+00  0.000000E+00

                    E I G E N V A L U E    N U M B E R     2


 displacements (vx,vy,vz) for set NALL and time  0.1000000E+01

         1  7.451822E-04  2.927829E-05  0.000000E+00
         2 -7.451822E-04 -2.927829E-05  0.000000E+00
)";

TEST(CalculixDat, ReadsFrequenciesAndNodeDisplacements) {
  const auto modes = calculix::read_frequency_dat(kDat, 2);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_EQ(modes[0].omega, 0.0);  // a negative round-off eigenvalue is a zero frequency
  EXPECT_EQ(modes[1].omega, 4.178405);
  EXPECT_EQ(modes[1].ux[1], -7.451822e-04);
  EXPECT_EQ(modes[1].uy[0], 2.927829e-05);
}

TEST(CalculixDat, AStaticStepsLastIncrementIsTheResult) {
  const std::string dat = R"(
 displacements (vx,vy,vz) for set NALL and time  0.5000000E+00

         1  1.000000E-01  0.000000E+00  0.000000E+00
         2  2.000000E-01  0.000000E+00  0.000000E+00

 displacements (vx,vy,vz) for set NALL and time  0.1000000E+01

         1  3.000000E-01 -1.000000E-02  0.000000E+00
         2  4.000000E-01  0.000000E+00  0.000000E+00
)";
  const auto s = calculix::read_static_dat(dat, 2);
  EXPECT_EQ(s.time, 1.0);
  EXPECT_EQ(s.increments, 2);
  EXPECT_EQ(s.ux[1], 0.4);
  EXPECT_EQ(s.uy[0], -0.01);
  EXPECT_THROW(calculix::read_static_dat(dat, 3), ring::NumericalError);
  EXPECT_THROW(calculix::read_static_dat("no increment\n", 2), ring::NumericalError);
}

TEST(CalculixDat, AStaticStepsDrivenNodeReactionIsReadPerIncrement) {
  const std::string dat = R"(
 displacements (vx,vy,vz) for set NALL and time  0.5000000E+00

         1  1.000000E-01  0.000000E+00  0.000000E+00
         2  2.000000E-01  0.000000E+00  0.000000E+00

 forces (fx,fy,fz) for set NDRIVE and time  0.5000000E+00

         2  3.000000E+00 -4.000000E+00  1.000000E-12

 displacements (vx,vy,vz) for set NALL and time  0.1000000E+01

         1  3.000000E-01 -1.000000E-02  0.000000E+00
         2  4.000000E-01  0.000000E+00  0.000000E+00

 forces (fx,fy,fz) for set NDRIVE and time  0.1000000E+01

         2  5.000000E+00 -6.000000E+00  0.000000E+00
)";
  const auto s = calculix::read_static_dat(dat, 2);
  ASSERT_EQ(s.all.size(), 2u);
  EXPECT_EQ(s.all[0].time, 0.5);
  EXPECT_EQ(s.all[0].force[0], 3.0);
  EXPECT_EQ(s.all[0].force[1], -4.0);
  EXPECT_EQ(s.all[1].ux[0], 0.3);
  EXPECT_EQ(s.force[1], -6.0);
  EXPECT_EQ(s.ux[1], 0.4);
  // A forces block of two nodes, or one before any displacements, is not what the deck asks.
  std::string two = dat;
  two.insert(two.find("         2  5.0"), "         1  5.000000E+00 -6.000000E+00  0.000000E+00\n");
  EXPECT_THROW(calculix::read_static_dat(two, 2), ring::NumericalError);
  EXPECT_THROW(calculix::read_static_dat(dat.substr(dat.find(" forces")), 2), ring::NumericalError);
}

TEST(CalculixDat, AMalformedFileIsANumericalErrorNamingTheLine) {
  std::string bad = kDat;
  bad.replace(bad.find("-7.451822E-04"), 13, "-7.45x822E-04");
  try {
    calculix::read_frequency_dat(bad, 2);
    FAIL();
  } catch (const ring::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("ring.dat, line 27"), std::string::npos) << e.what();
  }
  EXPECT_THROW(calculix::read_frequency_dat(kDat, 3), ring::NumericalError);  // a node missing
  EXPECT_THROW(calculix::read_frequency_dat("nothing here\n", 2), ring::NumericalError);
}

}  // namespace
