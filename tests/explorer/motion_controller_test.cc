#include "explorer/motion_controller.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_grids.h"

namespace stereonav {
namespace {

// Defaults: max turn rate 1.2 rad/s, min 0.25, turn braking 3 rad/s^2, facing within 0.2 rad,
// top speed 1.5 m/s, braking 0.8 m/s^2, lookahead 0.3 m, turn in place past 25 degrees.
ExplorerOptions options() { return ExplorerOptions{}; }

// 8 m x 4 m of known free floor, no obstacle; 0.1 m cells.
NavigationGrid openFloor() {
  TestGrid cells(80, 40);
  cells.free(0, 0, 79, 39);
  return NavigationGrid(cells.grid(), {}, NavigationGridOptions{});
}

// Row 20 from column `from` to column `to`.
std::vector<cv::Point> straightPath(int from, int to) {
  std::vector<cv::Point> path;
  for (int col = from; from <= to ? col <= to : col >= to; col += from <= to ? 1 : -1) path.emplace_back(col, 20);
  return path;
}

TEST(MotionControllerTest, TurnsTowardsAGoalBehindItAsFastAsItCanBrake) {
  const MotionController motion(options());
  const mrpt::poses::CPose2D pose(0.0, 0.0, 0.0);
  // Behind and slightly left: the full turn rate, anticlockwise; slightly right: clockwise.
  EXPECT_EQ(motion.turnTowards(pose, -1.0, 0.01).turn_rate, 1.2);
  EXPECT_EQ(motion.turnTowards(pose, -1.0, -0.01).turn_rate, -1.2);
  EXPECT_EQ(motion.turnTowards(pose, -1.0, 0.01).speed, 0.0);
  // 0.05 rad off: the rate it brakes from in 0.05 rad at 3 rad/s^2, sqrt(2 * 3 * 0.05).
  EXPECT_NEAR(motion.turnTowards(pose, std::cos(0.05), std::sin(0.05)).turn_rate, std::sqrt(0.3), 1e-9);
  // Nearly there: never slower than the minimum.
  EXPECT_EQ(motion.turnTowards(pose, 1.0, 0.001).turn_rate, 0.25);
  EXPECT_TRUE(motion.faces(pose, 1.0, 0.19));
  EXPECT_FALSE(motion.faces(pose, 1.0, 0.21));
}

TEST(MotionControllerTest, DrivesAStraightPathAtTopSpeedAndBrakesForItsEnd) {
  const NavigationGrid grid = openFloor();
  const MotionController motion(options());
  const mrpt::poses::CPose2D at_start(grid.centreX(10), grid.centreY(20), 0.0);
  const MotionController::Drive long_path = motion.drive(at_start, straightPath(10, 40), grid, false);
  EXPECT_TRUE(long_path.driving);
  // 3 m to go: braking allows sqrt(2 * 0.8 * 3) > 1.5, so top speed, straight on.
  EXPECT_NEAR(long_path.command.speed, 1.5, 1e-9);
  EXPECT_NEAR(long_path.command.turn_rate, 0.0, 1e-9);
  EXPECT_NEAR(long_path.path_length_m, 3.0, 1e-9);
  // 0.4 m to go: sqrt(2 * 0.8 * 0.4) = 0.8.
  EXPECT_NEAR(motion.drive(at_start, straightPath(10, 14), grid, true).command.speed, 0.8, 1e-9);
}

TEST(MotionControllerTest, FacesAPathBehindBeforeDrivingIt) {
  const NavigationGrid grid = openFloor();
  const MotionController motion(options());
  const mrpt::poses::CPose2D facing_west(grid.centreX(40), grid.centreY(20), M_PI);
  const MotionController::Drive drive = motion.drive(facing_west, straightPath(40, 70), grid, false);
  EXPECT_FALSE(drive.driving);
  EXPECT_EQ(drive.command.speed, 0.0);
  EXPECT_EQ(std::abs(drive.command.turn_rate), 1.2);
}

TEST(MotionControllerTest, WhileDrivingAHeadingErrorSlowsItWithItsSquare) {
  const NavigationGrid grid = openFloor();
  const MotionController motion(options());
  // 0.3 rad off the path: beyond the facing tolerance, within the turn-in-place angle.
  const mrpt::poses::CPose2D pose(grid.centreX(10), grid.centreY(20), -0.3);
  EXPECT_FALSE(motion.drive(pose, straightPath(10, 40), grid, false).driving);
  const MotionController::Drive drive = motion.drive(pose, straightPath(10, 40), grid, true);
  ASSERT_TRUE(drive.driving);
  const double share = 0.3 / (25.0 * M_PI / 180.0);
  EXPECT_NEAR(drive.command.speed, 1.5 * (1.0 - 0.7 * share * share), 1e-9);
  EXPECT_NEAR(drive.command.turn_rate, 0.6, 1e-9);  // heading gain 2 x 0.3 rad
}

TEST(MotionControllerTest, ALookAroundBegunAsContinuingStillTurnsAFullCircle) {
  // The explorer starts in its look-around phase, so its first call already says `continuing`.
  // A robot starting at heading 2.8 rad must still turn 2 pi from there: 0.5 rad per cycle, the
  // 13th step completes it, as from a fresh start.
  MotionController motion(options());
  int cycles = 0;
  for (double phi = 2.8; motion.lookAround(mrpt::poses::CPose2D(0.0, 0.0, phi), true).has_value(); phi += 0.5) ++cycles;
  EXPECT_EQ(cycles, 13);
  EXPECT_TRUE(motion.lookedAroundHere());
}

TEST(MotionControllerTest, ALookAroundEndsAfterAFullTurnAndHoldsUntilTheRobotMovesOn) {
  MotionController motion(options());
  ASSERT_TRUE(motion.lookAround(mrpt::poses::CPose2D(0.0, 0.0, 0.0), false).has_value());
  EXPECT_EQ(motion.lookAround(mrpt::poses::CPose2D(0.0, 0.0, 0.0), true)->turn_rate, 1.0);
  int cycles = 0;
  for (double phi = 0.5; motion.lookAround(mrpt::poses::CPose2D(0.0, 0.0, phi), true).has_value(); phi += 0.5) ++cycles;
  // 0.5 rad per cycle: the 13th step completes 2 pi.
  EXPECT_EQ(cycles, 12);
  EXPECT_TRUE(motion.lookedAroundHere());
  motion.forgetLookAroundIfMoved(mrpt::poses::CPose2D(0.9, 0.0, 0.0));
  EXPECT_TRUE(motion.lookedAroundHere());
  motion.forgetLookAroundIfMoved(mrpt::poses::CPose2D(1.1, 0.0, 0.0));
  EXPECT_FALSE(motion.lookedAroundHere());
}

TEST(MotionControllerTest, BacksOffOnlyWhereTheMapHasRoomBehind) {
  const MotionController motion(options());
  const NavigationGrid open = openFloor();
  const mrpt::poses::CPose2D pose(4.05, 2.05, 0.0);
  EXPECT_TRUE(motion.roomBehind(pose, open));
  EXPECT_EQ(motion.reverse().speed, -0.2);
  // A wall 0.5 m behind: reversing 0.3 m (0.2 m/s for 1.5 s) would bring the body's 0.3 m
  // radius onto it.
  TestGrid cells(80, 40);
  cells.free(0, 0, 79, 39).occupied(35, 0, 35, 39);
  EXPECT_FALSE(motion.roomBehind(pose, NavigationGrid(cells.grid(), {}, NavigationGridOptions{})));
}

TEST(MotionControllerTest, ApproachesAPointAheadAndTurnsToOneBeside) {
  const MotionController motion(options());
  const mrpt::poses::CPose2D pose(0.0, 0.0, 0.0);
  const VelocityCommand ahead = motion.approach(pose, {1.0, 0.1});
  EXPECT_EQ(ahead.speed, 0.2);
  EXPECT_NEAR(ahead.turn_rate, 2.0 * std::atan2(0.1, 1.0), 1e-9);
  const VelocityCommand beside = motion.approach(pose, {0.0, 1.0});
  EXPECT_EQ(beside.speed, 0.0);
  EXPECT_GT(beside.turn_rate, 0.0);
}

}  // namespace
}  // namespace stereonav
