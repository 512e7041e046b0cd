#include "compare/registry.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "calculix/modes.hpp"
#include "calculix/options.hpp"
#include "calculix/response.hpp"
#include "calculix/statics.hpp"
#include "compare/fem_module.hpp"
#include "compare/files.hpp"
#include "fem_reference/buckling.hpp"
#include "fem_reference/checks.hpp"
#include "fem_reference/options.hpp"
#include "lumped_mass/buckling.hpp"
#include "lumped_mass/checks.hpp"
#include "lumped_mass/options.hpp"
#include "multibody/backend.hpp"
#include "multibody/buckling.hpp"
#include "multibody/checks.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "lumped_mass/preload.hpp"
#include "compare/spin.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/modes.hpp"
#include "multibody/options.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"

namespace cmp {
namespace {

/// A solver's std::invalid_argument ("can never work") is an input error (exit 2) under
/// `name`; a message that already starts with "name: " keeps it once ("lumped: lumped:
/// masses[1] ..." read twice the same word).
template <class F>
auto as_input_error(const ring::Scene& s, const std::string& name, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what(), prefix = name + ": ";
    throw ring::InputError(s.file, name, what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
  }
}

/// What a solver's memory estimate reads of the scene (ring/memory_query.hpp).
ring::MemoryQuery memory_query(const ring::Scene& s, int count) {
  ring::MemoryQuery q;
  q.count = count;
  q.preload = s.modes.preload_static;
  q.response = s.response.has_value();
  q.statics = s.statics ? &*s.statics : nullptr;
  q.reference = s.needs_reference();
  return q;
}

/// True when the nonlinear request lists the solver.
bool runs(const ring::NonlinearRequest& q, const std::string& name) {
  return std::find(q.solvers.begin(), q.solvers.end(), name) != q.solvers.end();
}

/// modes.preload = "static" (frequencies under load) is the chains' and fem's.
void refuse_preload(const ring::Scene& s) {
  if (s.modes.preload_static)
    throw std::invalid_argument("modes.preload = \"static\" (the modes about the loaded equilibrium) is not "
                                "offered by this solver; the multibody and lumped chains and fem offer it "
                                "(modes.solvers = [\"multibody\", \"lumped\", \"fem\"], no table.reference)");
}

/// Chains and frames: n = 40, 80, ..., 2560 (from enough pieces for the modes asked).
std::vector<std::pair<std::string, ring::Scene>> doubling_sweep(const SolverEntry& e, const ring::Scene& s,
                                                                int modes) {
  std::vector<std::pair<std::string, ring::Scene>> v;
  for (int n = 40; n <= 2560; n *= 2) {
    ring::Scene r = s;
    e.set_size(r, n);
    if (e.elastic_modes(r) < modes) continue;
    v.emplace_back(e.curve(s), r);
  }
  return v;
}

SolverEntry multibody_entry() {
  SolverEntry e;
  e.name = "multibody";
  e.label = "multibody";
  e.size_key = "multibody.n";
  e.size_name = "n";
  e.options = multibody::option_schema();
  e.store = [](ring::Scene& s, const ring::OptionValues& v) { s.multibody = multibody::read_options(v); };
  e.size = [](const ring::Scene& s) { return s.multibody.n; };
  e.set_size = [](ring::Scene& s, int n) { s.multibody.n = n; };
  e.theory = [](const ring::Scene& s) { return s.multibody.theory.value_or(s.ring.theory); };
  e.theory_key = "multibody.theory";
  // n angles (+2 for a free ring) - 2 closures - the roller's row - 2 per further pin - the
  // rigid modes the supports leave (a clamp is a spring on the chain: multibody/attachments.hpp).
  e.elastic_modes = [](const ring::Scene& s) -> long long {
    const ring::Supports& sup = s.ring.supports;
    return s.multibody.n + (sup.free() ? 2 : 0) - 2 - (sup.roller ? 1 : 0) - 2 * static_cast<long long>(sup.pins.size()) -
           s.ring.rigid_modes();
  };
  e.inextensible = [](const ring::Scene&) { return true; };
  e.curve = [](const ring::Scene&) { return std::string("multibody"); };
  e.converge_steps = 5;
  e.richardson = true;
  e.paper = [](const ring::PaperRow& r) { return r.mb_corrected; };
  e.memory = [](const ring::Scene& s, int count) { return multibody::memory_estimate(s.ring, s.multibody, memory_query(s, count)); };
  e.check_modes = [](const ring::Scene& s) {
    if (s.modes.preload_static) multibody::check_preloaded_modes(s.ring, s.multibody, *s.statics);
    else multibody::check_modes(s.ring, s.multibody);
  };
  e.check_static = [](const ring::Scene& s) { multibody::check_static(s.ring, s.multibody, *s.statics); };
  e.check_response = [](const ring::Scene& s) { multibody::check_response(s.ring, s.multibody, *s.response); };
  e.modes = [](const ring::Scene& s, int count) {
    return as_input_error(s, "multibody", [&] {
      return s.modes.preload_static ? multibody::compute_modes_under_load(s.ring, s.multibody, *s.statics, count)
                                    : multibody::compute_modes(s.ring, s.multibody, count);
    });
  };
  e.statics = [](const ring::Scene& s) {
    return as_input_error(s, "static", [&] { return multibody::solve_static(s.ring, s.multibody, *s.statics); });
  };
  e.response = [](const ring::Scene& s) {
    return as_input_error(s, "response", [&] { return multibody::respond(s.ring, s.multibody, *s.response); });
  };
  e.check_buckling = [](const ring::Scene& s) { multibody::check_buckling(s.ring, s.multibody, *s.buckling); };
  // Dense n x n matrices: the tangent, K_1, the (n + 3)^2 prebuckling LU, the QR's Q, the
  // reduced pencil and its eigenvectors, about ten of them (to be measured).
  e.buckling_memory = [](const ring::Scene& s) { return 100.0 * s.multibody.n * s.multibody.n; };
  e.buckling = [](const ring::Scene& s) {
    return as_input_error(s, "buckling", [&] { return multibody::compute_buckling(s.ring, s.multibody, *s.buckling); });
  };
  return e;
}

SolverEntry lumped_entry() {
  SolverEntry e;
  e.name = "lumped";
  e.label = "lumped mass";
  e.size_key = "lumped.n";
  e.size_name = "n";
  e.options = lumped::option_schema();
  e.store = [](ring::Scene& s, const ring::OptionValues& v) { s.lumped = lumped::read_options(v); };
  e.size = [](const ring::Scene& s) { return s.lumped.n; };
  e.set_size = [](ring::Scene& s, int n) { s.lumped.n = n; };
  // The variant is the model (lumped_mass/checks.hpp check_theory): no lumped.theory.
  e.theory = [](const ring::Scene& s) {
    return s.lumped.variant == ring::LumpedOptions::Variant::timoshenko_frame ? ring::Theory::timoshenko
                                                                              : ring::Theory::euler_bernoulli;
  };
  e.theory_key = "lumped.variant";
  // Inertial DOFs (chain: n after the n link rows; frame: the 2n translations and the
  // rotations that carry a point inertia; frame-consistent and timoshenko-frame (rho I on
  // every rotation): all 3n) minus the supports'
  // constraint rows and the rigid modes. The chain's clamp is a spring (lumped_mass/model.hpp,
  // as multibody's), no row; the lumped frame's clamp blocks a massless rotation (no inertial
  // DOF) unless a point inertia sits there.
  e.elastic_modes = [](const ring::Scene& s) -> long long {
    const long long n = s.lumped.n;
    const ring::Supports& sup = s.ring.supports;
    const int held = sup.constraint_rows() + s.ring.rigid_modes();
    const double anchor = s.ring.anchor();
    auto node = [&](double deg) { return std::lround(ring::wrap_degrees(deg - anchor) * n / 360.0) % n; };
    std::vector<long> inertial_rotations;
    for (const ring::PointMass& m : s.ring.masses)
      if (m.inertia > 0.0 && std::find(inertial_rotations.begin(), inertial_rotations.end(), node(m.angle)) ==
                                 inertial_rotations.end())
        inertial_rotations.push_back(node(m.angle));
    const bool clamp_inertial =
        sup.clamp && std::find(inertial_rotations.begin(), inertial_rotations.end(), node(*sup.clamp)) !=
                         inertial_rotations.end();
    switch (s.lumped.variant) {
      case ring::LumpedOptions::Variant::chain: return n - held + (sup.clamp ? 1 : 0);
      case ring::LumpedOptions::Variant::frame:
        return 2 * n + static_cast<long long>(inertial_rotations.size()) - held +
               (sup.clamp && !clamp_inertial ? 1 : 0);
      case ring::LumpedOptions::Variant::frame_consistent:
      case ring::LumpedOptions::Variant::timoshenko_frame: return 3 * n - held;
    }
    return 0;
  };
  e.inextensible = [](const ring::Scene& s) { return s.lumped.variant == ring::LumpedOptions::Variant::chain; };
  e.curve = [](const ring::Scene& s) { return "lumped (" + ring::to_string(s.lumped.variant) + ")"; };
  e.converge_steps = 5;
  e.paper = [](const ring::PaperRow& r) { return r.lm_corrected; };
  e.memory = [](const ring::Scene& s, int count) { return lumped::memory_estimate(s.ring, s.lumped, memory_query(s, count)); };
  e.check_modes = [](const ring::Scene& s) {
    if (s.modes.preload_static) lumped::check_preloaded_modes(s.ring, s.lumped, *s.statics);
    else lumped::check_modes(s.ring, s.lumped);
  };
  e.check_static = [](const ring::Scene& s) {
    lumped::check_static(s.ring, s.lumped, *s.statics);
  };
  e.check_response = [](const ring::Scene& s) { lumped::check_response(s.ring, s.lumped, *s.response); };
  e.check_buckling = [](const ring::Scene& s) { lumped::check_buckling(s.ring, s.lumped, *s.buckling); };
  e.modes = [](const ring::Scene& s, int count) {
    return as_input_error(s, "lumped", [&] {
      return s.modes.preload_static ? lumped::compute_modes_under_load(s.ring, s.lumped, *s.statics, count)
                                    : lumped::compute_modes(s.ring, s.lumped, count);
    });
  };
  e.statics = [](const ring::Scene& s) {
    return as_input_error(s, "static", [&] { return lumped::solve_static(s.ring, s.lumped, *s.statics); });
  };
  e.response = [](const ring::Scene& s) {
    return as_input_error(s, "response", [&] { return lumped::respond(s.ring, s.lumped, *s.response); });
  };
  e.buckling = [](const ring::Scene& s) {
    return as_input_error(s, "buckling", [&] { return lumped::compute_buckling(s.ring, s.lumped, *s.buckling); });
  };
  return e;
}

SolverEntry fem_entry() {
  SolverEntry e;
  e.name = "fem";
  e.label = "FE";
  e.size_key = "fem.elements";
  e.size_name = "elements";
  e.options = fem::option_schema();  // fem_options: no deal.II, the plug-in stays unloaded
  e.store = [](ring::Scene& s, const ring::OptionValues& v) { s.fem = fem::read_options(v); };
  e.size = [](const ring::Scene& s) { return s.fem.elements; };
  e.set_size = [](ring::Scene& s, int n) { s.fem.elements = n; };
  e.theory = [](const ring::Scene& s) { return s.fem.theory.value_or(s.ring.theory); };
  e.theory_key = "fem.theory";
  // C0 elements of degree p: p nodes per cell and two displacement components (u, w), three
  // fields (u, w, psi) for a Timoshenko ring.
  e.elastic_modes = [](const ring::Scene& s) -> long long {
    const int held = s.ring.supports.constraint_rows() + s.ring.rigid_modes();
    const long long fields = s.ring.theory == ring::Theory::timoshenko ? 3 : 2;
    return fields * s.fem.elements * s.fem.degree - held;
  };
  e.inextensible = [](const ring::Scene& s) { return !s.fem.extensible; };
  e.curve = [](const ring::Scene& s) { return "fem (p = " + std::to_string(s.fem.degree) + ")"; };
  e.bench_sweep = [](const ring::Scene& s, int) {
    std::vector<std::pair<std::string, ring::Scene>> v;
    for (int p = 2; p <= 4; ++p)
      for (int cells : {10, 20, 40, 80, 160}) {
        ring::Scene r = s;
        r.fem.degree = p;
        r.fem.elements = cells;
        v.emplace_back("fem (p = " + std::to_string(p) + ")", r);
      }
    return v;
  };
  e.converge_steps = 4;
  e.paper = [](const ring::PaperRow& r) { return r.fe_corrected; };
  e.memory = [](const ring::Scene& s, int count) { return fem::memory_estimate(s.ring, s.fem, memory_query(s, count)); };
  // The deal.II plug-in and its libraries: peak RSS of the smallest FE run 162.7 MiB, the
  // process without it 7.8-8.8 MiB (compare/guard.cpp).
  e.code_bytes = 160.0 * (1 << 20);
  e.check_modes = [](const ring::Scene& s) {
    if (s.modes.preload_static) fem::check_preloaded_modes(s.ring, s.fem, *s.statics);
    else fem::check_modes(s.ring, s.fem);
  };
  e.check_static = [](const ring::Scene& s) {
    fem::check_static(s.ring, s.fem, *s.statics);
  };
  e.check_response = [](const ring::Scene& s) { fem::check_response(s.ring, s.fem, *s.response); };
  e.check_buckling = [](const ring::Scene& s) { fem::check_buckling(s.ring, s.fem, *s.buckling); };
  e.modes = [](const ring::Scene& s, int count) {
    if (!s.modes.preload_static) return fem_module::modes(s.ring, s.fem, count);
    return as_input_error(s, "modes", [&] { return fem_module::modes_under_load(s.ring, s.fem, *s.statics, count); });
  };
  e.statics = [](const ring::Scene& s) {
    return as_input_error(s, "static", [&] { return fem_module::statics(s.ring, s.fem, *s.statics); });
  };
  e.response = [](const ring::Scene& s) {
    return as_input_error(s, "response", [&] { return fem_module::respond(s.ring, s.fem, *s.response); });
  };
  e.buckling = [](const ring::Scene& s) {
    return as_input_error(s, "buckling", [&] { return fem_module::buckling(s.ring, s.fem, *s.buckling); });
  };
  e.write_vtu = [](const ring::Scene& s, int count, const std::string& dir) {
    fem_module::write_vtu(s.ring, s.fem, count, dir);
  };
  return e;
}

/// A ring::InputError thrown without the scene's file (the calculix deck writer, which
/// knows no scene) gets it.
template <class F>
auto with_scene_file(const ring::Scene& s, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const ring::InputError& e) {
    if (!e.file().empty()) throw;
    throw ring::InputError(s.file, "", e.what());
  }
}

/// ccx's job folder and process, known to ringvib's signal cleanup (compare/files.hpp).
calculix::Hooks signal_hooks() {
  calculix::Hooks h;
  h.folder_made = [](const std::string& dir) { register_temp_folder(dir); };
  h.folder_removed = [](const std::string& dir) { unregister_temp_folder(dir); };
  h.child = [](int pid) {
    static thread_local int running = 0;
    if (pid > 0) add_child(pid);
    else remove_child(running);
    running = pid;
  };
  h.poll = interrupt_check();  // the Python module's Ctrl-C (empty for the command)
  return h;
}

SolverEntry calculix_entry() {
  SolverEntry e;
  e.name = "calculix";
  e.label = "CalculiX";
  e.size_key = "calculix.elements";
  e.size_name = "elements";
  e.options = calculix::option_schema();
  e.store = [](ring::Scene& s, const ring::OptionValues& v) { s.calculix = calculix::read_options(v); };
  e.size = [](const ring::Scene& s) { return s.calculix.elements; };
  e.set_size = [](ring::Scene& s, int n) { s.calculix.elements = n; };
  // The beam nodes' in-plane degrees of freedom (ux, uy, rotation) bound the in-plane modes.
  e.elastic_modes = [](const ring::Scene& s) -> long long {
    const int held = s.ring.supports.constraint_rows() + s.ring.rigid_modes();
    return 3LL * calculix::node_count(s.ring, s.calculix) - held;
  };
  e.inextensible = [](const ring::Scene&) { return false; };
  e.curve = [](const ring::Scene& s) { return "calculix (" + ring::to_string(s.calculix.element) + ")"; };
  e.bench_sweep = [](const ring::Scene& s, int) {
    std::vector<std::pair<std::string, ring::Scene>> v;
    for (int n : {40, 80, 160, 320}) {
      ring::Scene r = s;
      r.calculix.elements = n;
      v.emplace_back("calculix (" + ring::to_string(s.calculix.element) + ")", r);
    }
    return v;
  };
  e.converge_steps = 4;
  e.memory = [](const ring::Scene& s, int count) { return calculix::memory_estimate(s.calculix, memory_query(s, count)); };
  e.check_modes = [](const ring::Scene& s) {
    refuse_preload(s);
    with_scene_file(s, [&] {
      calculix::check_deck(s.ring, s.calculix);
      calculix::check_spin(s.ring, s.calculix);
      calculix::require_environment();
    });
  };
  e.modes = [](const ring::Scene& s, int count) {
    return with_scene_file(s, [&] { return calculix::compute_modes(s.ring, s.calculix, count, signal_hooks(), s.title); });
  };
  // A history is one *STEP per leg, and a path ccx's converged increments (calculix/statics.cpp):
  // ccx steps the load, so a path that would pass a limit point stops there (exit 3).
  e.check_static = [](const ring::Scene& s) {
    with_scene_file(s, [&] {
      calculix::check_static(s.ring, s.calculix, *s.statics);
      calculix::require_environment();
    });
  };
  e.statics = [](const ring::Scene& s) {
    return with_scene_file(
        s, [&] { return calculix::solve_static(s.ring, s.calculix, *s.statics, signal_hooks(), s.title); });
  };
  e.check_response = [](const ring::Scene& s) {
    with_scene_file(s, [&] {
      calculix::check_response(s.ring, s.calculix, *s.response);
      calculix::require_environment();
    });
  };
  e.no_buckling_because =
      "CalculiX's *BUCKLE keeps only the stress stiffness of the linear prebuckling state, not the displacement "
      "terms of ringvib's one definition (docs/solvers.md, \"Buckling and the path to contact\"), so its factors would differ by model under loads "
      "that bend the ring";
  e.response = [](const ring::Scene& s) {
    return with_scene_file(
        s, [&] { return calculix::respond(s.ring, s.calculix, *s.response, signal_hooks(), s.title); });
  };
  return e;
}

/// Wraps an analysis so that a result holding a NaN or an infinity is a numerical failure
/// (require_finite), whatever solver and acceptance checks produced it.
template <class Result, class... Args>
std::function<Result(const ring::Scene&, Args...)> finite(std::function<Result(const ring::Scene&, Args...)> f) {
  if (!f) return f;
  return [f](const ring::Scene& s, Args... args) {
    Result r = f(s, args...);
    require_finite(r);
    return r;
  };
}

/// Wraps a nonlinear analysis so that its result names the solver and carries the wall
/// time even where the solver leaves them out.
template <class Result>
std::function<Result(const ring::Scene&)> named_and_timed(std::string name,
                                                          std::function<Result(const ring::Scene&)> f) {
  if (!f) return f;
  return [name, f](const ring::Scene& s) {
    const auto start = std::chrono::steady_clock::now();
    Result r = f(s);
    if (r.solver.empty()) r.solver = name;
    if (r.seconds == 0.0) r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  };
}

/// `f` run on the solver's model scene (model_scene): one place that hands every analysis,
/// check and estimate of an entry the ring in the solver's own theory.
template <class R, class... Args>
std::function<R(const ring::Scene&, Args...)> on_model(const SolverEntry& e,
                                                        std::function<R(const ring::Scene&, Args...)> f) {
  if (!f || !e.theory) return f;
  const auto theory = e.theory;
  return [theory, f](const ring::Scene& s, Args... args) {
    ring::Scene m = s;
    m.ring.theory = theory(s);
    return f(m, args...);
  };
}

/// The model's theory in the result's description (ModalResult::model, BucklingResult::model),
/// so that a table, report or JSON says which theory each column is.
template <class Result, class... Args>
std::function<Result(const ring::Scene&, Args...)> with_theory(std::function<Result(const ring::Scene&, Args...)> f) {
  if (!f) return f;
  return [f](const ring::Scene& s, Args... args) {
    Result r = f(s, args...);
    r.model["theory"] = ring::to_string(s.ring.theory);
    return r;
  };
}

void apply_model_theory(SolverEntry& e) {
  // with_theory inside on_model: the description reads the theory of the model scene.
  e.modes = on_model(e, with_theory(e.modes));
  e.buckling = on_model(e, with_theory(e.buckling));
  e.statics = on_model(e, e.statics);
  e.response = on_model(e, e.response);
  e.check_modes = on_model(e, e.check_modes);
  e.check_static = on_model(e, e.check_static);
  e.check_response = on_model(e, e.check_response);
  e.check_buckling = on_model(e, e.check_buckling);
  e.elastic_modes = on_model(e, e.elastic_modes);
  e.memory = on_model(e, e.memory);
  e.buckling_memory = on_model(e, e.buckling_memory);
  e.write_vtu = on_model(e, e.write_vtu);
}

/// An entry as the registry holds it: every analysis on the model scene, results finite,
/// named and timed, and a bench sweep by doubling where the solver gives none.
SolverEntry wrapped(SolverEntry e) {
  apply_model_theory(e);
  if (!e.bench_sweep) {
    const SolverEntry copy = e;
    e.bench_sweep = [copy](const ring::Scene& s, int modes) { return doubling_sweep(copy, s, modes); };
  }
  if (e.statics) {
    auto statics = e.statics;
    e.statics = [statics](const ring::Scene& s) {
      ring::StaticResult r = statics(s);
      r.driven = s.statics && s.statics->driven();
      r.plates = s.statics && s.statics->plates;
      return r;
    };
  }
  e.statics = finite(named_and_timed(e.name, e.statics));
  e.response = finite(named_and_timed(e.name, e.response));
  e.buckling = finite(named_and_timed(e.name, e.buckling));
  if (e.modes) {
    auto modes = e.modes;
    e.modes = [modes](const ring::Scene& s, int count) {
      ring::ModalResult r = modes(s, count);
      r.arch = s.ring.is_arch();
      finish_spin(r, s.ring.rotation.speed, s.modes.fixed_frame);
      return r;
    };
  }
  e.modes = finite(e.modes);
  return e;
}

/// What the scene reader needs of the entries.
ring::SceneSchema make_schema(const std::vector<SolverEntry>& entries) {
  ring::SceneSchema s;
  for (const auto& e : entries) {
    ring::SolverSchema m;
    m.name = e.name;
    m.size_key = e.size_key;
    m.size = e.size;
    m.elastic_modes = e.elastic_modes;
    m.statics = bool(e.statics);
    m.response = bool(e.response);
    m.buckling = bool(e.buckling);
    m.options = e.options;
    m.store = e.store;
    s.solvers.push_back(std::move(m));
  }
  s.default_solver = entries.front().name;  // the paper's method
  s.reference_solver = "fem";
  return s;
}

/// The registry and the reader's schema of it, built together on first use (thread-safe),
/// changed only by add_solver and remove_solver.
struct Registry {
  std::vector<SolverEntry> entries;
  std::size_t built_in = 0;
  ring::SceneSchema schema;
};

Registry& the_registry() {
  static Registry r = [] {
    Registry x;
    // The one list of the built-in solvers: adding one is its folder and an entry here.
    for (SolverEntry e : {multibody_entry(), lumped_entry(), fem_entry(), calculix_entry()})
      x.entries.push_back(wrapped(std::move(e)));
    x.built_in = x.entries.size();
    x.schema = make_schema(x.entries);
    return x;
  }();
  return r;
}

/// A number as a message shows it (270, 1e+300, nan).
std::string text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

/// Throws ring::NumericalError "<solver>: <what> is <x>, not a finite number" for the first
/// value of `values` that is not finite; `what(i)` names the i-th.
template <class Name>
void finite_values(const std::string& solver, const std::vector<double>& values, Name&& what) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw ring::NumericalError((solver.empty() ? std::string("result") : solver) + ": " + what(i) + " is " +
                                 text(values[i]) + ", not a finite number (the model's values overflowed "
                                 "or the solve broke down; nothing is printed as a result)");
}

