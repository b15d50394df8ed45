#include "closed_loop/exploration_config.h"

#include "common/ini_section.h"

namespace stereonav {

ExplorationConfig loadExplorationConfig(const std::string& path) {
  const mrpt::config::CConfigFileMemory file = readConfigFile(path);
  ExplorationConfig config;
  config.simulator = loadSimulatorConfig(file, path);
  config.explorer = loadIniSection(file, "explorer", [&](IniSection& section) {
    ExplorerOptions options = loadExplorerOptions(section);
    try {
      config.pose_source = parseMapPoseSource(section.getString("pose_source", "odometry"));
    } catch (const std::invalid_argument& error) {
      throw ConfigError(std::string("[explorer] pose_source: ") + error.what());
    }
    return options;
  }, path);
  try {
    config.mapping = loadMappingOptions(file);
  } catch (const ConfigError& error) {
    throw ConfigError(path + ": " + error.what());
  }
  if (config.explorer.robot_radius_m < config.simulator.robot.radius_m) {
    throw ConfigError(path + ": [explorer] robot_radius_m: smaller than the robot's ([sim_robot] radius_m)");
  }
  return config;
}

}  // namespace stereonav
