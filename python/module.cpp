// The `ringvib` Python module: the command's analyses over the registry (compare/), with
// results as NumPy arrays. Every function does what the command of the same name does with
// the same scene and overrides (the same checks, the same solver calls), so that each value
// equals the command's JSON (tests/python). The GIL is released while a solver runs; FE
// solves take turns (compare/fem_module.cpp), the other solvers run in parallel.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "compare/buckling.hpp"
#include "compare/commands.hpp"
#include "compare/files.hpp"
#include "compare/nonlinear.hpp"
#include "compare/registry.hpp"
#include "compare/runner.hpp"
#include "compare/sweep.hpp"
#include "compare/table.hpp"
#include "compare/trim.hpp"
#include "python/convert.hpp"
#include "ring/errors.hpp"
#include "ring/scene.hpp"

namespace py = pybind11;
using namespace ringvib_py;

namespace {

/// A scene as the module keeps it: its TOML text (read once), the name messages use (the
/// path), the overrides in order, and the validated scene they give.
struct Scene {
  std::string text, name;
  std::vector<std::string> overrides;
  ring::Scene scene;

  static Scene parse(std::string text, std::string name, std::vector<std::string> overrides) {
    Scene s{std::move(text), std::move(name), std::move(overrides), {}};
    s.scene = cmp::parse_scene(s.text, s.name, s.overrides);
    return s;
  }
};

/// The one solver a single-solver result is for (cmp::single_solver, as the commands pick
/// it); where the scene compares several, the function that compares them is named instead.
std::string single(const ring::Scene& s, const ring::NonlinearRequest& q, const std::string& solver,
                   const std::string& key, const std::string& table_function) {
  if (const auto one = cmp::single_solver(solver, q)) return *one;
  throw ring::InputError(s.file, key,
                         "the scene runs several solvers (or a reference); name one with solver=NAME, or "
                         "compare them with ringvib." +
                             table_function + "(scene)");
}

/// Runs `f`; a solver's std::invalid_argument ("can never work") becomes the InputError the
/// command reports with exit 2, naming the scene (compare/main.cpp).
template <class F>
auto input_checked(const ring::Scene& s, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw ring::InputError(s.file, "", e.what());
  }
}

py::object json_rows(const std::string& json) { return py::module_::import("json").attr("loads")(json)["rows"]; }

/// Thrown by CtrlC::poll to end a solve; the binding raises what Python's handler raised.
struct Interrupted : std::exception {
  const char* what() const noexcept override { return "interrupted"; }
};

/// Ctrl-C during a solve (issue 46). Python's own SIGINT handler only sets a flag; its
/// KeyboardInterrupt is raised when the main thread next runs Python code, which a solve
/// with the GIL released never does. So for the length of one call on the main thread
/// this is the thread's interrupt check (compare/files.hpp, interrupt_check()): the
/// solve's long loops call it (ccx's wait every 10 ms, the time-stepping driver at least
/// every 0.05 s), and at most every 0.05 s it takes the GIL and runs PyErr_CheckSignals().
/// When a handler raised, the exception is kept and Interrupted thrown: ccx is killed and
/// its folder removed on the way out (calculix/ccx.cpp), the module writes nothing, and
/// the call raises the kept exception (KeyboardInterrupt) instead of the solve's outcome.
/// Other threads' calls do not check: Python runs signal handlers on the main thread only.
class CtrlC {
 public:
  CtrlC() {  // with the GIL
    const auto main = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
    if (PyThread_get_thread_ident() != main) return;
    active_ = true;
    cmp::set_interrupt_check([this] { poll(); });
  }
  ~CtrlC() {
    if (active_) cmp::set_interrupt_check({});
  }
  CtrlC(const CtrlC&) = delete;
  CtrlC& operator=(const CtrlC&) = delete;

  /// On the solving thread, without the GIL.
  void poll() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(50)) return;
    last_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return;
    raised_.emplace();  // takes the raised exception from the thread state
    throw Interrupted();
  }
  /// With the GIL: raises what a signal handler raised during the solve, if anything.
  void raise_if_interrupted() {
    if (!raised_) return;
    py::error_already_set e = std::move(*raised_);
    raised_.reset();
    throw e;
  }

 private:
  bool active_ = false;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  std::optional<py::error_already_set> raised_;
};

/// Runs `f` with the GIL released and Ctrl-C honoured (CtrlC); returns its result or
/// rethrows its exception, unless a signal handler raised, whose exception wins.
template <class F>
auto released(F&& f) -> decltype(f()) {
  CtrlC ctrl_c;
  decltype(f()) out{};
  std::exception_ptr failure;
  {
    py::gil_scoped_release free;
    try {
      out = f();
    } catch (...) {
      failure = std::current_exception();
    }
  }
  ctrl_c.raise_if_interrupted();
  if (failure) std::rethrow_exception(failure);
  return out;
}