void finite_shapes(const std::string& solver, const std::vector<ring::ModeShape>& shapes, const std::string& what) {
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    auto at = [&](const char* part) {
      return [&, part](std::size_t s) {
        return what + " " + std::to_string(k + 1) + "'s " + part + " displacement at " +
               std::to_string(static_cast<int>(ring::station_angle(static_cast<int>(s)))) + " deg";
      };
    };
    finite_values(solver, shapes[k].radial, at("radial"));
    finite_values(solver, shapes[k].tangential, at("tangential"));
  }
}

void finite_points(const std::string& solver, const std::vector<ring::PointDisplacement>& points,
                   const std::string& where) {
  for (const auto& p : points) {
    const std::vector<double> u = {p.ux, p.uy};
    finite_values(solver, u, [&](std::size_t i) {
      return std::string(i ? "uy" : "ux") + " at " + text(p.angle) + " deg" + where;
    });
  }
}

}  // namespace

void require_finite(const ring::ModalResult& r) {
  finite_values(r.solver, r.omega, [](std::size_t i) { return "the frequency of mode " + std::to_string(i + 1); });
  if (r.max_residual)
    finite_values(r.solver, {*r.max_residual}, [](std::size_t) { return std::string("the max eigen-residual"); });
  finite_shapes(r.solver, r.shapes, "mode");
}

