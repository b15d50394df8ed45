#include "simulator/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/ini_section.h"
#include "observations/rawlog_reader.h"
#include "simulator/simulation_recorder.h"
#include "world_text.h"

namespace stereonav {
namespace {

CameraRig tinyRig() {
  CameraRig rig;
  rig.reference = {32, 24, 16.0, 15.5, 11.5};
  return rig;
}

DifferentialDriveOptions exactOdometry() {
  DifferentialDriveOptions robot;
  robot.odometry_distance_noise = 0.0;
  robot.odometry_turn_noise = 0.0;
  robot.odometry_drift_rad_per_m = 0.0;
  return robot;
}

TEST(Simulation, TimedCommandsAreDrivenForTheirDurationsWithFramesAtTheFrameRate) {
  const World world = worldFromText("[world]\nstart_pose = 1 2 0\n");
  const MotionPlan plan = parseMotionPlan("0 1 0\n2 0 0\n3 0 0\n", "plan.txt");
  Simulation simulation(world, tinyRig(), SensorOptions{}, exactOdometry(), SimulationOptions{});
  std::vector<double> frame_times;
  mrpt::poses::CPose2D last_pose;
  const SimulationSummary summary = simulation.run(plan, [&](const SimulatedFrame& frame) {
    frame_times.push_back(frame.time_s);
    last_pose = frame.true_pose;
    EXPECT_EQ(frame.images.reference.cols, 32);
    EXPECT_EQ(frame.images.secondaries.size(), 2u);
  });
  // 5 Hz over 3 s: t = 0, 0.2, ..., 3.0.
  ASSERT_EQ(frame_times.size(), 16u);
  for (size_t k = 0; k < frame_times.size(); ++k) EXPECT_NEAR(frame_times[k], 0.2 * k, 1e-9);
  // At 1 m/s^2 and 50 Hz: 0.51 m speeding up to 1 m/s, 1.0 m at 1 m/s, 0.49 m slowing down.
  EXPECT_NEAR(summary.distance_m, 2.0, 1e-9);
  EXPECT_NEAR(last_pose.x(), 3.0, 1e-9);
  EXPECT_NEAR(last_pose.y(), 2.0, 1e-12);
  EXPECT_TRUE(summary.plan_completed);
  EXPECT_EQ(summary.collisions, 0);
}

TEST(Simulation, WaypointsAreReachedInOrderAroundAnObstacle) {
  // A box between start and goal; the waypoints lead round it.
  const World world = worldFromText(
      "[world]\nstart_pose = 0 0 0\n[box.b]\ncenter = 2 0\nsize = 1 1\n");
  const MotionPlan plan = parseMotionPlan("1 1.5\n3 1.5\n4 0\n", "plan.txt");
  SimulationOptions options;
  options.waypoint_tolerance_m = 0.1;
  Simulation simulation(world, tinyRig(), SensorOptions{}, exactOdometry(), options);
  mrpt::poses::CPose2D last_pose;
  const SimulationSummary summary =
      simulation.run(plan, [&](const SimulatedFrame& frame) { last_pose = frame.true_pose; });
  EXPECT_TRUE(summary.plan_completed);
  EXPECT_EQ(summary.collisions, 0);
  EXPECT_LT(std::hypot(last_pose.x() - 4.0, last_pose.y()), 0.25);
}

TEST(Simulation, RunStopsAtTheTimeLimitWhenStuck) {
  const World world = worldFromText("[wall.w]\npoints = 2 -5; 2 5\n");
  const MotionPlan plan = parseMotionPlan("5 0\n", "plan.txt");
  SimulationOptions options;
  options.max_duration_s = 4.0;
  Simulation simulation(world, tinyRig(), SensorOptions{}, exactOdometry(), options);
  const SimulationSummary summary = simulation.run(plan, [](const SimulatedFrame&) {});
  EXPECT_FALSE(summary.plan_completed);
  EXPECT_EQ(summary.collisions, 1);
  EXPECT_NEAR(summary.duration_s, 4.0, 1e-9);
}

TEST(Simulation, ACollisionNamesTheSectionAndTextureOfWhatWasHit) {
  // Driving east at 1 m/s from x = 0: the painted wall at x = 2 (its face at 1.95, half its 0.1 m
  // thickness nearer) stops the body (radius 0.3 m) at x = 1.65. The crate beside the path is not
  // touched; the lamp over the body's stop (z 1.5 m, above its 1 m) is not hit.
  const World world = worldFromText(
      "[world]\nstart_pose = 0 0 0\n[texture.paint]\ntype = paint\nmean = 0.7\n"
      "[wall.east]\npoints = 2 -5; 2 5\ntexture = paint\n"
      "[box.crate]\ncenter = 1 1\nsize = 0.4 0.4\n[box.lamp]\ncenter = 1.8 0\nsize = 0.4 0.4\nz = 1.5\n");
  const MotionPlan plan = parseMotionPlan("0 1 0\n4 0 0\n", "plan.txt");
  Simulation simulation(world, tinyRig(), SensorOptions{}, exactOdometry(), SimulationOptions{});
  simulation.run(plan, [](const SimulatedFrame&) {});
  ASSERT_EQ(simulation.collisionEvents().size(), 1u);
  EXPECT_EQ(simulation.collisionEvents()[0].with, "wall.east (paint)");
  EXPECT_NEAR(simulation.collisionEvents()[0].x, 1.65, 0.03);
}

TEST(SimulationRecorder, ARigWhoseFirstCameraIsNotBesideTheReferenceIsRejectedNamingTheFile) {
  CameraRig rig = tinyRig();
  EXPECT_NO_THROW(SimulationRecorder::checkRecordable(rig, "sim.ini"));
  rig.secondaries = {{-1.0, -1.0}, {0.0, -1.0}};  // found by the black-box campaign
  try {
    SimulationRecorder::checkRecordable(rig, "sim.ini");
    FAIL() << "accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("sim.ini: [rig] secondary_cameras: ", 0), 0u) << error.what();
  }
  rig.secondaries = {{0.0, -1.0}, {1.0, 0.0}};  // beside the reference, but not first
  EXPECT_THROW(SimulationRecorder::checkRecordable(rig, "sim.ini"), ConfigError);
}

TEST(SimulationRecorder, RawlogHoldsEveryFrameWithOdometryAndTheTruthIsBesideIt) {
  const World world = worldFromText("[world]\nstart_pose = 0 0 0\n[wall.w]\npoints = 6 -5; 6 5\n");
  const MotionPlan plan = parseMotionPlan("0 0.5 0.1\n1 0 0\n", "plan.txt");
  DifferentialDriveOptions robot;  // noisy odometry
  const CameraRig rig = tinyRig();
  const std::filesystem::path directory = std::filesystem::path(STEREONAV_BINARY_DIR) / "simulation_recorder_test";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const std::string rawlog = (directory / "run.rawlog").string();
  std::vector<SimulatedFrame> frames;
  {
    SimulationRecorder recorder(rawlog, RawlogWriterOptions{}, rig);
    Simulation(world, rig, SensorOptions{}, robot, SimulationOptions{}).run(plan, [&](const SimulatedFrame& frame) {
      recorder.record(frame);
      frames.push_back(frame);
    });
    recorder.finish();
  }
  ASSERT_EQ(frames.size(), 6u);  // t = 0 .. 1 s at 5 Hz

  RawlogReader reader(rawlog, RawlogReaderOptions{});
  size_t k = 0;
  while (auto frame = reader.next()) {
    ASSERT_LT(k, frames.size());
    ASSERT_TRUE(frame->odometry.has_value());
    EXPECT_NEAR(frame->odometry->x(), frames[k].odometry.x(), 1e-6);
    EXPECT_NEAR(frame->odometry->phi(), frames[k].odometry.phi(), 1e-6);
    EXPECT_EQ(cv::norm(frame->reference, frames[k].images.reference, cv::NORM_INF), 0.0);
    ASSERT_EQ(frame->secondaries.size(), 2u);
    EXPECT_EQ(cv::norm(frame->secondaries[1], frames[k].images.secondaries[1], cv::NORM_INF), 0.0);
    ++k;
  }
  EXPECT_EQ(k, frames.size());

  std::ifstream truth((directory / "run.gt.txt").string());
  ASSERT_TRUE(truth.good());
  std::string line;
  size_t lines = 0;
  while (std::getline(truth, line)) {
    std::istringstream fields(line);
    double t, x, y, phi;
    ASSERT_TRUE(fields >> t >> x >> y >> phi) << line;
    ASSERT_LT(lines, frames.size());
    EXPECT_NEAR(t, frames[lines].time_s, 1e-6);
    EXPECT_NEAR(x, frames[lines].true_pose.x(), 1e-6);
    EXPECT_NEAR(phi, frames[lines].true_pose.phi(), 1e-6);
    ++lines;
  }
  EXPECT_EQ(lines, frames.size());
  EXPECT_EQ(SimulationRecorder::groundTruthPath("a/b.rawlog"), "a/b.gt.txt");
}

}  // namespace
}  // namespace stereonav
