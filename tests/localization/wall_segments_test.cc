#include "localization/wall_segments.h"

#include <gtest/gtest.h>

#include <mrpt/core/bits_math.h>

#include <algorithm>

#include "hand_drawn_map.h"

namespace stereonav {
namespace {

double lineAngle(double a) {
  double d = std::remainder(a, M_PI);
  return d >= M_PI / 2 ? d - M_PI : d;
}

TEST(WallSegmentsTest, AWallAheadIsOneSegmentAcrossTheRobotsHeading) {
  // The wall x = 1.5 runs along 90 degrees in the world; seen by a robot heading 20 degrees, it
  // runs along 70 degrees in the robot's frame.
  const std::vector<testing::Segment> wall = {{1.5, -3.0, 1.5, 3.0}};
  const mrpt::poses::CPose2D robot(0.0, 0.0, mrpt::DEG2RAD(20.0));
  WallSegmentOptions options;
  const std::vector<WallSegment> segments = wallSegments(testing::scanOf(wall, robot), options);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_NEAR(segments[0].direction_rad, mrpt::DEG2RAD(70.0), mrpt::DEG2RAD(0.1));
  // The 90 degree field of view spans bearings -25..65 degrees, so the wall from y = 1.5 tan(-25
  // deg) = -0.70 on, up to where it leaves max_range_m (2.5 m): y = sqrt(2.5^2 - 1.5^2) = 2.
  EXPECT_NEAR(segments[0].length_m, 2.7, 0.05);
  EXPECT_LT(segments[0].sigma_rad, mrpt::DEG2RAD(0.1));
  // The wall lies 1.5 m along world +x: -20 degrees in the robot's frame. The readings' centroid
  // is on it, 1.5 m along that normal.
  EXPECT_NEAR(segments[0].normal_rad, mrpt::DEG2RAD(-20.0), mrpt::DEG2RAD(0.1));
  const double normal = segments[0].normal_rad;
  EXPECT_NEAR(std::cos(normal) * segments[0].centroid.x + std::sin(normal) * segments[0].centroid.y, 1.5, 0.005);
  EXPECT_LT(segments[0].centroid_sigma_m, 0.005);
  // Its ends, back in the world, lie on the wall at y = -0.70 and y = 2.
  const mrpt::poses::CPose2D first = robot + mrpt::poses::CPose2D(segments[0].first.x, segments[0].first.y, 0.0);
  const mrpt::poses::CPose2D last = robot + mrpt::poses::CPose2D(segments[0].last.x, segments[0].last.y, 0.0);
  EXPECT_NEAR(first.x(), 1.5, 0.005);
  EXPECT_NEAR(first.y(), 1.5 * std::tan(mrpt::DEG2RAD(-25.0)), 0.05);
  EXPECT_NEAR(last.x(), 1.5, 0.005);
  EXPECT_NEAR(last.y(), 2.0, 0.05);
}

TEST(WallSegmentsTest, ReadingsThatShareTheirErrorsGiveWiderSigmas) {
  // The same noisy wall: readings that share their errors over 9 neighbours (a stereo scan's
  // SAD window) count as a ninth as many, so both sigmas are 3 times wider.
  const std::vector<testing::Segment> wall = {{1.5, -3.0, 1.5, 3.0}};
  mrpt::obs::CObservation2DRangeScan scan = testing::scanOf(wall, mrpt::poses::CPose2D());
  for (size_t ray = 0; ray < scan.getScanSize(); ray += 2) scan.setScanRange(ray, scan.getScanRange(ray) - 0.02f);
  WallSegmentOptions correlated;
  correlated.correlated_readings = 9;
  const std::vector<WallSegment> independent = wallSegments(scan, WallSegmentOptions{});
  const std::vector<WallSegment> shared = wallSegments(scan, correlated);
  ASSERT_EQ(independent.size(), 1u);
  ASSERT_EQ(shared.size(), 1u);
  EXPECT_NEAR(shared[0].direction_rad, independent[0].direction_rad, 1e-12);
  EXPECT_NEAR(shared[0].sigma_rad, 3.0 * independent[0].sigma_rad, 1e-9);
  EXPECT_NEAR(shared[0].centroid_sigma_m, 3.0 * independent[0].centroid_sigma_m, 1e-9);
}

TEST(WallSegmentsTest, ACornerSplitsIntoItsTwoWalls) {
  // The corner of a room at (1.5, 1.5), seen from the origin looking at it: the walls y = 1.5
  // and x = 1.5, each along a world axis.
  const std::vector<testing::Segment> corner = {{-1.0, 1.5, 1.5, 1.5}, {1.5, 1.5, 1.5, -1.0}};
  const mrpt::poses::CPose2D robot(0.0, 0.0, mrpt::DEG2RAD(45.0));
  const std::vector<WallSegment> segments = wallSegments(testing::scanOf(corner, robot), WallSegmentOptions{});
  ASSERT_EQ(segments.size(), 2u);
  for (const WallSegment& segment : segments) {
    // Along a world axis: 45 degrees off the robot's heading either way.
    EXPECT_NEAR(std::abs(lineAngle(segment.direction_rad)), mrpt::DEG2RAD(45.0), mrpt::DEG2RAD(0.1));
  }
  EXPECT_NEAR(std::abs(lineAngle(segments[0].direction_rad - segments[1].direction_rad)), M_PI / 2,
              mrpt::DEG2RAD(0.2));
}

TEST(WallSegmentsTest, AGapOrAShortStretchGivesNoSegment) {
  // Two 0.4 m stubs with a 1 m gap between them: each shorter than min_length_m (0.6 m), and the
  // gap keeps them from counting as one wall.
  const std::vector<testing::Segment> stubs = {{1.5, -0.9, 1.5, -0.5}, {1.5, 0.5, 1.5, 0.9}};
  const mrpt::poses::CPose2D robot(0.0, 0.0, 0.0);
  EXPECT_TRUE(wallSegments(testing::scanOf(stubs, robot), WallSegmentOptions{}).empty());

  WallSegmentOptions bridging;
  bridging.max_gap_m = 1.5;
  EXPECT_EQ(wallSegments(testing::scanOf(stubs, robot), bridging).size(), 1u);
}

TEST(WallSegmentsTest, ScatteredReadingsGiveAWiderSigma) {
  // The same wall with every other reading 4 cm nearer: still one segment (within the split
  // tolerance of 5 cm), its direction unchanged, its sigma wider than a clean wall's.
  const std::vector<testing::Segment> wall = {{1.5, -3.0, 1.5, 3.0}};
  const mrpt::poses::CPose2D robot(0.0, 0.0, 0.0);
  const mrpt::obs::CObservation2DRangeScan clean = testing::scanOf(wall, robot);
  mrpt::obs::CObservation2DRangeScan noisy = clean;
  for (size_t ray = 0; ray < noisy.getScanSize(); ray += 2) {
    noisy.setScanRange(ray, noisy.getScanRange(ray) - 0.04f);
  }
  const std::vector<WallSegment> a = wallSegments(clean, WallSegmentOptions{});
  const std::vector<WallSegment> b = wallSegments(noisy, WallSegmentOptions{});
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(b[0].direction_rad, a[0].direction_rad, mrpt::DEG2RAD(0.5));
  EXPECT_GT(b[0].sigma_rad, 5.0 * a[0].sigma_rad);
}

}  // namespace
}  // namespace stereonav
