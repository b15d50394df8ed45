// A wall in flat paint has nothing for stereo to match (issue 18): the map and the guard know it
// only from the textured floor's end at its foot (ProjectionOptions::floor_end_max_depth_m as a
// reading, floor_end_clear_max_depth_m for the guard), or, nearer than the floor the camera can
// see, from the floor missing from the image's bottom rows (ProjectionOptions::near_floor_m).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "closed_loop/exploration_run.h"
#include "closed_loop/simulated_robot_interface.h"
#include "explorer/safety_guard.h"
#include "mapping/map_outputs.h"
#include "mapping/stereo_mapper.h"
#include "simulator/simulation.h"
#include "simulator/world_loader.h"
#include "corridor_world.h"
#include "shipped_config.h"

namespace stereonav {
namespace {

// The corridor (corridor_world.h) with the robot starting at (start_x, 0.8), looking at its
// painted end wall.
World corridorFrom(double start_x) { return testing::corridorWorld(start_x, "flat"); }
constexpr double kEndWallFace = testing::kCorridorEndWallFace;

// Occupied cells in the strip just before and in the end wall (x 4.75 .. 5.05), across the
// corridor away from the side walls (y 0.45 .. 1.15: eight rows of 0.1 m cells).
int occupiedAtTheEndWall(const DisparityTaggedGrid& grid, const OccupancyScale& scale) {
  int rows = 0;
  for (double y = 0.45; y <= 1.15 + 1e-9; y += 0.1) {
    bool occupied = false;
    for (double x = 4.75; x <= 5.05 + 1e-9; x += 0.1) {
      int col = 0, row = 0;
      if (grid.cellAt(x, y, col, row)) occupied |= scale.classify(grid.occupancy(col, row)) == CellClass::kOccupied;
    }
    rows += occupied;
  }
  return rows;
}

// The robot stands at x = 3.2, 1.75 m from the painted wall, looking at it, for 2 s (ten frames).
int rowsMarkedFromAStandstill(const ExplorationConfig& config) {
  const World world = corridorFrom(3.2);
  const SimulatorConfig& simulator = config.simulator;
  Simulation simulation(world, simulator.rig, simulator.sensor, simulator.robot, simulator.simulation);
  StereoMapper mapper(config.mapping, simulator.rig);
  simulation.run(parseMotionPlan("0 0 0\n2 0 0\n", "stand.txt"), [&](const SimulatedFrame& frame) {
    mapper.process(rigFrameOf(frame, simulator.rig), frame.odometry);
  });
  const OccupancyScale& scale = config.mapping.grid.stereo.update.scale;
  return occupiedAtTheEndWall(gridOfMap(mapper.map(), scale), scale);
}

TEST(UnmatchedWallTest, TheMapMarksAFlatPaintedWallAtTheFloorsEnd) {
  ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  config.mapping.projection.floor_end_max_depth_m = 2.0;  // beyond the wall's 1.75 m
  EXPECT_GE(rowsMarkedFromAStandstill(config), 6);
  // The paper's projection: the paint matches nothing, so nothing is marked there.
  config.mapping.projection.floor_end_max_depth_m = 0.0;
  EXPECT_EQ(rowsMarkedFromAStandstill(config), 0);
}

// It explores towards the painted wall and stops short of it, without a collision.
void expectStopsShortOfThePaintedWall(const ExplorationConfig& config, const std::string& name) {
  SCOPED_TRACE(name);
  const World world = corridorFrom(0.8);
  const std::string directory = std::string(STEREONAV_BINARY_DIR) + "/test_outputs/closed_loop/unmatched_wall";
  std::filesystem::create_directories(directory);
  ExplorationJob job;
  job.output_prefix = directory + "/" + name;
  job.max_time_s = 90.0;
  const ExplorationReport report = runExploration(world, config, job);
  EXPECT_EQ(report.collisions, 0) << report.summary();
  // It drove down the corridor, and its body stayed short of the painted wall's face (the
  // true poses, x y yaw per line after the time).
  std::ifstream truth(job.output_prefix + ".truth.txt");
  double farthest = 0.0;
  for (std::string line; std::getline(truth, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double time = 0.0, x = 0.0;
    fields >> time >> x;
    farthest = std::max(farthest, x);
  }
  EXPECT_GT(farthest, 2.0) << report.summary();
  EXPECT_LT(farthest + config.simulator.robot.radius_m, kEndWallFace) << report.summary();
}

TEST(UnmatchedWallTest, TheExplorerStopsShortOfAFlatPaintedWall) {
  ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  expectStopsShortOfThePaintedWall(config, "corridor");
  config.mapping.projection.floor_end_max_depth_m = 2.0;
  expectStopsShortOfThePaintedWall(config, "corridor_floor_end");
}

// The explorer's guard, fed what the head senses (CSimulatedRobotInterface::setSensedScan, as
// exploration_run.cc feeds it), holds a robot told to drive at 0.5 m/s straight ahead from the
// world's start for 4 s. Returns the collisions.
int collisionsDrivingAt(const World& world, const ExplorationConfig& config) {
  const SimulatorConfig& simulator = config.simulator;
  Simulation simulation(world, simulator.rig, simulator.sensor, simulator.robot, simulator.simulation);
  CSimulatedRobotInterface robot(simulation, MapPoseSource::kGroundTruth);
  StereoMapper mapper(config.mapping, simulator.rig);
  SafetyGuard guard(config.explorer);
  while (!simulation.timeUp(4.0)) {
    if (simulation.frameDue()) {
      const SimulatedFrame frame = simulation.renderFrame();
      const RigFrame rig_frame = rigFrameOf(frame, simulator.rig);
      mapper.process(rig_frame, frame.odometry);
      robot.setSensedScan(mapper.disparityScan().scan, simulator.rig, config.explorer.robot_radius_m, 5.0,
                          rig_frame.timestamp, robot.pose());
    }
    guard.readScan(robot, robot.pose(), simulation.time(), nullptr);
    const VelocityCommand command = guard.guard({0.5, 0.0}, robot.pose());
    simulation.step(command.speed, command.turn_rate);
  }
  return static_cast<int>(simulation.collisionEvents().size());
}

// From 0.6 m, nearer than the floor the camera can see (from 0.82 m ahead of the robot's centre),
// the camera sees only paint: nothing is matched, and only the missing floor stops the robot.
TEST(UnmatchedWallTest, TheGuardHoldsTheRobotBeforeAPaintedWallNearerThanTheFloorItSees) {
  constexpr double kStartX = kEndWallFace - 0.6;
  ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  config.mapping.projection.near_floor_m = 0.3;
  EXPECT_EQ(collisionsDrivingAt(corridorFrom(kStartX), config), 0);
  config.mapping.projection.near_floor_m = 0.0;
  EXPECT_GT(collisionsDrivingAt(corridorFrom(kStartX), config), 0);
}

// From 1.2 m the camera sees the floor (from 0.82 m ahead of the robot's centre) up to the paint,
// and nothing of the paint: where the floor ends is the only sign of it.
TEST(UnmatchedWallTest, TheGuardStopsShortOfThePaintsFootWhereTheFloorEnds) {
  constexpr double kStartX = kEndWallFace - 1.2;
  ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  config.mapping.projection.floor_end_clear_max_depth_m = 8.0;  // as ini/explore_320x240.ini
  EXPECT_EQ(collisionsDrivingAt(corridorFrom(kStartX), config), 0);
  config.mapping.projection.floor_end_clear_max_depth_m = 0.0;
  EXPECT_GT(collisionsDrivingAt(corridorFrom(kStartX), config), 0);
}

}  // namespace
}  // namespace stereonav