void require_finite(const ring::BucklingResult& r) {
  finite_values(r.solver, r.factors, [](std::size_t i) { return "critical load factor " + std::to_string(i + 1); });
  finite_shapes(r.solver, r.shapes, "buckling mode");
}

/// The driven path's values in require_finite's order: reaction x, y, contact lengths.
std::string driven_value_name(std::size_t i) {
  static const char* names[] = {"the reaction's x", "the reaction's y", "the contact length on the plate at plates.axis",
                                "the contact length on the opposite plate"};
  return names[i];
}

void require_finite(const ring::StaticResult& r) {
  finite_points(r.solver, r.displacements, "");
  finite_values(r.solver, r.node_x, [](std::size_t i) { return "x of node " + std::to_string(i + 1); });
  finite_values(r.solver, r.node_y, [](std::size_t i) { return "y of node " + std::to_string(i + 1); });
  for (std::size_t k = 0; k < r.path.size(); ++k) {
    const ring::PathPoint& p = r.path[k];
    const std::string at = " at path point " + std::to_string(k + 1);
    finite_values(r.solver, {p.load_factor, p.ovalisation}, [&](std::size_t i) {
      return (i ? "the ovalisation" : "the load factor") + at;
    });
    finite_points(r.solver, p.displacements, at);
    finite_values(r.solver, p.node_x, [&](std::size_t i) { return "x of node " + std::to_string(i + 1) + at; });
    finite_values(r.solver, p.node_y, [&](std::size_t i) { return "y of node " + std::to_string(i + 1) + at; });
    finite_values(r.solver, {p.reaction[0], p.reaction[1], p.contact_length[0], p.contact_length[1]},
                  [&](std::size_t i) { return driven_value_name(i) + at; });
  }
  finite_values(r.solver, {r.reaction[0], r.reaction[1], r.contact_length[0], r.contact_length[1]}, driven_value_name);
}

