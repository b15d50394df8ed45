#include "explorer/escape_search.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_grids.h"

namespace stereonav {
namespace {

// A 4 m x 4 m room of free floor walled all round (columns and rows 0 and 39).
TestGrid room() {
  TestGrid cells(40, 40);
  cells.occupied(0, 0, 39, 39).free(1, 1, 38, 38);
  return cells;
}

CostToGoOptions bodyOf(double radius) {
  CostToGoOptions options;
  options.body_radius_m = radius;
  return options;
}

TEST(EscapeSearchTest, FindsTheNearestCellWhereTheBodyFits) {
  const TestGrid cells = room();
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  const CostToGoField field(grid, bodyOf(0.4));
  // Against the west wall, in the room's middle row: the body does not fit there.
  ASSERT_FALSE(field.traversable(2, 20));
  const std::optional<cv::Point2d> escape = findEscape(grid, field, 2, 20, 1.5, {}, 0.3);
  ASSERT_TRUE(escape.has_value());
  // Straight east along the row, at the first column where the body fits.
  int first_fitting = 2;
  while (!field.traversable(first_fitting, 20)) ++first_fitting;
  EXPECT_NEAR(escape->x, grid.centreX(first_fitting), 1e-9);
  EXPECT_NEAR(escape->y, grid.centreY(20), 1e-9);
}

TEST(EscapeSearchTest, SkipsCellsNearEscapesThatFailedAndGivesUpBeyondTheSearchRange) {
  const TestGrid cells = room();
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  const CostToGoField field(grid, bodyOf(0.4));
  const std::optional<cv::Point2d> first = findEscape(grid, field, 2, 20, 1.5, {}, 0.3);
  ASSERT_TRUE(first.has_value());
  const std::optional<cv::Point2d> second = findEscape(grid, field, 2, 20, 1.5, {*first}, 0.3);
  ASSERT_TRUE(second.has_value());
  EXPECT_GE(std::hypot(second->x - first->x, second->y - first->y), 0.3);
  // Within 0.1 m nothing fits.
  EXPECT_FALSE(findEscape(grid, field, 2, 20, 0.1, {}, 0.3).has_value());
}

TEST(EscapeSearchTest, NeverCrossesAnObstacleOrUnknownSpace) {
  TestGrid cells = room();
  // A pen 0.7 m across around the robot: free inside, walls all round.
  cells.occupied(15, 15, 23, 15).occupied(15, 23, 23, 23).occupied(15, 15, 15, 23).occupied(23, 15, 23, 23);
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  const CostToGoField field(grid, bodyOf(0.4));
  EXPECT_FALSE(findEscape(grid, field, 19, 19, 1.5, {}, 0.3).has_value());
}

}  // namespace
}  // namespace stereonav
