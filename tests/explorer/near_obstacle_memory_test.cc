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

TEST(NearObstacleMemory, KeepsPointsSeenUpCloseInTheMapFrameOnly) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  // A chair seat 1.5 m ahead of a robot at (2, 3) facing +y; a wall 4 m ahead is too far to keep.
  std::vector<mrpt::math::TPoint2D> scan = wallScan(4.0, -0.2, 0.2);
  for (double y = -0.2; y <= 0.2 + 1e-9; y += 0.05) scan.emplace_back(1.5, y);
  memory.update(scan, mrpt::poses::CPose2D(2.0, 3.0, M_PI / 2), everywhere);
  const auto points = memory.points();
  ASSERT_EQ(points.size(), 9u);
  for (const auto& point : points) {
    EXPECT_NEAR(point.y, 4.5, 1e-9);  // 1.5 m ahead of y = 3
    EXPECT_NEAR(point.x, 2.0, 0.2 + 1e-9);
  }
}

TEST(NearObstacleMemory, FarViewsThatSeeUnderItDoNotForgetIt) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  std::vector<mrpt::math::TPoint2D> close_view;
  for (double y = -0.2; y <= 0.2 + 1e-9; y += 0.05) close_view.emplace_back(1.2, y);
  memory.update(close_view, mrpt::poses::CPose2D(0.0, 0.0, 0.0), everywhere);
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
  std::vector<mrpt::math::TPoint2D> person;
  for (double y = -0.2; y <= 0.2 + 1e-9; y += 0.05) person.emplace_back(1.5, y);
  memory.update(person, mrpt::poses::CPose2D(0.0, 0.0, 0.0), everywhere);
  ASSERT_EQ(memory.size(), 9u);
  // The person has walked on: from where the robot stood, the scan sees the wall at 4 m.
  memory.update(wallScan(4.0), mrpt::poses::CPose2D(0.0, 0.0, 0.0), everywhere);
  EXPECT_EQ(memory.size(), 0u);
}

TEST(NearObstacleMemory, ABearingTheScanSawNothingAlongIsNoEvidenceOfAbsence) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  std::vector<mrpt::math::TPoint2D> post{{1.5, 0.0}};
  memory.update(post, mrpt::poses::CPose2D(0.0, 0.0, 0.0), everywhere);
  // The next scan matched nothing in the middle of the view (textureless), the wall elsewhere.
  memory.update(wallScan(4.0, -0.5, 0.5), mrpt::poses::CPose2D(0.0, 0.0, 0.0), everywhere);
  EXPECT_EQ(memory.size(), 1u);
}

TEST(NearObstacleMemory, KeepsOnlyWhatTheMapConfirms) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  // A robot at the origin facing +x; the map holds an obstacle only beyond x = 1.4.
  std::vector<mrpt::math::TPoint2D> scan{{1.0, 0.0}, {1.2, 0.5}, {1.5, -0.3}, {1.8, 0.2}};
  memory.update(scan, mrpt::poses::CPose2D(0.0, 0.0, 0.0), [](double x, double) { return x > 1.4; });
  const auto points = memory.points();
  ASSERT_EQ(points.size(), 2u);
  for (const auto& point : points) EXPECT_GT(point.x, 1.4);
}

TEST(NearObstacleMemory, WhatStoppedTheRobotIsRememberedUntilSeenPast) {
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
