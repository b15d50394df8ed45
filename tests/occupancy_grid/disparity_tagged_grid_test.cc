#include "occupancy_grid/disparity_tagged_grid.h"

#include <gtest/gtest.h>

#include "occupancy_grid/disparity_scan_inserter.h"
#include "test_scans.h"

namespace stereonav {
namespace {

GridLimits limits(double min_x, double max_x, double min_y, double max_y, double resolution) {
  GridLimits l;
  l.min_x = min_x;
  l.max_x = max_x;
  l.min_y = min_y;
  l.max_y = max_y;
  l.resolution = resolution;
  return l;
}

TEST(DisparityTaggedGridTest, StartsUnknownAndUntaggedOnTheResolutionLattice) {
  const DisparityTaggedGrid grid(limits(-1.02, 1.0, -0.5, 0.74, 0.25), OccupancyScale{});
  // -1.02 snaps down to -1.25, 0.74 up to 0.75 (multiples of 0.25, like MRPT's grids).
  EXPECT_DOUBLE_EQ(grid.minX(), -1.25);
  EXPECT_DOUBLE_EQ(grid.maxX(), 1.0);
  EXPECT_DOUBLE_EQ(grid.minY(), -0.5);
  EXPECT_DOUBLE_EQ(grid.maxY(), 0.75);
  EXPECT_EQ(grid.width(), 9);
  EXPECT_EQ(grid.height(), 5);
  EXPECT_EQ(grid.occupancy(8, 4), 128);
  EXPECT_EQ(grid.disparityTag(0, 0), DisparityTaggedGrid::kNoTag);
  int col = -1, row = -1;
  ASSERT_TRUE(grid.cellAt(0.1, -0.26, col, row));
  EXPECT_EQ(col, 5);  // (0.1 + 1.25) / 0.25 = 5.4
  EXPECT_EQ(row, 0);  // (-0.26 + 0.5) / 0.25 = 0.96
  EXPECT_FALSE(grid.cellAt(1.0, 0.0, col, row));
}

TEST(DisparityTaggedGridTest, TheWrittenCellsFollowTheRowsHandedOutAndTheGridsGrowthAndReset) {
  DisparityTaggedGrid grid(limits(-1, 1, -1, 1, 0.5), OccupancyScale{});  // 4 x 4 cells
  const CellWindow& written = grid.writtenCells();
  EXPECT_GE(written.col_begin, written.col_end);  // nothing yet
  grid.occupancyRow(1, 2, 3)[2] = 200;
  grid.tagRow(2, 1, 2)[1] = 7.0f;
  EXPECT_EQ(written.col_begin, 1);
  EXPECT_EQ(written.col_end, 3);
  EXPECT_EQ(written.row_begin, 1);
  EXPECT_EQ(written.row_end, 3);
  // 3 cells more on the left and 2 below: the same cells, moved.
  grid.growToInclude({-2.5, 1.0, -2.0, 1.0}, 0.0);
  EXPECT_EQ(written.col_begin, 4);
  EXPECT_EQ(written.col_end, 6);
  EXPECT_EQ(written.row_begin, 3);
  EXPECT_EQ(written.row_end, 5);
  // A row handed out without columns counts whole.
  grid.closeFreeRow(0);
  EXPECT_EQ(written.col_begin, 0);
  EXPECT_EQ(written.col_end, grid.width());
  EXPECT_EQ(written.row_begin, 0);
  grid.reset(limits(-1, 1, -1, 1, 0.5));
  EXPECT_GE(written.col_begin, written.col_end);
}

TEST(DisparityTaggedGridTest, GrowsByWholeCellsKeepingCellsAtTheirWorldCoordinates) {
  DisparityTaggedGrid grid(limits(-1, 1, -1, 1, 0.5), OccupancyScale{});
  int col = 0, row = 0;
  ASSERT_TRUE(grid.cellAt(0.75, -0.25, col, row));
  grid.occupancyRow(row)[col] = 200;
  grid.tagRow(row)[col] = 7.0f;

  // Sticks out 2 m to the left and 4 m up; with a 0.5 m margin: 2.5 m = 5 cells left and
  // 4.5 m = 9 cells up; right and bottom stay.
  grid.growToInclude({-3.0, 0.0, -0.5, 5.0}, 0.5);
  EXPECT_DOUBLE_EQ(grid.minX(), -3.5);
  EXPECT_DOUBLE_EQ(grid.maxX(), 1.0);
  EXPECT_DOUBLE_EQ(grid.minY(), -1.0);
  EXPECT_DOUBLE_EQ(grid.maxY(), 5.5);
  EXPECT_EQ(grid.width(), 9);
  EXPECT_EQ(grid.height(), 13);
  ASSERT_TRUE(grid.cellAt(0.75, -0.25, col, row));
  EXPECT_EQ(col, 8);
  EXPECT_EQ(row, 1);
  EXPECT_EQ(grid.occupancy(col, row), 200);
  EXPECT_EQ(grid.disparityTag(col, row), 7.0f);
  ASSERT_TRUE(grid.cellAt(-3.2, 5.2, col, row));
  EXPECT_EQ(grid.occupancy(col, row), 128);
  EXPECT_EQ(grid.disparityTag(col, row), DisparityTaggedGrid::kNoTag);

  grid.growToInclude({-1.0, 0.5, 0.0, 2.0}, 0.5);  // already inside: nothing changes
  EXPECT_EQ(grid.width(), 9);
  EXPECT_EQ(grid.height(), 13);
}

TEST(DisparityTaggedGridTest, GrowthStopsAtMaxCells) {
  GridLimits bounded = limits(-1, 1, -1, 1, 0.5);  // 4 x 4 cells
  bounded.max_cells = 64;
  DisparityTaggedGrid grid(bounded, OccupancyScale{});
  // Asks for 8 m (16 cells) on the right and 1e300 m up: both scaled down by one factor until
  // the grid has at most 64 cells.
  grid.growToInclude({-1.0, 9.0, -1.0, 1e300}, 0.0);
  EXPECT_TRUE(grid.reachedCellLimit());
  EXPECT_LE(static_cast<long>(grid.width()) * grid.height(), 64);
  EXPECT_GE(grid.width(), 4);
  EXPECT_GT(grid.height(), 4);  // it grew as far as it could
  EXPECT_DOUBLE_EQ(grid.minX(), -1.0);
  EXPECT_DOUBLE_EQ(grid.minY(), -1.0);

  DisparityTaggedGrid unbounded(limits(-1, 1, -1, 1, 0.5), OccupancyScale{});
  unbounded.growToInclude({-1.0, 9.0, -1.0, 1.0}, 0.0);
  EXPECT_FALSE(unbounded.reachedCellLimit());
  EXPECT_EQ(unbounded.width(), 20);
}

TEST(DisparityTaggedGridTest, InitialGridBeyondMaxCellsIsRefused) {
  GridLimits too_big = limits(-10, 10, -10, 10, 0.5);  // 40 x 40 cells
  too_big.max_cells = 1000;
  EXPECT_THROW(DisparityTaggedGrid(too_big, OccupancyScale{}), std::invalid_argument);
}

TEST(DisparityTaggedGridTest, InsertingFarOutsideTheBoundsGrowsTheGrid) {
  using testing::occupancyAt;
  using testing::robotAt;
  DisparityTaggedGrid grid(testing::unitLimits(2.0), OccupancyScale{});
  DisparityScanInserter inserter(SensorModelOptions{}, GridUpdateOptions{}, 1.0);
  inserter.insert(testing::scanOf({1.5f}), testing::unitCamera(), robotAt(-1, 0), grid);
  EXPECT_EQ(occupancyAt(grid, 1, 0), 148);  // X = 1 is 2 m ahead of the robot: OCC

  // 30 m away, looking down -y: depth 2..4 m below the robot (Y = -30). The near edge (depth 2,
  // Y = -32) is now the top of the OCC region, so by the half-open rule its centres go to CLEAR,
  // and the far edge (depth 4, Y = -34) is the bottom, whose centres are in.
  inserter.insert(testing::scanOf({1.5f}), testing::unitCamera(),
                  robotAt(30, -30, -M_PI / 2), grid);
  EXPECT_EQ(occupancyAt(grid, 30, -31), 108);
  EXPECT_EQ(occupancyAt(grid, 30, -32), 108);
  EXPECT_EQ(occupancyAt(grid, 30, -33), 148);
  EXPECT_EQ(occupancyAt(grid, 30, -34), 148);
  EXPECT_EQ(occupancyAt(grid, 1, 0), 148);  // the old reading is where it was
  EXPECT_EQ(occupancyAt(grid, 0, 0), 108);
  EXPECT_LE(grid.minY(), 0.5 - 34);   // the far edge
  EXPECT_GE(grid.maxX(), 0.5 + 32);   // the far corner, 2 m to the side
}

}  // namespace
}  // namespace stereonav