void require_finite(const ring::TimeHistory& r) {
  finite_values(r.solver, r.t, [](std::size_t i) { return "the time of step " + std::to_string(i); });
  for (std::size_t p = 0; p < r.ux.size() && p < r.record_angles.size(); ++p) {
    auto at = [&](const char* c) {
      return [&, c](std::size_t k) {
        return std::string(c) + " at " + text(r.record_angles[p]) + " deg, step " + std::to_string(k);
      };
    };
    finite_values(r.solver, r.ux[p], at("ux"));
    if (p < r.uy.size()) finite_values(r.solver, r.uy[p], at("uy"));
  }
  for (std::size_t k = 0; k < r.snapshot_x.size(); ++k) {
    auto at = [&](const char* c) {
      return [&, c](std::size_t i) { return std::string(c) + " of node " + std::to_string(i + 1) + " in snapshot " +
                                            std::to_string(k + 1); };
    };
    finite_values(r.solver, r.snapshot_x[k], at("x"));
    if (k < r.snapshot_y.size()) finite_values(r.solver, r.snapshot_y[k], at("y"));
  }
}

const std::vector<SolverEntry>& registry() { return the_registry().entries; }

void add_solver(SolverEntry entry) {
  Registry& r = the_registry();
  if (entry.name.empty() || find_solver(entry.name))
    throw std::invalid_argument("add_solver: the solver name \"" + entry.name + "\" is empty or taken");
  if (entry.options.section() != entry.name)
    throw std::invalid_argument("add_solver: the option schema of \"" + entry.name + "\" is for the section [" +
                                entry.options.section() + "]");
  r.entries.push_back(wrapped(std::move(entry)));
  r.schema = make_schema(r.entries);
}

