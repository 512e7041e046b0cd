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

#include "ring/plastic.hpp"

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

/// An elastic support at a point of the centroid line: springs to the ground in the
/// global x and y directions and in rotation (any may be 0; all >= 0).
struct Spring {
  double angle = 0.0;  ///< degrees (a node of every model)
  double kx = 0.0;     ///< N/m
  double ky = 0.0;     ///< N/m
  double kr = 0.0;     ///< N m/rad, on the rotation of the centroid line's tangent there
};

/// Supports shared by all solvers. No pin = free ring (three rigid modes, unless springs
/// or a foundation hold it).
/// `pin`: the first pinned point (both displacements zero, rotation free); the models
/// anchor their nodes there. `pins`: further pinned points. `clamp` (a pinned point, `pin`
/// or one of `pins`): its rotation is zero too. `roller` (needs a pin): that point stays
/// on the line through the pin and itself (the paper's section 5).
struct Supports {
  std::optional<double> pin;     ///< degrees
  std::optional<double> roller;  ///< degrees
  std::vector<double> pins;      ///< degrees, further pins (never `pin` itself)
  std::optional<double> clamp;   ///< degrees, equal to `pin` or to one of `pins`
  std::vector<Spring> springs;
  bool free() const { return !pin.has_value(); }
  /// Every pinned point: `pin`, then `pins`.
  std::vector<double> pinned() const;
  /// Constraint rows on the displacements: 2 per pinned point, 1 for the roller, 1 for
  /// the clamp's rotation.
  int constraint_rows() const { return 2 * static_cast<int>(pinned().size()) + (roller ? 1 : 0) + (clamp ? 1 : 0); }
  /// True for the paper's supports alone: a pin and/or a roller, nothing else.
  bool paper_only() const { return pins.empty() && !clamp && springs.empty(); }
};

/// A rigid point mass attached to the centroid line, with its rotary inertia about the
/// axis normal to the ring's plane (it turns with the centroid line's tangent).
struct PointMass {
  double angle = 0.0;    ///< degrees (a node of every model)
  double mass = 0.0;     ///< kg, >= 0
  double inertia = 0.0;  ///< kg m^2, >= 0
};

/// A Winkler foundation over the whole ring: a restoring force per unit length of the
/// centroid line, -radial * u_r and -tangential * u_t, with u_r, u_t the displacement of
/// the centroid line from its rest position along the radial and tangential directions of
/// the undeformed point (fixed directions, also under large displacements).
struct Foundation {
  double radial = 0.0;      ///< N/m per metre of ring (N/m^2), >= 0
  double tangential = 0.0;  ///< N/m per metre of ring (N/m^2), >= 0
  bool any() const { return radial > 0.0 || tangential > 0.0; }
};

/// Time history of a load factor f(t) that multiplies every load of a response.
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
};

/// A uniform pressure on the centroid line, per unit length of the undeformed centroid
/// line, positive inward. With p the value and ds0 an element of undeformed length at the
/// point x(s0) of the deformed ring:
///  - follower: p |dx/ds0| n ds0 with n the inward normal of the *deformed* ring (hydrostatic:
///    -p times the rotated tangent dx/ds0; it does work p dA on the enclosed area A and has a
///    symmetric load stiffness on a closed ring);
///  - dead: p n0 ds0 with n0 the inward normal of the *undeformed* point (fixed direction and
///    magnitude);
///  - central: p ds0 toward the ring's centre from the deformed point, -p x/|x| ds0.
/// All three equal p n0 ds0 on the undeformed ring, so linear analyses (and the first step
/// of a nonlinear one) see the same load; they differ in their load stiffness.
struct Pressure {
  enum class Kind { follower, dead, central };
  double value = 0.0;  ///< N/m, positive inward; 0 = no pressure
  Kind kind = Kind::follower;
  bool any() const { return value != 0.0; }
};

