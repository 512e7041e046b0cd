#include "compare/fem_module.hpp"

#include <dlfcn.h>
#include <link.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <vector>
#include <sys/stat.h>

#include "ring/errors.hpp"

#include "fem_reference/plugin.hpp"

namespace cmp::fem_module {
namespace {

// Where the FE plug-in is. Never a build path compiled in: a build tree and an installed
// prefix can both be moved, so the plug-in is looked up relative to the file this code runs
// from, which is the `ringvib` executable (or a test program) or the Python module that
// links compare statically. The layouts (the relative folders come from CMake,
// compare/CMakeLists.txt, so that they follow the install directories):
//   executable  build tree: bin/ringvib             -> bin/libringvib_fem.so
//               installed:  P/bin/ringvib           -> P/lib/ringvib/libringvib_fem.so
//   module      build tree: python/ringvib.*.so     -> bin/libringvib_fem.so
//               installed:  P/lib/python3/dist-packages/ringvib.*.so -> P/lib/ringvib/...
// $RINGVIB_FEM_MODULE, when set, names the plug-in and nothing else is tried.
constexpr const char* kPluginName = "libringvib_fem.so";

struct Anchor {
  std::string dir;          ///< the folder of the file this code runs from, symlinks resolved
  bool executable = true;   ///< the main program (true) or a shared object (the Python module)
};

/// The file that holds this code: dladdr() names the shared object (its link map has a
/// name); the main program's is empty, and /proc/self/exe names it instead.
Anchor find_anchor() {
  Anchor a;
  std::string file;
  Dl_info info{};
  link_map* map = nullptr;
  if (dladdr1(reinterpret_cast<void*>(&find_anchor), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) != 0 &&
      map != nullptr && map->l_name != nullptr && map->l_name[0] != '\0') {
    file = map->l_name;
    a.executable = false;
  } else {
    char buf[PATH_MAX];
    const ssize_t len = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (len > 0) file.assign(buf, len);
  }
  if (char* real = file.empty() ? nullptr : realpath(file.c_str(), nullptr)) {
    file = real;
    std::free(real);
  }
  const auto slash = file.rfind('/');
  a.dir = slash == std::string::npos ? std::string(".") : file.substr(0, slash);
  return a;
}

// Resolved when the program or the module is loaded, before anyone changes the working
// directory (Python names a module by a relative path when PYTHONPATH is relative).
const Anchor g_anchor = find_anchor();

/// dir/rel/libringvib_fem.so, without a "." folder.
std::string in(const std::string& dir, const char* rel) {
  return (std::string(rel) == "." ? dir : dir + "/" + rel) + "/" + kPluginName;
}

std::vector<std::string> candidates() {
  if (const char* p = std::getenv("RINGVIB_FEM_MODULE")) return {p};
  const std::string& d = g_anchor.dir;
  if (g_anchor.executable) return {in(d, RINGVIB_FEM_FROM_BUILD_BIN), in(d, RINGVIB_FEM_FROM_BINDIR)};
  return {in(d, RINGVIB_FEM_FROM_BUILD_PYTHON), in(d, RINGVIB_FEM_FROM_PYTHONDIR)};
}

bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

/// The first candidate that exists, as a real path (no "bin/.."); when none does, the first
/// one (for the message).
std::string fem_module_path() {
  const std::vector<std::string> c = candidates();
  for (const std::string& p : c)
    if (char* real = realpath(p.c_str(), nullptr)) {
      std::string r = real;
      std::free(real);
      return r;
    }
  return c.front();
}

/// Opens the plug-in: sets `plugin` and returns "", or returns why it cannot be used.
std::string load(const fem::Plugin*& plugin) {
  const std::string path = fem_module_path();
  // Lazy binding: the plug-in's own calls into deal.II resolve when first made, not all
  // at load (about 45 ms of a 0.25 s tiny FE run, bench/process.sh). 117 of the ~200
  // libraries deal.II pulls in are linked with BIND_NOW by Debian and resolve at load
  // anyway. A symbol missing at call time would abort, not report: fem_plugin_test opens
  // the same plug-in with RTLD_NOW, which fails on any missing symbol.
  void* h = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!h) {
    const char* why = dlerror();
    std::string tried;
    for (const std::string& p : candidates()) tried += (tried.empty() ? "" : ", ") + p;
    return std::string("the FE solver is not available: cannot load ") + path + " (" + (why ? why : "unknown") +
           "; looked for " + tried + "); build with -DRINGVIB_WITH_FEM=ON";
  }
  using Entry = const fem::Plugin* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(h, "ringvib_fem_plugin"));
  if (!entry) return "the FE module " + path + " has no entry point ringvib_fem_plugin";
  const fem::Plugin* p = entry();
  if (!p || p->abi_version != fem::kAbiVersion)
    return "the FE module " + path + " has ABI version " + (p ? std::to_string(p->abi_version) : std::string("?")) +
           ", expected " + std::to_string(fem::kAbiVersion) + " (rebuild it with this ringvib)";
  plugin = p;
  return "";
}