void remove_solver(const std::string& name) {
  Registry& r = the_registry();
  for (std::size_t i = r.built_in; i < r.entries.size(); ++i)
    if (r.entries[i].name == name) {
      r.entries.erase(r.entries.begin() + static_cast<std::ptrdiff_t>(i));
      r.schema = make_schema(r.entries);
      return;
    }
  throw std::invalid_argument("remove_solver: \"" + name + "\" is not a solver that add_solver added");
}

std::vector<std::string> solver_names() {
  std::vector<std::string> v;
  for (const auto& e : registry()) v.push_back(e.name);
  return v;
}

const SolverEntry* find_solver(const std::string& name) {
  for (const auto& e : registry())
    if (e.name == name) return &e;
  return nullptr;
}

const SolverEntry& solver(const std::string& name) {
  if (const SolverEntry* e = find_solver(name)) return *e;
  std::string known;
  for (const auto& e : registry()) known += (known.empty() ? "" : ", ") + e.name;
  throw ring::InputError("", "solver", "unknown solver \"" + name + "\"; expected one of " + known);
}

const ring::SceneSchema& scene_schema() { return the_registry().schema; }

std::string keys_markdown() {
  std::string o;
  for (const auto& e : registry()) o += (o.empty() ? "" : "\n") + ring::markdown(e.options);
  return o;
}

