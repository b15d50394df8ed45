#include "explorer/near_obstacle_memory.h"

#include <gtest/gtest.h>

#include <algorithm>
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

TEST(NearObstacleMemory, EveryPointStaysWithItsCellThroughForgettingAndNewSightings) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  // A row of points, one per 5 cm cell from x = 1.00 to 1.95 m.
  std::vector<mrpt::math::TPoint2D> row;
  for (int i = 0; i < 20; ++i) row.emplace_back(1.0 + 0.05 * i, 0.0);
  memory.remember(row);
  // Forget the first, a middle and the last one.
  const auto kept = [](double x, double) { return !(x < 1.01 || std::abs(x - 1.5) < 0.01 || x > 1.94); };
  EXPECT_EQ(memory.forgetUnconfirmed(kept), 3u);
  // Then see every other kept cell again, 1 cm higher.
  std::vector<mrpt::math::TPoint2D> moved;
  for (int i = 1; i < 19; i += 2) moved.emplace_back(1.0 + 0.05 * i, 0.01);
  memory.remember(moved);

  std::vector<mrpt::math::TPoint2D> expected;
  for (int i = 1; i < 19; ++i) {
    if (i != 10) expected.emplace_back(1.0 + 0.05 * i, i % 2 == 1 ? 0.01 : 0.0);
  }
  std::vector<mrpt::math::TPoint2D> points = memory.points();
  ASSERT_EQ(points.size(), expected.size());
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  for (size_t k = 0; k < points.size(); ++k) {
    EXPECT_NEAR(points[k].x, expected[k].x, 1e-12) << k;
    EXPECT_NEAR(points[k].y, expected[k].y, 1e-12) << k;
  }
  EXPECT_EQ(memory.size(), expected.size());
  // What the neighbourhood query finds is the same points, cell by cell.
  const std::vector<mrpt::math::TPoint2D> near = memory.pointsNear(1.5, 0.0, 1.0);
  ASSERT_EQ(near.size(), expected.size());
  for (size_t k = 0; k < near.size(); ++k) {
    EXPECT_NEAR(near[k].x, expected[k].x, 1e-12) << k;
    EXPECT_NEAR(near[k].y, expected[k].y, 1e-12) << k;
  }
}

// The 5 cm cell of a point, as (column, row).
std::pair<long, long> cellOf(const mrpt::math::TPoint2D& point) {
  return {std::lround(point.x / 0.05), std::lround(point.y / 0.05)};
}

TEST(NearObstacleMemory, PointsNearAPlaceAreThoseOfAllPointsWithinTheRadiusInTheOrderOfTheirCells) {
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  // A lattice of points 7 cm apart around the origin, on both sides of zero and off the 5 cm cells'
  // centres, several of them within a few millimetres of the radius.
  std::vector<mrpt::math::TPoint2D> lattice;
  for (int i = -40; i <= 40; ++i) {
    for (int j = -40; j <= 40; ++j) lattice.emplace_back(0.07 * i + 0.013, 0.07 * j - 0.021);
  }
  memory.remember(lattice);
  for (const mrpt::math::TPoint2D centre : {mrpt::math::TPoint2D(0.0, 0.0), mrpt::math::TPoint2D(-1.234, 0.871),
                                            mrpt::math::TPoint2D(2.6, -2.6)}) {
    for (const double radius : {0.0, 0.05, 0.5, 1.3}) {
      std::vector<mrpt::math::TPoint2D> expected;
      for (const auto& point : lattice) {
        if (std::hypot(point.x - centre.x, point.y - centre.y) <= radius) expected.push_back(point);
      }
      std::sort(expected.begin(), expected.end(), [](const auto& a, const auto& b) { return cellOf(a) < cellOf(b); });
      std::vector<mrpt::math::TPoint2D> within;
      for (const auto& point : memory.pointsNear(centre.x, centre.y, radius)) {
        if (std::hypot(point.x - centre.x, point.y - centre.y) <= radius) within.push_back(point);
      }
      ASSERT_EQ(within.size(), expected.size()) << centre.x << " " << centre.y << " r " << radius;
      for (size_t k = 0; k < within.size(); ++k) {
        EXPECT_EQ(within[k].x, expected[k].x);
        EXPECT_EQ(within[k].y, expected[k].y);
      }
    }
  }
  EXPECT_FALSE(memory.pointsNear(0.0, 0.0, 1.0).empty());
  EXPECT_TRUE(memory.pointsNear(10.0, 10.0, 1.0).empty());
}

TEST(NearObstacleMemory, AViewJudgesPointsUpToItsRangeWhereverTheyAre) {
  // Points at 1.99 m (just within the 2 m judged) around a robot away from the origin, at every
  // bearing: a scan that sees past them all forgets them all, and only them.
  NearObstacleMemory memory{NearObstacleMemoryOptions{}};
  const mrpt::poses::CPose2D pose(-3.27, 5.11, 0.4);
  std::vector<mrpt::math::TPoint2D> ring, beyond;
  for (int k = 0; k < 24; ++k) {
    const double bearing = k * M_PI / 12;
    ring.emplace_back(pose.x() + 1.99 * std::cos(bearing), pose.y() + 1.99 * std::sin(bearing));
    beyond.emplace_back(pose.x() + 2.2 * std::cos(bearing + 0.13), pose.y() + 2.2 * std::sin(bearing + 0.13));
  }
  memory.remember(ring);
  memory.remember(beyond);
  ASSERT_EQ(memory.size(), 48u);
  // The scan: a circle of wall 3 m out, a point per degree.
  std::vector<mrpt::math::TPoint2D> scan;
  for (int degree = 0; degree < 360; ++degree) {
    scan.emplace_back(3.0 * std::cos(degree * M_PI / 180), 3.0 * std::sin(degree * M_PI / 180));
  }
  memory.update(scan, pose, everywhere);
  const auto kept = memory.points();
  ASSERT_EQ(kept.size(), 24u);
  for (const auto& point : kept) EXPECT_NEAR(std::hypot(point.x - pose.x(), point.y - pose.y()), 2.2, 1e-9);
}

}  // namespace
}  // namespace stereonav
