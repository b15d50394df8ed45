#pragma once

#include <string>

#include "closed_loop/simulated_robot_interface.h"
#include "explorer/explorer_options.h"
#include "mapping/mapping_options.h"
#include "simulator/simulator_config.h"

namespace stereonav {

// Everything a closed-loop exploration run is configured with, from one ini file: the
// simulator's sections ([rig] [sim_sensor] [sim_robot] [simulation] [rawlog] [ground_truth_map],
// as `stereonav simulate` reads them), the mapping pipeline's (as `stereonav map` reads them,
// so a recorded run replays to the same map) and [explorer]. Unknown keys are rejected.
struct ExplorationConfig {
  // Of [simulation], frame_rate_hz, control_rate_hz and max_duration_s are used.
  SimulatorConfig simulator;
  MappingOptions mapping;
  ExplorerOptions explorer;
  // [explorer] pose_source = odometry | localized | ground_truth (simulated_robot_interface.h);
  // localized matches scans as mapping.localization says.
  MapPoseSource pose_source = MapPoseSource::kOdometry;
};

// Throws ConfigError naming the file, section and key.
ExplorationConfig loadExplorationConfig(const std::string& path);

}  // namespace stereonav
