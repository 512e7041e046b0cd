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
// - pin: both displacements of its node held (rotation free, so no rotation boundary
//   condition, which ccx would turn into a rigid knot of the expanded section);
// - roller: its node stays on the line through the pin and itself: one displacement held
//   if that line is along x or y, else a two-term *EQUATION.
// Every other term a ring spec may carry is refused until the deck can write it.
//
// Node k (1-based k + 1) sits at polar angle anchor + 360 k / nodes (degrees), anchor the
// pin or 0 for a free ring; B31: nodes = elements, B32/B32R: nodes = 2 elements (the
// middle nodes on the circle too).
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

struct Deck {
  std::string text;                 ///< the .inp file
  std::vector<double> node_angles;  ///< degrees, node k + 1 at node_angles[k]
  double anchor = 0.0;              ///< degrees: the angle of node 1
  double width = 0.0, height = 0.0; ///< m: the section written (height radial; circle: both the diameter)
};

/// Refuses what the deck cannot express (ring::InputError naming the key, exit 2). O(1).
void check_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options);

/// The deck of a frequency analysis. O(elements).
Deck frequency_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, const FrequencyStep& step,
                    const std::string& title = "");

/// The deck of the nonlinear statics under static.at/static.force: *STEP, NLGEOM with
/// *STATIC in static.steps equal increments (ccx may cut them), *CLOAD at the load's node,
/// *NODE PRINT of the beam nodes after every increment. Throws ring::InputError if the
/// load is not at a node. O(elements).
Deck static_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, const ring::StaticOptions& step,
                 const std::string& title = "");

/// The deck of the forced response: *STEP, NLGEOM with *DYNAMIC, DIRECT, ALPHA = 0
/// (Newmark's average acceleration, fixed dt to t_end), the load's history as an
/// *AMPLITUDE, *NODE PRINT of the recorded nodes after every increment. Throws
/// ring::InputError for what it cannot express (check_response_deck) or points off the
/// nodes. O(elements + t_end / dt).
Deck response_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options,
                   const ring::ResponseOptions& response, const std::string& title = "");

/// Refuses response options the deck cannot write: an integrator other than "newmark",
/// damping (Rayleigh, hinge). ring::InputError naming the key.
void check_response_deck(const ring::ResponseOptions& response);

/// Nodes of the model: elements (B31) or 2 elements (B32, B32R).
int node_count(const ring::CalculixOptions& options);

/// A number as ccx reads it: at most 20 characters (ccx's field width), 14 significant
/// digits (13 for a three-digit exponent).
std::string number(double x);

}  // namespace calculix
