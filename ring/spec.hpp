// The shared vocabulary of ringvib: what a ring is, how it is held and loaded,
// and how each solver discretizes it. Every solver takes these by const reference.
//
// Conventions (README): SI units; the ring's centre is the origin of the
// reporting frame; a point on the ring is named by its polar angle in degrees,
// counter-clockwise from +x; radial displacement positive outward, tangential
// positive counter-clockwise; frequencies are angular (rad/s).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ring {

/// Cross-section of the ring. The ring bends in its own plane, so `inertia` is the
/// second moment of area about the axis normal to that plane.
struct Section {
  enum class Shape { circle, rectangle, general };
  Shape shape = Shape::circle;
  double diameter = 0.0;  ///< circle: m
  double width = 0.0;     ///< rectangle: m, normal to the ring's plane
  double height = 0.0;    ///< rectangle: m, radial depth (in the ring's plane)
  double area_ = 0.0;     ///< general: m^2
  double inertia_ = 0.0;  ///< general: m^4

  double area() const;     ///< A, m^2
  double inertia() const;  ///< I, m^4 (in-plane bending)
  /// Radial extent used for the thin-ring check: diameter, height, or 2*sqrt(3)*radius
  /// of gyration for a general section (the height of a rectangle with the same A and I).
  double depth() const;
};

/// Supports shared by all solvers. No pin = free ring (three rigid modes).
/// `pin`: both displacements zero, rotation free. `roller` (needs a pin): that
/// point stays on the line through the pin and itself (the paper's section 5).
struct Supports {
  std::optional<double> pin;     ///< degrees
  std::optional<double> roller;  ///< degrees
  bool free() const { return !pin.has_value(); }
  /// Rigid modes the supports leave: 3 (free), 1 (pin), 0 (pin + roller).
  int rigid_modes() const { return !pin ? 3 : (roller ? 0 : 1); }
};

/// Time history of a load factor f(t) that multiplies a point load's force.
struct LoadHistory {
  enum class Kind { step, ramp, half_sine, harmonic };
  Kind kind = Kind::step;
  double period = 1.0;  ///< s: ramp time, pulse length, or harmonic period
  /// step: 1; ramp: min(t/T, 1); half-sine: sin(pi t/T) for t < T, else 0;
  /// harmonic: sin(2 pi t/T). Zero for t < 0.
  double factor(double t) const;
};

/// A force of fixed direction (dead load) applied at a point of the ring.
struct PointLoad {
  double angle = 0.0;                 ///< degrees, where it acts (a node of every model)
  std::array<double, 2> force{0, 0};  ///< N, ring-centred frame (x, y)
  LoadHistory history;
};

/// The ring itself: geometry, material and supports.
struct RingSpec {
  double radius = 10.0;  ///< m, centroid radius R
  double E = 2.1e11;     ///< Pa
  double rho = 7.8e3;    ///< kg/m^3
  Section section;
  Supports supports;

  double A() const { return section.area(); }
  double I() const { return section.inertia(); }
  double EI() const { return E * section.inertia(); }
  double EA() const { return E * section.area(); }
  double rhoA() const { return rho * section.area(); }
  /// sqrt(EI / (rho A R^4)), rad/s: the scale of every bending frequency.
  double bending_frequency_scale() const;
  /// R / radius of gyration sqrt(I/A): the slenderness of the ring.
  double slenderness() const;
};

// ---- Discretization options, one struct per solver (validated by the scene parser) ----

struct MultibodyOptions {
  int n = 40;                   ///< rigid segments (>= 4)
  bool rotary_inertia = true;   ///< segment rotary inertia m l^2 / 12
  enum class Dependent { robust, paper };
  Dependent dependent = Dependent::robust;  ///< choice of dependent angles
  enum class Method { automatic, dense, sparse };
  Method method = Method::automatic;  ///< dense angle coordinates or sparse large-n path
};

struct FemOptions {
  int elements = 40;      ///< cells around the ring (>= 4)
  int degree = 3;         ///< polynomial degree p (>= 2)
  enum class Geometry { curved, polygon };
  Geometry geometry = Geometry::curved;
  bool extensible = true;        ///< axial strain energy EA; false: inextensible limit
  bool rotary_inertia = false;   ///< cross-section rotary inertia rho I
  bool reference = false;        ///< refine until converged
  double tolerance = 1e-9;       ///< relative change that stops the refinement (modes, statics)
  double response_tolerance = 1e-3;  ///< the same for the peaks of the reference response
};

struct LumpedOptions {
  int n = 40;  ///< links / elements (>= 4)
  enum class Variant { chain, frame, frame_consistent };
  Variant variant = Variant::chain;
};

/// Node angles of a model with n equal pieces: anchor + 360 k / n, k = 0..n-1,
/// where the anchor is the pin (or, for a free ring, `fallback`).
std::vector<double> node_angles(const RingSpec& spec, int n, double fallback = 0.0);
/// True when `angle` (degrees) coincides with a node of an n-piece model anchored at `anchor`.
bool on_node(double angle, double anchor, int n);
/// Angle difference reduced to [0, 360).
double wrap_degrees(double a);

std::string to_string(MultibodyOptions::Dependent d);
std::string to_string(LumpedOptions::Variant v);
std::string to_string(FemOptions::Geometry g);
std::string to_string(LoadHistory::Kind k);

}  // namespace ring
