#include "localization/obstacle_distance_field.h"

#include <gtest/gtest.h>

#include "hand_drawn_map.h"

namespace stereonav {
namespace {

TEST(ObstacleDistanceFieldTest, DistancesToTheNearestOccupiedCellCapped) {
  // A wall along x = 1.085: in the cells [1.05, 1.10), whose centres are at x = 1.075.
  const DisparityTaggedGrid grid = testing::drawGrid({{1.085, -2.0, 1.085, 2.0}}, -3.0, 3.0, 0.05);
  const ObstacleDistanceField field(grid, 0.5);
  EXPECT_TRUE(field.hasObstacles());
  EXPECT_NEAR(field.distance(1.075, 0.025), 0.0, 1e-4);
  EXPECT_NEAR(field.distance(0.875, 0.025), 0.2, 1e-3);
  EXPECT_NEAR(field.distance(1.275, 0.525), 0.2, 1e-3);
  // Between cell centres the distance is interpolated.
  EXPECT_NEAR(field.distance(0.85, 0.025), 0.225, 1e-3);
  EXPECT_NEAR(field.distance(-1.0, 0.0), 0.5, 1e-6);  // capped
  EXPECT_DOUBLE_EQ(field.distance(10.0, 0.0), 0.5);  // outside the grid
}

TEST(ObstacleDistanceFieldTest, AGridWithoutObstaclesIsFarEverywhere) {
  const ObstacleDistanceField field(testing::drawGrid({}, -1.0, 1.0, 0.1), 0.7);
  EXPECT_FALSE(field.hasObstacles());
  EXPECT_NEAR(field.distance(0.0, 0.0), 0.7, 1e-6);
}

}  // namespace
}  // namespace stereonav