/// Everything that loads the ring in statics or a response, all scaled by one load factor
/// (statics: the load step; response: the history f(t)).
struct Loads {
  std::vector<PointLoad> points;         ///< dead point loads, at nodes of every model
  Pressure pressure;                     ///< uniform pressure
  std::array<double, 2> gravity{0, 0};   ///< m/s^2, acting on the ring and on the point masses
  bool has_gravity() const { return gravity[0] != 0.0 || gravity[1] != 0.0; }
  /// True when only point loads act (the paper's loading, in any number).
  bool points_only() const { return !pressure.any() && !has_gravity(); }
  /// True when a load's direction or size follows the deformed ring (follower or central
  /// pressure); the others (point loads, gravity, dead pressure) are constant forces.
  bool shape_dependent() const { return pressure.any() && pressure.kind != Pressure::Kind::dead; }
  /// The scene keys of the loads beyond one point load ("pressure", "gravity", "loads"), in
  /// `section` ("static", "response"), for refusals that name them.
  std::vector<std::string> beyond_one_point(const std::string& section) const;
};

/// ring.arc: an open arch whose centroid line runs counter-clockwise on the circle of radius R
/// from the polar angle `from` to `to` (degrees, 0 < to - from < 360). Its ends take the
/// supports at their angles (a pin, a clamp, springs); an end without one is free. Every model
/// of an arch puts a node at each end and cuts the arch into equal pieces from `from` to `to`.
struct Arc {
  double from = 0.0;  ///< degrees
  double to = 0.0;    ///< degrees, from < to < from + 360
  double span() const { return to - from; }
  /// True when the polar angle `deg` lies on the arch (ends included, to 1e-9 degrees), in any
  /// turn of the circle.
  bool contains(double deg) const;
  /// The position of `deg` along the arch, in degrees from `from` in [0, 360): in [0, span()]
  /// for a point of the arch.
  double offset(double deg) const;
};

/// The beam theory of the ring's wall.
/// euler_bernoulli: plane sections stay normal to the centroid line (no shear strain).
/// timoshenko: the cross-section turns independently of the centroid line's tangent; shear
/// strain energy kappa G A/2 gamma^2 with G = E / (2 (1 + nu)) and the shear coefficient
/// kappa, and the cross-section's rotary inertia rho I.
enum class Theory { euler_bernoulli, timoshenko };

/// [rotation]: the ring spins at `speed` rad/s about its axis (counter-clockwise positive) and
/// is analysed in the frame that turns with it: the Coriolis (gyroscopic) term 2 speed m S v,
/// the centrifugal softening -speed^2 m, and the spin's hoop tension or none.
struct Rotation {
  double speed = 0.0;  ///< rad/s; 0: at rest (every analysis as without [rotation])
  /// spin: the centrifugal body force's prestress (the hoop tension rho A speed^2 R^2 of the
  /// free ring) and its geometric stiffness; none: without it, as inflation-only tyre models.
  enum class Tension { spin, none } tension = Tension::spin;
  bool spinning() const { return speed != 0.0; }
};

/// ring.variations: one harmonic of an imperfect ring's variation around the circumference:
/// the section's radial depth and the density change by the relative amounts `thickness` and
/// `density` times cos(harmonic (theta - phase)). A rectangle keeps its width (A ~ depth,
/// I ~ depth^3), a circle scales its diameter (A ~ depth^2, I ~ depth^4); a section given by
/// {area, inertia} has no depth and takes only density variations (the scene reader).
struct Variation {
  int harmonic = 1;        ///< K >= 1
  double thickness = 0.0;  ///< relative amplitude of the radial depth's variation
  double density = 0.0;    ///< relative amplitude of the density's variation
  double phase = 0.0;      ///< degrees
};

