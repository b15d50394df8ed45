#include "explorer/frontier_finder.h"

#include <gtest/gtest.h>

#include "test_grids.h"

namespace stereonav {
namespace {

TEST(FrontierFinderTest, FreeSquareInUnknownHasItsWholeBorderAsOneFrontier) {
  TestGrid cells(20, 20);
  cells.free(5, 5, 9, 9);  // 5 x 5 cells: 16 border cells, 9 inner ones
  const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(cells.grid(), {}, 0.3), 1);
  ASSERT_EQ(frontiers.size(), 1u);
  EXPECT_EQ(frontiers[0].cells.size(), 16u);
  for (const cv::Point& cell : frontiers[0].cells) {
    EXPECT_TRUE(cell.x == 5 || cell.x == 9 || cell.y == 5 || cell.y == 9) << cell;
  }
  // Centre of the square: cells 5..9 -> 0.5 .. 1.0 m, centre 0.75.
  EXPECT_NEAR(frontiers[0].centroid_x, 0.75, 1e-9);
  EXPECT_NEAR(frontiers[0].centroid_y, 0.75, 1e-9);
}

TEST(FrontierFinderTest, CellsBesideAnObstacleAreNotFrontier) {
  TestGrid cells(20, 20);
  cells.free(5, 5, 9, 9).occupied(10, 4, 10, 10);
  const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(cells.grid(), {}, 0.3), 1);
  ASSERT_EQ(frontiers.size(), 1u);
  // The east side (col 9) only touches the wall, except its corners which touch unknown above/below.
  EXPECT_EQ(frontiers[0].cells.size(), 16u - 3u);
  for (const cv::Point& cell : frontiers[0].cells) EXPECT_FALSE(cell.x == 9 && cell.y > 5 && cell.y < 9) << cell;
}

TEST(FrontierFinderTest, ClosedRoomHasNoFrontier) {
  TestGrid cells(20, 20);
  cells.occupied(4, 4, 12, 12).free(5, 5, 11, 11);
  EXPECT_TRUE(findFrontiers(NavigationGrid(cells.grid(), {}, 0.3), 1).empty());
}

TEST(FrontierFinderTest, SeparateOpeningsAreSeparateFrontiersLargestFirstAndSmallOnesDropped) {
  TestGrid cells(30, 20);
  // A closed room with a 5-cell doorway on its west wall and a 1-cell hole in its east wall.
  cells.occupied(4, 4, 20, 14).free(5, 5, 19, 13).unknown(4, 7, 4, 11).unknown(20, 9, 20, 9);
  const NavigationGrid grid(cells.grid(), {}, 0.3);
  const std::vector<Frontier> all = findFrontiers(grid, 1);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].cells.size(), 5u);
  for (const cv::Point& cell : all[0].cells) EXPECT_EQ(cell.x, 5);
  EXPECT_EQ(all[1].cells.size(), 1u);
  EXPECT_EQ(all[1].cells[0], cv::Point(19, 9));
  const std::vector<Frontier> large = findFrontiers(grid, 2);
  ASSERT_EQ(large.size(), 1u);
  EXPECT_EQ(large[0].cells.size(), 5u);
}

TEST(NavigationGridTest, WhereTheRobotStoodIsFreeUnlessTheMapSaysOccupied) {
  TestGrid cells(20, 20);
  cells.occupied(10, 10, 10, 10);
  const NavigationGrid grid(cells.grid(), {mrpt::poses::CPose2D(1.0, 1.0, 0.0)}, 0.25);
  // Cell centres within 0.25 m of (1, 1) become free: (0.85, 0.85) is 0.21 m away, (0.75, 0.85)
  // 0.29 m and (1.25, 1.05) 0.255 m.
  EXPECT_EQ(grid.cellClass(8, 9), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(11, 10), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(8, 8), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(7, 8), NavigationGrid::kUnknown);
  EXPECT_EQ(grid.cellClass(10, 10), NavigationGrid::kOccupied);
  EXPECT_EQ(grid.cellClass(12, 10), NavigationGrid::kUnknown);
}

TEST(NavigationGridTest, ClearanceIsTheDistanceToTheNearestCellThatIsNotFree) {
  TestGrid cells(20, 20);
  cells.free(0, 0, 19, 19).occupied(10, 0, 10, 19);
  const NavigationGrid grid(cells.grid(), {}, 0.3);
  // Cell 3's centre is at x = 0.35: the grid's west edge (x = 0) is nearer than the wall (x = 1.0).
  EXPECT_NEAR(grid.clearance(3, 10), 0.35, 1e-6);
  EXPECT_NEAR(grid.obstacleDistance(3, 10), 0.35, 1e-6);
  EXPECT_NEAR(grid.clearance(8, 10), 0.15, 1e-6);  // 0.85 to the wall at 1.0
  EXPECT_NEAR(grid.obstacleDistance(8, 10), 0.15, 1e-6);
  EXPECT_NEAR(grid.clearance(10, 10), -0.05, 1e-6);  // blocked cells have no clearance
}

}  // namespace
}  // namespace stereonav
