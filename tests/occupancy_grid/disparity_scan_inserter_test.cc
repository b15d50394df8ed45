#include "occupancy_grid/disparity_scan_inserter.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "test_scans.h"

namespace stereonav {
namespace {

using testing::occupancyAt;
using testing::robotAt;
using testing::scanOf;
using testing::tagAt;
using testing::unitCamera;
using testing::unitLimits;

struct Fixture {
  explicit Fixture(const GridUpdateOptions& update = {})
      : grid(unitLimits(), update.scale), inserter(SensorModelOptions{}, update, 0.0) {}
  void insert(float disparity, const mrpt::poses::CPose2D& robot) {
    inserter.insert(scanOf({disparity}), unitCamera(), robot, grid);
  }
  DisparityTaggedGrid grid;
  DisparityScanInserter inserter;
};

TEST(DisparityScanInserterTest, OneReadingAddsKOverOccAndSubtractsKOverClear) {
  Fixture f;
  f.insert(1.5f, robotAt(0, 0));
  for (int x = 2; x <= 3; ++x) {
    for (int y = -1; y <= 1; ++y) {
      EXPECT_EQ(occupancyAt(f.grid, x, y), 128 + 20) << x << "," << y;
      EXPECT_EQ(tagAt(f.grid, x, y), 1.5f);
    }
  }
  EXPECT_EQ(occupancyAt(f.grid, 0, 0), 128 - 20);
  EXPECT_EQ(occupancyAt(f.grid, 1, 0), 128 - 20);
  EXPECT_EQ(tagAt(f.grid, 1, 0), DisparityTaggedGrid::kNoTag);  // CLEAR leaves tags alone
  // Just outside both regions.
  EXPECT_EQ(occupancyAt(f.grid, 1, 1), 128);
  EXPECT_EQ(occupancyAt(f.grid, 4, 0), 128);
  EXPECT_EQ(occupancyAt(f.grid, -1, 0), 128);
}

TEST(DisparityScanInserterTest, TheGridsWrittenCellsAreTheBoxOfEveryCellAScanChanged) {
  Fixture f;
  f.insert(1.5f, robotAt(0, 0));
  f.insert(1.5f, robotAt(-3, 4));
  const DisparityTaggedGrid& grid = f.grid;
  int first_col = grid.width(), last_col = -1, first_row = grid.height(), last_row = -1;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const bool changed = grid.occupancy(col, row) != grid.scale().unknown() ||
                           grid.disparityTag(col, row) != DisparityTaggedGrid::kNoTag || grid.closeFree(col, row);
      if (!changed) continue;
      first_col = std::min(first_col, col);
      last_col = std::max(last_col, col);
      first_row = std::min(first_row, row);
      last_row = std::max(last_row, row);
    }
  }
  ASSERT_GE(last_col, 0);
  const CellWindow& written = grid.writtenCells();
  EXPECT_EQ(written.col_begin, first_col);
  EXPECT_EQ(written.col_end, last_col + 1);
  EXPECT_EQ(written.row_begin, first_row);
  EXPECT_EQ(written.row_end, last_row + 1);
}

TEST(DisparityScanInserterTest, UpdatesClipAtGminAndGmaxAndCrossTheThresholds) {
  Fixture f;
  const OccupancyScale& scale = f.grid.scale();
  const int occupied[] = {148, 168, 188, 208, 228, 248, 255, 255};
  const int cleared[] = {108, 88, 68, 48, 28, 8, 0, 0};
  for (int i = 0; i < 8; ++i) {
    f.insert(1.5f, robotAt(0, 0));
    EXPECT_EQ(occupancyAt(f.grid, 3, 0), occupied[i]) << "insert " << i;
    EXPECT_EQ(occupancyAt(f.grid, 1, 0), cleared[i]) << "insert " << i;
  }
  // 148 is not yet "definitely obstructed" (> 150), 168 is; 68 is not free (< 50), 48 is.
  EXPECT_EQ(scale.classify(148), CellClass::kUnknown);
  EXPECT_EQ(scale.classify(168), CellClass::kOccupied);
  EXPECT_EQ(scale.classify(150), CellClass::kUnknown);
  EXPECT_EQ(scale.classify(151), CellClass::kOccupied);
  EXPECT_EQ(scale.classify(68), CellClass::kUnknown);
  EXPECT_EQ(scale.classify(50), CellClass::kUnknown);
  EXPECT_EQ(scale.classify(49), CellClass::kFree);
  EXPECT_EQ(scale.classify(48), CellClass::kFree);
}

