#include "closed_loop/exploration_run.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mapping/rawlog_mapping.h"
#include "simulator/world_loader.h"
#include "shipped_config.h"

namespace stereonav {
namespace {

// A 3.5 m x 3 m room with a partition and a crate behind it, small enough for the 160x120 rig's
// short sight (its depth steps are a metre deep beyond ~2.5 m) and for a closed loop in seconds.
// From the start the rig sees most of the room but not behind the partition: the robot has to
// drive round its end (a 1.3 m gap to the north wall).
constexpr const char* kRoom = R"(
[world]
start_pose = 0.8 1.5 0
ceiling_height = 2.5
[wall.room]
points = 0 0; 3.5 0; 3.5 3; 0 3; 0 0
[wall.partition]
points = 2 0; 2 1.7
[box.crate]
center = 2.8 0.8
size = 0.5 0.5
height = 0.8
)";

std::string outputDirectory(const std::string& name) {
  const std::string directory = std::string(STEREONAV_BINARY_DIR) + "/test_outputs/closed_loop/" + name;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

std::string readFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

TEST(ExplorationRunTest, ExploresASmallRoomWithoutCollisionAndTheRecordedRunReplaysToTheSameMap) {
  const World world = loadWorld(mrpt::config::CConfigFileMemory(kRoom), "room.ini");
  const ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  const std::string directory = outputDirectory("room");
  ExplorationJob job;
  job.output_prefix = directory + "/room";
  job.record_rawlog = directory + "/room.rawlog";
  job.max_time_s = 200.0;
  const ExplorationReport report = runExploration(world, config, job);

  // It finishes by itself, having run out of frontiers it can reach or resolve, well before the
  // time limit.
  EXPECT_EQ(report.stop_reason.rfind("no ", 0), 0u) << report.stop_reason;
  EXPECT_NE(report.stop_reason.find("frontier left"), std::string::npos) << report.stop_reason;
  EXPECT_LT(report.sim_time_s, 200.0);
  EXPECT_EQ(report.collisions, 0);
  // Most of the free floor is mapped free (what is missed lies behind the crate and along walls
  // seen only at a grazing angle). The floor inside the walls is 3.4 m x 2.9 m, 9.9 m2, less the
  // crate and the partition, 9.4 m2; the body cannot sweep all of it (corners, the gap beside
  // the crate), so the reachable part is less.
  EXPECT_GE(report.coverage.coverage, 0.7) << report.summary();
  EXPECT_GT(report.coverage.reachable_free_m2, 7.0);
  EXPECT_LT(report.coverage.reachable_free_m2, 9.4);
  // It drove to see past the crate and the partition, not only turned on the spot.
  EXPECT_GT(report.distance_m, 1.0);
  EXPECT_LE(report.top_speed_mps, config.explorer.max_speed_mps + 1e-9);
  EXPECT_NEAR(static_cast<double>(report.frames), report.sim_time_s * config.simulator.simulation.frame_rate_hz, 1.0);

  for (const char* suffix : {".gridmap", ".png", ".yaml", ".pgm", ".3Dscene", ".path.txt", ".truth.txt",
                             ".navlog.csv", ".reactivenavlog", ".path.png", ".plan.png", ".stats.json"}) {
    EXPECT_TRUE(std::filesystem::exists(job.output_prefix + suffix)) << suffix;
  }
  EXPECT_NE(readFile(job.output_prefix + ".stats.json").find("\"collisions\": 0"), std::string::npos);

  // `stereonav map` on the recorded rawlog (odometry poses, same ini) rebuilds the same map.
  MappingJob replay;
  replay.rawlog_path = job.record_rawlog;
  replay.output_prefix = directory + "/replay";
  const MappingReport replayed = mapRawlog(config.mapping, replay);
  EXPECT_EQ(replayed.frames_mapped, report.frames);
  const std::string explored_map = readFile(job.output_prefix + ".pgm");
  ASSERT_FALSE(explored_map.empty());
  EXPECT_EQ(readFile(replay.output_prefix + ".pgm"), explored_map);
}

// Localized poses come from the scan matcher as `stereonav map --poses localized` runs it, so the
// recorded run replays to the same map; each run reports the error of the poses it mapped with
// against the truth, which the files it writes give as well.
TEST(ExplorationRunTest, ALocalizedRunReplaysToTheSameMapAndEveryRunReportsItsPoseError) {
  const World world = loadWorld(mrpt::config::CConfigFileMemory(kRoom), "room.ini");
  ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  // A base whose distances read 3% long and turns 5% large: its dead reckoning drifts at once.
  config.simulator.robot.odometry_distance_bias = 0.03;
  config.simulator.robot.odometry_turn_bias = 0.05;
  // Each step measured on the floor where it is in view (as ini/explore_320x240.ini does): the
  // replay must measure the same steps.
  config.mapping.localization.floor.enabled = true;
  const std::string directory = outputDirectory("localized");
  ExplorationJob job;
  job.max_time_s = 30.0;

  config.pose_source = MapPoseSource::kGroundTruth;
  job.output_prefix = directory + "/truth";
  const ExplorationReport truth = runExploration(world, config, job);
  EXPECT_EQ(truth.trajectory_error.max_m, 0.0);
  EXPECT_EQ(truth.trajectory_error.max_heading_deg, 0.0);
  EXPECT_EQ(truth.frames_localized, 0u);

  config.pose_source = MapPoseSource::kOdometry;
  job.output_prefix = directory + "/odometry";
  const ExplorationReport odometry = runExploration(world, config, job);
  EXPECT_GT(odometry.trajectory_error.max_heading_deg, 1.0) << odometry.summary();
  const TrajectoryError from_files =
      trajectoryError(loadPoseList(job.output_prefix + ".path.txt"), loadPoseList(job.output_prefix + ".truth.txt"));
  EXPECT_NEAR(odometry.trajectory_error.rms_m, from_files.rms_m, 1e-4);
  EXPECT_NEAR(odometry.trajectory_error.max_heading_deg, from_files.max_heading_deg, 1e-2);

  config.pose_source = MapPoseSource::kLocalized;
  job.output_prefix = directory + "/localized";
  job.record_rawlog = directory + "/localized.rawlog";
  const ExplorationReport localized = runExploration(world, config, job);
  EXPECT_GT(localized.frames_localized, 0u) << localized.summary();
  EXPECT_LT(localized.frames_localized, localized.frames);  // the first frame has no map to match
  MappingJob replay;
  replay.rawlog_path = job.record_rawlog;
  replay.output_prefix = directory + "/replay";
  replay.pose_source = MapPoseSource::kLocalized;
  const MappingReport replayed = mapRawlog(config.mapping, replay);
  EXPECT_EQ(replayed.frames_localized, localized.frames_localized);
  // The first frame has no step, and some look at a wall with no floor in view.
  EXPECT_GT(localized.frames_floor_measured, 0u);
  EXPECT_LT(localized.frames_floor_measured, localized.frames);
  EXPECT_EQ(replayed.frames_floor_measured, localized.frames_floor_measured);
  const std::vector<mrpt::poses::CPose2D> explored_path = loadPoseList(job.output_prefix + ".path.txt");
  ASSERT_EQ(replayed.path.size(), explored_path.size());
  for (size_t i = 0; i < explored_path.size(); ++i) {
    EXPECT_NEAR(replayed.path[i].distanceTo(explored_path[i]), 0.0, 1e-4) << "frame " << i;
  }
  const std::string explored_map = readFile(job.output_prefix + ".pgm");
  ASSERT_FALSE(explored_map.empty());
  EXPECT_EQ(readFile(replay.output_prefix + ".pgm"), explored_map);
}

TEST(ExplorationRunTest, StopRequestEndsTheRunWithEveryOutputWrittenAndProgressCountsFrames) {
  const World world = loadWorld(mrpt::config::CConfigFileMemory(kRoom), "room.ini");
  const ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  ASSERT_EQ(config.simulator.simulation.frame_rate_hz, 5.0);
  const std::string directory = outputDirectory("stopped");
  ExplorationJob job;
  job.output_prefix = directory + "/room";
  job.record_rawlog = directory + "/room.rawlog";
  job.max_time_s = 60.0;
  std::vector<size_t> frames_seen;
  size_t frame_limit = 0;
  ExplorationCallbacks callbacks;
  callbacks.on_frame = [&](size_t frames, size_t limit) {
    frames_seen.push_back(frames);
    frame_limit = limit;
  };
  callbacks.stop_requested = [&] { return frames_seen.size() == 4; };
  const ExplorationReport report = runExploration(world, config, job, callbacks);

  EXPECT_TRUE(report.interrupted);
  EXPECT_EQ(report.stop_reason, "interrupted");
  EXPECT_EQ(frames_seen, (std::vector<size_t>{1, 2, 3, 4}));
  EXPECT_EQ(frame_limit, 301u);  // frames at t = 0, 0.2, ..., 60 s
  EXPECT_EQ(report.frames, 4u);
  for (const char* suffix : {".gridmap", ".png", ".path.png", ".path.txt", ".stats.json"}) {
    EXPECT_TRUE(std::filesystem::exists(job.output_prefix + suffix)) << suffix;
  }
  // The recorded rawlog is complete up to the stop: it replays all four frames.
  MappingJob replay;
  replay.rawlog_path = job.record_rawlog;
  replay.output_prefix = directory + "/replay";
  EXPECT_EQ(mapRawlog(config.mapping, replay).frames_mapped, 4u);
}

// The shipped exploration config with `from` replaced by `to`, written as `name` in `directory`
// and loaded: the ConfigError's message, or "" if it loaded.
std::string configErrorAfterEdit(const std::string& directory, const std::string& name,
                                 const std::string& from, const std::string& to) {
  std::string text = readFile(testing::shippedExplorationConfigPath());
  text.replace(text.find(from), from.size(), to);
  std::ofstream(directory + "/" + name) << text;
  try {
    loadExplorationConfig(directory + "/" + name);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(ExplorationRunTest, ConfigErrorsNameTheFileSectionAndKey) {
  const std::string directory = outputDirectory("config");
  const std::string small_radius =
      configErrorAfterEdit(directory, "small_radius.ini", "robot_radius_m = 0.3", "robot_radius_m = 0.2");
  EXPECT_NE(small_radius.find("small_radius.ini: [explorer] robot_radius_m"), std::string::npos)
      << "a radius below the robot's: '" << small_radius << "'";

  const std::string typo = configErrorAfterEdit(directory, "typo.ini", "lookahead_m", "lookahed_m");
  EXPECT_NE(typo.find("typo.ini"), std::string::npos) << "an unknown key: '" << typo << "'";
  EXPECT_NE(typo.find("lookahed_m"), std::string::npos) << typo;

  const std::string gps =
      configErrorAfterEdit(directory, "gps.ini", "pose_source = odometry", "pose_source = gps");
  EXPECT_NE(gps.find("gps.ini"), std::string::npos) << "an unknown pose source: '" << gps << "'";
  EXPECT_NE(gps.find("[explorer] pose_source"), std::string::npos) << gps;
  EXPECT_NE(gps.find("localized"), std::string::npos) << gps;
}

}  // namespace
}  // namespace stereonav
