#include "explorer/frontier_finder.h"

#include <gtest/gtest.h>

#include "test_grids.h"

namespace stereonav {
namespace {

TEST(FrontierFinderTest, FreeSquareInUnknownHasItsWholeBorderAsOneFrontier) {
  TestGrid cells(20, 20);
  cells.free(5, 5, 9, 9);  // 5 x 5 cells: 16 border cells, 9 inner ones
  const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(cells.grid(), {}, NavigationGridOptions{}), 1);
  ASSERT_EQ(frontiers.size(), 1u);
  EXPECT_EQ(frontiers[0].cells.size(), 16u);
  for (const cv::Point& cell : frontiers[0].cells) {
    EXPECT_TRUE(cell.x == 5 || cell.x == 9 || cell.y == 5 || cell.y == 9) << cell;
  }
  // Centre of the square: cells 5..9 -> 0.5 .. 1.0 m, centre 0.75.
  EXPECT_NEAR(frontiers[0].centroid_x, 0.75, 1e-9);
  EXPECT_NEAR(frontiers[0].centroid_y, 0.75, 1e-9);
}

TEST(FrontierFinderTest, AFrontierKnowsHowMuchUnseenSpaceLiesBehindIt) {
  // A walled 2 m x 2 m room (cells 1..20) with a 4 x 4 cell unknown pocket in it (a desk's
  // shadow) and a 5-cell door in its east wall (col 21, rows 8..12), unknown, to the unknown
  // space around: 416 cells, the 30 x 30 grid less the room and its walls (22 x 22).
  TestGrid cells(30, 30);
  cells.occupied(0, 0, 21, 21).free(1, 1, 20, 20).unknown(5, 5, 8, 8).unknown(21, 8, 21, 12);
  const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(cells.grid(), {}, NavigationGridOptions{}), 1);
  ASSERT_EQ(frontiers.size(), 2u);
  // Largest first: the pocket's ring (16 cells) before the door (5 cells).
  EXPECT_EQ(frontiers[0].cells.size(), 16u);
  EXPECT_NEAR(frontiers[0].unseen_area_m2, 16 * 0.01, 1e-9);
  EXPECT_EQ(frontiers[1].cells.size(), 5u);
  EXPECT_NEAR(frontiers[1].unseen_area_m2, (900 - 22 * 22 + 5) * 0.01, 1e-9);
  EXPECT_TRUE(frontiers[0].borders_unknown);
  EXPECT_TRUE(frontiers[1].borders_unknown);
}

TEST(FrontierFinderTest, TheUnseenSpaceBehindAFrontierReachesThePartsOfTheGridTheMapNeverWrote) {
  // A 10 x 10 cell free block in a 60 x 40 grid of 0.1 m cells; the map wrote nothing else, so
  // its frontier (the block's border) faces every other cell.
  const auto unseen_area = [](const TestGrid& cells) {
    const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(cells.grid(), {}, NavigationGridOptions{}), 1);
    EXPECT_EQ(frontiers.size(), 1u);
    return frontiers.empty() ? 0.0 : frontiers[0].unseen_area_m2;
  };
  TestGrid alone(60, 40);
  alone.free(20, 10, 29, 19);
  EXPECT_NEAR(unseen_area(alone), (60 * 40 - 100) * 0.01, 1e-9);
  // A wall across the whole grid at row 25 cuts off the 14 rows above it.
  TestGrid wall_across(60, 40);
  wall_across.free(20, 10, 29, 19).occupied(0, 25, 59, 25);
  EXPECT_NEAR(unseen_area(wall_across), (60 * 25 - 100) * 0.01, 1e-9);
  // A wall up the whole grid at column 45 cuts off the 14 columns right of it.
  TestGrid wall_up(60, 40);
  wall_up.free(20, 10, 29, 19).occupied(45, 0, 45, 39);
  EXPECT_NEAR(unseen_area(wall_up), (45 * 40 - 100) * 0.01, 1e-9);
}

TEST(FrontierFinderTest, CellsBesideAnObstacleAreNotFrontier) {
  TestGrid cells(20, 20);
  cells.free(5, 5, 9, 9).occupied(10, 4, 10, 10);
  const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(cells.grid(), {}, NavigationGridOptions{}), 1);
  ASSERT_EQ(frontiers.size(), 1u);
  // The east side (col 9) only touches the wall, except its corners which touch unknown above/below.
  EXPECT_EQ(frontiers[0].cells.size(), 16u - 3u);
  for (const cv::Point& cell : frontiers[0].cells) EXPECT_FALSE(cell.x == 9 && cell.y > 5 && cell.y < 9) << cell;
}