/// A progress stream for a Python callable: each line the study writes (ended by a newline
/// or a carriage return, as the command's progress redraws) is passed to `callback(line)`
/// with the GIL taken, from the solving thread. An exception the callback raises is kept,
/// later lines are dropped, and the call raises it when the study ends.
class CallbackProgress : public std::streambuf {
 public:
  explicit CallbackProgress(py::object callback) : callback_(std::move(callback)) {}
  ~CallbackProgress() override {
    py::gil_scoped_acquire gil;
    callback_ = py::object();
  }
  /// With the GIL: raises what the callback raised, if anything.
  void raise_if_failed() {
    if (!failed_) return;
    py::error_already_set e = std::move(*failed_);
    failed_.reset();
    throw e;
  }

 protected:
  int overflow(int c) override {
    if (c == EOF) return 0;
    if (c == '\n' || c == '\r') flush_line();
    else line_ += static_cast<char>(c);
    return c;
  }

 private:
  void flush_line() {
    if (line_.empty()) return;
    py::gil_scoped_acquire gil;
    if (!failed_) try {
        callback_(line_);
      } catch (py::error_already_set& e) {
        failed_.emplace(std::move(e));
      }
    line_.clear();
  }
  py::object callback_;
  std::string line_;
  std::optional<py::error_already_set> failed_;
};

/// A bench study's points as a dict of arrays (one entry per point).
py::dict bench_points(const cmp::BenchStudy& b) {
  std::vector<double> seconds, max_error, mean_error;
  std::vector<long long> size, unknowns, repeats;
  py::list curve;
  for (const cmp::BenchPoint& p : b.points) {
    curve.append(p.curve);
    size.push_back(p.size);
    unknowns.push_back(p.unknowns);
    repeats.push_back(p.repeats);
    seconds.push_back(p.seconds);
    max_error.push_back(p.max_error);
    mean_error.push_back(p.mean_error);
  }
  py::dict d;
  d["curve"] = curve;
  d["size"] = py::array_t<long long>(size.size(), size.data());
  d["unknowns"] = py::array_t<long long>(unknowns.size(), unknowns.data());
  d["seconds"] = py::array_t<double>(seconds.size(), seconds.data());
  d["repeats"] = py::array_t<long long>(repeats.size(), repeats.data());
  d["max_error_pct"] = py::array_t<double>(max_error.size(), max_error.data());
  d["mean_error_pct"] = py::array_t<double>(mean_error.size(), mean_error.data());
  return d;
}

const char* const kBudgetDoc =
    "max_memory_gib: the cost guard's budget (GiB; the command's --max-memory), force: skip the\n"
    "guard (--force).";

}  // namespace