TEST(DisparityScanInserterTest, CustomLimitsMoveTheMidpointAndTheClipping) {
  GridUpdateOptions update;
  update.scale.g_min = 10;
  update.scale.g_max = 240;
  update.scale.free_below = 60;
  update.scale.occupied_above = 180;
  update.update_step = 50;
  Fixture f(update);
  EXPECT_EQ(update.scale.unknown(), 125);  // 10 + ceil(230 / 2)
  EXPECT_EQ(occupancyAt(f.grid, 3, 0), 125);
  f.insert(1.5f, robotAt(0, 0));
  EXPECT_EQ(occupancyAt(f.grid, 3, 0), 175);
  EXPECT_EQ(occupancyAt(f.grid, 1, 0), 75);
  f.insert(1.5f, robotAt(0, 0));
  f.insert(1.5f, robotAt(0, 0));
  EXPECT_EQ(occupancyAt(f.grid, 3, 0), 240);
  EXPECT_EQ(occupancyAt(f.grid, 1, 0), 10);
}

// A far reading, d = 0.9 seen from 3 m further back (robot at X = -3): near depth 4/1.4 = 2.86,
// far depth 4/0.4 = 10, so its OCC region covers X in [-0.14, 7) and |Y| <= (X + 3)/2, which
// contains the near reading's cells X = 2, 3 (tag 1.5); its CLEAR covers X = -3 .. -1.
TEST(DisparityScanInserterTest, AccuracyPreservationSkipsAFarReadingExplainedByANearOne) {
  Fixture f;
  f.insert(1.5f, robotAt(0, 0));
  f.insert(0.9f, robotAt(-3, 0));
  EXPECT_EQ(occupancyAt(f.grid, 5, 0), 128);  // the far OCC update was skipped entirely...
  EXPECT_EQ(occupancyAt(f.grid, 2, 0), 148);
  EXPECT_EQ(tagAt(f.grid, 2, 0), 1.5f);
  EXPECT_EQ(occupancyAt(f.grid, -1, 0), 108);  // ...but its CLEAR region was applied

  // Where no near evidence lies (20 m to the side) the same far reading is applied.
  f.insert(0.9f, robotAt(-3, 20));
  EXPECT_EQ(occupancyAt(f.grid, 5, 20), 148);
  EXPECT_EQ(tagAt(f.grid, 5, 20), 0.9f);
  // And lower-disparity evidence never blocks a better reading.
  f.insert(1.5f, robotAt(0, 20));
  EXPECT_EQ(occupancyAt(f.grid, 3, 20), 168);
  EXPECT_EQ(tagAt(f.grid, 3, 20), 1.5f);
}

TEST(DisparityScanInserterTest, WithoutAccuracyPreservationTheFarReadingSmearsTheNearOne) {
  GridUpdateOptions update;
  update.accuracy_preservation = false;
  Fixture f(update);
  f.insert(1.5f, robotAt(0, 0));
  f.insert(0.9f, robotAt(-3, 0));
  EXPECT_EQ(occupancyAt(f.grid, 5, 0), 148);
  EXPECT_EQ(occupancyAt(f.grid, 2, 0), 168);
  EXPECT_EQ(tagAt(f.grid, 2, 0), 0.9f);
}

