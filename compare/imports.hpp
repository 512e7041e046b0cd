// Columns of other codes' results ([[table.import]]; docs/solvers.md, "Imported columns"): their
// frequencies, and optionally their mode shapes, read into a ring::ModalResult that the
// table pairs, differences, errors and gates like any solver's column.
//
// Frequencies: a CSV file with the header `mode,omega` (rad/s) or `mode,hz` (cycles/s),
// then one line per elastic mode, numbered 1, 2, 3, ... (rigid modes left out); every
// value finite and > 0. Lines starting with '#' and blank lines are skipped.
// Shapes (optional): the layout ringvib writes in shapes_<solver>.csv: the header
// `angle_deg,radial_1,tangential_1,radial_2,...` and one line per station at 0, 1, ...,
// 359 degrees, radial (outward) and tangential (counter-clockwise) displacement of each
// mode, as many modes as the frequency file has. With shapes the modes pair by MAC,
// without them by order.
// A file that breaks this is ring::InputError (exit 2) naming the file, the line and the
// column.
#pragma once

#include "ring/results.hpp"
#include "ring/scene.hpp"

namespace cmp {

/// Reads one imported column. O(modes x kStations).
ring::ModalResult read_imported(const ring::ImportedColumn& column);

}  // namespace cmp
