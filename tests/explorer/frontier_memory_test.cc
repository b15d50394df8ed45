#include "explorer/frontier_memory.h"

#include <gtest/gtest.h>

#include "test_grids.h"

namespace stereonav {
namespace {

// Defaults: looked-at range 1 m, 90 degree field of view, 12 resolving views, frontiers of 3 cells.
ExplorerOptions options() { return ExplorerOptions{}; }

NavigationGrid navigationGrid(const TestGrid& cells) { return NavigationGrid(cells.grid(), {}, NavigationGridOptions{}); }

// 4 m x 4 m of free floor with unknown beyond x = 3 (columns 30..39).
TestGrid openToTheEast() {
  TestGrid cells(40, 40);
  cells.free(0, 0, 29, 39);
  return cells;
}

// A memory anchored at `cells`' frame, as the explorer's is at its first map.
FrontierMemory anchoredMemory(const TestGrid& cells) {
  FrontierMemory memory(options());
  memory.anchor(cells.grid().frame());
  return memory;
}

// The foot of a wall stereo cannot match along x = 3.03 (the unknown columns 30..39 of
// openToTheEast), as the scan reports it: points from y 1.0 to 2.58 (rows 10..25).
std::vector<mrpt::math::TPoint2D> unmatchedWallFoot() {
  std::vector<mrpt::math::TPoint2D> scan;
  for (int k = 0; k < 80; ++k) scan.emplace_back(3.03, 1.0 + 0.02 * k);
  return scan;
}

Frontier column(int col, int row0, int row1) {
  Frontier frontier;
  for (int row = row0; row <= row1; ++row) frontier.cells.emplace_back(col, row);
  return frontier;
}

TEST(FrontierMemoryTest, CellsInViewWithinRangeOfALookAreDropped) {
  const TestGrid cells = openToTheEast();
  const NavigationGrid grid = navigationGrid(cells);
  FrontierMemory memory = anchoredMemory(cells);
  // Looking east from (2.2, 2.05): column 29 (x 2.95) is 0.75 m ahead.
  memory.lookedFrom(mrpt::poses::CPose2D(2.2, 2.05, 0.0));
  EXPECT_EQ(memory.looks(), 1u);
  EXPECT_TRUE(memory.isDropped(grid, 29, 20));
  // 0.75 m to the side and 0.6 m north: 38.7 degrees off the heading, within the 45 degree half view.
  EXPECT_TRUE(memory.isDropped(grid, 29, 26));
  // 0.75 m ahead and 0.8 m north: beyond both the range and the view.
  EXPECT_FALSE(memory.isDropped(grid, 29, 28));
  // Behind the robot.
  EXPECT_FALSE(memory.isDropped(grid, 15, 20));
}

TEST(FrontierMemoryTest, WithoutDroppedRemovesDroppedCellsAndFrontiersLeftTooSmall) {
  const TestGrid cells = openToTheEast();
  const NavigationGrid grid = navigationGrid(cells);
  FrontierMemory memory = anchoredMemory(cells);
  memory.drop(grid, {29, 5});
  memory.drop(grid, {29, 30});
  memory.drop(grid, {29, 31});
  const std::vector<Frontier> kept = memory.withoutDropped(grid, {column(29, 3, 8), column(29, 30, 33)});
  // The first loses one of its six cells; the second keeps two, under the three a frontier needs.
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].cells.size(), 5u);
  for (const cv::Point& cell : kept[0].cells) EXPECT_NE(cell.y, 5);
}

TEST(FrontierMemoryTest, ACellInPlainSightUpCloseIsDroppedAfterTheResolvingViews) {
  TestGrid cells = openToTheEast();
  cells.occupied(25, 21, 25, 35);  // hides the frontier's cells north of row 21 from the robot
  const NavigationGrid grid = navigationGrid(cells);
  FrontierMemory memory = anchoredMemory(cells);
  const std::vector<Frontier> frontiers = {column(29, 15, 35)};
  const mrpt::poses::CPose2D pose(2.2, 2.05, 0.0);
  for (int view = 1; view < 12; ++view) memory.countCloseViews(grid, frontiers, pose);
  EXPECT_FALSE(memory.isDropped(grid, 29, 20));
  memory.countCloseViews(grid, frontiers, pose);
  EXPECT_TRUE(memory.isDropped(grid, 29, 20));
  // In range and view (0.75 m east, 0.6 m north) but behind the wall: never counted.
  EXPECT_FALSE(memory.isDropped(grid, 29, 26));
}

TEST(FrontierMemoryTest, DroppedCellsKeepTheirNamesWhenTheGridGrows) {
  FrontierMemory memory(options());
  const DisparityTaggedGrid first(GridLimits{0.0, 4.0, 0.0, 4.0, 0.1, 1.0}, OccupancyScale{});
  memory.anchor(first.frame());
  const NavigationGrid small(first, {}, NavigationGridOptions{});
  memory.drop(small, {29, 20});  // x 2.9 .. 3.0, y 2.0 .. 2.1
  // The map grew by 1 m west and south: the same place is now cell (39, 30).
  const DisparityTaggedGrid grown(GridLimits{-1.0, 4.0, -1.0, 4.0, 0.1, 1.0}, OccupancyScale{});
  memory.anchor(grown.frame());
  const NavigationGrid larger(grown, {}, NavigationGridOptions{});
  EXPECT_TRUE(memory.isDropped(larger, 39, 30));
  EXPECT_FALSE(memory.isDropped(larger, 29, 20));
}

