#include "explorer/frontier_explorer.h"

#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/math/wrap2pi.h>

#include <mrpt/maps/CSimplePointsMap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "kinematic_robot.h"
#include "test_grids.h"

namespace stereonav {
namespace {

using testing::KinematicRobot;

ExplorerOptions testOptions() {
  ExplorerOptions options;
  options.initial_look_around = false;
  return options;
}

// A 5 m x 4 m walled area, all known free inside, its east wall missing: unknown from
// x = 5.1 on, so the only frontier runs along x = 5.05.
TestGrid openToTheEast() {
  TestGrid cells(70, 40);
  cells.occupied(0, 0, 50, 39).free(1, 1, 50, 38);
  return cells;
}

// Distance from a point to the rectangle [x0, x1] x [y0, y1].
double distanceToRect(double x, double y, double x0, double y0, double x1, double y1) {
  return std::hypot(std::max({x0 - x, 0.0, x - x1}), std::max({y0 - y, 0.0, y - y1}));
}

TEST(FrontierExplorerTest, DrivesTowardsAFrontierAhead) {
  const TestGrid cells = openToTheEast();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({1.0, 2.0, 0.0});
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  ASSERT_TRUE(explorer.controlStep(robot));
  EXPECT_GT(robot.speed_, 0.0);
  // Roughly east: within 12 degrees (the turn rate is heading_gain times the heading error).
  EXPECT_LT(std::abs(robot.turn_rate_), testOptions().heading_gain * 0.2);
  EXPECT_EQ(explorer.status().phase, ExplorerPhase::kDriving);
  EXPECT_GT(explorer.status().target_x, 4.0);  // a goal cell near the frontier
}

TEST(FrontierExplorerTest, TurnsOnTheSpotToLookBeforeDrivingTowardsAFrontierBehind) {
  const TestGrid cells = openToTheEast();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({1.0, 2.0, M_PI});
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  double first_forward_heading_error = -1.0;
  for (int i = 0; i < 200 && first_forward_heading_error < 0.0; ++i) {
    ASSERT_TRUE(explorer.controlStep(robot));
    if (robot.speed_ > 0.0) first_forward_heading_error = std::abs(robot.pose_.phi);
    robot.step(0.05);
  }
  // Never drives before the path is inside the 90 degree view (turn_in_place_deg), and the
  // path is straight east.
  ASSERT_GE(first_forward_heading_error, 0.0) << "never drove";
  EXPECT_LT(first_forward_heading_error, testOptions().turn_in_place_rad);
}

TEST(FrontierExplorerTest, TakesANewRouteWhenAnObstacleAppearsOnThePath) {
  TestGrid cells = openToTheEast();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({1.0, 2.0, 0.0});
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  ASSERT_TRUE(explorer.controlStep(robot));
  ASSERT_LT(std::abs(robot.turn_rate_), testOptions().heading_gain * 0.2);
  // A wall across the way east (x 2.0 .. 2.2, y up to 2.5), open at its north end (y 2.5 .. 3.9).
  cells.occupied(20, 1, 21, 24);
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  ASSERT_TRUE(explorer.controlStep(robot));
  EXPECT_GT(robot.turn_rate_, testOptions().heading_gain * 0.3) << "turns left, towards the opening";
  // Following the new plan gets it past the wall without touching it.
  double closest = 1e9;
  for (int i = 0; i < 600 && robot.pose_.x < 2.5; ++i) {
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
    closest = std::min(closest, distanceToRect(robot.pose_.x, robot.pose_.y, 2.0, 0.0, 2.2, 2.5));
  }
  EXPECT_GT(robot.pose_.x, 2.5);
  EXPECT_GE(closest, testOptions().robot_radius_m);
}

TEST(FrontierExplorerTest, LooksAroundOnceThenStopsWhenNoFrontierIsLeftAndSaysWhy) {
  TestGrid cells(40, 40);
  cells.occupied(0, 0, 39, 39).free(1, 1, 38, 38);
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({2.0, 2.0, 0.0});
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  int steps = 0;
  while (explorer.controlStep(robot) && steps < 1000) {
    robot.step(0.05);
    ++steps;
  }
  EXPECT_TRUE(explorer.finished());
  EXPECT_EQ(explorer.stopReason().rfind("no frontier left", 0), 0u) << explorer.stopReason();
  EXPECT_GE(robot.turned_, 2.0 * M_PI - 0.1);  // a full look around first
  EXPECT_LE(robot.turned_, 2.0 * M_PI + 0.5);
  EXPECT_GE(robot.stops_, 1);
  EXPECT_EQ(robot.speed_, 0.0);
}

TEST(FrontierExplorerTest, WhereNoCellNearKeepsTheMarginItTriesTheBareBodyBeforeGivingUp) {
  // All it knows is a strip of free floor 0.7 m wide (y 1.7 .. 2.4), unknown all round, as at a
  // start between walls stereo cannot match. The strip's middle row is 0.35 m from the unknown:
  // the bare body (0.3) fits there, the margin (0.4) nowhere. It looks around, then drives on
  // the bare body rather than stopping boxed in.
  TestGrid cells(60, 40);
  cells.free(5, 17, 40, 23);
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({2.0, 2.05, 0.0});
  double farthest = 0.0;
  for (int steps = 0; steps < 1200 && !explorer.finished(); ++steps) {
    if (steps % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
    farthest = std::max(farthest, std::abs(robot.pose_.x - 2.0));
  }
  EXPECT_EQ(explorer.stopReason().find("boxed in"), std::string::npos) << explorer.stopReason();
  EXPECT_GT(farthest, 1.0);
  EXPECT_GE(robot.turned_, 2.0 * M_PI - 0.1);  // the look around came first
}

// Walled area, east wall at x = 5.0 with a 0.5 m door (the bare body needs 0.7 m of free cells),
// a walled passage beyond it to x = 6.1, then unknown: the frontier (x = 6.05) is 1.4 m past the
// last cell where the body fits (x = 4.65, 0.35 m from the wall's cells).
TestGrid doorTooNarrowForTheBody() {
  TestGrid cells(70, 40);
  cells.occupied(0, 0, 60, 39).free(1, 1, 49, 38).free(50, 18, 60, 22).unknown(61, 18, 61, 22);
  return cells;
}

TEST(FrontierExplorerTest, LooksFromTheNearestPlaceItReachesAtAFrontierBeyondADoorTooNarrowThenGivesItUp) {
  const TestGrid cells = doorTooNarrowForTheBody();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({2.0, 2.0, M_PI / 2});
  bool faced_the_frontier_from_the_door = false;
  int steps = 0;
  for (; steps < 6000 && !explorer.finished(); ++steps) {
    if (steps % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
    faced_the_frontier_from_the_door |= explorer.status().phase == ExplorerPhase::kLookingAtFrontier &&
                                        robot.pose_.x > 4.4 && std::abs(robot.pose_.phi) < 0.3;
  }
  EXPECT_TRUE(faced_the_frontier_from_the_door) << robot.pose_.asString();
  EXPECT_EQ(explorer.stopReason().rfind("no frontier left: the rest were looked at", 0), 0u)
      << explorer.stopReason() << " " << phaseName(explorer.status().phase) << " " << robot.pose_.asString();
}

// Walled area, east wall at x = 5.0 with a door of 0.7 m (y 1.7 .. 2.4) and free floor beyond it to
// x = 6.1, then unknown. With the shipped margin (0.05) the body needs 0.35 m from both jambs:
// one row of cells (y 2.0 .. 2.1) plans through the door.
TestGrid doorOneCellOfPlanWide() {
  TestGrid cells(70, 40);
  cells.occupied(0, 0, 60, 39).free(1, 1, 49, 38).free(50, 17, 60, 23).free(51, 1, 60, 38).unknown(61, 1, 61, 38);
  return cells;
}

TEST(FrontierExplorerTest, ARobotAFewCentimetresOffAOneCellPlanThroughADoorDrivesOnWhereItsBodyFits) {
  ExplorerOptions options = testOptions();
  options.safety_margin_m = 0.05;
  const TestGrid cells = doorOneCellOfPlanWide();
  // Heading east 0.15 m below the plan's row, it is a millimetre short of that row at x = 4.81:
  // in a cell whose centre is 0.29 m from the jamb, though the robot itself is 0.35 m from the
  // jamb's corner at (5.0, 1.7). Judged by its cell it escaped and never went through.
  {
    FrontierExplorer explorer(options);
    KinematicRobot robot({4.5, 1.9, 0.0});
    bool escaped = false;
    double farthest_east = 0.0;
    for (int steps = 0; steps < 400 && !explorer.finished(); ++steps) {
      if (steps % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
      if (!explorer.controlStep(robot)) break;
      robot.step(0.05);
      escaped |= explorer.status().phase == ExplorerPhase::kEscaping;
      farthest_east = std::max(farthest_east, robot.pose_.x);
    }
    EXPECT_FALSE(escaped);
    EXPECT_GT(farthest_east, 5.5) << robot.pose_.asString();
  }
  // Nearer the jamb (0.22 m from its corner) not even the bare body fits: it escapes.
  {
    FrontierExplorer explorer(options);
    KinematicRobot robot({4.94, 1.91, 0.0});
    explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
    ASSERT_TRUE(explorer.controlStep(robot));
    EXPECT_EQ(explorer.status().phase, ExplorerPhase::kEscaping);
  }
}

TEST(FrontierExplorerTest, BeforeEndingItTriesEveryFrontierItGaveUpOnceMore) {
  // The door too narrow: looked at from the nearest place the body reaches, its frontier is given
  // up, and one look around there (2 pi) ends the first pass. Once the robot has turned more than
  // that in its look around, the door is widened to 1.3 m, as when a person who stood in it
  // leaves: the frontier beyond, given up in the first pass, is tried again.
  TestGrid cells = doorTooNarrowForTheBody();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({2.0, 2.0, M_PI / 2});
  bool looked_at_the_door = false, opened = false;
  double turned_before_looking_around = -1.0;
  for (int steps = 0; steps < 8000 && !explorer.finished(); ++steps) {
    const ExplorerPhase phase = explorer.status().phase;
    looked_at_the_door |= phase == ExplorerPhase::kLookingAtFrontier && robot.pose_.x > 4.4;
    if (looked_at_the_door && turned_before_looking_around < 0.0 && phase == ExplorerPhase::kLookingAround) {
      turned_before_looking_around = robot.turned_;
    }
    if (!opened && turned_before_looking_around >= 0.0 &&
        robot.turned_ > turned_before_looking_around + 2.0 * M_PI + 1.0) {
      cells.free(50, 14, 60, 26).unknown(61, 14, 61, 26);
      opened = true;
    }
    if (steps % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
  }
  EXPECT_TRUE(opened) << explorer.stopReason();
  EXPECT_GT(robot.pose_.x, 5.2) << explorer.stopReason();  // through the door (the wall: x 5.0 .. 5.1)
}

TEST(FrontierExplorerTest, AfterTheSecondPassTheStopReasonSaysSo) {
  // The door too narrow, never opening: the frontier beyond is given up, tried again in the
  // second pass, given up again.
  const TestGrid cells = doorTooNarrowForTheBody();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({2.0, 2.0, M_PI / 2});
  for (int steps = 0; steps < 8000 && !explorer.finished(); ++steps) {
    if (steps % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
  }
  EXPECT_EQ(explorer.stopReason().rfind("no frontier left: the rest were looked at", 0), 0u) << explorer.stopReason();
  EXPECT_NE(explorer.stopReason().find("second pass"), std::string::npos) << explorer.stopReason();
}

TEST(FrontierExplorerTest, StopsWhenTheOnlyFrontierIsBeyondADoorTooNarrowAndFartherThanItLooksFrom) {
  const TestGrid cells = doorTooNarrowForTheBody();
  ExplorerOptions options = testOptions();
  options.look_from_afar_m = 1.0;  // the frontier is 1.4 m beyond the last place the body fits
  FrontierExplorer explorer(options);
  KinematicRobot robot({2.0, 2.0, 0.0});
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  int steps = 0;
  while (explorer.controlStep(robot) && steps < 1000) {
    robot.step(0.05);
    ++steps;
  }
  EXPECT_EQ(explorer.stopReason().rfind("no reachable frontier left", 0), 0u)
      << explorer.stopReason() << " " << phaseName(explorer.status().phase) << " " << robot.pose_.asString();
  EXPECT_NEAR(robot.pose_.x, 2.0, 1e-9);
}

// From (2, 2) facing east, with a frontier beyond a door too narrow and farther than it looks
// from: how far the robot turned and why it stopped (if it did) within 120 s. Once it has turned
// more than one look around, the door is widened to 1.3 m if `door_opens`, as when a person who
// stood in it leaves.
struct RecoveryOutcome {
  double turned = 0.0;
  double final_x = 0.0;
  std::string stop_reason;
};
RecoveryOutcome recoverAtADoorTooNarrow(const ExplorerOptions& options, bool door_opens) {
  TestGrid cells = doorTooNarrowForTheBody();
  FrontierExplorer explorer(options);
  KinematicRobot robot({2.0, 2.0, 0.0});
  bool opened = false;
  for (int steps = 0; steps < 2400 && !explorer.finished(); ++steps) {
    if (door_opens && !opened && robot.turned_ > 2.0 * M_PI + 1.0) {
      cells.free(50, 14, 60, 26).unknown(61, 14, 61, 26);
      opened = true;
    }
    if (steps % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
  }
  return {robot.turned_, robot.pose_.x, explorer.stopReason()};
}

TEST(FrontierExplorerTest, BeforeGivingUpItLooksAroundAgainAndTakesAWayThatHasOpenedSince) {
  ExplorerOptions options = testOptions();
  options.look_from_afar_m = 1.0;
  const RecoveryOutcome opened = recoverAtADoorTooNarrow(options, true);
  EXPECT_GT(opened.final_x, 5.2) << opened.stop_reason;  // through the door (the wall: x 5.0 .. 5.1)
  // Nothing opens: one look around, one more after the ladder's end, then it stops, the second
  // end coming sooner than recovery_restart_spacing_s after the first.
  const RecoveryOutcome closed = recoverAtADoorTooNarrow(options, false);
  EXPECT_EQ(closed.stop_reason.rfind("no reachable frontier left", 0), 0u) << closed.stop_reason;
  EXPECT_GE(closed.turned, 4.0 * M_PI - 0.2);
  EXPECT_LE(closed.turned, 4.0 * M_PI + 1.0);
  EXPECT_NEAR(closed.final_x, 2.0, 1e-9);
  // Without restarts it gives up after the first look, and the door never opens.
  options.recovery_restarts = 0;
  const RecoveryOutcome at_once = recoverAtADoorTooNarrow(options, true);
  EXPECT_EQ(at_once.stop_reason.rfind("no reachable frontier left", 0), 0u) << at_once.stop_reason;
  EXPECT_LE(at_once.turned, 2.0 * M_PI + 0.5);
  EXPECT_NEAR(at_once.final_x, 2.0, 1e-9);
}

TEST(FrontierExplorerTest, WhenNothingElseIsReachableItPlansPastALoneSpeckInAPassage) {
  // A passage 1.1 m wide (free y 1.1 .. 2.2) with the only frontier at its end (x = 4.0), and
  // one obstacle cell in its middle at x = 2.0: inflated by the body it closes the passage, a
  // repeated stereo mismatch that no look from nearby clears.
  TestGrid cells(60, 40);
  cells.occupied(0, 10, 40, 22).free(1, 11, 40, 21).unknown(41, 11, 41, 21).occupied(20, 16, 20, 16);
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({1.0, 1.65, 0.0});
  int steps = 0;
  for (; steps < 3000 && robot.pose_.x < 3.0; ++steps) {
    if (steps % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
  }
  EXPECT_GT(robot.pose_.x, 3.0) << explorer.stopReason() << " " << robot.pose_.asString();
  // Three cells long, it is an obstacle, not a speck: the robot stops.
  cells.occupied(20, 15, 20, 17);
  FrontierExplorer blocked(testOptions());
  KinematicRobot stopped({1.0, 1.65, 0.0});
  for (steps = 0; steps < 3000 && !blocked.finished(); ++steps) {
    if (steps % 4 == 0) blocked.updateMap(cells.grid(), mrpt::poses::CPose2D(stopped.pose_));
    if (!blocked.controlStep(stopped)) break;
    stopped.step(0.05);
  }
  EXPECT_EQ(blocked.stopReason().rfind("no reachable frontier left", 0), 0u) << blocked.stopReason();
  EXPECT_LT(stopped.pose_.x, 2.0);
}

// Where the explorer heads first from `start` with the pocket penalty at `penalty_m`.
cv::Point2d firstTarget(const TestGrid& cells, const mrpt::math::TPose2D& start, double penalty_m) {
  ExplorerOptions options = testOptions();
  options.pocket_penalty_m = penalty_m;
  FrontierExplorer explorer(options);
  KinematicRobot robot(start);
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  EXPECT_TRUE(explorer.controlStep(robot));
  EXPECT_TRUE(explorer.status().has_target);
  return {explorer.status().target_x, explorer.status().target_y};
}

TEST(FrontierExplorerTest, HeadsForTheRestOfTheBuildingBeforeAPocketNearby) {
  // A walled 6 m x 3 m room with a 0.4 m x 0.4 m unknown pocket 0.5 m from the robot (a desk's
  // shadow) and a door in its far east wall to unknown space, 5 m away.
  TestGrid cells(80, 40);
  cells.occupied(0, 0, 61, 31).free(1, 1, 60, 30).unknown(15, 14, 18, 17).unknown(61, 12, 61, 18);
  EXPECT_GT(firstTarget(cells, {1.0, 1.55, 0.0}, 10.0).x, 5.0);
  EXPECT_LT(firstTarget(cells, {1.0, 1.55, 0.0}, 0.0).x, 2.5);
}

TEST(FrontierExplorerTest, HeadsForUnknownSpaceBeforeAWallSeenOnlyFromFar) {
  // A walled 6 m x 3 m room (cells 1..60 x 5..34) with unknown space all round it, a door in its
  // far east wall (x 6.1, 5.5 m from the robot) and a 0.7 m stretch of its south wall beside the
  // robot seen only from far (disparity 2): looking there would pin down where that wall is,
  // looking through the door shows new floor.
  TestGrid cells(80, 40);
  cells.occupied(0, 4, 61, 35).free(1, 5, 60, 34).tag(8, 4, 14, 4, 2.0f).unknown(61, 16, 61, 22);
  EXPECT_GT(firstTarget(cells, {1.0, 1.2, -1.57}, 10.0).x, 5.0);
  const cv::Point2d unpenalised = firstTarget(cells, {1.0, 1.2, -1.57}, 0.0);
  EXPECT_LT(unpenalised.x, 2.0);
  EXPECT_LT(unpenalised.y, 1.2);
}

// A walled 4 m x 4 m room, known free but for an unknown 0.3 m x 0.3 m pocket (under a table
// top, say): cells 25..27 x 21..23, x 2.5 .. 2.8, y 2.1 .. 2.4. Its ring of free cells is the
// only frontier; a robot at (1.9, 2.25) facing east sees the ring's near side (column 24) 0.55 m
// ahead, and not its far side (column 28), hidden behind the pocket. Optionally a wall in column
// 23 hides the near side too.
TestGrid roomWithAnUnresolvablePocket(bool wall_between) {
  TestGrid cells(40, 40);
  cells.occupied(0, 0, 39, 39).free(1, 1, 38, 38).unknown(25, 21, 27, 23);
  if (wall_between) cells.occupied(23, 15, 23, 30);
  return cells;
}

bool isFrontierInPlan(const FrontierExplorer& explorer, int col, int row) {
  const cv::Mat3b plan = explorer.planImage();
  return plan(plan.rows - 1 - row, col) == cv::Vec3b(255, 0, 0);
}

TEST(FrontierExplorerTest, DropsFrontierCellsInPlainSightUpCloseThatViewsDoNotResolve) {
  // Views are counted per map, 5 maps a second. Resolving takes up to eleven CLEAR updates (the
  // look hold, 2.4 s): after 2 s of views the near side is still a frontier, after 3 s it is
  // given up; the hidden far side stays.
  for (const bool wall_between : {false, true}) {
    SCOPED_TRACE(wall_between ? "wall between" : "in plain sight");
    const TestGrid cells = roomWithAnUnresolvablePocket(wall_between);
    FrontierExplorer explorer(testOptions());
    const mrpt::poses::CPose2D pose(1.9, 2.25, 0.0);
    for (int map = 1; map <= 10; ++map) explorer.updateMap(cells.grid(), pose);
    EXPECT_TRUE(isFrontierInPlan(explorer, 24, 22));
    for (int map = 11; map <= 15; ++map) explorer.updateMap(cells.grid(), pose);
    EXPECT_EQ(isFrontierInPlan(explorer, 24, 22), wall_between);
    EXPECT_TRUE(isFrontierInPlan(explorer, 28, 22));
  }
}

TEST(FrontierExplorerTest, BrakesForWhatOnlyTheSensorShowsAndThenPlansRoundIt) {
  // The map shows the way east clear; the sensor sees a 0.4 m wide post across it at x = 2.5 (a
  // table edge the map lost, a person): points 5 cm apart on its west face.
  const TestGrid cells = openToTheEast();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({1.0, 2.0, 0.0});
  for (double y = 1.8; y <= 2.2 + 1e-9; y += 0.05) robot.sensed_.emplace_back(2.5, y);
  double closest = 1e9;
  for (int i = 0; i < 1200 && robot.pose_.x < 3.0; ++i) {
    if (i % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
    for (const mrpt::math::TPoint2D& point : robot.sensed_) {
      closest = std::min(closest, std::hypot(point.x - robot.pose_.x, point.y - robot.pose_.y));
    }
  }
  // It never touches the post (the body's radius), and gets past it.
  EXPECT_GT(closest, testOptions().robot_radius_m);
  EXPECT_GT(robot.pose_.x, 3.0) << robot.pose_.asString();
}

TEST(FrontierExplorerTest, HeldByWhatItSeesAheadItDoesNotReverseIntoAWallBehind) {
  // Backed up to the west wall (its cells end at x = 0.1; the body's back is at 0.15), facing
  // east, and a post the sensor sees 0.5 m ahead holds it: the cameras do not see behind, the
  // map does, so it must not back off into the wall (it turns on the spot instead). The map is
  // given once: a new one would hold the post the guard remembers, and the plan would turn away
  // from it before the robot is found blocked.
  const TestGrid cells = openToTheEast();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({0.45, 2.0, 0.0});
  for (double y = 1.8; y <= 2.2 + 1e-9; y += 0.05) robot.sensed_.emplace_back(0.95, y);
  double westmost = robot.pose_.x;
  int backing_off = 0;
  explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));
  for (int i = 0; i < 200; ++i) {
    if (!explorer.controlStep(robot)) break;
    backing_off += explorer.status().phase == ExplorerPhase::kBackingOff ? 1 : 0;
    robot.step(0.05);
    westmost = std::min(westmost, robot.pose_.x);
  }
  EXPECT_GT(backing_off, 0);  // it was held, and the back-off was asked for
  EXPECT_GT(westmost - testOptions().robot_radius_m, 0.1) << westmost;
}

TEST(FrontierExplorerTest, KeepsClearOfAnObstacleItWasToldOfAfterTheSensorHasLostIt) {
  // The map shows the way east clear, the sensor shows nothing, and the robot was told once of a
  // 0.4 m wide post across the way at x = 2.5 that the map cannot hold (seen nearer than the
  // disparity range): it goes round the post all the same.
  const TestGrid cells = openToTheEast();
  FrontierExplorer explorer(testOptions());
  KinematicRobot robot({1.0, 2.0, 0.0});
  std::vector<mrpt::math::TPoint2D> post;
  for (double y = 1.8; y <= 2.2 + 1e-9; y += 0.05) post.emplace_back(2.5, y);
  explorer.rememberObstacles(post);
  double closest = 1e9;
  for (int i = 0; i < 1200 && robot.pose_.x < 3.0; ++i) {
    if (i % 4 == 0) explorer.updateMap(cells.grid(), mrpt::poses::CPose2D(robot.pose_));  // 5 Hz
    if (!explorer.controlStep(robot)) break;
    robot.step(0.05);
    for (const mrpt::math::TPoint2D& point : post) {
      closest = std::min(closest, std::hypot(point.x - robot.pose_.x, point.y - robot.pose_.y));
    }
  }
  EXPECT_GT(closest, testOptions().robot_radius_m);
  EXPECT_GT(robot.pose_.x, 3.0) << robot.pose_.asString();
}

// A 7.8 m x 2.6 m room with a doorway at each end (unknown beyond): the east one 1.4 m from the
// robot, the west one 6.4 m. `east_closed` maps the east doorway as wall: a frontier that vanishes
// whenever the robot faces it, as one did in the exploration benchmark's world 20 (session 89).
TestGrid roomWithTwoDoorways(bool east_closed) {
  TestGrid cells(120, 40);
  cells.occupied(10, 5, 89, 32).free(11, 6, 88, 31).unknown(10, 15, 10, 22);
  if (east_closed) return cells;
  cells.unknown(89, 15, 89, 22);
  return cells;
}

TEST(FrontierExplorerTest, LeavesASpotWhereItsTargetFlipsBetweenAFrontierThatVanishesWhenFacedAndAnother) {
  // The east doorway is a frontier only while the robot faces away from it, so the target flips
  // between it and the west doorway whenever the robot turns, and each flip is a new target
  // whose progress watch starts afresh. The spot watch, which a new target does not restart,
  // gives up the one the robot steers for after stuck_timeout_s on the spot; it then drives west.
  const TestGrid open = roomWithTwoDoorways(false);
  const TestGrid closed = roomWithTwoDoorways(true);
  const ExplorerOptions options = testOptions();
  FrontierExplorer explorer(options);
  KinematicRobot robot({7.5, 1.9, M_PI});
  double westmost = robot.pose_.x;
  double turned_on_the_spot_s = 0.0;
  for (int i = 0; i < 1600 && westmost > 5.5; ++i) {  // 80 s
    if (i % 4 == 0) {
      const bool faces_east = std::abs(robot.pose_.phi) < M_PI / 4.0;
      explorer.updateMap((faces_east ? closed : open).grid(), mrpt::poses::CPose2D(robot.pose_));
    }
    if (!explorer.controlStep(robot)) break;
    if (robot.speed_ == 0.0 && robot.turn_rate_ != 0.0) turned_on_the_spot_s += 0.05;
    robot.step(0.05);
    westmost = std::min(westmost, robot.pose_.x);
  }
  EXPECT_LT(westmost, 5.5) << explorer.stopReason();
  // It turned back and forth for the watch's time first: the flip is real in this map.
  EXPECT_GT(turned_on_the_spot_s, options.stuck_timeout_s);
}

}  // namespace
}  // namespace stereonav