/// The ring itself: geometry, material and supports.
struct RingSpec {
  double radius = 10.0;  ///< m, centroid radius R
  double E = 2.1e11;     ///< Pa
  double rho = 7.8e3;    ///< kg/m^3
  Theory theory = Theory::euler_bernoulli;
  double nu = 0.3;       ///< Poisson's ratio, (-1, 0.5)
  /// kappa of the Timoshenko theory; 0 = Cowper's (1966) value for the section's shape:
  /// rectangle 10 (1 + nu) / (12 + 11 nu), circle 6 (1 + nu) / (7 + 6 nu). A general
  /// {area, inertia} section has no shape, so the scene must give it.
  double shear_coefficient = 0.0;
  Section section;
  Supports supports;
  std::vector<PointMass> masses;
  Foundation foundation;
  /// ring.arc: an arch from `from` to `to`; none: the closed ring.
  std::optional<Arc> arc;
  bool is_arch() const { return arc.has_value(); }
  /// ring.plastic: the elastic–plastic bending law (ring/plastic.hpp); none: elastic.
  std::optional<Plastic> plastic;
  /// [rotation]: the spin of the ring and the frame it is analysed in.
  Rotation rotation;
  /// ring.variations: the imperfect ring's section and density around the circumference
  /// (empty: uniform). The *_at(deg) members below give the local values.
  std::vector<Variation> variations;
  bool varies() const { return !variations.empty(); }
  /// The local radial depth and density over the uniform ones at the polar angle `deg`:
  /// 1 + sum thickness cos(K (deg - phase)), 1 + sum density cos(K (deg - phase)); > 0 (the
  /// scene reader keeps the sums of |amplitude| below 1).
  double depth_factor(double deg) const;
  double density_factor(double deg) const;
  /// Local section and mass properties at `deg` (the uniform A(), I(), EI(), ... when uniform).
  double A_at(double deg) const;
  double I_at(double deg) const;
  double EI_at(double deg) const { return E * I_at(deg); }
  double EA_at(double deg) const { return E * A_at(deg); }
  double rhoA_at(double deg) const { return rho * density_factor(deg) * A_at(deg); }
  double rhoI_at(double deg) const { return rho * density_factor(deg) * I_at(deg); }
  double kGA_at(double deg) const { return kappa() * G() * A_at(deg); }
  /// Degrees: where the models of a free ring (no pin) put their node 0, so that every model
  /// of every solver has the same nodes. The scene reader sets it to the first point load of
  /// the scene (static, then response, then buckling; 0 without one). A pinned
  /// ring's models start at the pin and ignore it.
  double free_anchor = 0.0;
  /// Where every model puts its node 0: an arch's `from` end; a ring's pin, or free_anchor.
  double anchor() const { return arc ? arc->from : supports.pin.value_or(free_anchor); }

  /// The angle the centroid line subtends, rad: 2 pi for a ring, an arch's span.
  double opening() const;
  /// The centroid line's length, m: radius x opening().
  double length() const { return radius * opening(); }

  double A() const { return section.area(); }
  double I() const { return section.inertia(); }
  double EI() const { return E * section.inertia(); }
  double EA() const { return E * section.area(); }
  double rhoA() const { return rho * section.area(); }
  double rhoI() const { return rho * section.inertia(); }
  double G() const { return E / (2.0 * (1.0 + nu)); }
  /// The shear coefficient in use: shear_coefficient, or Cowper's for the shape (0 for a
  /// general section without one: the scene reader refuses that under timoshenko).
  double kappa() const;
  /// kappa G A, N: the shear stiffness of the Timoshenko theory.
  double kGA() const { return kappa() * G() * A(); }
  /// sqrt(EI / (rho A R^4)), rad/s: the scale of every bending frequency.
  double bending_frequency_scale() const;
  /// R / radius of gyration sqrt(I/A): the slenderness of the ring.
  double slenderness() const;
  /// Rigid-body motions (two translations, the rotation about the centre) that the
  /// supports, springs and foundation leave free of constraint and of energy: 3 - the rank
  /// of their rows on those motions (0 to 3). Every solver counts its rigid modes by it.
  int rigid_modes() const;
  /// True for the paper's ring: a pin and/or a roller and nothing of supports.pins,
  /// supports.clamp, supports.springs, masses or foundation.
  bool paper_terms_only() const { return supports.paper_only() && masses.empty() && !foundation.any(); }
  /// The scene keys of the terms beyond the paper's ring that this spec has
  /// ("supports.clamp", "masses", "foundation", ...), for refusals that name them.
  std::vector<std::string> terms_beyond_paper() const;
};

