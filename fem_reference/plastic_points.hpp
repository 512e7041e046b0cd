// Internal to fem_reference/: the elastic–plastic bending of the geometrically exact beams
// (ring.plastic: the resultant law of ring/plastic.hpp or the fibre law, both through
// ring::SectionLaw, ring/section_law.hpp) at their bending points. No deal.II here.
//
// A beam's bending energy density EI/2 kappa^2 becomes, at each bending point, the section
// law's incremental potential ring::SectionLaw(spec).at(committed, kappa).potential
// (kappa the curvature change, 1/m, exactly as the elastic beam measures it; the resultant
// law: one state per point, the bilinear law (EI, Mp, h, rule); the fibre law: 64 states per
// point, the fibres' uniaxial law on the strain y kappa summed over the section's depth):
// its derivative
// is the moment M, its second the tangent dM/dkappa, so the beam's internal force gains
// M dkappa and its tangent dM/dkappa dkappa dkappa^T + M d2kappa (chain rule through the
// exact curvature). The trial is always evaluated from the committed states (the return
// map from the last accepted equilibrium), so a rejected trial leaves nothing behind; the
// statics (static_path.cpp) commit at every accepted equilibrium, the response
// (nonlinear.cpp, BeamStepper) at every accepted time step.
// The fibre law has no axial strain here: the membrane strain stays elastic (EA/2 eps^2 on
// the p + 2 Gauss points) and the fibres see the bending strain y kappa only
// (ring::SectionLaw has no axial strain); a ring whose hoop force matters to its yield
// (pressure) is then yielded later than in a beam with coupled fibres.
//
// The points of a model, in its order (BeamModel::bending_points):
//  - Euler-Bernoulli (RingModel): per cell the p + 1 Gauss-Lobatto points, from the left
//    end to the right end (index cell (p + 1) + k). The bending is integrated there (the
//    membrane stays on the elastic beam's p + 2 Gauss points), not on the p + 2 Gauss
//    points: the curvature is a polynomial of degree p in a cell, which p + 2 points
//    over-determine (a plastic curvature cannot concentrate at one point while its
//    neighbours stay elastic); p + 1 points determine it, and the ends put a point where a
//    load is, at a vertex, where perfect plasticity under a point load yields at that point
//    alone. The ends' moments are also those of the interior penalty's consistency term
//    {M} [[phi]] at the vertex. Then, index cells (p + 1) + v, the hinge of every vertex v:
//    a plastic hinge at a point load is a jump of the rotation, which the interior
//    penalty's jump term (stiffness P = sigma EI / h) would hold elastically. Measured on
//    the pinched ring (fem_plastic_test): the law at the p + 2 Gauss points alone, or at the
//    Lobatto points alone, left the closing 24 to 29 % short at 8, 16 and 32 cells (and the
//    path lost stability spuriously at 64); with the vertex hinges it converges at order 4.
//    (The hinges with the Gauss points were not tried.) Written as
//    {M} J + P/2 J^2 = P/2 e^2 - {M}^2 / (2 P), e = J + {M} / P, P e = {M} + P J being
//    the moment the vertex passes on, the penalty becomes the law with stiffness P and
//    yield Mp at the strain e (rad): W_P(e) - {M}^2 / (2 P), exactly the elastic term
//    while it does not yield; a yielded hinge keeps a plastic jump (rad), reported as a
//    curvature over the cell length.
//    The fibre law (ring.plastic.stress) takes the same points and the same vertex hinges,
//    the hinge a bilinear law of stiffness P yielding at the section's fully plastic moment
//    sigma_y Z (SectionLaw::plastic_moment; hardening and rule the scene's). The fibre law has
//    no concentrated hinge, but near collapse it nearly has one: the moment-curvature law
//    tends to Mp with kappa ~ (Mp - M)^(-1/2) (the solid circle), so the curvature under a
//    point load peaks like |s|^(-1/2) as the load nears P_c, which a cell's polynomial cannot
//    follow; the vertex hinge, which yields once the vertex's moment P e reaches sigma_y Z,
//    carries that concentrated part. Measured on the pinched ring (fem_plastic_test, FemFibre;
//    Mp = sigma_y Z = 1e-6 EI / R, 64 fibres, the oracle tests/support/fibre_ring.hpp on the
//    same fibres), closing error at 8, 12, 16, 24, 32 cells: at 0.9 P_c, with the vertex
//    hinges 1.3e-2, 1.6e-5, 1.9e-3, 1.4e-3, 1.2e-3; without them (the Lobatto points alone)
//    0.31, 0.27, 0.25, 0.21, 0.18 (order 0.38: the peak). At 0.60 and 0.74 P_c the vertex
//    hinges do not yield and both are the same (see the test's printout for the orders).
//  - Timoshenko (TimoshenkoModel): none yet; check_static refuses ring.plastic with
//    ring.theory = "timoshenko". Its bending's p + 1 Gauss points over-determine the
//    curvature psi'/R (a polynomial of degree p - 1 in a cell) and psi is continuous, so
//    the law at those points formed no hinge (measured: the pinched ring's closing 26 %
//    short at 16 cells, and a spurious loss of stability at 64). The p-point Gauss-Lobatto
//    rule, ends included, as the Euler beam's, was tried: the path lost stability
//    spuriously as the ends yielded (8 cells, at 0.909 of the load: a yielded end leaves
//    the cell's curvature a mode without bending energy, which the axial compression
//    destabilizes), so the Reissner beam needs more than the Euler beam's points.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "ring/plastic.hpp"
#include "ring/section_law.hpp"

