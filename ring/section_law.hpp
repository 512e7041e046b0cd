// The bending law of a plastic ring's wall at one material point, for either law of
// `ring.plastic`, in the curvature kappa (1/m):
//  - resultant (`moment = Mp`): the bilinear moment–curvature law (ring/plastic.hpp) with
//    stiffness EI, yield moment Mp and the tangent h EI past it: one state per point;
//  - fibre (`stress = sigma_y`): the uniaxial bilinear stress–strain law (stiffness E,
//    yield sigma_y, tangent h E) at the fibres of the section's shape, strain y kappa at the
//    depth y, the moment the sum of y sigma a over the fibres: one state per fibre. The
//    fibres are Gauss–Legendre points on each half of the depth (over the angle t, y = r sin t,
//    for the circle), their areas scaled so that sum y^2 a is the section's I exactly:
//    elastic, the law is EI kappa to round-off; the fully plastic moment is sigma_y Z
//    (Z = b h^2 / 4, d^3 / 6) to round-off (rectangle) or to Gauss's exponential rate (circle);
//    in between, the kinks of the stress at the elastic core's edges converge as 1/fibres^2
//    (measured in tests/ring/test_plastic.cpp). The bending fibre law has no axial strain: the chains are
//    inextensible, and the FE beam's membrane strain stays elastic (docs/solvers.md).
// A chain's hinge, which stands for a segment of length l at uniform curvature theta / l,
// uses the law through HingeLaw: force M, tangent dM/dkappa / l, potential l int M dkappa.
#pragma once

#include <vector>

#include "ring/plastic.hpp"

namespace ring {

struct RingSpec;

class SectionLaw {
 public:
  static constexpr int kFibres = 64;  ///< Gauss points through the depth of a fibre section

  /// The law of spec.plastic (which must be set) on spec's section; `fibres` (even) Gauss
  /// points through the depth, half on each side of the centroid.
  explicit SectionLaw(const RingSpec& spec, int fibres = kFibres);

  /// PlasticStates per material point: 1 (resultant) or kFibres (fibre).
  int states() const { return fibres_.empty() ? 1 : static_cast<int>(fibres_.size()); }

  /// The moment at curvature kappa from the committed states s[0 .. states()).
  BilinearLaw::Point at(const PlasticState* s, double kappa) const;
  /// Commits the states s at the converged curvature kappa.
  void commit(PlasticState* s, double kappa) const;
  /// The plastic work per unit length of the step from s to kappa, J/m.
  double dissipated(const PlasticState* s, double kappa) const;
  /// The plastic curvature left at kappa when unloaded elastically: kappa - M / EI, 1/m.
  double plastic_curvature(const PlasticState* s, double kappa) const;
  /// The elastic energy per unit length stored at kappa (M^2 / (2 EI) for the resultant law,
  /// the fibres' sum of sigma^2 a / (2E) for the fibre law), J/m.
  double stored(const PlasticState* s, double kappa) const;
  /// The fully plastic moment: Mp, or sigma_y sum |y| a of the fibres, N m.
  double plastic_moment() const;
  double EI() const { return EI_; }

 private:
  struct Fibre {
    double y = 0.0, area = 0.0;
  };
  double EI_;
  BilinearLaw law_;            ///< the resultant law on kappa, or the fibres' uniaxial law on strain
  std::vector<Fibre> fibres_;  ///< empty: the resultant law
  double yield_ = 0.0;         ///< sigma_y (fibre) or Mp
};

/// A chain's hinge of segment length l: the section law at the uniform curvature theta / l
/// of the segment the hinge stands for; the strain is the hinge's turning angle from rest.
class HingeLaw {
 public:
  HingeLaw(const SectionLaw& section, double length) : section_(section), l_(length) {}
  int states() const { return section_.states(); }
  /// force: the moment (N m); tangent: dM/dtheta (N m/rad); potential: l int M dkappa (J).
  BilinearLaw::Point at(const PlasticState* s, double theta) const {
    BilinearLaw::Point p = section_.at(s, theta / l_);
    p.tangent /= l_;
    p.potential *= l_;
    return p;
  }
  void commit(PlasticState* s, double theta) const { section_.commit(s, theta / l_); }
  double dissipated(const PlasticState* s, double theta) const { return section_.dissipated(s, theta / l_) * l_; }
  double stored(const PlasticState* s, double theta) const { return section_.stored(s, theta / l_) * l_; }
  /// The hinge's plastic rotation over the segment length, 1/m.
  double plastic_curvature(const PlasticState* s, double theta) const {
    return section_.plastic_curvature(s, theta / l_);
  }

 private:
  const SectionLaw& section_;
  double l_;
};

}  // namespace ring
