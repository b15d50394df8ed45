#include "explorer/safety_guard.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kinematic_robot.h"

namespace stereonav {
namespace {

using testing::KinematicRobot;

// Defaults: body radius 0.3, guard margin 0.1, braking 0.8 m/s^2, stop gap 0.3, horizon 2.5.
ExplorerOptions options() { return ExplorerOptions{}; }

// A guard that has read one scan showing `sensed` (robot frame), the robot at the origin.
SafetyGuard guardAfterScan(const std::vector<mrpt::math::TPoint2D>& sensed) {
  KinematicRobot robot({0.0, 0.0, 0.0});
  robot.time_ = 1.0;  // its scans are stamped 1 s into the run
  robot.sensed_ = sensed;
  SafetyGuard guard(options());
  guard.readScan(robot, mrpt::poses::CPose2D(), 0.0, nullptr);
  return guard;
}

TEST(SafetyGuardTest, BrakesToStopTheGapShortOfAScanObstacleAhead) {
  SafetyGuard guard = guardAfterScan({{1.2, 0.0}});
  const VelocityCommand allowed = guard.guard({1.5, 0.0}, mrpt::poses::CPose2D());
  // The body's edge plus margin meets the point after 1.2 - 0.3 - 0.1 = 0.8 m; braking at 0.8
  // m/s^2 to stop 0.3 m short of that allows sqrt(2 * 0.8 * 0.5).
  // (Scan points are single precision.)
  EXPECT_NEAR(guard.freeTravel(), 0.8, 1e-6);
  EXPECT_NEAR(allowed.speed, std::sqrt(0.8), 1e-6);
  EXPECT_EQ(allowed.turn_rate, 0.0);
  // A slower command is left alone.
  EXPECT_EQ(guard.guard({0.5, 0.1}, mrpt::poses::CPose2D()).speed, 0.5);
}

TEST(SafetyGuardTest, StopsForAnObstacleWithinTheStopGapAndRemembersIt) {
  SafetyGuard guard = guardAfterScan({{0.65, 0.0}});  // free travel 0.25 m, inside the 0.3 m gap
  EXPECT_EQ(guard.guard({1.0, 0.0}, mrpt::poses::CPose2D()).speed, 0.0);
  // What holds the robot is now a near obstacle, whatever a map says.
  ASSERT_EQ(guard.nearObstacles().points().size(), 1u);
  EXPECT_NEAR(guard.nearObstacles().points()[0].x, 0.65, 0.05);
}

TEST(SafetyGuardTest, APointUnderTheFrontOfTheBodyStopsItAndIsRememberedAtTheBodysEdge) {
  // What a blind column reports (column_projection/blind_column_points.h): 0.28 m ahead and a
  // little to the left, inside the 0.3 m body.
  SafetyGuard guard = guardAfterScan({{0.28, 0.05}});
  EXPECT_EQ(guard.guard({1.0, 0.0}, mrpt::poses::CPose2D()).speed, 0.0);
  // Nothing solid stands under the body: what the robot cannot see is remembered for the planner
  // on the point's bearing, 0.05 m beyond the body's edge (as a contact).
  ASSERT_EQ(guard.nearObstacles().points().size(), 1u);
  const mrpt::math::TPoint2D remembered = guard.nearObstacles().points()[0];
  EXPECT_NEAR(std::atan2(remembered.y, remembered.x), std::atan2(0.05, 0.28), 0.1);
  EXPECT_NEAR(std::hypot(remembered.x, remembered.y), 0.35, 0.04);  // kept one per 5 cm cell
  // The robot may back away or turn on the spot.
  EXPECT_EQ(guard.guard({-0.3, 0.0}, mrpt::poses::CPose2D()).speed, -0.3);
  EXPECT_EQ(guard.guard({0.0, 1.0}, mrpt::poses::CPose2D()).turn_rate, 1.0);
}

TEST(SafetyGuardTest, SlowsButDoesNotHoldTheRobotInADoorNarrowerThanBodyAndMargins) {
  KinematicRobot robot({0.0, 0.0, 0.0});
  robot.time_ = 1.0;  // its scans are stamped 1 s into the run
  // The jambs of a door 0.8 m wide, 0.4 m ahead, the robot 0.05 m left of its centre line: the body
  // passes 0.05 m clear of the right jamb, less than the margin.
  robot.sensed_ = {{0.4, 0.45}, {0.4, -0.35}};
  SafetyGuard guard(options());
  guard.readScan(robot, mrpt::poses::CPose2D(), 0.0, nullptr);
  // The widened disc meets the right jamb after 0.4 - sqrt(0.4^2 - 0.35^2) = 0.206 m, inside the
  // stop gap: it slows to pass_beside_speed_mps, and nothing is remembered as holding it.
  const VelocityCommand allowed = guard.guard({1.0, 0.0}, mrpt::poses::CPose2D());
  EXPECT_NEAR(guard.freeTravel(), 0.4 - std::sqrt(0.0375), 1e-6);
  EXPECT_EQ(allowed.speed, options().pass_beside_speed_mps);
  EXPECT_TRUE(guard.nearObstacles().points().empty());
  // 0.35 m on, the right jamb is 0.05 m ahead and sqrt(0.05^2 + 0.35^2) = 0.354 m off, within
  // the margin: the bare body passes it, but the robot keeps creeping until it is behind.
  EXPECT_EQ(guard.guard({1.0, 0.0}, mrpt::poses::CPose2D(0.35, 0.0, 0.0)).speed, options().pass_beside_speed_mps);
  EXPECT_EQ(guard.guard({1.0, 0.0}, mrpt::poses::CPose2D(0.45, 0.0, 0.0)).speed, 1.0);
  // A wall ahead within the stop gap (0.65 - 0.4 = 0.25 m of free travel) still holds it.
  robot.sensed_ = {{0.4, 0.45}, {0.4, -0.35}, {0.65, 0.0}};
  robot.time_ = 1.5;  // a new scan
  guard.readScan(robot, mrpt::poses::CPose2D(), 0.2, nullptr);
  EXPECT_EQ(guard.guard({1.0, 0.0}, mrpt::poses::CPose2D()).speed, 0.0);
}

TEST(SafetyGuardTest, LetsTheRobotCreepToAPathEndWhereTheBodyAndSafetyMarginFit) {
  // A jamb 0.6 m ahead and 0.2 m to the left: the widened disc meets it after
  // 0.6 - sqrt(0.4^2 - 0.2^2) = 0.254 m, inside the stop gap; the bare body after
  // 0.6 - sqrt(0.3^2 - 0.2^2) = 0.376 m.
  SafetyGuard guard = guardAfterScan({{0.6, 0.2}});
  const mrpt::poses::CPose2D origin;
  EXPECT_EQ(guard.guard({1.0, 0.0}, origin).speed, 0.0);
  // The path ends 0.25 m on: stopping there, the bare body is 0.376 - 0.25 = 0.126 m short of
  // the jamb, more than the 0.1 m safety margin, so the robot creeps there.
  EXPECT_EQ(guard.guard({1.0, 0.0}, origin, 0.25).speed, options().pass_beside_speed_mps);
  // Ending 0.3 m on, it would be 0.076 m short, less than the margin: held.
  EXPECT_EQ(guard.guard({1.0, 0.0}, origin, 0.3).speed, 0.0);
}

TEST(SafetyGuardTest, PassesCommandsAwayFromTheObstacleAndTurnsOnTheSpot) {
  SafetyGuard guard = guardAfterScan({{0.65, 0.0}});
  const VelocityCommand reverse = guard.guard({-0.2, 0.0}, mrpt::poses::CPose2D());
  EXPECT_EQ(reverse.speed, -0.2);
  EXPECT_EQ(guard.freeTravel(), 2.5);  // nothing behind within the horizon
  const VelocityCommand turn = guard.guard({0.0, 1.0}, mrpt::poses::CPose2D());
  EXPECT_EQ(turn.speed, 0.0);
  EXPECT_EQ(turn.turn_rate, 1.0);
  EXPECT_TRUE(guard.nearObstacles().points().empty());
}

TEST(SafetyGuardTest, AScanCountsForScanMemorySecondsAfterItWasRead) {
  KinematicRobot robot({0.0, 0.0, 0.0});
  robot.time_ = 1.0;  // its scans are stamped 1 s into the run
  robot.sensed_ = {{1.2, 0.0}};
  SafetyGuard guard(options());
  guard.readScan(robot, mrpt::poses::CPose2D(), 0.0, nullptr);
  robot.sensed_.clear();  // the sensor reports nothing new
  guard.readScan(robot, mrpt::poses::CPose2D(), 0.9, nullptr);
  EXPECT_NEAR(guard.guard({1.5, 0.0}, mrpt::poses::CPose2D()).speed, std::sqrt(0.8), 1e-6);
  guard.readScan(robot, mrpt::poses::CPose2D(), 1.1, nullptr);
  EXPECT_EQ(guard.guard({1.5, 0.0}, mrpt::poses::CPose2D()).speed, 1.5);
}

TEST(SafetyGuardTest, FindsTheRobotBlockedAfterBlockedSecondsOfCommandedButNoMotion) {
  SafetyGuard guard(options());
  EXPECT_FALSE(guard.blocked(0.5, 0.0, 0.0));
  EXPECT_FALSE(guard.blocked(0.5, 0.0, 0.9));
  EXPECT_TRUE(guard.blocked(0.5, 0.0, 1.0));
  // Moving (above 0.02 m/s) or told to creep (below 0.1 m/s) starts the watch again.
  EXPECT_FALSE(guard.blocked(0.5, 0.05, 1.1));
  EXPECT_FALSE(guard.blocked(0.5, 0.0, 1.2));
  EXPECT_FALSE(guard.blocked(0.05, 0.0, 2.0));
  EXPECT_FALSE(guard.blocked(0.5, 0.0, 2.5));
  EXPECT_TRUE(guard.blocked(0.5, 0.0, 3.5));
  guard.clearBlocked();
  EXPECT_FALSE(guard.blocked(0.5, 0.0, 3.75));
}

TEST(SafetyGuardTest, AContactIsRememberedJustBeyondTheFrontOfTheBody) {
  SafetyGuard guard(options());
  guard.rememberContact(mrpt::poses::CPose2D(1.0, 2.0, M_PI / 2));
  const std::vector<cv::Point2d> obstacles = guard.rememberedObstacles();
  ASSERT_EQ(obstacles.size(), 5u);
  for (const cv::Point2d& point : obstacles) {
    EXPECT_NEAR(std::hypot(point.x - 1.0, point.y - 2.0), 0.35, 1e-9);
    EXPECT_GT(point.y, 2.0 + 0.35 * std::cos(0.6) - 1e-9);  // within 0.6 rad of straight ahead
  }
  EXPECT_NEAR(obstacles[2].x, 1.0, 1e-9);
  EXPECT_NEAR(obstacles[2].y, 2.35, 1e-9);
}

}  // namespace
}  // namespace stereonav