namespace fem::detail {

/// A bending point at a displacement: its curvature change and its weight.
struct BendingPoint {
  double curvature = 0.0;   ///< kappa, 1/m (a vertex hinge: its strain e, rad)
  double weight = 0.0;      ///< ds0 of the point's quadrature, m (a vertex hinge: 1)
  double per_length = 1.0;  ///< its plastic strain times this is a curvature, 1/m (a hinge: 1 / cell length)
  /// A vertex hinge's own law (stiffness P, one state); nullopt: a bending point, the
  /// section's law on section.states() states.
  std::optional<ring::BilinearLaw> law;
};

/// ring.plastic as the beam integrates it: the section's law at the bending points
/// (ring::SectionLaw: resultant or fibre) and a hinge at every vertex (above).
struct PlasticLaw {
  ring::Plastic plastic;
  ring::SectionLaw section;
  /// The vertex force's symmetry term with the elastic moment's variation (ring_beam.cpp:
  /// continuous where a cell end yields, but no potential's gradient there). Set by the
  /// statics with the resultant law, whose ends' single tangent drop stalled their Newton;
  /// the response (BeamStepper, whose energy identity needs the potential, and whose steps
  /// are held by the inertia) and the fibre law (64 small drops) keep the potential's.
  bool elastic_symmetry = false;
  /// The plastic states of a model with `points` bending points and `vertices` vertices:
  /// section.states() per bending point, then one per vertex hinge.
  std::size_t states(std::size_t points, std::size_t vertices) const {
    return points * static_cast<std::size_t>(section.states()) + vertices;
  }
  /// The vertex hinge's law: stiffness P (the interior penalty's), yield the section's
  /// fully plastic moment (Mp of the resultant law).
  ring::BilinearLaw hinge(double P) const {
    return ring::BilinearLaw(P, section.plastic_moment(), plastic.hardening, plastic.rule);
  }
};

/// The beam's law of ring.plastic (spec.plastic set; the fibre law needs spec.section's shape).
inline PlasticLaw plastic_law(const ring::RingSpec& spec, const ring::Plastic& p) {
  return PlasticLaw{p, ring::SectionLaw(spec)};
}

/// The law and the committed states of every bending point (the model's order, above).
struct Plasticity {
  const PlasticLaw& law;
  const std::vector<ring::PlasticState>& committed;
  /// The first committed state of bending point i (section.states() of them).
  const ring::PlasticState* point(std::size_t i) const { return &committed[i * law.section.states()]; }
};

/// What committing a step did: the plastic work of the step over the ring (J) and the
/// largest |plastic curvature| after it (1/m; a vertex hinge's plastic rotation over the cell length).
struct Committed {
  double dissipated = 0.0;
  double largest_plastic = 0.0;
};

/// Commits every point at its converged strain (`at`: bending points, then vertex hinges,
/// as BeamModel::bending_points gives them): the states move, the step's plastic work
/// sum weight * dissipated is returned. O(states).
inline Committed commit(const PlasticLaw& law, const std::vector<BendingPoint>& at,
                        std::vector<ring::PlasticState>& states) {
  Committed c;
  std::size_t k = 0;  // the point's first state
  for (const BendingPoint& b : at) {
    if (b.law) {
      if (b.law->at(states[k], b.curvature).yielding) {  // else the state stays, bit for bit
        c.dissipated += b.weight * b.law->dissipated(states[k], b.curvature);
        states[k] = b.law->commit(states[k], b.curvature);
      }
      c.largest_plastic = std::max(c.largest_plastic, std::abs(states[k].plastic) * b.per_length);
      ++k;
      continue;
    }
    ring::PlasticState* s = &states[k];
    if (law.section.at(s, b.curvature).yielding) {
      c.dissipated += b.weight * law.section.dissipated(s, b.curvature);
      law.section.commit(s, b.curvature);
    }
    // kappa - M / EI: the resultant law's e_p exactly; the fibre law's curvature left when
    // the point is unloaded elastically (0 while no fibre has yielded: the fibres' EI is the
    // section's only to round-off, so kappa - M / EI is not computed there).
    const int n = law.section.states();
    if (std::any_of(s, s + n, [](const ring::PlasticState& x) { return x.plastic != 0.0 || x.accumulated != 0.0; }))
      c.largest_plastic = std::max(c.largest_plastic, std::abs(law.section.plastic_curvature(s, b.curvature)));
    k += static_cast<std::size_t>(n);
  }
  return c;
}

}  // namespace fem::detail