TEST(DisparityScanInserterTest, ClearedEvidenceNoLongerExplainsReadings) {
  Fixture f;
  f.insert(1.5f, robotAt(0, 0));  // X = 2, 3 -> 148, tag 1.5
  // d = 0.7 from the same place: CLEAR depth < 4/1.2 = 3.33 brings X = 2, 3 back to 128 (the
  // obstacle moved); its OCC (X = 4 .. 19) holds no better evidence and is applied with tag 0.7.
  f.insert(0.7f, robotAt(0, 0));
  EXPECT_EQ(occupancyAt(f.grid, 2, 0), 128);
  EXPECT_EQ(tagAt(f.grid, 2, 0), 1.5f);  // the stale tag stays, inert at G = unknown
  EXPECT_EQ(occupancyAt(f.grid, 5, 0), 148);
  // The far reading that was explained before is now applied: X = 2 has no evidence any more
  // and X = 5's evidence comes from a lower disparity (0.7 < 0.9).
  f.insert(0.9f, robotAt(-3, 0));
  EXPECT_EQ(occupancyAt(f.grid, 5, 0), 168);
  EXPECT_EQ(occupancyAt(f.grid, 2, 0), 148);
  EXPECT_EQ(tagAt(f.grid, 2, 0), 0.9f);
}

bool closeFreeAt(const DisparityTaggedGrid& grid, int x, int y) {
  int col = 0, row = 0;
  return grid.cellAt(0.5 + x, 0.5 + y, col, row) && grid.closeFree(col, row);
}

// Free-space preservation within R = 2.5 m. Accuracy preservation is off so that only the new
// rule decides. d = 1.0 from X = 0: CLEAR ends at depth 4/1.5 = 2.67 (X = 0, 1, 2 on the axis),
// OCC covers X = 3 .. 7. d = 0.7 from X = -6: a far reading (depth 4/1.2 = 3.33 > R) whose OCC
// region covers X = -2 .. 3 (it ends at the sensor model's 10 m).
TEST(DisparityScanInserterTest, FreePreservationSparesCellsSeenFreeFromCloseOnly) {
  GridUpdateOptions update;
  update.accuracy_preservation = false;
  update.free_preservation_range_m = 2.5;
  Fixture f(update);
  f.insert(1.0f, robotAt(0, 0));
  EXPECT_TRUE(closeFreeAt(f.grid, 1, 0));
  EXPECT_TRUE(closeFreeAt(f.grid, 2, 0));
  EXPECT_FALSE(closeFreeAt(f.grid, 3, 0));  // OCC, and beyond R anyway

  f.insert(0.7f, robotAt(-6, 0));
  EXPECT_EQ(occupancyAt(f.grid, 1, 0), 108);   // seen free from 1 m: spared
  EXPECT_EQ(occupancyAt(f.grid, 2, 0), 108);   // from 2 m: spared
  EXPECT_EQ(occupancyAt(f.grid, 3, 0), 168);   // obstacle evidence: applied
  EXPECT_EQ(occupancyAt(f.grid, -1, 0), 148);  // never seen: applied
  EXPECT_EQ(tagAt(f.grid, 1, 0), DisparityTaggedGrid::kNoTag);

  // d = 2.0 from X = -1 (depth 1.6 .. 2.67 < R): an obstacle seen from close at X = 1 is
  // mapped, and the cell is no longer spared from far readings.
  f.insert(2.0f, robotAt(-1, 0));
  EXPECT_EQ(occupancyAt(f.grid, 1, 0), 128);
  EXPECT_FALSE(closeFreeAt(f.grid, 1, 0));
  f.insert(0.7f, robotAt(-6, 0));
  EXPECT_EQ(occupancyAt(f.grid, 1, 0), 148);
  EXPECT_EQ(occupancyAt(f.grid, 2, 0), 108);
}

TEST(DisparityScanInserterTest, WithoutFreePreservationAFarReadingCoversFloorSeenFromClose) {
  GridUpdateOptions update;
  update.accuracy_preservation = false;
  Fixture f(update);
  f.insert(1.0f, robotAt(0, 0));
  f.insert(0.7f, robotAt(-6, 0));
  EXPECT_EQ(occupancyAt(f.grid, 1, 0), 128);
  EXPECT_EQ(occupancyAt(f.grid, 2, 0), 128);
  EXPECT_FALSE(closeFreeAt(f.grid, 1, 0));
}

}  // namespace
}  // namespace stereonav
