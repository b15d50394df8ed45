#include "simulator/differential_drive_robot.h"

#include <gtest/gtest.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cmath>

#include "world_text.h"

namespace stereonav {
namespace {

DifferentialDriveOptions exactOdometry() {
  DifferentialDriveOptions options;
  options.odometry_distance_noise = 0.0;
  options.odometry_turn_noise = 0.0;
  options.odometry_drift_rad_per_m = 0.0;
  return options;
}

TEST(DifferentialDriveRobot, SpeedAndAccelerationAreLimited) {
  const World open_floor = worldFromText("");
  DifferentialDriveRobot robot(open_floor, exactOdometry(), mrpt::poses::CPose2D(0, 0, 0));
  const double dt = 0.1;
  double previous_speed = 0.0;
  for (int i = 0; i < 100; ++i) {
    robot.step(5.0, 0.0, dt, {});
    EXPECT_LE(robot.speed(), 1.5 + 1e-12);
    EXPECT_LE(robot.speed() - previous_speed, 1.0 * dt + 1e-12);
    previous_speed = robot.speed();
  }
  // 15 steps accelerating by 0.1 m/s (0.1 + 0.2 + ... + 1.5) * 0.1 s = 1.2 m, then 85 steps at
  // 1.5 m/s = 12.75 m.
  EXPECT_NEAR(robot.pose().x(), 13.95, 1e-9);
  EXPECT_NEAR(robot.pose().y(), 0.0, 1e-12);
  EXPECT_EQ(robot.collisionCount(), 0);
}

TEST(DifferentialDriveRobot, TurnRateIsLimitedAndArcsAreExact) {
  const World open_floor = worldFromText("");
  DifferentialDriveOptions options = exactOdometry();
  options.max_acceleration = 1000.0;
  options.max_turn_acceleration = 1000.0;
  DifferentialDriveRobot robot(open_floor, options, mrpt::poses::CPose2D(0, 0, 0));
  robot.step(0.0, 10.0, 0.1, {});
  EXPECT_DOUBLE_EQ(robot.turnRate(), 2.0);
  // Half a circle of radius 2 (v = 1, w = 0.5) in pi / 0.5 seconds ends at (0, 4) facing back.
  DifferentialDriveRobot circling(open_floor, options, mrpt::poses::CPose2D(0, 0, 0));
  const int steps = 1000;
  const double dt = (M_PI / 0.5) / steps;
  for (int i = 0; i < steps; ++i) circling.step(1.0, 0.5, dt, {});
  EXPECT_NEAR(circling.pose().x(), 0.0, 1e-9);
  EXPECT_NEAR(circling.pose().y(), 4.0, 1e-9);
  EXPECT_NEAR(std::abs(circling.pose().phi()), M_PI, 1e-9);
}

TEST(DifferentialDriveRobot, DrivingIntoAWallStopsAtContactAndCountsOneCollision) {
  // Wall face at x = 2.95; a robot of radius 0.3 touches it with its centre at x = 2.65.
  const World world = worldFromText("[wall.w]\npoints = 3 -5; 3 5\nthickness = 0.1\n");
  DifferentialDriveRobot robot(world, exactOdometry(), mrpt::poses::CPose2D(0, 0, 0));
  const double dt = 0.2;
  for (int i = 0; i < 50; ++i) {
    robot.step(1.5, 0.0, dt, {});
    ASSERT_LT(robot.pose().x(), 2.65);  // never into or through the wall
  }
  EXPECT_NEAR(robot.pose().x(), 2.65, 1e-4);
  EXPECT_EQ(robot.collisionCount(), 1);  // pushing on is the same contact
  EXPECT_TRUE(robot.inContact());
  for (int i = 0; i < 10; ++i) robot.step(-0.5, 0.0, dt, {});
  EXPECT_FALSE(robot.inContact());
  for (int i = 0; i < 20; ++i) robot.step(1.0, 0.0, dt, {});
  EXPECT_EQ(robot.collisionCount(), 2);
}

TEST(DifferentialDriveRobot, TouchingAWallItStillTurnsOnTheSpot) {
  const World world = worldFromText("[wall.w]\npoints = 3 -5; 3 5\nthickness = 0.1\n");
  DifferentialDriveRobot robot(world, exactOdometry(), mrpt::poses::CPose2D(2.65 - 1e-6, 0, 0));
  robot.step(1.0, 0.0, 0.1, {});
  ASSERT_TRUE(robot.inContact());
  const double x = robot.pose().x();
  // Told to go on forward while turning left at 1 rad/s for 0.5 s: it cannot advance, but turns.
  for (int i = 0; i < 5; ++i) robot.step(1.0, 1.0, 0.1, {});
  EXPECT_NEAR(robot.pose().x(), x, 1e-6);
  EXPECT_GT(robot.pose().phi(), 0.3);
  EXPECT_EQ(robot.collisionCount(), 1);
}

TEST(DifferentialDriveRobot, TableTopStopsATallRobotButNotALowOne) {
  // Top 1.2 x 0.8 at (3, 0), 0.72 high: its near edge is at x = 2.4; legs are off the path.
  const World world = worldFromText("[table.t]\ncenter = 3 0\nsize = 1.2 0.8\n");
  DifferentialDriveOptions tall = exactOdometry();
  tall.radius_m = 0.2;
  tall.height_m = 1.0;
  DifferentialDriveOptions low = tall;
  low.height_m = 0.5;
  low.radius_m = 0.1;
  DifferentialDriveRobot tall_robot(world, tall, mrpt::poses::CPose2D(0, 0, 0));
  DifferentialDriveRobot low_robot(world, low, mrpt::poses::CPose2D(0, 0, 0));
  for (int i = 0; i < 60; ++i) {
    tall_robot.step(1.0, 0.0, 0.1, {});
    low_robot.step(1.0, 0.0, 0.1, {});
  }
  EXPECT_NEAR(tall_robot.pose().x(), 2.2, 1e-4);
  EXPECT_EQ(tall_robot.collisionCount(), 1);
  EXPECT_GT(low_robot.pose().x(), 4.0);
  EXPECT_EQ(low_robot.collisionCount(), 0);
}

TEST(DifferentialDriveRobot, ThinWallIsNotJumpedOverAtTopSpeed) {
  // A 1 cm panel, a small robot and long steps: 1.5 m/s * 1 s is far more than the robot's size.
  const World world = worldFromText("[wall.w]\npoints = 3 -5; 3 5\nthickness = 0.01\n");
  DifferentialDriveOptions options = exactOdometry();
  options.radius_m = 0.05;
  options.max_acceleration = 100.0;
  DifferentialDriveRobot robot(world, options, mrpt::poses::CPose2D(0, 0, 0));
  for (int i = 0; i < 5; ++i) robot.step(1.5, 0.0, 1.0, {});
  EXPECT_NEAR(robot.pose().x(), 3.0 - 0.005 - 0.05, 1e-4);
  EXPECT_EQ(robot.collisionCount(), 1);
}

TEST(DifferentialDriveRobot, OdometryDriftsReproduciblyFromItsSeed) {
  const World open_floor = worldFromText("");
  DifferentialDriveOptions options;  // default noise
  DifferentialDriveRobot a(open_floor, options, mrpt::poses::CPose2D(0, 0, 0));
  DifferentialDriveRobot b(open_floor, options, mrpt::poses::CPose2D(0, 0, 0));
  options.seed = 2;
  DifferentialDriveRobot c(open_floor, options, mrpt::poses::CPose2D(0, 0, 0));
  for (int i = 0; i < 100; ++i) {
    a.step(1.0, 0.3, 0.1, {});
    b.step(1.0, 0.3, 0.1, {});
    c.step(1.0, 0.3, 0.1, {});
  }
  EXPECT_EQ(a.odometry().x(), b.odometry().x());
  EXPECT_NE(a.odometry().x(), c.odometry().x());
  EXPECT_EQ(a.pose().x(), c.pose().x());  // noise is in the odometry, not the motion
  const double error = std::hypot(a.odometry().x() - a.pose().x(), a.odometry().y() - a.pose().y());
  EXPECT_GT(error, 1e-4);
  EXPECT_LT(error, 1.0);  // ~9.5 m travelled at 2 % per metre
}

TEST(DifferentialDriveRobot, WheelCalibrationBiasScalesOdometry) {
  // A wheel radius 2 % large over-reads every metre by 2 %; a wheel base 5 % small over-reads
  // every turn by 5 %. Straight 2 m, then a quarter turn on the spot.
  const World open_floor = worldFromText("");
  DifferentialDriveOptions options = exactOdometry();
  options.odometry_distance_bias = 0.02;
  options.odometry_turn_bias = 0.05;
  DifferentialDriveRobot robot(open_floor, options, mrpt::poses::CPose2D(0, 0, 0));
  while (robot.pose().x() < 2.0 - 1e-9) robot.step(std::min(1.0, (2.0 - robot.pose().x()) / 0.1), 0.0, 0.1, {});
  for (int i = 0; i < 200 && robot.speed() > 0.0; ++i) robot.step(0.0, 0.0, 0.1, {});
  const double driven = robot.pose().x();
  EXPECT_NEAR(robot.odometry().x(), 1.02 * driven, 1e-9);
  const double heading_before = robot.pose().phi();
  for (int i = 0; i < 100 && std::abs(robot.pose().phi() - heading_before) < M_PI / 2 - 1e-3; ++i) {
    robot.step(0.0, std::min(1.0, (M_PI / 2 - (robot.pose().phi() - heading_before)) / 0.1), 0.1, {});
  }
  EXPECT_NEAR(robot.odometry().phi(), 1.05 * robot.pose().phi(), 1e-9);

  mrpt::config::CConfigFileMemory config("[sim_robot]\nodometry_distance_bias = 0.6\n");
  IniSection section(config, "sim_robot");
  EXPECT_THROW(loadDifferentialDriveOptions(section), ConfigError);
}

}  // namespace
}  // namespace stereonav
