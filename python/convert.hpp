// Between Python and the driver's vocabulary: Python values as TOML override text, result
// types (ring/results.hpp) as NumPy arrays, ring's errors as the module's exceptions.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "ring/results.hpp"

namespace ringvib_py {

namespace py = pybind11;

/// One override "section.key=<value>" as `ringvib ... --set` takes it: the Python value in
/// TOML syntax. bool -> true/false; int (and anything with __index__) in decimal; float as
/// Python's repr (the shortest text that reads back to the same double; inf, nan); str as
/// a TOML basic string with escapes; list, tuple and 1-D ndarray as arrays; dict as an inline
/// table. Throws ring::InputError naming the key for anything else.
std::string override_text(const std::string& key, py::handle value);
/// Every item of a {"section.key": value} mapping, in its order.
std::vector<std::string> overrides_from(py::handle mapping);

/// A modal result: `Modes`, with NumPy arrays (module.cpp registers the class).
struct Modes {
  std::string solver;
  py::dict model;
  int rigid_modes = 0;
  py::object omega, shapes, stations_deg;
  long long unknowns = 0;
  double seconds = 0.0, error_estimate = 0.0;
  std::optional<double> max_residual;  ///< None where the solver reports none (ccx, imports)
  std::string residual_norm;
  py::list pairs;  ///< the split pairs (compare/pairs.hpp): dicts as modes --json's "pairs"
  /// A spinning ring (compare/spin.hpp): the frame of omega ("rotating", "fixed"; "" at rest),
  /// each mode's wave number and direction, the wave pairs as modes --json's "wave_pairs".
  std::string frame;
  py::list wave, direction, wave_pairs;
};
Modes to_python(const ring::ModalResult& m);

/// A nonlinear static equilibrium: `Static`.
struct Static {
  std::string solver;
  py::object displacements, nodes;
  py::object path;  ///< structured ndarray, one row per accepted equilibrium (None without a path)
  py::object branch_points;
  py::object limit_points;  ///< structured ndarray: load_factor, ux_<deg>, uy_<deg> (None without one)
  py::object reaction;      ///< static.displacement: (Fx, Fy) at the driven point, N (None otherwise)
  py::object contact_length;  ///< [plates]: (on the plate at plates.axis, on the other), m (None otherwise)
  std::string end;
  double end_load = 1.0, dissipated = 0.0, plastic_curvature = 0.0;
  long long unknowns = 0;
  int steps = 0, newton_iterations = 0;
  double seconds = 0.0;
};
Static to_python(const ring::StaticResult& r);

/// A forced response: `Response`.
struct Response {
  std::string solver;
  py::object history, record_angles, t, ux, uy, snapshot_t, snapshots;
  long long unknowns = 0;
  double seconds = 0.0;
};
Response to_python(const ring::TimeHistory& h);

/// Creates ringvib.InputError (a ValueError) and ringvib.NumericalError (a RuntimeError)
/// in `m`, and translates ring::InputError, ring::NumericalError and
/// ring::IntegrationFailure into them, with their fields as attributes.
void register_errors(py::module_& m);

}  // namespace ringvib_py
