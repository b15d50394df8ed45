#include "column_projection/blind_column_points.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_scenes.h"

namespace stereonav {
namespace {

// A scan of testRig's 201 columns that saw no obstacle, blind in columns [first, last].
DisparityScan blindScan(int first, int last) {
  DisparityScan scan;
  scan.column_disparity.assign(201, kInvalidDisparity);
  scan.column_row.assign(201, -1);
  scan.column_blind.assign(201, 0);
  for (int column = first; column <= last; ++column) scan.column_blind[column] = 1;
  return scan;
}

// The camera 0.1 m ahead of the robot's centre, 0.5 m up, tilted 30 degrees down. Its bottom row
// (v = 0.5) looks, per unit of camera depth, cos30 - 0.5 sin30 = 0.616 ahead, -u to the left and
// sin30 + 0.5 cos30 = 0.933 down: it meets the floor at depth 0.5 / 0.933 = 0.536 m, 0.330 m
// ahead of the camera and -0.536 u to the left. Ahead of a 0.3 m body: |u| <= 0.3 / 0.536, the
// 111 columns 45..155.
CameraRig tiltedRig() { return testRig(0.1, 0, 0, 30); }

TEST(BlindColumnPointsTest, OnePointJustInsideTheBodysFrontPerBlindColumnAheadOfTheBody) {
  const auto points = blindColumnPoints(blindScan(0, 200), tiltedRig(), 0.3);
  ASSERT_EQ(points.size(), 111u);
  // Column 100 looks straight ahead: 0.02 m inside the body's edge.
  EXPECT_NEAR(points[100 - 45].x, 0.28, 1e-9);
  EXPECT_NEAR(points[100 - 45].y, 0.0, 1e-9);
  // Column 150 (u = 0.5): on the line from the camera (0.1, 0) along (0.616, -0.5), 0.28 m from
  // the robot's centre.
  const mrpt::math::TPoint2D right = points[150 - 45];
  const double forward_per_depth = std::sqrt(3.0) / 2.0 - 0.25;
  EXPECT_NEAR(std::hypot(right.x, right.y), 0.28, 1e-9);
  EXPECT_NEAR((right.x - 0.1) * -0.5 - right.y * forward_per_depth, 0.0, 1e-9);
  EXPECT_GT(right.x, 0.1);
  EXPECT_LT(right.y, 0.0);
  // Ahead of a body 0.5 m wide a side: |u| <= 0.5 / 0.536, columns 7..193.
  EXPECT_EQ(blindColumnPoints(blindScan(0, 200), tiltedRig(), 0.5).size(), 187u);
}

TEST(BlindColumnPointsTest, NoneWhileMostOfTheFloorAheadIsSeen) {
  // 56 of the 111 columns ahead blind: more than half.
  EXPECT_EQ(blindColumnPoints(blindScan(45, 100), tiltedRig(), 0.3).size(), 56u);
  // 55 of 111, a door jamb beside the path: none.
  EXPECT_TRUE(blindColumnPoints(blindScan(45, 99), tiltedRig(), 0.3).empty());
  // Columns beside the body do not count.
  EXPECT_TRUE(blindColumnPoints(blindScan(0, 44), tiltedRig(), 0.3).empty());
  DisparityScan unchecked = blindScan(0, 200);
  unchecked.column_blind.clear();  // near_floor_m off
  EXPECT_TRUE(blindColumnPoints(unchecked, tiltedRig(), 0.3).empty());
}

}  // namespace
}  // namespace stereonav
