// The dlopen boundary: build/bin/libringvib_fem.so loads, reports ABI 4 (modes, VTU,
// statics, response, buckling, modes under load), and gives exactly the numbers of the
// statically linked solvers;
// a failed integration comes back as code 3 with its partial history.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "fem_reference/buckling.hpp"
#include "fem_reference/modes.hpp"
#include "fem_reference/nonlinear.hpp"
#include "fem_reference/preload.hpp"
#include "ring/errors.hpp"
#include "fem_reference/plugin.hpp"
#include "support/paper.hpp"

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
  EXPECT_EQ(plugin->abi_version, 8);  // fem_reference/plugin.hpp: 8 added the plates' fields
  const auto spec = ringtest::pinned_ring();
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

ring::RingSpec held() {
  ring::RingSpec s = ringtest::pinned_ring();
  s.supports.roller = 0.0;
  return s;
}

TEST(FemPlugin, BucklingGivesTheSameNumbers) {
  const fem::Plugin* plugin = load();
  ASSERT_NE(plugin, nullptr);
  ring::FemOptions o;
  o.elements = 20;
  ring::BucklingOptions b;
  b.loads.pressure = {1.0, ring::Pressure::Kind::follower};
  b.count = 2;
  ring::BucklingResult out;
  std::string error;
  ASSERT_EQ(plugin->buckling(held(), o, b, out, error), 0) << error;
  const auto direct = fem::compute_buckling(held(), o, b);
  ASSERT_EQ(out.factors.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(out.factors[i], direct.factors[i]);  // same code, same data
  // A refusal is code 2 with the key in the message.
  b.count = 0;
  EXPECT_EQ(plugin->buckling(held(), o, b, out, error), 2);
  EXPECT_NE(error.find("buckling.count"), std::string::npos) << error;
}

TEST(FemPlugin, ModesUnderLoadGiveTheSameNumbers) {
  const fem::Plugin* plugin = load();
  ASSERT_NE(plugin, nullptr);
  ring::FemOptions o;
  o.elements = 8;
  ring::StaticOptions st;
  st.loads.pressure = {3000.0, ring::Pressure::Kind::follower};  // ~0.46 of the critical pressure
  ring::ModalResult out;
  std::string error;
  ASSERT_EQ(plugin->modes_under_load(held(), o, st, 2, out, error), 0) << error;
  const auto direct = fem::compute_modes_under_load(held(), o, st, 2);
  ASSERT_EQ(out.omega.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(out.omega[i], direct.omega[i]);  // same code, same data
  EXPECT_EQ(std::get<std::string>(out.model.at("preload")), "static");
  // A refusal is code 2 naming the key; past the critical pressure (6.49 kN/m on 8 cubic
  // elements) a numerical failure, code 3.
  o.reference = true;
  EXPECT_EQ(plugin->modes_under_load(held(), o, st, 2, out, error), 2);
  EXPECT_NE(error.find("fem.reference"), std::string::npos) << error;
  o.reference = false;
  st.loads.pressure.value = 7000.0;
  EXPECT_EQ(plugin->modes_under_load(held(), o, st, 2, out, error), 3);
  EXPECT_NE(error.find("critical load"), std::string::npos) << error;
}

TEST(FemPlugin, NonlinearAnalysesGiveTheSameNumbers) {
  const fem::Plugin* plugin = load();
  ASSERT_NE(plugin, nullptr);
  ring::FemOptions o;
  o.elements = 20;
  ring::StaticOptions st;
  st.loads.points = {{0.0, {-20e3, 0.0}}};
  st.record = {0.0, 90.0};
  ring::StaticResult sr;
  std::string error;
  ASSERT_EQ(plugin->statics(held(), o, st, sr, error), 0) << error;
  const auto sd = fem::solve_static(held(), o, st);
  ASSERT_EQ(sr.displacements.size(), 2u);
  EXPECT_EQ(sr.displacements[0].ux, sd.displacements[0].ux);
  EXPECT_EQ(sr.displacements[1].uy, sd.displacements[1].uy);
  ring::ResponseOptions rs;
  rs.loads = st.loads;
  rs.dt = 0.01;
  rs.t_end = 0.2;
  rs.record = {0.0};
  ring::TimeHistory h;
  int reason = -1;
  double t_reached = 0.0;
  ASSERT_EQ(plugin->respond(held(), o, rs, h, reason, t_reached, error), 0) << error;
  EXPECT_EQ(h.ux[0].back(), fem::respond(held(), o, rs).ux[0].back());
  // A step far too large for Newton from rest (the whole 20 MN load at once) fails with
  // code 3, the reason and the history so far (the state at t = 0).
  rs.loads.points.at(0).force = {-2e7, 0.0};
  rs.dt = 1.0;
  rs.t_end = 2.0;
  EXPECT_EQ(plugin->respond(held(), o, rs, h, reason, t_reached, error), 3);
  EXPECT_EQ(reason, static_cast<int>(ring::IntegrationFailure::Reason::step_too_small)) << error;
  EXPECT_FALSE(h.t.empty());
  EXPECT_EQ(t_reached, h.t.back());
}

TEST(FemPlugin, ErrorsBecomeCodesNotExceptions) {
  const fem::Plugin* plugin = load();
  ASSERT_NE(plugin, nullptr);
  const auto spec = ringtest::pinned_ring();
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
  ASSERT_EQ(plugin->write_vtu(ringtest::pinned_ring(), ring::FemOptions{}, 3, dir.string(), error), 0) << error;
  EXPECT_GT(std::filesystem::file_size(dir / "fem_modes.vtu"), 1000u);
  std::filesystem::remove_all(dir);
}

}  // namespace
