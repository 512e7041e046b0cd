// Internal to fem_reference/: the elastic–plastic bending of the geometrically exact beams
// (ring.plastic, the resultant law of ring/plastic.hpp) at their bending points. No deal.II
// here.
//
// A beam's bending energy density EI/2 kappa^2 becomes, at each bending point, the law's
// incremental potential ring::BilinearLaw(EI, Mp, h, rule).at(committed, kappa).potential
// (kappa the curvature change, 1/m, exactly as the elastic beam measures it): its derivative
// is the moment M, its second the tangent dM/dkappa, so the beam's internal force gains
// M dkappa and its tangent dM/dkappa dkappa dkappa^T + M d2kappa (chain rule through the
// exact curvature). The trial is always evaluated from the committed states (the return
// map from the last accepted equilibrium), so a rejected trial leaves nothing behind; the
// statics (static_path.cpp) commit at every accepted equilibrium.
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

namespace fem::detail {

/// A bending point at a displacement: its curvature change and its weight.
struct BendingPoint {
  double curvature = 0.0;   ///< kappa, 1/m (a vertex hinge: its rotation, rad)
  double weight = 0.0;      ///< ds0 of the point's quadrature, m (a vertex hinge: 1)
  double per_length = 1.0;  ///< its plastic strain times this is a curvature, 1/m (a hinge: 1 / cell length)
  /// The point's own law where it is not the bending law (a vertex hinge: stiffness P).
  std::optional<ring::BilinearLaw> law;
};

/// The law and the committed state of every bending point (the model's order, above).
struct Plasticity {
  ring::BilinearLaw law;
  const std::vector<ring::PlasticState>& committed;
};

/// The law of ring.plastic (resultant) at a beam's bending point: stiffness EI, yield Mp.
inline ring::BilinearLaw bending_law(const ring::Plastic& p, double EI) {
  return ring::BilinearLaw(EI, p.moment, p.hardening, p.rule);
}

/// What committing a step did: the plastic work of the step over the ring (J) and the
/// largest |plastic curvature| after it (1/m; a vertex hinge's plastic rotation over the cell length).
struct Committed {
  double dissipated = 0.0;
  double largest_plastic = 0.0;
};

/// Commits every point at its converged curvature: the state moves, the step's plastic
/// work sum weight * law.dissipated is returned. O(points).
inline Committed commit(const ring::BilinearLaw& law, const std::vector<BendingPoint>& at,
                        std::vector<ring::PlasticState>& states) {
  Committed c;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const ring::BilinearLaw& of = at[i].law ? *at[i].law : law;
    if (of.at(states[i], at[i].curvature).yielding) {  // else the state stays, bit for bit
      c.dissipated += at[i].weight * of.dissipated(states[i], at[i].curvature);
      states[i] = of.commit(states[i], at[i].curvature);
    }
    c.largest_plastic = std::max(c.largest_plastic, std::abs(states[i].plastic) * at[i].per_length);
  }
  return c;
}

}  // namespace fem::detail
