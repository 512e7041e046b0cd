// The CalculiX input deck of a ring (Abaqus-style keywords, read by ccx): nodes on the
// circle, beam elements that ccx expands into bricks of the section's shape, the
// supports as boundary conditions or equations, and one step. The deck is written for a
// person to read: a comment says what each block is.
//
// What the deck expresses (and what it refuses, with ring::InputError naming the key):
// - the ring: R, E, rho; Poisson's ratio 0 (the ring spec has none; with 0 the expanded
//   section does not deform in its own plane, so the bricks act as a beam with shear
//   modulus E/2 and rotary inertia);
// - the section: the equivalent rectangle (default: same A and I, width A/h, radial
//   height h = sqrt(12 I / A)), or as given (CIRC with the diameter, RECT width x height;
//   a general {area, inertia} section has no shape and is refused);
// - in-plane motion: the out-of-plane displacement of every beam node is held;
// - pins (supports.pin and supports.pins): both displacements of the node held (rotation
//   free, so no rotation boundary condition, which ccx would turn into a rigid knot of the
//   expanded section);
// - clamp: a pin whose rotation about z (degree of freedom 6) is held too;
// - roller: its node stays on the line through the pin and itself: one displacement held
//   if that line is along x or y, else a two-term *EQUATION;
// - elastic supports: SPRING1 elements in x and y on the node (a rotational spring kr is
//   refused: ccx ignores a SPRING1 on the rotation of an expanded beam's node);
// - point masses (frequency and response decks): MASS elements on the node (rotary inertia
//   refused: ccx has none); the out-of-plane displacement of their nodes held by a one-term
//   *EQUATION, since a MASS element beside a held degree of freedom stops ccx 2.20;
// - the Winkler foundation: SPRING1 elements at every node in the cylindrical system about
//   z (radial and tangential of the undeformed node), the modulus times the node's share of
//   the ring (B31: L; B32/B32R: L/3 at an end node, 2L/3 at a middle node);
// - with springs, masses, the foundation or nodal loads, the section is made rigid across
//   its width (E_z = 1e4 E; no in-plane stress involves it at Poisson's ratio 0), since ccx
//   ties them to the corners of the expanded section;
// - loads (statics, response): point loads and the masses' weight as *CLOAD, a follower
//   pressure as the beam pressure P2 (a face pressure of the expanded section, following it
//   under NLGEOM), a dead pressure as the undeformed ring's consistent nodal forces (*CLOAD),
//   gravity as *DLOAD GRAV; a central pressure is refused (ccx has no such load).
//
// Node k (1-based k + 1) sits at polar angle spec.anchor() + 360 k / nodes (degrees), the
// anchor of every solver (the pin, or a free ring's free_anchor); B31: nodes = elements,
// B32/B32R: nodes = 2 elements (the middle nodes on the circle too).
// An arch (ring.arc = [from, to]) is an open line of the same elements from `from` to `to`:
// node k + 1 at from + span k / pieces, k = 0..pieces (pieces = elements for B31, 2 elements
// for B32/B32R: one node more than the ring's), node 1 at `from`; the ends take the supports
// at their angles (pin: both displacements held; clamp: the rotation too; none: free).
#pragma once

#include <string>
#include <vector>

#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace calculix {

/// The analysis step a deck holds.
struct FrequencyStep {
  int eigenvalues = 0;  ///< ccx's *FREQUENCY count (in-plane, rigid and out-of-plane modes together)
};

/// The steps of a spinning ring's modes (rotation.speed != 0): spinning_deck.
struct SpinStep {
  int eigenvalues = 0;  ///< the real modes of the *FREQUENCY step, the basis of the complex ones
  int complex = 0;      ///< ccx's *COMPLEX FREQUENCY count (at most eigenvalues)
};

struct Deck {
  std::string text;                 ///< the .inp file
  std::vector<double> node_angles;  ///< degrees, node k + 1 at node_angles[k]
  double anchor = 0.0;              ///< degrees: the angle of node 1
  double width = 0.0, height = 0.0; ///< m: the section written (height radial; circle: both the diameter)
  int last_element = 0;             ///< the highest element number written (the next terms number on)
};

/// Whether the analysis has inertia: a point mass's rotary inertia, which ccx cannot
/// write, is refused in modes and responses and ignored in statics.
enum class Inertia { matters, ignored };

/// Refuses what the deck cannot express (ring::InputError naming the key, exit 2): a
/// rotational spring, a point mass's rotary inertia (Inertia::matters), a point term off
/// the nodes, a general section as given. O(terms).
void check_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                Inertia inertia = Inertia::matters);

/// The deck of a frequency analysis. O(elements).
Deck frequency_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, const FrequencyStep& step,
                    const std::string& title = "");

