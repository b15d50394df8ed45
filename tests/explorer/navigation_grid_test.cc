#include "explorer/navigation_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "test_grids.h"

namespace stereonav {
namespace {

TEST(NavigationGridTest, WhereTheRobotStoodIsFreeUnlessTheMapSaysOccupied) {
  TestGrid cells(20, 20);
  cells.occupied(10, 10, 10, 10);
  NavigationGridOptions options;
  options.body_radius_m = 0.25;
  const NavigationGrid grid(cells.grid(), {mrpt::poses::CPose2D(1.0, 1.0, 0.0)}, options);
  // Cell centres within 0.25 m of (1, 1) become free: (0.85, 0.85) is 0.21 m away, (0.75, 0.85)
  // 0.29 m and (1.25, 1.05) 0.255 m.
  EXPECT_EQ(grid.cellClass(8, 9), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(11, 10), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(8, 8), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(7, 8), NavigationGrid::kUnknown);
  EXPECT_EQ(grid.cellClass(10, 10), NavigationGrid::kOccupied);
  EXPECT_EQ(grid.cellClass(12, 10), NavigationGrid::kUnknown);
}

TEST(NavigationGridTest, FloorSeenFreeUpCloseIsFreeUnlessTheMapHoldsAPreciseObstacle) {
  TestGrid cells(20, 20);
  cells.unknown(0, 0, 19, 19).occupied(5, 5, 5, 5).tag(5, 5, 5, 5, 2.0f).occupied(6, 5, 6, 5).tag(6, 5, 6, 5, 12.0f);
  NavigationGridOptions options;
  options.precise_min_disparity = 8.0f;
  const std::vector<cv::Point2d> seen_free = {{0.45, 0.55}, {0.55, 0.55}, {0.65, 0.55}, {1.95, 1.95}};
  const NavigationGrid grid(cells.grid(), {}, options, {}, seen_free);
  EXPECT_EQ(grid.cellClass(4, 5), NavigationGrid::kFree);      // unknown in the map
  EXPECT_EQ(grid.cellClass(5, 5), NavigationGrid::kFree);      // a far reading's smear
  EXPECT_EQ(grid.cellClass(6, 5), NavigationGrid::kOccupied);  // seen up close since
  EXPECT_EQ(grid.cellClass(19, 19), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(7, 5), NavigationGrid::kUnknown);
  // A contact (what stopped the body) outranks the memory.
  const NavigationGrid touched(cells.grid(), {}, options, {cv::Point2d(0.45, 0.55)}, seen_free);
  EXPECT_EQ(touched.cellClass(4, 5), NavigationGrid::kOccupied);
}

TEST(NavigationGridTest, TheMapHoldsAnObstacleWhereItsOccupancyIsSureOfOne) {
  TestGrid cells(20, 20);
  cells.free(0, 0, 19, 19).occupied(10, 10, 10, 10).occupied(3, 3, 3, 3).tag(3, 3, 3, 3, 1.0f);
  cells.fill(12, 10, 12, 10, 199).fill(13, 10, 13, 10, 200);
  NavigationGridOptions options;
  options.precise_min_disparity = 2.0f;
  options.sure_obstacle_g = 200;
  const NavigationGrid grid(cells.grid(), {}, options, {cv::Point2d(1.55, 1.55)});
  EXPECT_TRUE(grid.mapHoldsObstacle(1.05, 1.05));
  EXPECT_TRUE(grid.mapHoldsObstacle(0.35, 0.35));  // imprecise: an obstacle all the same
  EXPECT_FALSE(grid.mapHoldsObstacle(1.25, 1.05));  // occupied (> 150), but not sure
  EXPECT_EQ(grid.cellClass(12, 10), NavigationGrid::kOccupied);
  EXPECT_TRUE(grid.mapHoldsObstacle(1.35, 1.05));
  EXPECT_EQ(grid.cellClass(15, 15), NavigationGrid::kOccupied);  // the contact
  EXPECT_FALSE(grid.mapHoldsObstacle(1.55, 1.55));
  EXPECT_FALSE(grid.mapHoldsObstacle(0.55, 1.05));
  EXPECT_FALSE(grid.mapHoldsObstacle(-0.5, 1.05));  // off the map
}

TEST(NavigationGridTest, ClearanceIsTheDistanceToTheNearestCellThatIsNotFree) {
  TestGrid cells(20, 20);
  cells.free(0, 0, 19, 19).occupied(10, 0, 10, 19);
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  // Cell 3's centre is at x = 0.35: the grid's west edge (x = 0) is nearer than the wall (x = 1.0).
  EXPECT_NEAR(grid.clearance(3, 10), 0.35, 1e-6);
  EXPECT_NEAR(grid.obstacleDistance(3, 10), 0.35, 1e-6);
  EXPECT_NEAR(grid.clearance(8, 10), 0.15, 1e-6);  // 0.85 to the wall at 1.0
  EXPECT_NEAR(grid.obstacleDistance(8, 10), 0.15, 1e-6);
  EXPECT_NEAR(grid.clearance(10, 10), -0.05, 1e-6);  // blocked cells have no clearance
}

TEST(NavigationGridTest, ClearanceAtAPointIsItsDistanceToTheNearestBlockedCellsSquare) {
  TestGrid cells(20, 20);
  cells.free(0, 0, 19, 19).occupied(10, 0, 10, 9);  // a wall x in [1.0, 1.1], y in [0, 1.0], open above
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  // Beside the wall: its face at x = 1.0, whatever cell the point is in.
  EXPECT_NEAR(grid.clearanceAt(0.73, 0.5, 1.0), 0.27, 1e-9);
  EXPECT_NEAR(grid.clearanceAt(0.77, 0.5, 1.0), 0.23, 1e-9);
  // Above the wall's end: to its corner at (1.0, 1.0) (3-4-5), and straight down to its top.
  EXPECT_NEAR(grid.clearanceAt(0.7, 1.4, 1.0), 0.5, 1e-9);
  EXPECT_NEAR(grid.clearanceAt(1.05, 1.3, 1.0), 0.3, 1e-9);
  // The grid's edge counts as blocked, and nothing within the search gives the search.
  EXPECT_NEAR(grid.clearanceAt(0.12, 1.5, 1.0), 0.12, 1e-9);
  EXPECT_NEAR(grid.clearanceAt(1.6, 1.6, 0.2), 0.2, 1e-9);
  // Inside a blocked cell: none.
  EXPECT_NEAR(grid.clearanceAt(1.05, 0.5, 1.0), 0.0, 1e-9);
}

TEST(NavigationGridTest, ClearanceOfFreePatchesInUnknownCountsUnknownAndTheGridEdgeAsBlocked) {
  TestGrid cells(40, 40);  // unknown but for two patches of free floor, 0.1 m cells
  cells.free(10, 5, 19, 8).free(0, 36, 3, 39);
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  EXPECT_NEAR(grid.clearance(12, 6), 0.15, 1e-6);  // row 4 two cells away: (2 - 0.5) x 0.1
  EXPECT_NEAR(grid.clearance(14, 7), 0.15, 1e-6);  // row 9
  EXPECT_NEAR(grid.clearance(10, 5), 0.05, 1e-6);  // in the patch's corner
  EXPECT_NEAR(grid.clearance(1, 38), 0.15, 1e-6);  // the grid's edges two cells away
  EXPECT_NEAR(grid.clearance(3, 36), 0.05, 1e-6);
  EXPECT_NEAR(grid.clearance(30, 30), -0.05, 1e-6);  // unknown
  EXPECT_NEAR(grid.clearance(9, 5), -0.05, 1e-6);
  // Unknown is no obstacle: the distance to obstacles runs to the grid's edge.
  EXPECT_NEAR(grid.obstacleDistance(12, 6), 0.65, 1e-6);  // the south edge, 7 cells away
}

TEST(NavigationGridTest, ObstacleDistancesAreExactUpToTheHorizonAndAtLeastItBeyond) {
  // 0.1 m cells: a free room (columns 5-34, rows 5-24) in unknown, a wall at column 20 in it and a
  // post far out in the unknown at (50, 15).
  TestGrid cells(60, 30);
  cells.free(5, 5, 34, 24).occupied(20, 5, 20, 12).occupied(50, 15, 50, 15);
  NavigationGridOptions options;
  options.distance_horizon_m = 0.5;
  const NavigationGrid grid(cells.grid(), {}, options);
  EXPECT_EQ(grid.freeCells(), cv::Rect(5, 5, 30, 20));
  // Beside the wall, 3 cells west of it: (3 - 0.5) x 0.1, as without a horizon.
  EXPECT_NEAR(grid.obstacleDistance(17, 8), 0.25, 1e-6);
  // Diagonally off the wall's end (20, 12): a hypotenuse of 3 and 4 cells.
  EXPECT_NEAR(grid.obstacleDistance(23, 16), 0.45, 1e-6);
  // Farther than the horizon from any obstacle or the grid's edge: at least the horizon.
  EXPECT_GE(grid.obstacleDistance(34, 15), 0.5f);
  EXPECT_GE(grid.obstacleDistance(10, 22), 0.5f);
  EXPECT_NEAR(grid.obstacleDistance(20, 8), -0.05, 1e-6);  // the wall itself
  // Without a horizon the far values are exact: from (34, 15) the wall's end (20, 12) is 14 and 3
  // cells away, nearer than the post (16 cells) and the grid's north edge (15 cells).
  const NavigationGrid exact(cells.grid(), {}, NavigationGridOptions{});
  EXPECT_NEAR(exact.obstacleDistance(34, 15), (std::sqrt(14.0 * 14.0 + 3.0 * 3.0) - 0.5) * 0.1, 1e-6);
  EXPECT_NEAR(exact.obstacleDistance(17, 8), 0.25, 1e-6);
  EXPECT_NEAR(exact.obstacleDistance(23, 16), 0.45, 1e-6);
}

// Every free cell of `updated` holds the distances `fresh` holds, where these are within the
// horizon, and at least the horizon where they are not.
void expectSameDistancesWithin(const NavigationGrid& updated, const NavigationGrid& fresh, double horizon_m) {
  for (int row = 0; row < fresh.height(); ++row) {
    for (int col = 0; col < fresh.width(); ++col) {
      if (fresh.cellClass(col, row) != NavigationGrid::kFree) continue;
      SCOPED_TRACE(testing::Message() << "cell " << col << ", " << row);
      if (fresh.clearance(col, row) < horizon_m) {
        EXPECT_EQ(updated.clearance(col, row), fresh.clearance(col, row));
      } else {
        EXPECT_GE(updated.clearance(col, row), horizon_m);
      }
      if (fresh.obstacleDistance(col, row) < horizon_m) {
        EXPECT_EQ(updated.obstacleDistance(col, row), fresh.obstacleDistance(col, row));
      } else {
        EXPECT_GE(updated.obstacleDistance(col, row), horizon_m);
      }
    }
  }
}

TEST(NavigationGridTest, AGridMadeAfterAnotherTakesAgainOnlyWhatChangedAndHoldsTheSameDistances) {
  // 0.1 m cells: a free room in unknown; then a new wall in it, a strip of it seen free beyond
  // and a pillar gone, and an obstacle speck that freeSpecks removes.
  TestGrid before(60, 40);
  before.free(5, 5, 44, 34).occupied(30, 20, 31, 21);
  TestGrid after(60, 40);
  after.free(5, 5, 54, 34).occupied(12, 5, 12, 18).occupied(40, 30, 40, 30);
  NavigationGridOptions options;
  options.distance_horizon_m = 0.5;
  const NavigationGrid updated(after.grid(), {}, options, {}, {},
                               std::make_unique<NavigationGrid>(before.grid(), std::vector<mrpt::poses::CPose2D>{}, options));
  const NavigationGrid fresh(after.grid(), {}, options);
  expectSameDistancesWithin(updated, fresh, 0.5);
  // Beside the new wall, 2 cells east of it, both say (2 - 0.5) x 0.1.
  EXPECT_NEAR(updated.obstacleDistance(14, 10), 0.15, 1e-6);
  EXPECT_NEAR(updated.clearance(14, 10), 0.15, 1e-6);
  // Where the pillar stood, nothing is near any more.
  EXPECT_GE(updated.obstacleDistance(30, 20), 0.5f);

  NavigationGrid specks_freed(after.grid(), {}, options, {}, {},
                              std::make_unique<NavigationGrid>(before.grid(), std::vector<mrpt::poses::CPose2D>{}, options));
  specks_freed.freeSpecks(1);
  NavigationGrid specks_freed_fresh(after.grid(), {}, options);
  specks_freed_fresh.freeSpecks(1);
  EXPECT_EQ(specks_freed.cellClass(40, 30), NavigationGrid::kFree);
  expectSameDistancesWithin(specks_freed, specks_freed_fresh, 0.5);
  EXPECT_GE(specks_freed.obstacleDistance(41, 30), 0.5f);
}

TEST(NavigationGridTest, AGridMadeAfterAnotherAddsTheNewPositionsAndSeenCellsToWhatItTookOver) {
  // 0.1 m cells, all unknown but an obstacle at (20, 20); the robot stood at (1, 1), then also
  // at (2, 2), beside the obstacle; it saw (0.45, 0.55) free, then also (2.55, 0.55).
  TestGrid cells(30, 30);
  cells.occupied(20, 20, 20, 20);
  NavigationGridOptions options;
  options.body_radius_m = 0.25;
  const std::vector<mrpt::poses::CPose2D> stood_before = {mrpt::poses::CPose2D(1.0, 1.0, 0.0)};
  const std::vector<mrpt::poses::CPose2D> stood = {mrpt::poses::CPose2D(1.0, 1.0, 0.0), mrpt::poses::CPose2D(2.0, 2.0, 0.0)};
  const std::vector<cv::Point2d> seen_before = {{0.45, 0.55}};
  const std::vector<cv::Point2d> seen = {{0.45, 0.55}, {2.55, 0.55}};
  const NavigationGrid updated(cells.grid(), stood, options, {}, seen,
                               std::make_unique<NavigationGrid>(cells.grid(), stood_before, options, std::vector<cv::Point2d>{},
                                                                seen_before));
  // A previous grid of other cells (before the map grew) is drawn afresh.
  TestGrid smaller(20, 20);
  const NavigationGrid regrown(cells.grid(), stood, options, {}, seen,
                               std::make_unique<NavigationGrid>(smaller.grid(), stood_before, options, std::vector<cv::Point2d>{},
                                                                seen_before));
  for (const NavigationGrid* grid : {&updated, &regrown}) {
    EXPECT_EQ(grid->cellClass(9, 9), NavigationGrid::kFree);     // under the body at (1, 1)
    EXPECT_EQ(grid->cellClass(19, 19), NavigationGrid::kFree);   // under the body at (2, 2)
    EXPECT_EQ(grid->cellClass(20, 20), NavigationGrid::kOccupied);
    EXPECT_EQ(grid->cellClass(17, 19), NavigationGrid::kUnknown);  // (1.75, 1.95): 0.255 m away
    EXPECT_EQ(grid->cellClass(4, 5), NavigationGrid::kFree);
    EXPECT_EQ(grid->cellClass(25, 5), NavigationGrid::kFree);
    EXPECT_EQ(grid->cellClass(24, 5), NavigationGrid::kUnknown);
  }
  const NavigationGrid fresh(cells.grid(), stood, options, {}, seen);
  EXPECT_EQ(cv::countNonZero(updated.cellClasses() != fresh.cellClasses()), 0);
  EXPECT_EQ(cv::countNonZero(regrown.cellClasses() != fresh.cellClasses()), 0);
}

TEST(NavigationGridTest, SmallUnknownIslandsInsideFreeSpaceAreFreeButNotThoseTouchingObstacles) {
  TestGrid cells(20, 20);
  cells.free(0, 0, 19, 19).unknown(5, 5, 6, 6).unknown(10, 5, 12, 6).unknown(15, 5, 15, 5).occupied(16, 5, 16, 5);
  NavigationGridOptions options;
  options.max_hole_cells = 4;
  const NavigationGrid grid(cells.grid(), {}, options);
  EXPECT_EQ(grid.cellClass(5, 5), NavigationGrid::kFree);      // 4 cells amid free cells
  EXPECT_EQ(grid.cellClass(10, 5), NavigationGrid::kUnknown);  // 6 cells: too large
  EXPECT_EQ(grid.cellClass(15, 5), NavigationGrid::kUnknown);  // beside an obstacle
  options.max_hole_cells = 0;
  EXPECT_EQ(NavigationGrid(cells.grid(), {}, options).cellClass(5, 5), NavigationGrid::kUnknown);
}

TEST(NavigationGridTest, UnknownNotchesInTheEdgeOfTheFreeFloorAreNoIslands) {
  TestGrid cells(30, 30);  // a free patch in unknown, with notches of unknown cells in its edges
  cells.free(5, 5, 20, 15).unknown(5, 9, 5, 9).unknown(12, 15, 13, 15).unknown(20, 7, 20, 7).unknown(10, 10, 11, 10);
  NavigationGridOptions options;
  options.max_hole_cells = 4;
  const NavigationGrid grid(cells.grid(), {}, options);
  EXPECT_EQ(grid.cellClass(5, 9), NavigationGrid::kUnknown);   // west edge: beyond it is unknown
  EXPECT_EQ(grid.cellClass(12, 15), NavigationGrid::kUnknown);  // north edge
  EXPECT_EQ(grid.cellClass(20, 7), NavigationGrid::kUnknown);   // east edge
  EXPECT_EQ(grid.cellClass(10, 10), NavigationGrid::kFree);     // a hole amid free cells
  EXPECT_EQ(grid.cellClass(11, 10), NavigationGrid::kFree);
}

TEST(NavigationGridTest, FreeingSpecksClearsLoneObstacleCellsOnlyAndTheClearanceWithThem) {
  TestGrid cells(30, 20);
  cells.free(0, 0, 29, 19)
      .occupied(3, 10, 3, 10)                          // one cell
      .occupied(8, 10, 9, 11).tag(8, 10, 9, 11, 1.0f)  // imprecise, 4 cells: too large
      .occupied(14, 10, 14, 10).occupied(15, 11, 15, 11)  // two cells, touching diagonally
      .occupied(20, 10, 20, 10).unknown(21, 10, 21, 10)   // beside unknown space
      .occupied(25, 0, 25, 0);                            // at the grid's edge
  NavigationGridOptions options;
  options.precise_min_disparity = 3.0f;
  NavigationGrid grid(cells.grid(), {}, options);
  EXPECT_NEAR(grid.clearance(3, 13), 0.25, 1e-6);
  grid.freeSpecks(2);
  EXPECT_EQ(grid.cellClass(3, 10), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(8, 10), NavigationGrid::kImprecise);
  EXPECT_EQ(grid.cellClass(14, 10), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(15, 11), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(20, 10), NavigationGrid::kOccupied);
  EXPECT_EQ(grid.cellClass(25, 0), NavigationGrid::kOccupied);
  // The nearest blocked cell to (3, 13) is now the grid's border beyond column 0, 3.5 cells from
  // its centre.
  EXPECT_NEAR(grid.clearance(3, 13), 0.35, 1e-6);
  EXPECT_NEAR(grid.obstacleDistance(3, 10), 0.35, 1e-6);
}

TEST(NavigationGridTest, SpecksHoldingAPointToKeepStay) {
  // Three lone specks in free floor; a point to keep (where the guard held the robot) lies in
  // the second, and another in one cell of the third, a two-cell island.
  TestGrid cells(30, 20);
  cells.free(0, 0, 29, 19).occupied(5, 10, 5, 10).occupied(15, 10, 15, 10).occupied(20, 10, 20, 10).occupied(21, 11, 21, 11);
  NavigationGrid grid(cells.grid(), {}, NavigationGridOptions());
  grid.freeSpecks(2, {{1.55, 1.05}, {2.14, 1.17}});
  EXPECT_EQ(grid.cellClass(5, 10), NavigationGrid::kFree);
  EXPECT_EQ(grid.cellClass(15, 10), NavigationGrid::kOccupied);
  EXPECT_EQ(grid.cellClass(20, 10), NavigationGrid::kOccupied);  // kept with the cell of its island
  EXPECT_EQ(grid.cellClass(21, 11), NavigationGrid::kOccupied);
  // Two cells north of the kept speck: 1.5 cells from its edge.
  EXPECT_NEAR(grid.clearance(15, 12), 0.15, 1e-6);
  // Where a freed speck stood, the nearest blocked cell is the grid's border beyond column 0.
  EXPECT_NEAR(grid.clearance(5, 12), 0.55, 1e-6);
}

TEST(NavigationGridTest, ObstaclesSeenOnlyAtLowDisparityAreImprecise) {
  TestGrid cells(20, 20);
  cells.free(0, 0, 19, 19).occupied(10, 0, 10, 19).tag(10, 0, 10, 9, 2.5f).tag(10, 10, 10, 19, 3.0f);
  NavigationGridOptions options;
  options.precise_min_disparity = 3.0f;
  const NavigationGrid grid(cells.grid(), {}, options);
  EXPECT_EQ(grid.cellClass(10, 5), NavigationGrid::kImprecise);
  EXPECT_EQ(grid.cellClass(10, 15), NavigationGrid::kOccupied);
  // Both block and repel alike.
  EXPECT_NEAR(grid.clearance(8, 5), 0.15, 1e-6);
  EXPECT_NEAR(grid.obstacleDistance(8, 5), 0.15, 1e-6);
}

TEST(NavigationGridTest, EveryOccupancyValueTakesThePapersClassAndOnlyLowDisparityObstaclesAreImprecise) {
  // Each row holds every value G = 0..255 and three more (a row's end after whole vectors), with
  // no tag, a tag below precise_min_disparity, and one at it.
  const int width = 259;
  TestGrid cells(width, 3);
  for (int col = 0; col < width; ++col) cells.fill(col, 0, col, 2, static_cast<uint8_t>(col % 256));
  cells.tag(0, 0, width - 1, 0, DisparityTaggedGrid::kNoTag).tag(0, 1, width - 1, 1, 2.5f).tag(0, 2, width - 1, 2, 3.0f);
  NavigationGridOptions options;
  options.precise_min_disparity = 3.0f;
  options.sure_obstacle_g = 200;
  const NavigationGrid grid(cells.grid(), {}, options);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < width; ++col) {
      const int g = col % 256;
      // Free below 50, occupied above 150 (paper section 3.4), unknown between.
      uint8_t expected = g < 50 ? NavigationGrid::kFree : g > 150 ? NavigationGrid::kOccupied : NavigationGrid::kUnknown;
      if (expected == NavigationGrid::kOccupied && row == 1) expected = NavigationGrid::kImprecise;
      EXPECT_EQ(grid.cellClass(col, row), expected) << "G " << g << ", row " << row;
      EXPECT_EQ(grid.mapHoldsObstacle(grid.centreX(col), grid.centreY(row)), g >= 200) << "G " << g << ", row " << row;
    }
  }
}

}  // namespace
}  // namespace stereonav
