#include "compare/fem_module.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <sys/stat.h>

#include "ring/errors.hpp"

#include "fem_reference/plugin.hpp"

namespace cmp::fem_module {
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
    // Lazy binding: the plug-in's own calls into deal.II resolve when first made, not all
    // at load (about 45 ms of a 0.25 s tiny FE run, bench/process.sh). 117 of the ~200
    // libraries deal.II pulls in are linked with BIND_NOW by Debian and resolve at load
    // anyway. A symbol missing at call time would abort, not report: fem_plugin_test opens
    // the same plug-in with RTLD_NOW, which fails on any missing symbol.
    void* h = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
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
    if (plugin->abi_version != fem::kAbiVersion) {
      failure = "the FE module " + path + " has ABI version " + std::to_string(plugin->abi_version) + ", expected " +
                std::to_string(fem::kAbiVersion) + " (rebuild it with this ringvib)";
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
  throw ring::NumericalError(error.rfind("fem", 0) == 0 ? error : "fem: " + error);
}

}  // namespace

// ARPACK keeps its state in Fortran SAVE variables and deal.II's solvers are not meant
// to be entered from several threads at once: one FE solve at a time per process
// (a threaded `ringvib sweep` runs its other solvers in parallel around it).
std::mutex g_solve;

ring::ModalResult modes(const ring::RingSpec& spec, const ring::FemOptions& options, int count) {
  std::lock_guard<std::mutex> lock(g_solve);
  ring::ModalResult out;
  std::string error;
  check(fem_plugin().modes(spec, options, count, out, error), error);
  return out;
}

void write_vtu(const ring::RingSpec& spec, const ring::FemOptions& options, int count, const std::string& dir) {
  std::lock_guard<std::mutex> lock(g_solve);
  std::string error;
  check(fem_plugin().write_vtu(spec, options, count, dir, error), error);
}

ring::StaticResult statics(const ring::RingSpec& spec, const ring::FemOptions& options,
                           const ring::StaticOptions& statics) {
  std::lock_guard<std::mutex> lock(g_solve);
  ring::StaticResult out;
  std::string error;
  const int status = fem_plugin().statics(spec, options, statics, out, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  check(status, error);
  return out;
}

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::FemOptions& options,
                          const ring::ResponseOptions& response) {
  std::lock_guard<std::mutex> lock(g_solve);
  ring::TimeHistory out;
  std::string error;
  int reason = 0;
  double t_reached = 0.0;
  const int status = fem_plugin().respond(spec, options, response, out, reason, t_reached, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  if (status == 3 && reason >= 0)
    throw ring::IntegrationFailure(static_cast<ring::IntegrationFailure::Reason>(reason), t_reached, std::move(out),
                                   error);
  check(status, error);
  return out;
}

ring::BucklingResult buckling(const ring::RingSpec& spec, const ring::FemOptions& options,
                              const ring::BucklingOptions& buckling) {
  std::lock_guard<std::mutex> lock(g_solve);
  ring::BucklingResult out;
  std::string error;
  const int status = fem_plugin().buckling(spec, options, buckling, out, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  check(status, error);
  return out;
}

ring::ModalResult modes_under_load(const ring::RingSpec& spec, const ring::FemOptions& options,
                                   const ring::StaticOptions& statics, int count) {
  std::lock_guard<std::mutex> lock(g_solve);
  ring::ModalResult out;
  std::string error;
  const int status = fem_plugin().modes_under_load(spec, options, statics, count, out, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  check(status, error);
  return out;
}

bool loaded() { return g_loaded; }

bool available() {
  struct stat st;
  return stat(fem_module_path().c_str(), &st) == 0;
}

}  // namespace cmp::fem_module
