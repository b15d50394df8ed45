#include "column_projection/range_top_points.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_scenes.h"

namespace stereonav {
namespace {

// A scan of testRig's 201 columns, all in row `row`, reading a far surface at disparity 2
// (Z = 5 m) except `near` columns, which read `near_disparity`; the matcher searched up to 20
// (f B / 20 = 0.5 m).
DisparityScan scanReading(const std::vector<int>& near, float near_disparity, int row) {
  DisparityScan scan;
  scan.column_disparity.assign(201, 2.0f);
  scan.column_row.assign(201, row);
  for (const int column : near) scan.column_disparity[column] = near_disparity;
  scan.range_top = 20.0f;
  return scan;
}

TEST(RangeTopPointsTest, OnePointPerColumnReadAtTheTopAtItsBoundDepth) {
  // Level camera 0.2 m ahead of the robot's centre: a column read at d = 20 puts its surface
  // 0.5 m ahead of the camera, and column x (100 - x) / 100 of that to the left.
  const auto points = rangeTopPoints(scanReading({50, 100, 150}, 20.0f, 50), testRig(0.2, 0, 0, 0));
  ASSERT_EQ(points.size(), 3u);
  EXPECT_NEAR(points[0].x, 0.7, 1e-9);
  EXPECT_NEAR(points[0].y, 0.25, 1e-9);
  EXPECT_NEAR(points[1].x, 0.7, 1e-9);
  EXPECT_NEAR(points[1].y, 0.0, 1e-9);
  EXPECT_NEAR(points[2].x, 0.7, 1e-9);
  EXPECT_NEAR(points[2].y, -0.25, 1e-9);
}

TEST(RangeTopPointsTest, FollowsTheHeadsTilt) {
  // Tilted 30 degrees down, 0.1 m ahead: the centre pixel's ray goes cos30 ahead per unit of depth.
  const auto points = rangeTopPoints(scanReading({100}, 20.0f, 50), testRig(0.1, 0, 0, 30));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].x, 0.1 + 0.5 * std::sqrt(3.0) / 2.0, 1e-9);
  EXPECT_NEAR(points[0].y, 0.0, 1e-9);
}

TEST(RangeTopPointsTest, NoneBelowTheTopOrWithoutIt) {
  EXPECT_TRUE(rangeTopPoints(scanReading({100}, 19.5f, 50), testRig(0.2, 0, 0, 0)).empty());
  DisparityScan unknown_top = scanReading({100}, 20.0f, 50);
  unknown_top.range_top = kInvalidDisparity;
  EXPECT_TRUE(rangeTopPoints(unknown_top, testRig(0.2, 0, 0, 0)).empty());
  DisparityScan invalid = scanReading({100}, kInvalidDisparity, 50);
  EXPECT_TRUE(rangeTopPoints(invalid, testRig(0.2, 0, 0, 0)).empty());
  DisparityScan no_rows = scanReading({100}, 20.0f, 50);
  no_rows.column_row.clear();
  EXPECT_TRUE(rangeTopPoints(no_rows, testRig(0.2, 0, 0, 0)).empty());
}

}  // namespace
}  // namespace stereonav
