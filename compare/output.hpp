// Number formats shared by the tables, reports and figures (files.hpp writes them).
#pragma once

#include <string>

#include "ring/results.hpp"

namespace cmp {

/// A model description value as text (booleans as true/false).
std::string model_value(const ring::ModelValue& v);

/// Formats a frequency to 4 significant digits like the paper (2.463, 11.30, 101.5).
std::string sig4(double v);
/// Formats a percentage with two decimals (-0.93).
std::string pct2(double v);
/// A modal result's max_residual in a table or a line of text (1.2e-14), or "-" where the
/// solver reports none (ccx, an imported column).
std::string residual_cell(const ring::ModalResult& m);

}  // namespace cmp