TEST(FrontierMemoryTest, ACellWhoseUnknownSideAScanShowsASurfaceOnIsDropped) {
  // unmatchedWallFoot, read from (1.5, 2.05).
  const TestGrid cells = openToTheEast();
  const NavigationGrid grid = navigationGrid(cells);
  FrontierMemory memory = anchoredMemory(cells);
  std::vector<mrpt::math::TPoint2D> scan = unmatchedWallFoot();
  // And one beyond the 2 m of seen_free_range_m: (3.03, 3.95) is 2.5 m away.
  scan.emplace_back(3.03, 3.95);
  memory.dropSurfaced(grid, {column(29, 0, 39)}, scan, mrpt::poses::CPose2D(1.5, 2.05, 0.0));
  EXPECT_TRUE(memory.isDropped(grid, 29, 10));
  EXPECT_TRUE(memory.isDropped(grid, 29, 25));
  // Beside the surface seen, and beside the far point: still open.
  EXPECT_FALSE(memory.isDropped(grid, 29, 9));
  EXPECT_FALSE(memory.isDropped(grid, 29, 26));
  EXPECT_FALSE(memory.isDropped(grid, 29, 39));
}

TEST(FrontierMemoryTest, ACellWithAnUnknownSideNoSurfaceWasSeenOnStaysOpen) {
  // A corner of the unknown: cell (29, 20) has unknown cells east (30, 20) and, with the cell
  // north of it unknown too, north (29, 21). The scan shows a surface only on the east one.
  TestGrid cells = openToTheEast();
  cells.unknown(0, 21, 29, 39);
  const NavigationGrid grid = navigationGrid(cells);
  FrontierMemory memory = anchoredMemory(cells);
  const std::vector<mrpt::math::TPoint2D> scan{{3.03, 2.05}, {3.03, 1.95}};
  const Frontier corner = column(29, 19, 20);
  memory.dropSurfaced(grid, {corner}, scan, mrpt::poses::CPose2D(1.5, 2.0, 0.0));
  EXPECT_FALSE(memory.isDropped(grid, 29, 20));
  EXPECT_TRUE(memory.isDropped(grid, 29, 19));
}

TEST(FrontierMemoryTest, TheSecondPassForgetsEveryCellGivenUpOnce) {
  const TestGrid cells = openToTheEast();
  const NavigationGrid grid = navigationGrid(cells);
  FrontierMemory memory = anchoredMemory(cells);
  // Nothing given up yet: no second pass is needed, and it stays available.
  EXPECT_FALSE(memory.beginSecondPass());
  EXPECT_FALSE(memory.inSecondPass());
  // Fresh memory, each rule used once: a look east from (2.2, 2.05) (rows 14..26 of column 29),
  // an explicit drop (row 35) and unmatchedWallFoot read from 1.5 m (rows 10..25).
  FrontierMemory used = anchoredMemory(cells);
  used.lookedFrom(mrpt::poses::CPose2D(2.2, 2.05, 0.0));
  used.drop(grid, {29, 35});
  const std::vector<mrpt::math::TPoint2D> wall = unmatchedWallFoot();
  const mrpt::poses::CPose2D reading_pose(1.5, 2.05, 0.0);
  used.dropSurfaced(grid, {column(29, 0, 39)}, wall, reading_pose);
  EXPECT_TRUE(used.isDropped(grid, 29, 10));
  EXPECT_TRUE(used.isDropped(grid, 29, 26));
  EXPECT_TRUE(used.isDropped(grid, 29, 35));

  EXPECT_FALSE(used.inSecondPass());
  EXPECT_TRUE(used.beginSecondPass());
  EXPECT_TRUE(used.inSecondPass());
  EXPECT_EQ(used.looks(), 0u);
  for (int row = 0; row < 40; ++row) EXPECT_FALSE(used.isDropped(grid, 29, row)) << row;
  // The rules hold in the second pass: the wall read again and a look drop cells as before.
  used.dropSurfaced(grid, {column(29, 0, 39)}, wall, reading_pose);
  EXPECT_TRUE(used.isDropped(grid, 29, 10));
  EXPECT_FALSE(used.isDropped(grid, 29, 26));  // beyond the wall's rows, within the look's view
  EXPECT_FALSE(used.isDropped(grid, 29, 35));
  used.lookedFrom(mrpt::poses::CPose2D(2.2, 2.05, 0.0));
  EXPECT_TRUE(used.isDropped(grid, 29, 26));
  // Once only.
  EXPECT_FALSE(used.beginSecondPass());
  EXPECT_TRUE(used.isDropped(grid, 29, 10));
  EXPECT_TRUE(used.isDropped(grid, 29, 26));
}

}  // namespace
}  // namespace stereonav
