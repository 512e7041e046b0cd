// The dlopen boundary: build/bin/libringvib_fem.so loads, reports ABI 1, and gives
// exactly the numbers of the statically linked fem::compute_modes.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "fem_reference/modes.hpp"
#include "fem_reference/plugin.hpp"
#include "tests/fem_reference/paper_ring.hpp"

namespace {

const fem::Plugin* load() {
  void* handle = dlopen(RINGVIB_BINARY_DIR "/bin/libringvib_fem.so", RTLD_NOW | RTLD_LOCAL);
  if (!handle) return nullptr;
  auto entry = reinterpret_cast<const fem::Plugin* (*)()>(dlsym(handle, "ringvib_fem_plugin"));
  return entry ? entry() : nullptr;
}

TEST(FemPlugin, DlopenGivesTheSameNumbers) {
  const fem::Plugin* plugin = load();
  ASSERT_NE(plugin, nullptr) << dlerror();
  EXPECT_EQ(plugin->abi_version, 1);
  const auto spec = femtest::paper_ring(180.0);
  ring::FemOptions o;
  ring::ModalResult out;
  std::string error;
  ASSERT_EQ(plugin->modes(spec, o, 23, out, error), 0) << error;
  const auto direct = fem::compute_modes(spec, o, 23);
  ASSERT_EQ(out.omega.size(), direct.omega.size());
  // Same code, same deterministic start vector: identical to round-off of reordering.
  for (std::size_t i = 0; i < out.omega.size(); ++i) EXPECT_NEAR(out.omega[i], direct.omega[i], 1e-12 * direct.omega[i]);
  EXPECT_EQ(out.rigid_modes, direct.rigid_modes);
  EXPECT_EQ(out.unknowns, direct.unknowns);
}

TEST(FemPlugin, ErrorsBecomeCodesNotExceptions) {
  const fem::Plugin* plugin = load();
  ASSERT_NE(plugin, nullptr);
  const auto spec = femtest::paper_ring(180.0);
  ring::FemOptions o;
  o.degree = 1;
  ring::ModalResult out;
  std::string error;
  EXPECT_EQ(plugin->modes(spec, o, 5, out, error), 2);
  EXPECT_NE(error.find("fem.degree"), std::string::npos) << error;
}

TEST(FemPlugin, WritesVtu) {
  const fem::Plugin* plugin = load();
  ASSERT_NE(plugin, nullptr);
  const auto dir = std::filesystem::temp_directory_path() / "ringvib_fem_vtu_test";
  std::filesystem::create_directories(dir);
  std::string error;
  ASSERT_EQ(plugin->write_vtu(femtest::paper_ring(180.0), ring::FemOptions{}, 3, dir.string(), error), 0) << error;
  EXPECT_GT(std::filesystem::file_size(dir / "fem_modes.vtu"), 1000u);
  std::filesystem::remove_all(dir);
}

}  // namespace