ring::Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return ring::load_scene(path, overrides, scene_schema());
}

ring::Scene parse_scene(const std::string& toml_text, const std::string& name,
                        const std::vector<std::string>& overrides) {
  return ring::parse_scene(toml_text, name, overrides, scene_schema());
}

void check_scene(const ring::Scene& scene) {
  // Values whose products overflow are refused before any solver runs (the rule:
  // ring/spec.hpp, scale_violation): a ring of E = 1e300 Pa solved to NaN, not to an error.
  // Here and not in the reader: a scene is valid TOML with valid values; that no solver's
  // arithmetic holds it is a refusal of the solvers, like their own checks below.
  if (const auto v = ring::scale_violation(scene.ring)) throw ring::InputError(scene.file, v->key, v->what);
  // One analysis of one solver; a std::invalid_argument names the solver's key.
  auto check = [&](const std::function<void(const ring::Scene&)>& f, const ring::Scene& s, const std::string& what) {
    if (f) as_input_error(s, what, [&] { f(s); });
  };
  for (const SolverEntry& e : registry()) {
    if (scene.column(e.name)) check(e.check_modes, scene, e.name);
    if (scene.statics && runs(scene.static_request, e.name)) check(e.check_static, scene, e.name);
    if (scene.response && runs(scene.response_request, e.name)) check(e.check_response, scene, e.name);
    if (scene.buckling && runs(scene.buckling_request, e.name)) check(e.check_buckling, scene, e.name);
  }
  const SolverEntry& ref = solver(scene.reference_solver);
  const ring::Scene r = reference_scene(scene);
  if (scene.needs_reference()) check(ref.check_modes, r, ref.name);
  if (scene.statics && scene.static_request.reference) check(ref.check_static, r, ref.name);
  if (scene.response && scene.response_request.reference) check(ref.check_response, r, ref.name);
  if (scene.buckling && scene.buckling_request.reference) check(ref.check_buckling, r, ref.name);
}

