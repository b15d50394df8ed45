#include "explorer/near_obstacle_memory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stereonav {
namespace {

bool everywhere(double, double) { return true; }

// A scan seeing a wall across the view at x = `distance` (robot frame), points every 5 cm over
// y in [-1, 1], with a gap where a nearer obstacle hides the wall.
std::vector<mrpt::math::TPoint2D> wallScan(double distance, double hidden_from_y = 1.0, double hidden_to_y = -1.0) {
  std::vector<mrpt::math::TPoint2D> scan;
  for (int i = -20; i <= 20; ++i) {
    const double y = 0.05 * i;
    if (y >= hidden_from_y && y <= hidden_to_y) continue;
    scan.emplace_back(distance, y);
  }
  return scan;
}

// Map points as a robot at `pose` sees them.
std::vector<mrpt::math::TPoint2D> seenFrom(const mrpt::poses::CPose2D& pose, const std::vector<mrpt::math::TPoint2D>& map_points) {
  std::vector<mrpt::math::TPoint2D> scan;
  for (const auto& point : map_points) scan.push_back(pose.inverseComposePoint(point));
  return scan;
}

// A 0.4 m wide obstacle face at x = 1.5 (map frame), points 5 cm apart.
std::vector<mrpt::math::TPoint2D> faceAt(double x) {
  std::vector<mrpt::math::TPoint2D> face;
  for (int i = -4; i <= 4; ++i) face.emplace_back(x, 0.05 * i);
  return face;
}

// The robot sees `map_points` from (0, 0) and from (0.3, 0), facing +x: two places.
void seeFromTwoPlaces(NearObstacleMemory& memory, const std::vector<mrpt::math::TPoint2D>& map_points) {
  for (const double x : {0.0, 0.3}) {
    const mrpt::poses::CPose2D pose(x, 0.0, 0.0);
    memory.update(seenFrom(pose, map_points), pose, everywhere);
  }
}

TEST(NearObstacleMemory, KeepsPointsSeenUpCloseFromTwoPlacesInTheMapFrame) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  // A chair seat 1.5 m ahead of a robot at (2, 3) facing +y; a wall 4 m ahead is too far to keep.
  std::vector<mrpt::math::TPoint2D> map_points;
  for (int i = -4; i <= 4; ++i) map_points.emplace_back(2.0 + 0.05 * i, 4.5);
  for (int i = -20; i <= 20; ++i) map_points.emplace_back(2.0 + 0.05 * i, 7.0);
  const mrpt::poses::CPose2D first(2.0, 3.0, M_PI / 2), turned(2.0, 3.0, M_PI / 2 + 0.2),
      second(2.0, 3.4, M_PI / 2);
  memory.update(seenFrom(first, map_points), first, everywhere);
  // Turning on the spot the robot sees the same noise again and again: one place is not enough.
  memory.update(seenFrom(turned, map_points), turned, everywhere);
  EXPECT_EQ(memory.size(), 0u);
  memory.update(seenFrom(second, map_points), second, everywhere);
  const auto points = memory.points();
  ASSERT_EQ(points.size(), 9u);
  for (const auto& point : points) {
    EXPECT_NEAR(point.y, 4.5, 1e-9);
    EXPECT_NEAR(point.x, 2.0, 0.2 + 1e-9);
  }
}

TEST(NearObstacleMemory, FarViewsThatSeeUnderItDoNotForgetIt) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  seeFromTwoPlaces(memory, faceAt(1.2));
  ASSERT_EQ(memory.size(), 9u);
  // From 3 m back the scan sees the wall behind (at x = 4) through the seat: beyond the range
  // in which a view may judge (2 m), so the seat is kept.
  memory.update(wallScan(7.0), mrpt::poses::CPose2D(-3.0, 0.0, 0.0), everywhere);
  EXPECT_EQ(memory.size(), 9u);
  // Right next to it (0.5 m, below the view of the tilted cameras), the scan sees past it too:
  // kept as well.
  memory.update(wallScan(3.3), mrpt::poses::CPose2D(0.7, 0.0, 0.0), everywhere);
  EXPECT_EQ(memory.size(), 9u);
}

TEST(NearObstacleMemory, AViewFromNearbyThatSeesPastItForgetsIt) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  seeFromTwoPlaces(memory, faceAt(1.5));
  ASSERT_EQ(memory.size(), 9u);
  // The person has walked on: from where the robot stood, the scan sees the wall at 4 m.
  memory.update(wallScan(4.0), mrpt::poses::CPose2D(0.0, 0.0, 0.0), everywhere);
  EXPECT_EQ(memory.size(), 0u);
}

TEST(NearObstacleMemory, ABearingTheScanSawNothingAlongIsNoEvidenceOfAbsence) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  seeFromTwoPlaces(memory, {{1.5, 0.0}});
  ASSERT_EQ(memory.size(), 1u);
  // The next scan matched nothing in the middle of the view (textureless), the wall elsewhere.
  memory.update(wallScan(4.0, -0.5, 0.5), mrpt::poses::CPose2D(0.0, 0.0, 0.0), everywhere);
  EXPECT_EQ(memory.size(), 1u);
}

TEST(NearObstacleMemory, KeepsOnlyWhatTheMapConfirms) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  // The map holds an obstacle only beyond x = 1.4.
  const std::vector<mrpt::math::TPoint2D> map_points{{1.0, 0.0}, {1.2, 0.5}, {1.5, -0.3}, {1.8, 0.2}};
  for (const double x : {0.0, 0.3}) {
    const mrpt::poses::CPose2D pose(x, 0.0, 0.0);
    memory.update(seenFrom(pose, map_points), pose, [](double px, double) { return px > 1.4; });
  }
  const auto points = memory.points();
  ASSERT_EQ(points.size(), 2u);
  for (const auto& point : points) EXPECT_GT(point.x, 1.4);
}

TEST(NearObstacleMemory, WhatStoppedTheRobotIsRememberedAtOnceUntilSeenPast) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  memory.remember({{1.5, 0.0}, {1.52, 0.0}, {1.5, 0.1}});
  EXPECT_EQ(memory.size(), 2u);  // one point per 5 cm cell
  memory.update(wallScan(4.0), mrpt::poses::CPose2D(0.0, 0.0, 0.0), [](double, double) { return false; });
  EXPECT_EQ(memory.size(), 0u);
}

TEST(NearObstacleMemory, ForgetsWhatTheMapNoLongerHolds) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  memory.remember({{1.0, 0.0}, {2.0, 0.0}, {3.0, 0.0}});
  EXPECT_EQ(memory.forgetUnconfirmed([](double x, double) { return x > 1.5; }), 1u);
  const auto points = memory.points();
  ASSERT_EQ(points.size(), 2u);
  for (const auto& point : points) EXPECT_GT(point.x, 1.5);
}

}  // namespace
}  // namespace stereonav
