#include "compare/registry.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "compare/fem_module.hpp"
#include "fem_reference/checks.hpp"
#include "lumped_mass/checks.hpp"
#include "multibody/checks.hpp"
#include "lumped_mass/modes.hpp"
#include "lumped_mass/nonlinear.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/modes.hpp"
#include "multibody/statics.hpp"
#include "ring/errors.hpp"

namespace cmp {
namespace {

/// A solver's std::invalid_argument ("can never work") is an input error (exit 2).
template <class F>
auto as_input_error(const ring::Scene& s, const std::string& name, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw ring::InputError(s.file, name, e.what());
  }
}

/// True when the nonlinear request lists the solver.
bool runs(const ring::NonlinearRequest& q, const std::string& name) {
  return std::find(q.solvers.begin(), q.solvers.end(), name) != q.solvers.end();
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
  e.size = [](const ring::Scene& s) { return s.multibody.n; };
  e.set_size = [](ring::Scene& s, int n) { s.multibody.n = n; };
  // n angles - 2 closures (+2 for a free ring) - what the supports hold or leave rigid.
  e.elastic_modes = [](const ring::Scene& s) -> long long { return s.multibody.n - 3; };
  e.inextensible = [](const ring::Scene&) { return true; };
  e.curve = [](const ring::Scene&) { return std::string("multibody"); };
  e.converge_steps = 5;
  e.richardson = true;
  e.paper = [](const ring::PaperRow& r) { return r.mb_corrected; };
  // Dense: a few n x n matrices; O(n) modes: ~1 KiB per segment (measured 1 GB at 10^6)
  // plus the Lanczos basis, n x (2 count + 20) doubles; O(n) nonlinear solves (count = 0):
  // ~10 KiB per segment, the sparse LU's factors (statics measured 352 MB at n = 4e4).
  e.memory = [](const ring::Scene& s, int count) {
    const double n = s.multibody.n;
    const bool dense = s.multibody.method == ring::MultibodyOptions::Method::dense ||
                       (s.multibody.method == ring::MultibodyOptions::Method::automatic && n <= 256 && count > 0);
    const double per_segment = count > 0 ? 1024.0 : 10240.0;
    return (dense ? 12.0 * 8.0 * n * n : per_segment * n) + 8.0 * n * (2.0 * count + 20.0);
  };
  e.check = [](const ring::Scene& s) {
    as_input_error(s, "multibody", [&] {
      if (s.needs("multibody")) multibody::check_modes(s.ring, s.multibody);
      if (s.statics && runs(s.static_request, "multibody")) multibody::check_static(s.ring, s.multibody, *s.statics);
      if (s.response && runs(s.response_request, "multibody"))
        multibody::check_response(s.ring, s.multibody, *s.response);
    });
  };
  e.modes = [](const ring::Scene& s, int count) {
    return as_input_error(s, "multibody", [&] { return multibody::compute_modes(s.ring, s.multibody, count); });
  };
  e.statics = [](const ring::Scene& s) {
    return as_input_error(s, "static", [&] { return multibody::solve_static(s.ring, s.multibody, *s.statics); });
  };
  e.response = [](const ring::Scene& s) {
    return as_input_error(s, "response", [&] { return multibody::respond(s.ring, s.multibody, *s.response); });
  };
  return e;
}

SolverEntry lumped_entry() {
  SolverEntry e;
  e.name = "lumped";
  e.label = "lumped mass";
  e.size_key = "lumped.n";
  e.size_name = "n";
  e.size = [](const ring::Scene& s) { return s.lumped.n; };
  e.set_size = [](ring::Scene& s, int n) { s.lumped.n = n; };
  e.elastic_modes = [](const ring::Scene& s) -> long long {
    const long long n = s.lumped.n;
    const auto& sup = s.ring.supports;
    const int held = (sup.pin ? 2 : 0) + (sup.roller ? 1 : 0) + sup.rigid_modes();
    switch (s.lumped.variant) {
      case ring::LumpedOptions::Variant::chain: return n - 3;
      case ring::LumpedOptions::Variant::frame: return 2 * n - held;
      case ring::LumpedOptions::Variant::frame_consistent: return 3 * n - held;
    }
    return 0;
  };
  e.inextensible = [](const ring::Scene& s) { return s.lumped.variant == ring::LumpedOptions::Variant::chain; };
  e.curve = [](const ring::Scene& s) { return "lumped (" + ring::to_string(s.lumped.variant) + ")"; };
  e.converge_steps = 5;
  e.paper = [](const ring::PaperRow& r) { return r.lm_corrected; };
  // Sparse factorization: measured 468 MB at n = 10^5 (~4.7 KB per node), plus the basis.
  e.memory = [](const ring::Scene& s, int count) {
    const double n = s.lumped.n;
    return 4800.0 * n + 3.0 * 8.0 * n * (2.0 * count + 20.0);
  };
  e.check = [](const ring::Scene& s) {
    as_input_error(s, "lumped", [&] {
      if (s.statics && runs(s.static_request, "lumped")) lumped::check_static(s.ring, s.lumped, *s.statics);
      if (s.response && runs(s.response_request, "lumped")) lumped::check_response(s.ring, s.lumped, *s.response);
    });
  };
  e.modes = [](const ring::Scene& s, int count) {
    return as_input_error(s, "lumped", [&] { return lumped::compute_modes(s.ring, s.lumped, count); });
  };
  e.statics = [](const ring::Scene& s) {
    return as_input_error(s, "static", [&] { return lumped::solve_static(s.ring, s.lumped, *s.statics); });
  };
  e.response = [](const ring::Scene& s) {
    return as_input_error(s, "response", [&] { return lumped::respond(s.ring, s.lumped, *s.response); });
  };
  return e;
}

SolverEntry fem_entry() {
  SolverEntry e;
  e.name = "fem";
  e.label = "FE";
  e.size_key = "fem.elements";
  e.size_name = "elements";
  e.size = [](const ring::Scene& s) { return s.fem.elements; };
  e.set_size = [](ring::Scene& s, int n) { s.fem.elements = n; };
  // C0 elements of degree p: p nodes per cell and two displacement components.
  e.elastic_modes = [](const ring::Scene& s) -> long long {
    const auto& sup = s.ring.supports;
    const int held = (sup.pin ? 2 : 0) + (sup.roller ? 1 : 0) + sup.rigid_modes();
    return 2LL * s.fem.elements * s.fem.degree - held;
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
  // Unknowns 2 p N; UMFPACK fill and ARPACK basis ~ (30 p + 2 count + 20) doubles per unknown
  // (measured ~1.7 KB per unknown at p = 3 with 23 modes). The reference raises p to 16.
  e.memory = [](const ring::Scene& s, int count) {
    const double p = s.fem.reference || s.needs_reference() ? 16.0 : s.fem.degree;
    const double unknowns = 2.0 * p * s.fem.elements;
    return 8.0 * unknowns * (30.0 * p + 2.0 * count + 20.0);
  };
  // The reference runs with fem.reference on: its checks are the reference's.
  e.check = [](const ring::Scene& s) {
    as_input_error(s, "fem", [&] {
      ring::FemOptions reference = s.fem;
      reference.reference = true;
      if (s.column("fem")) fem::check_modes(s.ring, s.fem);
      if (s.needs_reference()) fem::check_modes(s.ring, reference);
      if (s.statics && runs(s.static_request, "fem")) fem::check_static(s.ring, s.fem, *s.statics);
      if (s.statics && s.static_request.reference) fem::check_static(s.ring, reference, *s.statics);
      if (s.response && runs(s.response_request, "fem")) fem::check_response(s.ring, s.fem, *s.response);
      if (s.response && s.response_request.reference) fem::check_response(s.ring, reference, *s.response);
    });
  };
  e.modes = [](const ring::Scene& s, int count) { return fem_module::modes(s.ring, s.fem, count); };
  e.statics = [](const ring::Scene& s) {
    return as_input_error(s, "static", [&] { return fem_module::statics(s.ring, s.fem, *s.statics); });
  };
  e.response = [](const ring::Scene& s) {
    return as_input_error(s, "response", [&] { return fem_module::respond(s.ring, s.fem, *s.response); });
  };
  e.write_vtu = [](const ring::Scene& s, int count, const std::string& dir) {
    fem_module::write_vtu(s.ring, s.fem, count, dir);
  };
  return e;
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

std::vector<SolverEntry> make_registry() {
  std::vector<SolverEntry> v = {multibody_entry(), lumped_entry(), fem_entry()};
  for (auto& e : v) {
    if (!e.bench_sweep) {
      const SolverEntry copy = e;
      e.bench_sweep = [copy](const ring::Scene& s, int modes) { return doubling_sweep(copy, s, modes); };
    }
    e.statics = named_and_timed(e.name, e.statics);
    e.response = named_and_timed(e.name, e.response);
  }
  return v;
}

}  // namespace

const std::vector<SolverEntry>& registry() {
  static const std::vector<SolverEntry> r = make_registry();
  return r;
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

const ring::SceneSchema& scene_schema() {
  static const ring::SceneSchema schema = [] {
    ring::SceneSchema s;
    for (const auto& e : registry())
      s.solvers.push_back({e.name, e.size_key, e.size, e.elastic_modes, bool(e.statics), bool(e.response)});
    s.default_solver = registry().front().name;  // the paper's method
    s.reference_solver = "fem";
    return s;
  }();
  return schema;
}

ring::Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return ring::load_scene(path, overrides, scene_schema());
}

ring::Scene parse_scene(const std::string& toml_text, const std::string& name,
                        const std::vector<std::string>& overrides) {
  return ring::parse_scene(toml_text, name, overrides, scene_schema());
}

void check_scene(const ring::Scene& scene) {
  for (const SolverEntry& e : registry())
    if (e.check) e.check(scene);
}

ring::ModalResult solve_modes(const ring::Scene& scene, const std::string& name, int count) {
  return solver(name).modes(scene, count);
}

ring::ModalResult reference_modes(const ring::Scene& scene, int count) {
  ring::Scene s = scene;
  s.fem.reference = true;
  ring::ModalResult out = solver(scene.reference_solver).modes(s, count);
  out.solver = "reference";
  return out;
}

ring::StaticResult reference_static(const ring::Scene& scene) {
  const SolverEntry& e = solver(scene.reference_solver);
  if (!e.statics) throw ring::InputError(scene.file, "static.reference", "the " + e.name + " solver has no statics");
  ring::Scene s = scene;
  s.fem.reference = true;
  ring::StaticResult out = e.statics(s);
  out.solver = "reference";
  return out;
}

ring::TimeHistory reference_response(const ring::Scene& scene) {
  const SolverEntry& e = solver(scene.reference_solver);
  if (!e.response)
    throw ring::InputError(scene.file, "response.reference", "the " + e.name + " solver has no forced response");
  ring::Scene s = scene;
  s.fem.reference = true;
  ring::TimeHistory out = e.response(s);
  out.solver = "reference";
  return out;
}

}  // namespace cmp
