
#include <iostream>
#include <optional>

#include "command_line.h"
#include "commands.h"
#include "common/ini_section.h"
#include "simulator/ground_truth_map.h"
#include "simulator/motion_plan.h"
#include "simulator/simulation.h"
#include "simulator/simulation_recorder.h"
#include "simulator/simulator_config.h"
#include "simulator/world_loader.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav simulate --world W.ini --config C.ini --path PATH.txt --out OUT.rawlog\n"
    "                          [--gt-map MAP.yaml]\n"
    "Drives a simulated robot through the world along PATH.txt (lines 'x y': waypoints, or\n"
    "'t v w': velocity commands from time t) and records the rig's frames with odometry in\n"
    "OUT.rawlog, the true pose of every frame in OUT.gt.txt ('t x y phi'), and optionally the\n"
    "world's true occupancy as a ROS map. C.ini sections: [rig], [sim_sensor], [sim_robot],\n"
    "[simulation], [rawlog], [ground_truth_map].\n";

}  // namespace

int runSimulateCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string world_path = command_line.required("world");
  const std::string config_path = command_line.required("config");
  const std::string plan_path = command_line.required("path");
  const std::string rawlog_path = command_line.required("out");
  const std::optional<std::string> map_path = command_line.value("gt-map");
  command_line.rejectUnknown();

  const World world = loadWorld(world_path);
  const SimulatorConfig config = loadSimulatorConfig(readConfigFile(config_path), config_path);
  const MotionPlan plan = loadMotionPlan(plan_path);

  // Built before the run, so that a world too large for its map fails before the work.
  std::optional<GroundTruthMap> ground_truth_map;
  if (map_path) {
    try {
      ground_truth_map.emplace(world, config.ground_truth);
    } catch (const ConfigError& error) {
      throw ConfigError(config_path + ": " + error.what() + " (world " + world_path + ")");
    }
  }
  SimulationRecorder::checkRecordable(config.rig, config_path);
  SimulationRecorder recorder(rawlog_path, config.rawlog, config.rig);
  Simulation simulation(world, config.rig, config.sensor, config.robot, config.simulation);
  const SimulationSummary summary = simulation.run(plan, [&](const SimulatedFrame& frame) { recorder.record(frame); });
  recorder.finish();
  if (ground_truth_map) ground_truth_map->writeRosMap(*map_path);

  std::cout << "simulated " << summary.frames << " frames over " << summary.duration_s << " s, "
            << summary.distance_m << " m driven, " << summary.collisions << " collision(s); "
            << (summary.plan_completed ? "path completed" : "stopped at max_duration_s before the end of the path")
            << "\nwrote " << rawlog_path << " and " << SimulationRecorder::groundTruthPath(rawlog_path)
            << (map_path ? " and " + *map_path : "") << "\n";
  return 0;
}

}  // namespace stereonav::app