/// Throws std::invalid_argument "`who` does not take a spinning ring (rotation.speed) yet" when
/// spec spins, for a solver or analysis that has only the ring at rest.
void refuse_rotation(const RingSpec& spec, const std::string& who);

/// Throws std::invalid_argument "`who` does not take ring.variations yet" when spec varies
/// around its circumference, for a solver or analysis that has only the uniform ring.
void refuse_variations(const RingSpec& spec, const std::string& who);

/// Throws std::invalid_argument "`who` has no Timoshenko model yet (ring.theory, or the
/// solver's multibody.theory or fem.theory)" when spec.theory is Timoshenko, for a solver or
/// analysis that has only the Euler-Bernoulli theory. The driver hands each solver the spec
/// with its model theory in spec.theory (compare/registry.hpp model_scene), so the key that
/// set it may be the solver's own.
void refuse_timoshenko(const RingSpec& spec, const std::string& who);

/// Throws std::invalid_argument "`who` does not take an arch (ring.arc) yet" when spec is an
/// arch, for a solver or analysis that has only the closed ring.
void refuse_arch(const RingSpec& spec, const std::string& who);

/// Throws std::invalid_argument "`who` does not take KEYS yet" when `spec` has terms beyond
/// the paper's ring (RingSpec::terms_beyond_paper), for an analysis that lacks them.
void refuse_terms_beyond_paper(const RingSpec& spec, const std::string& who);


/// The window of magnitudes that the solvers' arithmetic holds, for every scale of the model
/// (check_scales). Why 1e100: a discretized model multiplies a scale by at most
/// (n / 2 pi)^4 <= 1e30 (a fourth difference over n <= 1e8 pieces), and the residuals, norms
/// and Gram products square their entries, so an entry must stay within [1e-154, 1e154] for
/// its square to remain a normal double: 1e100 x 1e30 = 1e130 and 1e-100 / 1e30 = 1e-130
/// leave a factor 1e24 to spare. A ring outside it (E = 1e300 Pa, a foundation of 1e200
/// N/m^2) overflowed to NaN residuals that passed as eigenpairs (issue 46).
constexpr double kMinScale = 1e-100, kMaxScale = 1e100;

/// One scale of the model outside [kMinScale, kMaxScale]: the scene key (or keys) that set
/// it and what was found and expected.
struct ScaleViolation {
  std::string key;
  std::string what;
};

/// The first scale of `spec` outside the window, or nothing. The rule (docs/scenes.md, "The scale
/// rule"), in SI units:
/// - the ring's own scales, EI/R^4 and EA/R^2 (N/m^2), rho A (kg/m) and its squared
///   frequency scale EI/(rho A R^4) (1/s^2), lie within [kMinScale, kMaxScale];
/// - each term added to the ring is at most kMaxScale as a stiffness or mass per metre of
///   ring, and so is its frequency scale against the ring's mass: the foundation moduli k
///   (N/m^2, and k/(rho A)), each spring's kx/R, ky/R, kr/R^3 (N/m^2, and over rho A), each
///   point mass's m/R and inertia/R^3 (kg/m). A term may be as small as it likes (0 is none).
/// O(supports + masses).
std::optional<ScaleViolation> scale_violation(const RingSpec& spec);

/// The rigid motions that a static analysis under `loads` leaves free: spec.rigid_modes(),
/// less the rotation about a single pin when gravity holds it (the ring hangs from the pin:
/// the centre (an arch's centroid) lies below it, g . (centre - pin) > 0, so turning raises the centre of mass).
/// A static analysis needs 0.
int static_rigid_modes(const RingSpec& spec, const Loads& loads);

/// A force scale of the loads at load factor 1, N: the sum of the point loads' magnitudes, of
/// |pressure| times the circumference and of the weight of the ring and the point masses.
double load_scale(const RingSpec& spec, const Loads& loads);

// ---- Discretization options, one struct per solver (validated by the scene parser) ----

