// The paper's Table 1 (compare/data/table1.csv, Yin & Wang 1989/90), n = 40, ring pinned
// at 180 deg: the lumped-mass column is the hinged chain with midpoint point masses, the
// SAP5 column is 40 straight frame elements with consistent mass (docs/paper.md, items 4-5).
#include <gtest/gtest.h>

#include <cstdio>

#include "lumped_mass/modes.hpp"
#include "ring/paper_table.hpp"
#include "common.hpp"
#include "tests/support/close.hpp"

namespace {

std::vector<ring::PaperRow> table() {
  return ring::read_paper_table(RINGVIB_SOURCE_DIR "/compare/data/table1.csv");
}

TEST(LumpedPaper, ChainReproducesLumpedMassColumnModes1To9) {
  const auto rows = table();
  const ring::ModalResult r =
      lumped::compute_modes(ringtest::pinned_ring(), lumptest::options(40, lumptest::kChain), 20);
  EXPECT_EQ(r.rigid_modes, 1);  // pinned: free to turn about the pin
  for (const auto& row : rows) {
    if (!row.lm_corrected || row.mode > 20) continue;
    const double w = r.omega[row.mode - 1], lm = *row.lm_corrected;
    std::printf("[lumped chain n=40] mode %2d  %10.4f  paper LM %8.4g  diff %+6.2f %%\n", row.mode, w, lm,
                (w - lm) / lm * 100);
    // 1.0 %: the chain's specified agreement with the paper for modes 1-9 (docs/paper.md, item 5, found 0.95 %);
    // above mode 9 the printed values fall increasingly below this model (up to 3.9 %),
    // cause unknown, so they are printed, not asserted.
    if (row.mode <= 9) {
      EXPECT_TRUE(ringtest::IsClose(w, lm, 0.010)) << "mode " << row.mode;
    }
  }
}

TEST(LumpedPaper, FrameConsistentReproducesSap5ColumnAll23Modes) {
  const auto rows = table();
  const ring::ModalResult r =
      lumped::compute_modes(ringtest::pinned_ring(), lumptest::options(40, lumptest::kConsistent), 23);
  EXPECT_EQ(r.rigid_modes, 1);
  ASSERT_EQ(r.omega.size(), 23u);
  for (const auto& row : rows) {
    ASSERT_TRUE(row.fe_corrected.has_value());
    const double w = r.omega[row.mode - 1], fe = *row.fe_corrected;
    std::printf("[lumped frame-consistent n=40] mode %2d  %10.4f  paper SAP5 %8.4g  diff %+7.3f %%\n", row.mode,
                w, fe, (w - fe) / fe * 100);
    // 0.05 %: the table's printed precision: it prints 4 significant digits (rounding alone
    // is up to 0.05 % for values like 2.486), docs/paper.md, item 4, found 0.03 %.
    EXPECT_TRUE(ringtest::IsClose(w, fe, 5e-4)) << "mode " << row.mode;
  }
}

}  // namespace
