#include "simulator/moving_traffic.h"

#include <gtest/gtest.h>

#include <cmath>

#include "world_text.h"

namespace stereonav {
namespace {

// A person (r = 0.25) walking east along y = 0 from x = 0 to x = 10 at 1 m/s.
constexpr const char* kWalker = "[moving.person]\nshape = cylinder\nradius = 0.25\npath = 0 0; 10 0\nspeed = 1\n";

TEST(MovingTraffic, ObstaclesFollowTheirPathsWhileTheRobotIsOutOfTheWay) {
  const World world = worldFromText(kWalker);
  MovingTraffic traffic(world);
  ASSERT_EQ(traffic.solids().size(), 1u);
  EXPECT_DOUBLE_EQ(traffic.solids()[0].x, 0.0);
  const mrpt::poses::CPose2D far_away(5.0, 5.0, 0.0);
  for (int i = 0; i < 30; ++i) traffic.advance(0.1, far_away, 0.0, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 3.0, 1e-9);
  EXPECT_NEAR(traffic.solids()[0].y, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(traffic.waitedS()[0], 0.0);
}

TEST(MovingTraffic, AnObstacleWaitsForARobotStandingInItsWayAndGoesOnWhenItHasLeft) {
  const World world = worldFromText(kWalker);
  MovingTraffic traffic(world);
  // A robot (r = 0.3) standing on the path at x = 3: the person keeps its 0.25 + 0.3 + 0.4 m,
  // stopping at the last 0.1 s step before x = 3 - 0.95.
  const mrpt::poses::CPose2D in_the_way(3.0, 0.0, 0.0);
  for (int i = 0; i < 50; ++i) traffic.advance(0.1, in_the_way, 0.0, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 2.0, 1e-9);
  EXPECT_NEAR(traffic.waitedS()[0], 5.0 - 2.0, 1e-9);
  // The robot moves off the path: the person walks on from where it waited.
  const mrpt::poses::CPose2D aside(3.0, 2.0, 0.0);
  for (int i = 0; i < 10; ++i) traffic.advance(0.1, aside, 0.0, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 3.0, 1e-9);
}

TEST(MovingTraffic, AnObstacleDoesNotStepInFrontOfAMovingRobot) {
  const World world = worldFromText(kWalker);
  MovingTraffic traffic(world);
  // The robot at (3, -2) drives north at 1 m/s: in 1 s its disc reaches (3, -1), 1 m short of the
  // path; it will cross it, but not within the second the person looks ahead.
  const mrpt::poses::CPose2D approaching(3.0, -2.0, M_PI / 2);
  for (int i = 0; i < 10; ++i) traffic.advance(0.1, approaching, 1.0, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 1.0, 1e-9);
  // 0.5 m from the path at 1 m/s the robot's disc will be on it within the second: the person
  // keeps 0.25 + 0.3 + 0.4 m from where the disc will pass, x = 3 - 0.95, stopping before it.
  const mrpt::poses::CPose2D about_to_cross(3.0, -0.5, M_PI / 2);
  for (int i = 0; i < 30; ++i) traffic.advance(0.1, about_to_cross, 1.0, 0.3);
  EXPECT_LE(traffic.solids()[0].x, 3.0 - 0.95);
  EXPECT_GT(traffic.solids()[0].x, 3.0 - 0.95 - 0.1 - 1e-9);
  // Stopped 1 m from the path the robot is out of the person's way: it walks on past.
  const mrpt::poses::CPose2D stopped(3.0, -1.0, M_PI / 2);
  for (int i = 0; i < 20; ++i) traffic.advance(0.1, stopped, 0.0, 0.3);
  EXPECT_GT(traffic.solids()[0].x, 3.5);
}

TEST(MovingTraffic, AnObstacleTheRobotHasComeTooCloseToWalksAwayButNeverCloser) {
  const World world = worldFromText(kWalker);
  MovingTraffic traffic(world);
  // The robot drove up behind the person, 0.5 m from its path: walking on takes it away.
  const mrpt::poses::CPose2D behind(-0.2, 0.5, 0.0);
  for (int i = 0; i < 10; ++i) traffic.advance(0.1, behind, 0.0, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 1.0, 1e-9);
  // Now it stands just ahead, inside the person's 0.25 + 0.3 + 0.4 m: the person waits.
  const mrpt::poses::CPose2D ahead(1.4, 0.5, 0.0);
  for (int i = 0; i < 10; ++i) traffic.advance(0.1, ahead, 0.0, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 1.0, 1e-9);
}

}  // namespace
}  // namespace stereonav
