// Sampling mode shapes at the common stations of results.hpp.
#pragma once

#include <vector>

#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace ring {

/// Samples a polygonal model whose node k sits at polar angle anchor + 360 k / n
/// (n = ux.size()) and moves by (ux[k], uy[k]) in the ring-centred frame, with
/// displacements varying linearly along each side (exact for rigid segments and for
/// the translational part of straight two-node elements at their nodes). Returns
/// radial/tangential components at every station, normalized with `normalize`.
/// O(kStations).
ModeShape sample_polygon(double anchor_deg, const std::vector<double>& ux,
                         const std::vector<double>& uy);

/// Samples an arch's polygonal model: node k at from + span k / n, k = 0..n (n + 1 =
/// ux.size() nodes), displacements linear along each side as sample_polygon. Stations
/// outside the arch are 0 (no ring there), so MAC compares arches station by station.
/// Normalized with `normalize`. O(kStations).
ModeShape sample_arc(const Arc& arc, const std::vector<double>& ux, const std::vector<double>& uy);

/// Scales a shape so that its largest |component| is 1 and positive.
void normalize(ModeShape& shape);

/// Modal assurance criterion of two shapes at the common stations, in [0, 1]:
/// |a.b|^2 / ((a.a)(b.b)) over radial and tangential components together.
double mac(const ModeShape& a, const ModeShape& b);

}  // namespace ring