TEST(FrontierFinderTest, ClosedRoomHasNoFrontier) {
  TestGrid cells(20, 20);
  cells.occupied(4, 4, 12, 12).free(5, 5, 11, 11);
  EXPECT_TRUE(findFrontiers(NavigationGrid(cells.grid(), {}, NavigationGridOptions{}), 1).empty());
}

TEST(FrontierFinderTest, SeparateOpeningsAreSeparateFrontiersLargestFirstAndSmallOnesDropped) {
  TestGrid cells(30, 20);
  // A closed room with a 5-cell doorway on its west wall and a 1-cell hole in its east wall.
  cells.occupied(4, 4, 20, 14).free(5, 5, 19, 13).unknown(4, 7, 4, 11).unknown(20, 9, 20, 9);
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
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

TEST(FrontierFinderTest, FreeCellsBesideAnObstacleSeenOnlyFromFarAreFrontier) {
  TestGrid cells(20, 20);
  cells.occupied(4, 4, 12, 12).free(5, 5, 11, 11);
  cells.tag(4, 4, 12, 12, 8.0f).tag(12, 6, 12, 8, 2.0f);  // the east wall's middle: disparity 2
  NavigationGridOptions options;
  options.precise_min_disparity = 3.0f;
  const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(cells.grid(), {}, options), 1);
  ASSERT_EQ(frontiers.size(), 1u);
  ASSERT_EQ(frontiers[0].cells.size(), 3u);
  for (const cv::Point& cell : frontiers[0].cells) EXPECT_EQ(cell.x, 11);
  // Behind the wall lies unknown space, but the frontier itself only faces the wall.
  EXPECT_FALSE(frontiers[0].borders_unknown);
  EXPECT_GT(frontiers[0].unseen_area_m2, 1.0);
  options.precise_min_disparity = 0.0f;
  EXPECT_TRUE(findFrontiers(NavigationGrid(cells.grid(), {}, options), 1).empty());
}

TEST(FrontierFinderTest, AThinUnresolvedSeamAlongAPinnedDownWallIsNotAFrontier) {
  // A closed room (walls cols/rows 4 and 12, precise) with unresolved cells along its east wall,
  // rows 6..10, one or two cells deep (cols 11, or 10 and 11): a seam between the free floor and
  // the wall, not an opening.
  NavigationGridOptions options;
  options.precise_min_disparity = 3.0f;
  const auto room = [] {
    TestGrid cells(20, 20);
    cells.occupied(4, 4, 12, 12).tag(4, 4, 12, 12, 8.0f).free(5, 5, 11, 11);
    return cells;
  };
  TestGrid one_deep = room();
  one_deep.unknown(11, 6, 11, 10);
  EXPECT_TRUE(findFrontiers(NavigationGrid(one_deep.grid(), {}, options), 1).empty());
  TestGrid two_deep = room();
  two_deep.unknown(10, 6, 11, 10);
  EXPECT_TRUE(findFrontiers(NavigationGrid(two_deep.grid(), {}, options), 1).empty());
  // Three deep (cols 9..11) the middle column is 2 cells from anything resolved: not a seam.
  TestGrid three_deep = room();
  three_deep.unknown(9, 6, 11, 10);
  EXPECT_EQ(findFrontiers(NavigationGrid(three_deep.grid(), {}, options), 1).size(), 1u);
  // The same one-deep band with the wall behind it gone joins the unknown outside: an opening,
  // faced by col 10 (rows 6..10) and the band's ends (col 11, rows 5 and 11).
  TestGrid open = room();
  open.unknown(11, 6, 12, 10);
  const std::vector<Frontier> frontiers = findFrontiers(NavigationGrid(open.grid(), {}, options), 1);
  ASSERT_EQ(frontiers.size(), 1u);
  ASSERT_EQ(frontiers[0].cells.size(), 7u);
  for (const cv::Point& cell : frontiers[0].cells) {
    EXPECT_TRUE((cell.x == 10 && cell.y >= 6 && cell.y <= 10) || (cell.x == 11 && (cell.y == 5 || cell.y == 11)))
        << cell;
  }
}

}  // namespace
}  // namespace stereonav