struct MultibodyOptions {
  int n = 40;                   ///< rigid segments (>= 4)
  bool rotary_inertia = true;   ///< segment rotary inertia m l^2 / 12
  enum class Dependent { robust, paper };
  Dependent dependent = Dependent::robust;  ///< choice of dependent angles
  enum class Method { automatic, dense, sparse };
  Method method = Method::automatic;  ///< dense angle coordinates or sparse large-n path
  /// The beam theory of the model (multibody.theory); empty: ring.theory. ring.theory is
  /// the physics (what the reference solves); this is the model the chain is, so an
  /// Euler-Bernoulli chain of a Timoshenko ring measures what the thin-ring model misses.
  /// The driver hands the solver the spec with RingSpec::theory replaced by it.
  std::optional<Theory> theory;
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
  /// The beam theory of the FE model (fem.theory); empty: ring.theory. As
  /// MultibodyOptions::theory; the converged reference ignores it and solves ring.theory.
  std::optional<Theory> theory;
};

struct LumpedOptions {
  int n = 40;  ///< links / elements (>= 4)
  /// The variant is the model's theory (there is no lumped.theory): chain, frame,
  /// frame_consistent are Euler-Bernoulli models (of either ring.theory: on a Timoshenko
  /// ring they are its thin-ring model); timoshenko_frame has shear-flexible elements with
  /// rotary inertia (lumped_mass/model.hpp), on a ring whose shear coefficient is defined
  /// (lumped_mass/checks.hpp check_theory).
  enum class Variant { chain, frame, frame_consistent, timoshenko_frame };
  Variant variant = Variant::chain;
};

/// The external CalculiX column (calculix/): beam elements around the ring, expanded by
/// ccx into 20-node (B32, B32R) or 8-node (B31) bricks of the section's shape.
struct CalculixOptions {
  int elements = 160;  ///< beam elements around the ring (>= 4)
  enum class Element { b31, b32r, b32 };
  Element element = Element::b32r;  ///< B32R: quadratic, reduced integration (the default)
  /// equivalent_rectangle: a RECT section with the ring's A and I (width A/h, radial
  /// height h = sqrt(12 I / A)); as_given: the scene's circle (CIRC) or rectangle (RECT).
  enum class Section { equivalent_rectangle, as_given };
  Section section = Section::equivalent_rectangle;
  double timeout = 600.0;  ///< s, the longest a ccx run may take (then exit 3)
  int threads = 1;         ///< OMP_NUM_THREADS and CCX_NPROC_* of the ccx process
};

/// Node angles of a model with n equal pieces, in [0, 360): a ring's n nodes
/// spec.anchor() + 360 k / n, k = 0..n-1; an arch's n + 1 nodes from + span k / n, k = 0..n.
std::vector<double> node_angles(const RingSpec& spec, int n);
/// The number of nodes of a model with n equal pieces: n for a ring, n + 1 for an arch.
inline int node_count(const RingSpec& spec, int n) { return spec.arc ? n + 1 : n; }
/// True when `angle` (degrees) coincides with a node of an n-piece model anchored at `anchor`
/// (a closed ring).
bool on_node(double angle, double anchor, int n);
/// The index k of the node of an n-piece model of `spec` (ring or arch) at `angle`, or -1 when
/// none is there (to 1e-9 of a piece, as on_node). O(1).
int node_index(const RingSpec& spec, double angle, int n);
/// True when `angle` is a node of an n-piece model of `spec` (ring or arch).
inline bool on_node(const RingSpec& spec, double angle, int n) { return node_index(spec, angle, n) >= 0; }
/// Angle difference reduced to [0, 360).
double wrap_degrees(double a);

std::string to_string(MultibodyOptions::Dependent d);
std::string to_string(LumpedOptions::Variant v);
std::string to_string(FemOptions::Geometry g);
std::string to_string(LoadHistory::Kind k);
std::string to_string(Pressure::Kind k);
std::string to_string(Theory t);
std::string to_string(CalculixOptions::Element e);
std::string to_string(CalculixOptions::Section s);

}  // namespace ring