PYBIND11_MODULE(ringvib, m) {
  m.doc() =
      "ringvib: in-plane vibration, statics and forced response of circular rings, computed by\n"
      "independent solvers (the multibody chain of Yin & Wang 1989/90, lumped masses, deal.II\n"
      "finite elements). The same analyses as the `ringvib` command, results as NumPy arrays.\n"
      "SI units: m, kg, s, N, Pa; frequencies angular (rad/s); angles in degrees counter-\n"
      "clockwise from +x; radial displacement positive outward, tangential counter-clockwise.\n\n"
      "    import ringvib\n"
      "    s = ringvib.Scene.load('scenes/paper1990.toml', set={'multibody.n': 160})\n"
      "    m = ringvib.modes(s, 'multibody')\n"
      "    m.omega          # rad/s, ascending, rigid modes left out\n\n"
      "Bad input raises ringvib.InputError (a ValueError), a numerical failure\n"
      "ringvib.NumericalError. Nothing is printed.";
  m.attr("__version__") = RINGVIB_VERSION;
  m.attr("STATIONS") = ring::kStations;

  register_errors(m);

  py::class_<Scene>(m, "Scene",
                    "A scene: what to compute (docs/scenes.md), read and validated once.\n"
                    "Immutable; Scene.with_() gives a new scene with more overrides.")
      .def_static(
          "load",
          [](const std::string& path, py::object set) {
            std::vector<std::string> o = overrides_from(set);
            std::string text = ring::read_scene_text(path);
            return Scene::parse(std::move(text), path, std::move(o));
          },
          py::arg("path"), py::arg("set") = py::none(),
          "Reads the scene file at `path` (TOML, at most 1 MiB) with the overrides of `set`, a\n"
          "dict {'section.key': value} (the command's --set; values as Python bool, int, float,\n"
          "str, list or dict, written as TOML). Raises InputError naming the file and the key.")
      .def_static(
          "from_toml",
          [](const std::string& text, const std::string& name, py::object set) {
            return Scene::parse(text, name, overrides_from(set));
          },
          py::arg("text"), py::arg("name") = "<toml>", py::arg("set") = py::none(),
          "A scene from TOML text; `name` stands for the file name in messages.")
      .def(
          "with_",
          [](const Scene& s, py::object set, py::kwargs kw) {
            std::vector<std::string> o = s.overrides;
            for (const auto& x : overrides_from(set)) o.push_back(x);
            // multibody__n=160 is multibody.n = 160 (a keyword cannot hold a dot).
            for (auto [k, v] : kw) {
              std::string key = k.cast<std::string>();
              for (std::size_t at; (at = key.find("__")) != std::string::npos;) key.replace(at, 2, ".");
              o.push_back(override_text(key, v));
            }
            return Scene::parse(s.text, s.name, std::move(o));
          },
          py::arg("set") = py::none(),
          "The scene with more overrides, applied after this scene's: a dict {'section.key':\n"
          "value}, or keywords with '__' for the dot: s.with_(multibody__n=160).")
      .def_property_readonly(
          "file", [](const Scene& s) { return s.scene.file; },
          "The path it was read from, or the name given to from_toml.")
      .def_property_readonly("title", [](const Scene& s) { return s.scene.title; })
      .def_property_readonly(
          "overrides", [](const Scene& s) { return s.overrides; },
          "The overrides as the command's --set arguments ('multibody.n=160').")
      .def_property_readonly(
          "toml", [](const Scene& s) { return s.scene.resolved_toml; }, "The scene after the overrides, as TOML.")
      .def_property_readonly(
          "warnings", [](const Scene& s) { return s.scene.warnings; },
          "What the command would print as warnings (the thin-ring assumption "
          "stretched, ...); the module prints nothing.")
      .def_property_readonly(
          "modes_count", [](const Scene& s) { return s.scene.modes.count; },
          "modes.count: elastic modes computed by default.")
      .def(py::pickle(  // for a ProcessPoolExecutor: the text, the name and the overrides
          [](const Scene& s) { return py::make_tuple(s.text, s.name, s.overrides); },
          [](const py::tuple& t) {
            return Scene::parse(t[0].cast<std::string>(), t[1].cast<std::string>(),
                                t[2].cast<std::vector<std::string>>());
          }))
      .def("__repr__", [](const Scene& s) {
        std::string r = "<ringvib.Scene " + py::repr(py::str(s.scene.file)).cast<std::string>();
        if (!s.overrides.empty()) r += " set " + py::repr(py::cast(s.overrides)).cast<std::string>();
        return r + ">";
      });

  py::class_<Modes>(m, "Modes", "The lowest elastic modes of one solver (`ringvib modes --json`).")
      .def_readonly("solver", &Modes::solver)
      .def_readonly("model", &Modes::model, "The discretization (n, degree, ...), as in the JSON's 'model'.")
      .def_readonly("rigid_modes", &Modes::rigid_modes, "Zero modes found (0 to 3), not numbered.")
      .def_readonly("omega", &Modes::omega, "Elastic angular frequencies, rad/s, ascending: ndarray (modes,).")
      .def_readonly("shapes", &Modes::shapes,
                    "Mode shapes at the common stations: ndarray (modes, 360, 2), [..., 0] radial (outward),\n"
                    "[..., 1] tangential (counter-clockwise), each mode scaled so that its largest |component|\n"
                    "is 1 and positive (dimensionless).")
      .def_readonly("stations_deg", &Modes::stations_deg, "The stations' polar angles, degrees: ndarray (360,).")
      .def_readonly("unknowns", &Modes::unknowns, "Size of the eigenproblem solved.")
      .def_readonly("seconds", &Modes::seconds, "Solver wall time, s.")
      .def_readonly("max_residual", &Modes::max_residual,
                    "Largest relative eigen-residual ||Kx - w^2 Mx|| / (||Kx|| + w^2 ||Mx||) of the returned\n"
                    "modes, in the norm residual_norm names (docs/commands.md, `modes --json`); None where the solver\n"
                    "reports none (calculix).")
      .def_readonly("residual_norm", &Modes::residual_norm)
      .def_readonly("pairs", &Modes::pairs,
                    "The pairs of modes the scene's terms split (masses, springs, supports): a list of dicts\n"
                    "{wave, modes (lower, upper; 1-based), omega (rad/s), split (rad/s), relative_split (of the\n"
                    "pair's mean), orientation_deg (the lower mode's radial antinode, in [0, 180/wave))}, as\n"
                    "`modes --json`'s \"pairs\"; empty for a perfect ring.")
      .def_readonly("frame", &Modes::frame,
                    "A spinning ring ([rotation]): the frame of omega, \"rotating\" (turning with the ring) or\n"
                    "\"fixed\" (modes.frame); \"\" at rest.")
      .def_readonly("wave", &Modes::wave, "A spinning ring: each mode's wave number k (list; empty at rest).")
      .def_readonly("direction", &Modes::direction,
                    "A spinning ring: each mode's travelling direction in its frame, \"forward\" (with the spin),\n"
                    "\"backward\" or \"standing\" (list; empty at rest).")
      .def_readonly("wave_pairs", &Modes::wave_pairs,
                    "A spinning ring's wave pairs: dicts {wave, forward, backward (turning frame, rad/s),\n"
                    "forward_fixed, backward_fixed (fixed frame, signed, rad/s), bryan (Bryan's factor: the\n"
                    "standing pattern's turn in space over the spin's)}, as `modes --json`'s \"wave_pairs\".")
      .def_readonly("error_estimate", &Modes::error_estimate,
                    "Estimated remaining relative error of a converged reference (0: not estimated).")
      .def_property_readonly(
          "hz", [](const Modes& o) { return o.omega.attr("__truediv__")(2 * M_PI); }, "omega / 2 pi, Hz.")
      .def("__repr__", [](const Modes& o) {
        return "<ringvib.Modes " + o.solver + ": " + std::to_string(py::len(o.omega)) + " modes, " +
               std::to_string(o.unknowns) + " unknowns>";
      });

  py::class_<Static>(m, "Static", "A nonlinear static equilibrium of one solver (`ringvib static --json`).")
      .def_readonly("solver", &Static::solver)
      .def_readonly("displacements", &Static::displacements,
                    "The recorded points: structured ndarray with fields angle (deg), ux, uy (m, ring-centred\n"
                    "frame).")
      .def_readonly("nodes", &Static::nodes, "The deformed ring at every node: ndarray (nodes, 2) of x, y (m).")
      .def_readonly("path", &Static::path,
                    "static.path or static.history: every accepted equilibrium from rest, a structured ndarray\n"
                    "with the columns of static_path_<solver>.csv: load_factor, ovalisation, ux_<deg>, uy_<deg>\n"
                    "per recorded point (m), dissipated (J), plastic_curvature (1/m), and with\n"
                    "static.displacement or [plates] reaction_x, reaction_y (N), and with [plates]\n"
                    "contact_length, contact_length_opposite (m). None without a path.")
      .def_readonly("branch_points", &Static::branch_points, "Load factors where the path switched onto a branch.")
      .def_readonly("limit_points", &Static::limit_points,
                    "static.path: the located limit points (maxima of the load factor along the path), a\n"
                    "structured ndarray with load_factor and ux_<deg>, uy_<deg> per recorded point (m). None\n"
                    "without one.")
      .def_readonly("end", &Static::end, "How the path ended: 'full load' or 'contact: <where>'.")
      .def_readonly("end_load", &Static::end_load, "The load factor where the path ended.")
      .def_readonly("dissipated", &Static::dissipated, "ring.plastic: the plastic work done, J (0 if elastic).")
      .def_readonly("plastic_curvature", &Static::plastic_curvature,
                    "ring.plastic: the largest plastic curvature left in the ring, 1/m.")
      .def_readonly("reaction", &Static::reaction,
                    "static.displacement: the force (Fx, Fy) the ring needs at the driven point at the end, N;\n"
                    "[plates]: the force of the plate at plates.axis on the ring. None when loads drive the path.")
      .def_readonly("contact_length", &Static::contact_length,
                    "[plates]: the contact length (on the plate at plates.axis, on the other) at the end, m.\n"
                    "None without plates.")
      .def_readonly("unknowns", &Static::unknowns, "Size of the nonlinear system.")
      .def_readonly("steps", &Static::steps, "Load steps (or arc-length steps) taken.")
      .def_readonly("newton_iterations", &Static::newton_iterations)
      .def_readonly("seconds", &Static::seconds, "Solver wall time, s.")
      .def("__repr__", [](const Static& o) { return "<ringvib.Static " + o.solver + ">"; });

  py::class_<Response>(m, "Response", "A forced nonlinear response of one solver (`ringvib respond --csv`).")
      .def_readonly("solver", &Response::solver)
      .def_readonly("history", &Response::history,
                    "One row per accepted step (t = 0 first): structured ndarray with the CSV's columns t (s),\n"
                    "ux_<deg>, uy_<deg> per recorded point (m, ring-centred frame), kinetic, strain, (a plastic\n"
                    "ring: dissipated, the plastic work), work, energy_error (J), constraint_residual,\n"
                    "newton_iterations (int).")
      .def_readonly("record_angles", &Response::record_angles, "The recorded points, degrees: ndarray (points,).")
      .def_readonly("t", &Response::t, "Time, s: ndarray (steps,).")
      .def_readonly("ux", &Response::ux, "Displacement x, m: ndarray (points, steps).")
      .def_readonly("uy", &Response::uy, "Displacement y, m: ndarray (points, steps).")
      .def_readonly("snapshot_t", &Response::snapshot_t, "Instants of the deformed-ring snapshots, s.")
      .def_readonly("snapshots", &Response::snapshots,
                    "The deformed ring at each snapshot: list of ndarray (nodes, 2), m.")
      .def_readonly("unknowns", &Response::unknowns, "Size of the nonlinear system per step.")
      .def_readonly("seconds", &Response::seconds, "Solver wall time, s.")
      .def("__repr__", [](const Response& o) {
        return "<ringvib.Response " + o.solver + ": " + std::to_string(py::len(o.t)) + " steps>";
      });

  m.def(
      "solvers",
      [] {
        py::list out;
        for (const cmp::SolverEntry& e : cmp::registry()) {
          py::list analyses;
          if (e.modes) analyses.append("modes");
          if (e.statics) analyses.append("static");
          if (e.response) analyses.append("response");
          py::dict d;
          d["name"] = e.name;
          d["label"] = e.label;
          d["size_key"] = e.size_key;
          d["size_name"] = e.size_name;
          d["analyses"] = analyses;
          out.append(d);
        }
        return out;
      },
      "The solver registry, in its order (the paper's method first): a list of dicts with name\n"
      "(scene and command-line name), label (table header), size_key (the discretization key),\n"
      "size_name and analyses ('modes', 'static', 'response').");

  m.def(
      "modes",
      [](const Scene& s, const std::string& solver, std::optional<int> count, double max_memory_gib, bool force) {
        // As `ringvib modes SCENE --solver NAME [--count K]`.
        const ring::ModalResult r = released([&] {
          return input_checked(s.scene, [&] {
            cmp::check_runnable(s.scene, max_memory_gib, force);
            return cmp::run_modes(s.scene, solver, count, "count");
          });
        });
        return to_python(r);
      },
      py::arg("scene"), py::arg("solver"), py::arg("count") = py::none(), py::kw_only(),
      py::arg("max_memory_gib") = 8.0, py::arg("force") = false,
      (std::string("The `count` (default modes.count) lowest elastic modes of `solver` ('multibody',\n"
                   "'lumped', 'fem') under the scene's options: a Modes (omega in rad/s, shapes at 360\n"
                   "stations). As `ringvib modes SCENE --solver NAME --json`. ") +
       kBudgetDoc)
          .c_str());

  m.def(
      "table",
      [](const Scene& s, bool paper, double max_memory_gib, bool force) {
        const std::string json = released([&] {
          return input_checked(s.scene, [&] {
            cmp::check_runnable(s.scene, max_memory_gib, force);
            return cmp::format_json(cmp::run_table(s.scene, paper, nullptr));
          });
        });
        return json_rows(json);
      },
      py::arg("scene"), py::kw_only(), py::arg("paper") = false, py::arg("max_memory_gib") = 8.0,
      py::arg("force") = false,
      (std::string("The comparison table of the scene's solvers, one dict per mode: the rows of\n"
                   "`ringvib table SCENE --format json` (mode, <solver> in rad/s, <solver>_mode,\n"
                   "<solver>_mac, <solver>_diff_pct, reference, <solver>_error_pct, and with paper=True\n"
                   "paper_<solver> and <solver>_vs_paper_pct; percentages in %). pandas.DataFrame(rows)\n"
                   "makes a frame of it. ") +
       kBudgetDoc)
          .c_str());

  m.def(
      "static",
      [](const Scene& s, const std::string& solver, double max_memory_gib, bool force) {
        const ring::StaticResult r = released([&] {
          const ring::Scene n = cmp::narrowed(s.scene, &ring::Scene::static_request, solver);
          return input_checked(n, [&] {
            cmp::check_runnable(n, max_memory_gib, force);
            cmp::require_section(n, "static");
            return cmp::run_static(n, single(n, n.static_request, solver, "static.solvers", "static_table"), nullptr);
          });
        });
        return to_python(r);
      },
      py::arg("scene"), py::arg("solver") = "", py::kw_only(), py::arg("max_memory_gib") = 8.0,
      py::arg("force") = false,
      (std::string("The nonlinear static equilibrium of the scene's [static] with `solver` (default: the\n"
                   "one static.solvers lists): a Static. As `ringvib static SCENE [--solver NAME] --json`.\n"
                   "A path that does not reach the full load raises NumericalError with load_factor. ") +
       kBudgetDoc)
          .c_str());

  m.def(
      "respond",
      [](const Scene& s, const std::string& solver, double max_memory_gib, bool force) {
        const ring::TimeHistory h = released([&] {
          const ring::Scene n = cmp::narrowed(s.scene, &ring::Scene::response_request, solver);
          return input_checked(n, [&] {
            cmp::check_runnable(n, max_memory_gib, force);
            cmp::require_section(n, "response");
            const std::string one = single(n, n.response_request, solver, "response.solvers", "response_table");
            try {
              return cmp::run_response(n, one, nullptr);
            } catch (const ring::IntegrationFailure& e) {
              // The partial history names its solver, as a finished one does.
              ring::TimeHistory partial = e.partial();
              if (partial.solver.empty()) partial.solver = one;
              throw ring::IntegrationFailure(e.reason(), e.t_reached(), std::move(partial), e.what());
            }
          });
        });
        return to_python(h);
      },
      py::arg("scene"), py::arg("solver") = "", py::kw_only(), py::arg("max_memory_gib") = 8.0,
      py::arg("force") = false,
      (std::string("The forced nonlinear response of the scene's [response] with `solver` (default: the\n"
                   "one response.solvers lists): a Response whose history has the columns of\n"
                   "`ringvib respond SCENE [--solver NAME] --csv`. A failed integration raises\n"
                   "NumericalError with t_reached and the partial Response. ") +
       kBudgetDoc)
          .c_str());

  m.def(
      "buckling",
      [](const Scene& s, const std::string& solver, double max_memory_gib, bool force) {
        const ring::BucklingResult r = released([&] {
          const ring::Scene n = cmp::narrowed(s.scene, &ring::Scene::buckling_request, solver);
          return input_checked(n, [&] {
            cmp::check_runnable(n, max_memory_gib, force);
            cmp::require_section(n, "buckling");
            return cmp::run_buckling_of(n, single(n, n.buckling_request, solver, "buckling.solvers", "buckling_table"),
                                        nullptr);
          });
        });
        // The shapes as the modes carry them (cmp::as_modal: the factors in omega's place).
        const Modes as_modes = to_python(cmp::as_modal(r));
        py::dict d;
        d["solver"] = r.solver;
        d["model"] = as_modes.model;
        d["factors"] = as_modes.omega;
        d["shapes"] = as_modes.shapes;
        d["stations_deg"] = as_modes.stations_deg;
        d["unknowns"] = r.unknowns;
        d["seconds"] = r.seconds;
        return d;
      },
      py::arg("scene"), py::arg("solver") = "", py::kw_only(), py::arg("max_memory_gib") = 8.0,
      py::arg("force") = false,
      (std::string("The linear buckling of the scene's [buckling] with `solver` (default: the one\n"
                   "buckling.solvers lists): a dict with solver, model, factors (the critical load factors\n"
                   "lambda, ascending: ndarray), shapes (ndarray (k, 360, 2): radial, tangential at the\n"
                   "stations), stations_deg, unknowns and seconds. As `ringvib buckling SCENE --solver NAME\n"
                   "--json`, with the shapes. ") +
       kBudgetDoc)
          .c_str());
  m.def(
      "buckling_table",
      [](const Scene& s, double max_memory_gib, bool force) {
        const std::string json = released([&] {
          return input_checked(s.scene, [&] {
            cmp::check_runnable(s.scene, max_memory_gib, force);
            return cmp::format_json(cmp::buckling_comparison(s.scene, nullptr));
          });
        });
        return json_rows(json);
      },
      py::arg("scene"), py::kw_only(), py::arg("max_memory_gib") = 8.0, py::arg("force") = false,
      "The comparison of buckling.solvers (and the reference), paired by MAC: the rows of\n"
      "`ringvib buckling SCENE --format json` (mode, <solver> load factor, <solver>_diff_pct,\n"
      "reference, <solver>_error_pct in %; None where not defined).");

  m.def(
      "trim",
      [](const Scene& s, int mode, std::vector<double> at, const std::string& solver, double tolerance,
         double max_memory_gib, bool force) {
        cmp::TrimArgs t;
        t.mode = mode;
        t.at = std::move(at);
        t.solver = solver;
        t.tolerance = tolerance;
        const cmp::TrimResult r = released([&] {
          return input_checked(s.scene, [&] {
            cmp::check_runnable(s.scene, max_memory_gib, force);
            return cmp::run_trim(s.text, s.name, s.overrides, t);
          });
        });
        py::dict out;
        out["mode"] = r.mode;
        out["wave"] = r.wave;
        out["solver"] = r.solver;
        py::list masses;
        for (std::size_t i = 0; i < r.masses.size(); ++i) {
          py::dict d;
          d["at"] = r.at[i];
          d["mass"] = r.masses[i];
          masses.append(d);
        }
        out["masses"] = masses;
        out["split_before"] = r.before.relative();
        out["split_after"] = r.after.wave ? r.after.relative() : 0.0;
        out["orientation_before"] = r.before.orientation;
        out["steps"] = r.steps;
        out["scene"] = Scene::parse(r.trimmed_scene, s.name, s.overrides);
        return out;
      },
      py::arg("scene"), py::arg("mode"), py::arg("at"), py::kw_only(), py::arg("solver") = "",
      py::arg("tolerance") = 1e-6, py::arg("max_memory_gib") = 8.0, py::arg("force") = false,
      (std::string("`ringvib trim SCENE --mode N --at A,B`: the point masses at the angles `at` (one or two,\n"
                   "degrees, nodes of every model) that cancel the split of the pair holding mode `mode`\n"
                   "(1-based), measured by `solver` (default: the scene's first modal solver) down to the\n"
                   "relative `tolerance`. A dict with mode, wave, solver, masses ([{at, mass (kg)}]),\n"
                   "split_before, split_after (relative to the pair's mean frequency), orientation_before\n"
                   "(deg), steps and scene (the trimmed Scene). InputError for angles that cannot trim the\n"
                   "pair; NumericalError when a mass would have to be negative or the split stays. ") +
       kBudgetDoc)
          .c_str());

  m.def(
      "converge",
      [](const Scene& s, double max_memory_gib, bool force) {
        const cmp::ConvergenceStudy c = released([&] {
          return input_checked(s.scene, [&] {
            cmp::check_runnable(s.scene, max_memory_gib, force);
            return cmp::run_converge(s.scene, nullptr);
          });
        });
        py::list series;
        for (const cmp::ConvergenceSeries& x : c.series) {
          py::dict d;
          d["name"] = x.name;
          d["parameter"] = x.parameter;
          d["size"] = py::array_t<double>(x.size.size(), x.size.data());
          d["max_error_pct"] = py::array_t<double>(x.max_error.size(), x.max_error.data());
          d["mean_error_pct"] = py::array_t<double>(x.mean_error.size(), x.mean_error.data());
          d["seconds"] = py::array_t<double>(x.seconds.size(), x.seconds.data());
          d["fitted_order"] = x.order;
          series.append(d);
        }
        py::dict out;
        out["modes"] = c.modes;
        out["reference_estimate"] = c.reference_estimate;
        out["series"] = series;
        return out;
      },
      py::arg("scene"), py::kw_only(), py::arg("max_memory_gib") = 8.0, py::arg("force") = false,
      (std::string("The convergence study of `ringvib converge SCENE` (its convergence.csv with --out):\n"
                   "a dict with modes, reference_estimate (the references' largest remaining relative\n"
                   "error) and series, a list of dicts with name, parameter ('n' or 'elements'), size,\n"
                   "max_error_pct, mean_error_pct, seconds (ndarrays, one value per refinement) and\n"
                   "fitted_order. ") +
       kBudgetDoc)
          .c_str());

  m.def(
      "bench",
      [](const Scene& s, py::object progress, double max_memory_gib, bool force) {
        std::optional<CallbackProgress> buffer;
        std::optional<std::ostream> stream;
        if (!progress.is_none()) {
          buffer.emplace(progress);
          stream.emplace(&*buffer);
        }
        const cmp::BenchRun r = released([&] {
          return input_checked(s.scene, [&] {
            cmp::check_runnable(s.scene, max_memory_gib, force);
            return cmp::run_bench(s.scene, stream ? &*stream : nullptr);
          });
        });
        if (buffer) buffer->raise_if_failed();
        py::dict out;
        out["modal"] = py::none();
        if (r.modal) {
          py::dict d;
          d["modes"] = r.modal->modes;
          d["reference_seconds"] = r.modal->reference_seconds;
          d["points"] = bench_points(*r.modal);
          out["modal"] = d;
        }
        py::list nonlinear;
        for (const cmp::NonlinearBench& b : r.nonlinear) {
          py::dict d;
          d["analysis"] = b.analysis;
          d["loaded_point"] = b.loaded_point;
          d["reference_value"] = b.reference_value;
          d["reference_seconds"] = b.reference_seconds;
          d["points"] = bench_points(b.study);
          nonlinear.append(d);
        }
        out["nonlinear"] = nonlinear;
        return out;
      },
      py::arg("scene"), py::kw_only(), py::arg("progress") = py::none(), py::arg("max_memory_gib") = 8.0,
      py::arg("force") = false,
      (std::string("Run time against error, as `ringvib bench SCENE` (its bench*.csv with --out): a dict\n"
                   "with 'modal' (None, or a dict of modes, reference_seconds and points) and 'nonlinear' (a\n"
                   "list of dicts, one per analysis: analysis, loaded_point (deg), reference_value (m),\n"
                   "reference_seconds and points). points: a dict of curve (list of names), size, unknowns,\n"
                   "seconds (median solver time), repeats, max_error_pct, mean_error_pct (ndarrays, one value\n"
                   "per point). progress: a callable given each progress line (str), from the solving thread\n"
                   "with the GIL held; an exception it raises is raised when the study ends. Times are this\n"
                   "machine's, under its load: read them as ratios within one study. ") +
       kBudgetDoc)
          .c_str());

  m.def(
      "sweep",
      [](const Scene& s, py::dict vary, bool zip, int jobs, py::object progress, double max_memory_gib, bool force) {
        // Each list as the --vary text of the command: the overrides' TOML for the list.
        std::vector<std::string> lists;
        for (const auto& [k, v] : vary) lists.push_back(override_text(k.cast<std::string>(), v));
        cmp::CommonArgs a;
        a.scene = s.name;
        a.set = s.overrides;
        a.max_memory_gib = max_memory_gib;
        a.force = force;
        std::optional<py::error_already_set> failed;
        const std::function<void(int, int, int)> on_case = [&](int done, int total, int failures) {
          if (progress.is_none()) return;
          py::gil_scoped_acquire gil;
          if (!failed) try {
              progress(done, total, failures);
            } catch (py::error_already_set& e) {
              failed.emplace(std::move(e));
            }
        };
        const cmp::SweepTable t = released([&] { return cmp::run_sweep(s.text, a, lists, zip, jobs, on_case); });
        if (failed) throw *failed;
        return json_rows(cmp::sweep_json(t.keys, t.rows));
      },
      py::arg("scene"), py::arg("vary"), py::kw_only(), py::arg("zip") = false, py::arg("jobs") = 0,
      py::arg("progress") = py::none(), py::arg("max_memory_gib") = 8.0, py::arg("force") = false,
      (std::string("The scene over many values, as `ringvib sweep SCENE --vary KEY=[...]` (its sweep.json's\n"
                   "rows): vary maps each key to its list of values ({'multibody.n': [20, 40, 80]}); every\n"
                   "combination, or with zip=True the lists in lockstep. Cases run on `jobs` threads (0: all\n"
                   "cores) with the GIL released; a case that fails is a row with its status and message.\n"
                   "A list of dicts: case, the varied keys' values (TOML text), solver, analysis, quantity,\n"
                   "value (rad/s or m), error_pct (None without a reference), unknowns, seconds, status,\n"
                   "message. progress: a callable progress(done, total, failed) after each case, with the GIL\n"
                   "held; an exception it raises is raised when the sweep ends. Raises NumericalError when\n"
                   "every case failed. ") +
       kBudgetDoc)
          .c_str());

  auto nonlinear_table = [](bool response) {
    return [response](const Scene& s, double max_memory_gib, bool force) {
      const std::string json = released([&] {
        return input_checked(s.scene, [&] {
          cmp::check_runnable(s.scene, max_memory_gib, force);
          cmp::require_section(s.scene, response ? "response" : "static");
          const cmp::NonlinearRun r = cmp::run_nonlinear(s.scene, "", nullptr);
          return cmp::format_json(response ? cmp::response_comparison(s.scene, r) : cmp::static_comparison(s.scene, r));
        });
      });
      return json_rows(json);
    };
  };
  m.def("static_table", nonlinear_table(false), py::arg("scene"), py::kw_only(), py::arg("max_memory_gib") = 8.0,
        py::arg("force") = false,
        "The comparison of static.solvers (and the reference): the rows of `ringvib static SCENE\n"
        "--format json` (point in deg, quantity ux | uy | u, <solver> in m, <solver>_diff_pct,\n"
        "reference, <solver>_error_pct in %; None where not defined).");
  m.def("response_table", nonlinear_table(true), py::arg("scene"), py::kw_only(), py::arg("max_memory_gib") = 8.0,
        py::arg("force") = false,
        "The comparison of response.solvers (and the reference): the rows of `ringvib respond SCENE\n"
        "--format json` (point in deg, quantity peak_u in m | t_peak in s, <solver>, <solver>_diff_pct,\n"
        "reference, <solver>_error_pct in %; None where not defined).");
}
