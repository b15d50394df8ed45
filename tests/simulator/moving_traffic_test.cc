#include "simulator/moving_traffic.h"

#include <gtest/gtest.h>

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
  for (int i = 0; i < 30; ++i) traffic.advance(0.1, far_away, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 3.0, 1e-9);
  EXPECT_NEAR(traffic.solids()[0].y, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(traffic.waitedS()[0], 0.0);
}

TEST(MovingTraffic, AnObstacleWaitsForARobotStandingInItsWayAndGoesOnWhenItHasLeft) {
  const World world = worldFromText(kWalker);
  MovingTraffic traffic(world);
  // A robot (r = 0.3) standing on the path at x = 3: the person keeps its 0.25 + 0.3 + 0.1 m,
  // stopping at the last 0.1 s step before x = 3 - 0.65.
  const mrpt::poses::CPose2D in_the_way(3.0, 0.0, 0.0);
  for (int i = 0; i < 50; ++i) traffic.advance(0.1, in_the_way, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 2.3, 1e-9);
  EXPECT_NEAR(traffic.waitedS()[0], 5.0 - 2.3, 1e-9);
  // The robot moves off the path: the person walks on from where it waited.
  const mrpt::poses::CPose2D aside(3.0, 2.0, 0.0);
  for (int i = 0; i < 10; ++i) traffic.advance(0.1, aside, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 3.3, 1e-9);
}

TEST(MovingTraffic, AnObstacleTheRobotHasComeTooCloseToMovesOn) {
  // The robot drove up beside the person: waiting would hold it there for ever; it may leave.
  const World world = worldFromText(kWalker);
  MovingTraffic traffic(world);
  const mrpt::poses::CPose2D alongside(0.2, 0.6, 0.0);
  for (int i = 0; i < 10; ++i) traffic.advance(0.1, alongside, 0.3);
  EXPECT_NEAR(traffic.solids()[0].x, 1.0, 1e-9);
}

}  // namespace
}  // namespace stereonav
