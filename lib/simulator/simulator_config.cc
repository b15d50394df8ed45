#include "simulator/simulator_config.h"

namespace stereonav {

SimulatorConfig loadSimulatorConfig(const mrpt::config::CConfigFileBase& file, const std::string& path) {
  SimulatorConfig config;
  config.rig = loadIniSection(file, "rig", loadCameraRig, path);
  config.sensor = loadIniSection(file, "sim_sensor", loadSensorOptions, path);
  config.robot = loadIniSection(file, "sim_robot", loadDifferentialDriveOptions, path);
  config.simulation = loadIniSection(file, "simulation", loadSimulationOptions, path);
  config.rawlog = loadIniSection(file, "rawlog", loadRawlogWriterOptions, path);
  config.ground_truth = loadIniSection(file, "ground_truth_map", loadGroundTruthMapOptions, path);
  config.ground_truth.band_max_z = config.robot.height_m;
  return config;
}

}  // namespace stereonav
