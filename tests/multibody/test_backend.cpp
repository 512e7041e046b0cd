// The one crossover table (multibody/backend.hpp). Oracle for the modes' count rule: the
// rule as solve_modes applied it before the table, on the chain's own unknowns r =
// Chain::dofs() - Chain::constraint_count().
#include <gtest/gtest.h>

#include <algorithm>

#include "multibody/backend.hpp"
#include "multibody/chain.hpp"
#include "tests/multibody/common.hpp"

namespace {

using multibody::Analysis;
using multibody::Backend;
using Method = ring::MultibodyOptions::Method;

ring::MultibodyOptions opts(int n, Method method = Method::automatic) {
  ring::MultibodyOptions o;
  o.n = n;
  o.method = method;
  return o;
}

TEST(MultibodyBackend, EveryAnalysisSwitchesAtItsCrossover) {
  for (Analysis a : {Analysis::modes, Analysis::statics, Analysis::response}) {
    const int from = multibody::sparse_crossover(a);
    EXPECT_EQ(multibody::backend(opts(from - 1), a), Backend::dense);
    EXPECT_EQ(multibody::backend(opts(from), a), Backend::banded);
    EXPECT_EQ(multibody::backend(opts(10, Method::sparse), a), Backend::banded);
    EXPECT_EQ(multibody::backend(opts(100000, Method::dense), a), Backend::dense);
  }
  // Today's values: modes above 256, statics from 1000, the response from 100.
  EXPECT_EQ(multibody::sparse_crossover(Analysis::modes), 257);
  EXPECT_EQ(multibody::sparse_crossover(Analysis::statics), 1000);
  EXPECT_EQ(multibody::sparse_crossover(Analysis::response), 100);
  ring::MultibodyOptions paper = opts(100000);
  paper.dependent = ring::MultibodyOptions::Dependent::paper;
  EXPECT_EQ(multibody::backend(paper, Analysis::modes), Backend::dense);
  EXPECT_EQ(multibody::backend(paper, Analysis::response), Backend::banded);
}

// "auto" keeps the modes dense when a third of the spectrum or more is wanted, or when the
// Lanczos would fill the whole space (4 nev + 60 >= r: backend.hpp), for every support.
TEST(MultibodyBackend, ModesStayDenseForAThirdOfTheSpectrum) {
  const ring::RingSpec free = ringtest::free_ring(), pinned = ringtest::pinned_ring(), held = ringtest::pin_roller_ring();
  for (const ring::RingSpec* spec : {&free, &pinned, &held})
    for (int n : {256, 258, 300, 1000}) {  // even: the roller sits opposite the pin
      const multibody::Chain chain(*spec, opts(n));
      const int r = chain.dofs() - chain.constraint_count(), rigid = spec->rigid_modes();
      for (int count = 1; count <= r - rigid; ++count) {
        const int nev = std::min(r, count + rigid + 2);
        const bool sparse = n > 256 && 3 * nev <= r && 4 * nev + 60 < r;
        EXPECT_EQ(multibody::backend(opts(n), *spec, count), sparse ? Backend::banded : Backend::dense)
            << "n " << n << ", count " << count << ", rigid " << rigid;
        EXPECT_EQ(multibody::backend(opts(n, Method::sparse), *spec, count), Backend::banded);
      }
    }
}

}  // namespace