/// The deck of the modes of a spinning ring (rotation.speed = Omega about +z), in the frame
/// that turns with it:
/// 1. *STEP, NLGEOM with *STATIC: the centrifugal body force *DLOAD ERING, CENTRIF, Omega^2,
///    point (0, 0, 0), axis (0, 0, 1) (rotation.tension = "spin": the prestressed equilibrium;
///    "none": the same step without a load, so that the next step is a perturbation of the
///    unstressed ring);
/// 2. *STEP, PERTURBATION with *FREQUENCY, STORAGE=YES: the real modes of the tangent with the
///    prestress's geometric stiffness and the centrifugal softening -Omega^2 M (e_c3d adds the
///    softening in a perturbation step only, which is why "none" needs step 1 too; with "none"
///    the CENTRIF load is given in this step);
/// 3. *STEP, PERTURBATION with *COMPLEX FREQUENCY, CORIOLIS: the gyroscopic modes in the basis
///    of step 2's modes, printed with their beam nodes' real and imaginary parts.
/// It writes what check_spin refuses too (a free ring: the tests measure ccx with it); the
/// column does not use it (the springs' MPCs spoil ccx's Coriolis matrix: spinning_brick_deck).
/// O(elements).
Deck spinning_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, const SpinStep& step,
                   const std::string& title = "");

/// A spinning ring as C3D20R bricks written by the deck (spinning_brick_deck) and where its
/// centroid line's displacement is read.
struct BrickRing {
  Deck deck;   ///< node_angles: the 2 elements stations of the centroid line (B32R's nodes)
  int nodes = 0;  ///< brick nodes, 1 .. nodes
  /// [station k]: the brick nodes (1-based) whose mean displacement is the centroid's at
  /// deck.node_angles[k]: the two at the centroid radius on the width's faces at an element's
  /// end, the four inner and outer corners of the faces at its middle.
  std::vector<std::vector<int>> stations;
};

/// The deck of the modes of a spinning ring with the bricks written by the deck, not expanded
/// by ccx from beam elements: ccx 2.20 assembles the Coriolis matrix wrongly at the degrees of
/// freedom an MPC makes dependent (calculix/README.md, "Spinning rings"), and every spring,
/// mass or support on an expanded beam's node is such an MPC. So: one C3D20R brick through the
/// depth and one through the width per element (the section of the beam deck: the equivalent
/// rectangle, or the rectangle as given), `elements` around, the 20-node grid of theta
/// half-steps, radial and width levels 0..2 (at most one of them odd); Poisson's ratio 0;
/// the out-of-plane displacement of every node held; a pin as both displacements of the two
/// centroid nodes of its end section held (*BOUNDARY), a clamp as all eight nodes of the
/// section held, an axis-aligned roller as one displacement of the two centroid nodes, an
/// elastic support as SPRING1 on the two centroid nodes (half each), the foundation as
/// SPRING1 on every station's nodes in the cylindrical system (each node L/6: the end
/// section's L/3 on two nodes, the middle's 2L/3 on four). No *EQUATION anywhere. The three
/// steps of spinning_deck, *NODE PRINT of every node. check_spin's refusals apply (the point
/// terms at element ends, no oblique roller). O(elements).
BrickRing spinning_brick_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, const SpinStep& step,
                              const std::string& title = "");

/// Refuses a spinning ring the deck cannot write (ring::InputError naming the key): an arch
/// (ring.arc), rigid modes (rotation.speed: the spin's softening makes a free motion
/// unstable, as the scene reader says), point masses (masses: ccx 2.20's Coriolis matrix,
/// mafillcorio, assembles solid elements only and its MASS elements get neither the Coriolis
/// term nor the centrifugal softening), an element other than B32R (calculix.element: measured
/// on the foundation ring of tests/calculix/calculix_spin_test.cpp, B31's real step puts the
/// k = 1 pair at 7.25 rad/s where the translation on the foundation is 10.80, and B32's split
/// is 5.2 % low at 40 and 160 elements), what the bricks of spinning_brick_deck cannot carry
/// without an MPC: a point term (support, spring) off the element ends (its key: the bricks
/// have no node on the centroid line at an element's middle), a roller whose line is not
/// along x or y (supports.roller: an *EQUATION), a circle as given (calculix.section). Nothing
/// at rest.
void check_spin(const ring::RingSpec& spec, const ring::CalculixOptions& options);

