#include "python/convert.hpp"

#include <pybind11/numpy.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "compare/pairs.hpp"
#include "compare/spin.hpp"
#include "ring/errors.hpp"
#include "ring/scene.hpp"

namespace ringvib_py {

namespace {

std::string toml_string(const std::string& s) { return ring::toml_quoted(s); }

bool bare_key(const std::string& k) {
  if (k.empty()) return false;
  for (char c : k)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

std::string toml(const std::string& key, py::handle v) {
  // NumPy's scalars (numpy.bool_, numpy.float64, numpy.int64) as Python's.
  const bool numpy_bool = !py::isinstance<py::array>(v) && py::hasattr(v, "dtype") &&
                          py::str(v.attr("dtype").attr("kind")).cast<std::string>() == "b";
  if (py::isinstance<py::bool_>(v) || numpy_bool)
    return py::bool_(py::reinterpret_borrow<py::object>(v)) ? "true" : "false";
  if (py::isinstance<py::float_>(v))  // the shortest text that reads back: 0.1, 1e-300, inf, nan
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(v))).cast<std::string>();
  if (py::isinstance<py::int_>(v) || (!py::isinstance<py::str>(v) && py::hasattr(v, "__index__")))
    return py::str(py::int_(py::reinterpret_borrow<py::object>(v))).cast<std::string>();
  if (py::isinstance<py::str>(v)) return toml_string(v.cast<std::string>());
  if (py::isinstance<py::array>(v)) return toml(key, v.attr("tolist")());  // a list, or a 0-d array's scalar
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::string o = "[";
    bool first = true;
    for (py::handle item : v) {
      o += (first ? "" : ", ") + toml(key, item);
      first = false;
    }
    return o + "]";
  }
  if (py::isinstance<py::dict>(v)) {
    std::string o = "{";
    bool first = true;
    for (auto [k, item] : v.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k))
        throw ring::InputError("", key, "an inline table's keys are strings, got " + py::repr(k).cast<std::string>());
      const std::string name = k.cast<std::string>();
      o += std::string(first ? " " : ", ") + (bare_key(name) ? name : toml_string(name)) + " = " + toml(key, item);
      first = false;
    }
    return o + (first ? "}" : " }");
  }
  throw ring::InputError("", key,
                         "cannot write a " + py::str(v.get_type().attr("__name__")).cast<std::string>() +
                             " as TOML; expected bool, int, float, str, a list or a dict");
}

