#include "compare/solvers.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <sys/stat.h>

#include "ring/errors.hpp"

#ifdef RINGVIB_HAVE_MULTIBODY
#include "multibody/modes.hpp"
#endif
#ifdef RINGVIB_HAVE_LUMPED_MASS
#include "lumped_mass/modes.hpp"
#endif
#include "fem_reference/plugin.hpp"

namespace cmp {
namespace {

/// Where the FE plug-in is: $RINGVIB_FEM_MODULE, else beside the executable.
std::string fem_module_path() {
  if (const char* p = std::getenv("RINGVIB_FEM_MODULE")) return p;
  char buf[PATH_MAX];
  const ssize_t len = readlink("/proc/self/exe", buf, sizeof buf - 1);
  std::string dir = ".";
  if (len > 0) {
    dir.assign(buf, len);
    dir = dir.substr(0, dir.rfind('/'));
  }
  return dir + "/libringvib_fem.so";
}

bool g_loaded = false;

const fem::Plugin& fem_plugin() {
  static const fem::Plugin* plugin = nullptr;
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    const std::string path = fem_module_path();
    void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) {
      failure = std::string("the FE solver is not available: cannot load ") + path + " (" + dlerror() +
                "); build with -DRINGVIB_WITH_FEM=ON";
      return;
    }
    using Entry = const fem::Plugin* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(h, "ringvib_fem_plugin"));
    if (!entry) {
      failure = "the FE module " + path + " has no entry point ringvib_fem_plugin";
      return;
    }
    plugin = entry();
    if (plugin->abi_version != 1) {
      failure = "the FE module " + path + " has ABI version " + std::to_string(plugin->abi_version) + ", expected 1";
      plugin = nullptr;
      return;
    }
    g_loaded = true;
  });
  if (!plugin) throw ring::InputError("", "solver fem", failure);
  return *plugin;
}

void check(int status, const std::string& error) {
  if (status == 0) return;
  if (status == 2) throw ring::InputError("", "fem", error);
  throw ring::NumericalError("fem: " + error);
}

[[noreturn]] void not_built(const std::string& solver) {
  throw ring::InputError("", "solver " + solver, "the " + solver + " solver is not built yet in this version");
}

}  // namespace

ring::ModalResult solve_modes(const ring::Scene& scene, const std::string& solver, int count) {
  if (solver == "multibody") {
#ifdef RINGVIB_HAVE_MULTIBODY
    return multibody::compute_modes(scene.ring, scene.multibody, count);
#else
    not_built(solver);
#endif
  }
  if (solver == "lumped") {
#ifdef RINGVIB_HAVE_LUMPED_MASS
    return lumped::compute_modes(scene.ring, scene.lumped, count);
#else
    not_built(solver);
#endif
  }
  if (solver == "fem") {
    ring::ModalResult out;
    std::string error;
    check(fem_plugin().modes(scene.ring, scene.fem, count, out, error), error);
    return out;
  }
  throw ring::InputError(scene.file, "solver", "unknown solver \"" + solver + "\"; expected multibody, lumped or fem");
}

ring::ModalResult reference_modes(const ring::Scene& scene, int count) {
  ring::FemOptions o = scene.fem;
  o.reference = true;
  ring::ModalResult out;
  std::string error;
  check(fem_plugin().modes(scene.ring, o, count, out, error), error);
  out.solver = "reference";
  return out;
}

void write_fem_vtu(const ring::Scene& scene, int count, const std::string& dir) {
  std::string error;
  check(fem_plugin().write_vtu(scene.ring, scene.fem, count, dir, error), error);
}

bool fem_module_loaded() { return g_loaded; }

bool solver_available(const std::string& solver) {
#ifdef RINGVIB_HAVE_MULTIBODY
  if (solver == "multibody") return true;
#endif
#ifdef RINGVIB_HAVE_LUMPED_MASS
  if (solver == "lumped") return true;
#endif
  if (solver == "fem") {
    struct stat st;
    return stat(fem_module_path().c_str(), &st) == 0;
  }
  return false;
}

}  // namespace cmp