/// The deck of the nonlinear statics under static's loads: *STEP, NLGEOM with *STATIC in
/// static.steps equal increments (ccx may cut them), the load blocks (see above; point
/// masses only as their weight), *NODE PRINT of the beam nodes after every increment.
/// static.displacement: the driven node (set NDRIVE) held by *BOUNDARY at the value for load
/// factor 1, its RF printed after the displacements. static.history: one such *STEP per leg
/// (period 1 each), the loads and the boundary with AMPLITUDE=LOAD, an amplitude in total time
/// through (k, s_k). [plates]: plates_block's springs, the plate nodes (sets NPLATE0,
/// NPLATE1) moved along the plates' normal by s travel / 2 as the driven node is, their RF
/// totals printed after the displacements. Throws ring::InputError for a load or a driven
/// point off the nodes (static.displacement.at), a load ccx cannot express, or plates it
/// cannot write (check_plates). O(elements + legs).
Deck static_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::StaticOptions& step,
                 const std::string& title = "");

/// [plates] as ccx elements (ring::PlatePair's law, integrated as the foundation is: at the
/// beam nodes, each for its share of the ring, L/3 at an element's end node and 2L/3 at its
/// middle node). For every beam node on the half of the ring facing plate p (cos(theta -
/// axis) > 0 for p = 0, < 0 for p = 1; the nodes at axis +- 90 can touch neither) an extra
/// "plate" node lies kPlateSpringLength beyond the plate's line along d_p, and a SPRINGA
/// element joins it to the beam node. The plate nodes carry a rectangular *TRANSFORM with
/// local 1 = e (the plates' direction) and local 2 = d_0; local 2 is driven by -+ s travel / 2
/// (the step's boundary, static_deck), local 1 is tied to the beam node's e . u by an
/// *EQUATION (a one-term boundary at the two nodes of first contact, whose e . u is held
/// anyway), so that each spring stays along d_p: the plates are frictionless. Its length is
/// then kPlateSpringLength + g, g = PlatePair::gap at the beam node (ccx prints the beam node
/// as the mean of the expanded section, the centroid line), and its nonlinear force–elongation
/// table (*SPRING, NONLINEAR) is 0 while the gap is open and k w g beyond (k w: the penalty
/// times the node's share; elongation = g - g_0, g_0 = R (1 - |cos(theta - axis)|) the rest
/// gap). ccx takes the tangent of a table at one of its rows from the segment above it, so the
/// two nodes of first contact (g_0 = 0, touching at rest) have the stiff slope over a window of
/// kPlateWindow above 0 (the ring would be free along the axis in the first iteration
/// otherwise; the window's tension, at most k w kPlateWindow, acts only with the gap inside
/// it). The no-slide rows: e . u = 0 at the nodes at axis and axis + 180 (*BOUNDARY of one
/// displacement when e is along x or y, else a two-term *EQUATION). The string is the model
/// part (before the steps).
std::string plates_block(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                         const ring::StaticOptions& st, Deck& deck);

/// A plate node's distance beyond its plate's line, times R (the springs' length at contact); it
/// needs only to exceed the penalty's sinking, and is short so that the elongation, a
/// difference of lengths, keeps its digits.
constexpr double kPlateSpringLength = 0.1;
/// Times R: the window of the stiff slope above a touching node's kink (plates_block).
constexpr double kPlateWindow = 1e-15;

/// Refuses [plates] the deck cannot write (ring::InputError naming the key): an arch
/// (ring.arc), loads or supports beside them (the scene reader's rules, for the library's
/// callers), an element other than B32R (calculix.element: the only one validated), a
/// history leg that draws the plates back (static.history: ccx's first iteration of a return
/// finds the springs open, and its Newton alternates between open and deep contact), the nodes at axis and axis + 180
/// not nodes of the model (plates.axis).
void check_plates(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::StaticOptions& st);

/// The deck of the forced response: *STEP, NLGEOM with *DYNAMIC, DIRECT, ALPHA = 0
/// (Newmark's average acceleration, fixed dt to t_end), every load times the history as an
/// *AMPLITUDE, *NODE PRINT of the recorded nodes after every increment. Throws
/// ring::InputError for what it cannot express (check_response_deck) or points off the
/// nodes. O(elements + t_end / dt).
Deck response_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                   const ring::ResponseOptions& response, const std::string& title = "");

/// Refuses response options the deck cannot write: an integrator other than "newmark",
/// damping (Rayleigh, hinge). ring::InputError naming the key.
void check_response_deck(const ring::ResponseOptions& response);

/// Nodes of a ring's model: elements (B31) or 2 elements (B32, B32R).
int node_count(const ring::CalculixOptions& options);
/// Nodes of the model of `spec`: a ring's as above, an arch's one more (both ends).
int node_count(const ring::RingSpec& spec, const ring::CalculixOptions& options);

/// A number as ccx reads it: at most 20 characters (ccx's field width), 14 significant
/// digits (13 for a three-digit exponent).
std::string number(double x);

}  // namespace calculix
