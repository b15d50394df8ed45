#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>

#include "observations/rawlog_writer.h"
#include "rig/camera_rig.h"
#include "simulator/differential_drive_robot.h"
#include "simulator/ground_truth_map.h"
#include "simulator/rig_renderer.h"
#include "simulator/simulation.h"

namespace stereonav {

// The simulator's part of a run configuration, as `stereonav simulate` and `stereonav explore`
// both read it: [rig] [sim_sensor] [sim_robot] [simulation] [rawlog] [ground_truth_map].
struct SimulatorConfig {
  CameraRig rig;
  SensorOptions sensor;
  DifferentialDriveOptions robot;
  SimulationOptions simulation;
  RawlogWriterOptions rawlog;
  // Its height band is the robot's body ([sim_robot] height_m), so the true map shows what the
  // robot can hit.
  GroundTruthMapOptions ground_truth;
};

// Unknown keys in these sections are rejected; errors are ConfigErrors naming `path`, the
// section and the key.
SimulatorConfig loadSimulatorConfig(const mrpt::config::CConfigFileBase& file, const std::string& path);

}  // namespace stereonav
