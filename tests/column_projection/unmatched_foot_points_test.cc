#include "column_projection/unmatched_foot_points.h"

#include <gtest/gtest.h>

#include "test_scenes.h"

namespace stereonav {
namespace {

// A scan of testRig's 201 columns, each reading a far surface at disparity 2 (Z = 5 m), whose
// floor ends at an unmatched surface in `row` for the columns in `feet`.
DisparityScan scanWithFeet(const std::vector<int>& feet, int row) {
  DisparityScan scan;
  scan.column_disparity.assign(201, 2.0f);
  scan.column_row.assign(201, 40);
  scan.column_clear_end.assign(201, kInvalidDisparity);
  scan.column_clear_end_row.assign(201, -1);
  for (const int column : feet) {
    // On the floor plane a level camera 0.5 m up sees row y at Z = 0.5 / ((y - 50) / 100), d = 10 / Z;
    // a row that meets no floor gets a disparity all the same, which the row overrules.
    scan.column_clear_end[column] = row > 50 ? static_cast<float>((row - 50) / 5.0) : 1.0f;
    scan.column_clear_end_row[column] = row;
  }
  return scan;
}

TEST(UnmatchedFootPointsTest, OnePointWhereEachColumnsFloorEnds) {
  // Level camera 0.2 m ahead of the robot's centre, 0.5 m up. Row 75 looks 0.25 down per unit of
  // depth: it meets the floor at Z = 2 m, 2.2 m ahead of the centre; column x lies (100 - x) / 100
  // of the depth to the left.
  const auto points = unmatchedFootPoints(scanWithFeet({50, 100, 150}, 75), testRig(0.2, 0, 0, 0));
  ASSERT_EQ(points.size(), 3u);
  EXPECT_NEAR(points[0].x, 2.2, 1e-9);
  EXPECT_NEAR(points[0].y, 1.0, 1e-9);
  EXPECT_NEAR(points[1].x, 2.2, 1e-9);
  EXPECT_NEAR(points[1].y, 0.0, 1e-9);
  EXPECT_NEAR(points[2].x, 2.2, 1e-9);
  EXPECT_NEAR(points[2].y, -1.0, 1e-9);
  // Row 100 (0.5 down per unit of depth): Z = 1 m.
  const auto nearer = unmatchedFootPoints(scanWithFeet({100}, 100), testRig(0.2, 0, 0, 0));
  ASSERT_EQ(nearer.size(), 1u);
  EXPECT_NEAR(nearer[0].x, 1.2, 1e-9);
  EXPECT_NEAR(nearer[0].y, 0.0, 1e-9);
}

TEST(UnmatchedFootPointsTest, FollowsTheHeadsTilt) {
  // Tilted 30 degrees down, 0.1 m ahead: per unit of depth the centre row looks cos30 ahead and
  // sin30 down, so the floor is at Z = 1 m, 0.866 m ahead of the camera.
  const auto points = unmatchedFootPoints(scanWithFeet({100}, 50), testRig(0.1, 0, 0, 30));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].x, 0.1 + std::sqrt(3.0) / 2.0, 1e-9);
  EXPECT_NEAR(points[0].y, 0.0, 1e-9);
}

TEST(UnmatchedFootPointsTest, NoneWithoutFeet) {
  EXPECT_TRUE(unmatchedFootPoints(scanWithFeet({}, 75), testRig(0.2, 0, 0, 0)).empty());
  DisparityScan unchecked = scanWithFeet({100}, 75);
  unchecked.column_clear_end.clear();  // floor_end_clear_max_depth_m off
  unchecked.column_clear_end_row.clear();
  EXPECT_TRUE(unmatchedFootPoints(unchecked, testRig(0.2, 0, 0, 0)).empty());
  // A row level with the camera or above it meets no floor.
  EXPECT_TRUE(unmatchedFootPoints(scanWithFeet({100}, 50), testRig(0.2, 0, 0, 0)).empty());
}

}  // namespace
}  // namespace stereonav