py::array_t<double> vector(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

/// A (rows, 2) array of (x, y) pairs.
py::array_t<double> pairs(const std::vector<double>& x, const std::vector<double>& y) {
  py::array_t<double> a({static_cast<py::ssize_t>(x.size()), py::ssize_t(2)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < x.size(); ++i) {
    m(i, 0) = x[i];
    m(i, 1) = y[i];
  }
  return a;
}

/// A structured array of `rows` rows with the named float64 (or int64) columns, filled.
struct Columns {
  std::vector<std::pair<std::string, const std::vector<double>*>> real;
  std::vector<std::pair<std::string, const std::vector<int>*>> integer;
  std::vector<std::string> order;  ///< field order
};

py::object structured(std::size_t rows, const Columns& c) {
  py::module_ np = py::module_::import("numpy");
  py::list fields;
  for (const auto& name : c.order) {
    bool is_int = false;
    for (const auto& [n, col] : c.integer) is_int |= n == name;
    fields.append(py::make_tuple(name, is_int ? "<i8" : "<f8"));
  }
  py::object a = np.attr("zeros")(rows, np.attr("dtype")(fields));
  for (const auto& [name, col] : c.real) a[py::str(name)] = vector(*col);
  for (const auto& [name, col] : c.integer) {
    py::array_t<long long> v(static_cast<py::ssize_t>(col->size()));
    std::copy(col->begin(), col->end(), v.mutable_data());
    a[py::str(name)] = v;
  }
  return a;
}

/// The label of a recorded point in field names, as the response CSV writes it (ux_90).
std::string degrees(double a) {
  std::ostringstream s;
  s << a;
  return s.str();
}

}  // namespace

std::string override_text(const std::string& key, py::handle value) { return key + "=" + toml(key, value); }

std::vector<std::string> overrides_from(py::handle mapping) {
  std::vector<std::string> v;
  if (mapping.is_none()) return v;
  if (!py::isinstance<py::dict>(mapping))
    throw ring::InputError("", "set",
                           "expected a dict {\"section.key\": value}, got a " +
                               py::str(mapping.get_type().attr("__name__")).cast<std::string>());
  for (auto [k, value] : mapping.cast<py::dict>()) {
    if (!py::isinstance<py::str>(k))
      throw ring::InputError("", "set", "keys are \"section.key\" strings, got " + py::repr(k).cast<std::string>());
    v.push_back(override_text(k.cast<std::string>(), value));
  }
  return v;
}

Modes to_python(const ring::ModalResult& m) {
  Modes o;
  o.solver = m.solver;
  for (const auto& [k, v] : m.model) std::visit([&, k = k](const auto& x) { o.model[py::str(k)] = py::cast(x); }, v);
  o.rigid_modes = m.rigid_modes;
  o.omega = vector(m.omega);
  const auto k = static_cast<py::ssize_t>(m.shapes.size());
  py::array_t<double> shapes({k, py::ssize_t(ring::kStations), py::ssize_t(2)});
  auto s = shapes.mutable_unchecked<3>();
  for (py::ssize_t i = 0; i < k; ++i)
    for (int j = 0; j < ring::kStations; ++j) {
      s(i, j, 0) = m.shapes[i].radial[j];
      s(i, j, 1) = m.shapes[i].tangential[j];
    }
  o.shapes = shapes;
  std::vector<double> stations;
  for (int j = 0; j < ring::kStations; ++j) stations.push_back(ring::station_angle(j));
  o.stations_deg = vector(stations);
  o.unknowns = m.unknowns;
  o.seconds = m.seconds;
  o.max_residual = m.max_residual;
  o.residual_norm = m.residual_norm;
  o.error_estimate = m.error_estimate;
  for (const auto& p : cmp::split_pairs(m)) {
    py::dict d;
    d["wave"] = p.wave;
    d["modes"] = py::make_tuple(p.lower, p.upper);
    d["omega"] = py::make_tuple(p.omega_lower, p.omega_upper);
    d["split"] = p.split();
    d["relative_split"] = p.relative();
    d["orientation_deg"] = p.orientation;
    o.pairs.append(d);
  }
  o.frame = m.frame;
  for (const auto& w : m.waves) o.wave.append(w.number), o.direction.append(cmp::direction_name(w.direction));
  for (const auto& p : m.spin_pairs) {
    py::dict d;
    d["wave"] = p.wave;
    d["forward"] = p.forward;
    d["backward"] = p.backward;
    d["forward_fixed"] = p.forward_fixed;
    d["backward_fixed"] = p.backward_fixed;
    d["bryan"] = p.bryan;
    o.wave_pairs.append(d);
  }
  return o;
}

Static to_python(const ring::StaticResult& r) {
  Static o;
  o.solver = r.solver;
  std::vector<double> angle, ux, uy;
  for (const auto& d : r.displacements) {
    angle.push_back(d.angle);
    ux.push_back(d.ux);
    uy.push_back(d.uy);
  }
  o.displacements =
      structured(angle.size(), {{{"angle", &angle}, {"ux", &ux}, {"uy", &uy}}, {}, {"angle", "ux", "uy"}});
  o.nodes = pairs(r.node_x, r.node_y);
  o.path = py::none();
  o.limit_points = py::none();
  // The columns of static_path_<solver>.csv, in its order (`whole`), or the load factor and
  // the recorded points' displacements alone.
  auto table = [&r](const std::vector<ring::PathPoint>& path, bool whole) {
    const std::size_t n = path.size(), points = path.front().displacements.size();
    std::vector<double> load(n), oval(n), dissipated(n), plastic(n), rx(n), ry(n), c0(n), c1(n);
    std::vector<std::vector<double>> ux(points, std::vector<double>(n)), uy = ux;
    for (std::size_t k = 0; k < n; ++k) {
      const ring::PathPoint& p = path[k];
      load[k] = p.load_factor;
      oval[k] = p.ovalisation;
      dissipated[k] = p.dissipated;
      plastic[k] = p.plastic_curvature;
      rx[k] = p.reaction[0];
      ry[k] = p.reaction[1];
      c0[k] = p.contact_length[0];
      c1[k] = p.contact_length[1];
      for (std::size_t i = 0; i < points && i < p.displacements.size(); ++i) {
        ux[i][k] = p.displacements[i].ux;
        uy[i][k] = p.displacements[i].uy;
      }
    }
    Columns c;
    c.order = {"load_factor"};
    c.real = {{"load_factor", &load}};
    if (whole) {
      c.order.push_back("ovalisation");
      c.real.push_back({"ovalisation", &oval});
    }
    for (std::size_t i = 0; i < points; ++i) {
      const std::string d = degrees(path.front().displacements[i].angle);
      c.order.push_back("ux_" + d);
      c.real.push_back({"ux_" + d, &ux[i]});
      c.order.push_back("uy_" + d);
      c.real.push_back({"uy_" + d, &uy[i]});
    }
    if (whole) {
      c.order.push_back("dissipated");
      c.real.push_back({"dissipated", &dissipated});
      c.order.push_back("plastic_curvature");
      c.real.push_back({"plastic_curvature", &plastic});
    }
    if (r.driven) {
      c.order.push_back("reaction_x");
      c.real.push_back({"reaction_x", &rx});
      c.order.push_back("reaction_y");
      c.real.push_back({"reaction_y", &ry});
    }
    if (r.plates) {
      c.order.push_back("contact_length");
      c.real.push_back({"contact_length", &c0});
      c.order.push_back("contact_length_opposite");
      c.real.push_back({"contact_length_opposite", &c1});
    }
    return structured(n, c);
  };
  if (!r.path.empty()) o.path = table(r.path, true);
  if (!r.limit_points.empty()) o.limit_points = table(r.limit_points, false);
  o.branch_points = vector(r.branch_points);
  o.end = r.end;
  o.end_load = r.end_load;
  o.dissipated = r.dissipated;
  o.plastic_curvature = r.plastic_curvature;
  o.reaction = r.driven ? py::object(py::make_tuple(r.reaction[0], r.reaction[1])) : py::none();
  o.contact_length = r.plates ? py::object(py::make_tuple(r.contact_length[0], r.contact_length[1])) : py::none();
  o.unknowns = r.unknowns;
  o.steps = r.steps;
  o.newton_iterations = r.newton_iterations;
  o.seconds = r.seconds;
  return o;
}

Response to_python(const ring::TimeHistory& h) {
  Response o;
  o.solver = h.solver;
  Columns c;
  c.order.push_back("t");
  c.real.push_back({"t", &h.t});
  for (std::size_t p = 0; p < h.record_angles.size(); ++p) {
    const std::string d = degrees(h.record_angles[p]);
    c.order.push_back("ux_" + d);
    c.real.push_back({"ux_" + d, &h.ux[p]});
    c.order.push_back("uy_" + d);
    c.real.push_back({"uy_" + d, &h.uy[p]});
  }
  // The CSV's energy columns (compare/response.cpp), a plastic ring's plastic work among them.
  std::vector<std::pair<const char*, const std::vector<double>*>> energies{{"kinetic", &h.kinetic}, {"strain", &h.strain}};
  if (!h.dissipated.empty()) energies.emplace_back("dissipated", &h.dissipated);
  for (const auto& e : std::vector<std::pair<const char*, const std::vector<double>*>>{
           {"work", &h.work}, {"energy_error", &h.energy_error}, {"constraint_residual", &h.constraint_residual}})
    energies.push_back(e);
  for (const auto& [name, col] : energies) {
    c.order.push_back(name);
    c.real.push_back({name, col});
  }
  c.order.push_back("newton_iterations");
  c.integer.push_back({"newton_iterations", &h.newton_iterations});
  o.history = structured(h.t.size(), c);
  o.record_angles = vector(h.record_angles);
  o.t = vector(h.t);
  const auto points = static_cast<py::ssize_t>(h.record_angles.size()), steps = static_cast<py::ssize_t>(h.t.size());
  py::array_t<double> ux({points, steps}), uy({points, steps});
  auto x = ux.mutable_unchecked<2>(), y = uy.mutable_unchecked<2>();
  for (py::ssize_t p = 0; p < points; ++p)
    for (py::ssize_t k = 0; k < steps; ++k) {
      x(p, k) = h.ux[p][k];
      y(p, k) = h.uy[p][k];
    }
  o.ux = ux;
  o.uy = uy;
  o.snapshot_t = vector(h.snapshot_t);
  py::list snaps;
  for (std::size_t k = 0; k < h.snapshot_t.size(); ++k) snaps.append(pairs(h.snapshot_x[k], h.snapshot_y[k]));
  o.snapshots = snaps;
  o.unknowns = h.unknowns;
  o.seconds = h.seconds;
  return o;
}

namespace {

// The exception classes, owned by the module (a reference is kept in its attributes).
PyObject* g_input_error = nullptr;
PyObject* g_numerical_error = nullptr;

void raise(PyObject* type, const char* message, const std::vector<std::pair<const char*, py::object>>& fields) {
  py::object e = py::reinterpret_borrow<py::object>(type)(message);
  for (const auto& [name, value] : fields) e.attr(name) = value;
  PyErr_SetObject(type, e.ptr());
}

/// The load factor a continuation's failure names last: where it stopped
/// (paths::failure_message), or None. ring::NumericalError carries only its message.
py::object load_factor(const std::string& what) {
  const std::string tag = "load factor ";
  const auto at = what.rfind(tag);
  if (at == std::string::npos) return py::none();
  const char* start = what.c_str() + at + tag.size();
  char* end = nullptr;
  const double v = std::strtod(start, &end);
  return end == start ? py::object(py::none()) : py::object(py::float_(v));
}

PyObject* new_exception(py::module_& m, const char* name, PyObject* base, const char* doc) {
  const std::string qualified = std::string("ringvib.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::reinterpret_borrow<py::object>(type));
  return type;  // the new reference stays: the class lives as long as the process
}

}  // namespace

void register_errors(py::module_& m) {
  g_input_error =
      new_exception(m, "InputError", PyExc_ValueError,
                    "Bad input: the message is the command's exit-2 message, naming the file (or the scene's\n"
                    "name), the key and what was expected. Attributes: file, key (str; '' where none).");
  g_numerical_error =
      new_exception(m, "NumericalError", PyExc_RuntimeError,
                    "A numerical failure (the command's exit 3): NaN, divergence, Newton not converging, a\n"
                    "path past a limit point to self-contact, energy growth. Attributes: t_reached (s, the\n"
                    "last accepted time step of a failed response, else None), partial (the Response up to\n"
                    "t_reached, else None), load_factor (the load factor a failed static path names last:\n"
                    "where it stopped; else None).");
  for (PyObject* t : {g_input_error})
    for (const char* a : {"file", "key"}) PyObject_SetAttrString(t, a, py::str("").ptr());
  for (const char* a : {"t_reached", "partial", "load_factor"}) PyObject_SetAttrString(g_numerical_error, a, Py_None);

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ring::InputError& e) {
      raise(g_input_error, e.what(), {{"file", py::str(e.file())}, {"key", py::str(e.key())}});
    } catch (const ring::IntegrationFailure& e) {
      raise(g_numerical_error, e.what(),
            {{"t_reached", py::float_(e.t_reached())},
             {"partial", py::cast(to_python(e.partial()))},
             {"load_factor", py::none()}});
    } catch (const ring::NumericalError& e) {
      raise(g_numerical_error, e.what(),
            {{"t_reached", py::none()}, {"partial", py::none()}, {"load_factor", load_factor(e.what())}});
    }
  });
}

}  // namespace ringvib_py