bool g_loaded = false;

/// The plug-in, loaded by the first call. A plain mutex around a plain "tried" flag, not
/// std::call_once: a failed load is remembered and refused at once in every thread, and
/// nothing is left in a state that another thread waits on (issue 46: two threads of a
/// ThreadPoolExecutor hung on a plug-in that could not be loaded). The load never runs
/// under g_solve, so a refusal never waits for another thread's solve either.
const fem::Plugin& fem_plugin() {
  static std::mutex m;
  static bool tried = false;
  static const fem::Plugin* plugin = nullptr;
  static std::string failure;
  {
    std::lock_guard<std::mutex> lock(m);
    if (!tried) {
      tried = true;
      failure = load(plugin);
      if (plugin) g_loaded = true;
    }
  }
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
  const fem::Plugin& plugin = fem_plugin();
  std::lock_guard<std::mutex> lock(g_solve);
  ring::ModalResult out;
  std::string error;
  check(plugin.modes(spec, options, count, out, error), error);
  return out;
}

void write_vtu(const ring::RingSpec& spec, const ring::FemOptions& options, int count, const std::string& dir) {
  const fem::Plugin& plugin = fem_plugin();
  std::lock_guard<std::mutex> lock(g_solve);
  std::string error;
  check(plugin.write_vtu(spec, options, count, dir, error), error);
}

ring::StaticResult statics(const ring::RingSpec& spec, const ring::FemOptions& options,
                           const ring::StaticOptions& statics) {
  const fem::Plugin& plugin = fem_plugin();
  std::lock_guard<std::mutex> lock(g_solve);
  ring::StaticResult out;
  std::string error;
  const int status = plugin.statics(spec, options, statics, out, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  check(status, error);
  return out;
}

ring::TimeHistory respond(const ring::RingSpec& spec, const ring::FemOptions& options,
                          const ring::ResponseOptions& response) {
  const fem::Plugin& plugin = fem_plugin();
  std::lock_guard<std::mutex> lock(g_solve);
  ring::TimeHistory out;
  std::string error;
  int reason = 0;
  double t_reached = 0.0;
  const int status = plugin.respond(spec, options, response, out, reason, t_reached, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  if (status == 3 && reason >= 0)
    throw ring::IntegrationFailure(static_cast<ring::IntegrationFailure::Reason>(reason), t_reached, std::move(out),
                                   error);
  check(status, error);
  return out;
}

ring::BucklingResult buckling(const ring::RingSpec& spec, const ring::FemOptions& options,
                              const ring::BucklingOptions& buckling) {
  const fem::Plugin& plugin = fem_plugin();
  std::lock_guard<std::mutex> lock(g_solve);
  ring::BucklingResult out;
  std::string error;
  const int status = plugin.buckling(spec, options, buckling, out, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  check(status, error);
  return out;
}

ring::ModalResult modes_under_load(const ring::RingSpec& spec, const ring::FemOptions& options,
                                   const ring::StaticOptions& statics, int count) {
  const fem::Plugin& plugin = fem_plugin();
  std::lock_guard<std::mutex> lock(g_solve);
  ring::ModalResult out;
  std::string error;
  const int status = plugin.modes_under_load(spec, options, statics, count, out, error);
  if (status == 2) throw std::invalid_argument(error);  // the registry names the file and key
  check(status, error);
  return out;
}

bool loaded() { return g_loaded; }

bool available() { return exists(fem_module_path()); }

std::string plugin_path() {
  const std::string p = fem_module_path();
  return exists(p) ? p : std::string();
}

std::vector<std::string> plugin_candidates() { return candidates(); }

}  // namespace cmp::fem_module