void check_modes_of(const ring::Scene& scene, const SolverEntry& e) {
  if (e.check_modes) as_input_error(scene, e.name, [&] { e.check_modes(scene); });
}

ring::Scene reference_scene(const ring::Scene& scene) {
  ring::Scene s = scene;
  s.fem.reference = true;
  s.fem.theory.reset();  // the reference solves the ring's physics, ring.theory
  return s;
}

ring::Scene model_scene(const ring::Scene& scene, const SolverEntry& e) {
  ring::Scene s = scene;
  if (e.theory) s.ring.theory = e.theory(scene);
  return s;
}

ring::ModalResult solve_modes(const ring::Scene& scene, const std::string& name, int count) {
  return solver(name).modes(scene, count);
}

ring::ModalResult reference_modes(const ring::Scene& scene, int count) {
  const ring::Scene s = reference_scene(scene);
  ring::ModalResult out = solver(scene.reference_solver).modes(s, count);
  out.solver = "reference";
  return out;
}

ring::StaticResult reference_static(const ring::Scene& scene) {
  const SolverEntry& e = solver(scene.reference_solver);
  if (!e.statics) throw ring::InputError(scene.file, "static.reference", "the " + e.name + " solver has no statics");
  const ring::Scene s = reference_scene(scene);
  ring::StaticResult out = e.statics(s);
  out.solver = "reference";
  return out;
}

ring::TimeHistory reference_response(const ring::Scene& scene) {
  const SolverEntry& e = solver(scene.reference_solver);
  if (!e.response)
    throw ring::InputError(scene.file, "response.reference", "the " + e.name + " solver has no forced response");
  const ring::Scene s = reference_scene(scene);
  ring::TimeHistory out = e.response(s);
  out.solver = "reference";
  return out;
}

ring::BucklingResult reference_buckling(const ring::Scene& scene) {
  const SolverEntry& e = solver(scene.reference_solver);
  if (!e.buckling) throw ring::InputError(scene.file, "buckling.reference", "the " + e.name + " solver has no buckling");
  const ring::Scene s = reference_scene(scene);
  ring::BucklingResult out = e.buckling(s);
  out.solver = "reference";
  return out;
}

}  // namespace cmp
