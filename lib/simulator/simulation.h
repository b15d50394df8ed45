#pragma once

#include <mrpt/poses/CPose2D.h>

#include <functional>

#include "common/ini_section.h"
#include "rig/camera_rig.h"
#include "simulator/differential_drive_robot.h"
#include "simulator/motion_plan.h"
#include "simulator/rig_renderer.h"
#include "simulator/world.h"

namespace stereonav {

struct SimulationOptions {
  double frame_rate_hz = 5.0;     // the paper processes stereo at 5 Hz (abstract)
  double control_rate_hz = 50.0;  // robot motion is integrated and commanded at this rate
  // Waypoint following: cruising speed, how near a waypoint counts as reached, and the turn rate
  // commanded per radian of heading error.
  double cruise_speed_mps = 1.0;
  double waypoint_tolerance_m = 0.25;
  double heading_gain = 2.0;
  double max_duration_s = 600.0;  // a run that has not finished its plan by then stops
};

// Section [simulation]: frame_rate_hz, control_rate_hz (>= frame_rate_hz), cruise_speed_mps,
// waypoint_tolerance_m, heading_gain, max_duration_s.
SimulationOptions loadSimulationOptions(IniSection& section);

// What the rig saw at one frame time, and the truth about that moment.
struct SimulatedFrame {
  double time_s = 0.0;  // since the start of the run
  RigImages images;
  mrpt::poses::CPose2D true_pose;
  mrpt::poses::CPose2D odometry;
  int collisions = 0;  // so far
};

struct SimulationSummary {
  size_t frames = 0;
  double duration_s = 0.0;
  double distance_m = 0.0;
  int collisions = 0;
  bool plan_completed = false;  // false: stopped at max_duration_s
};

// Drives a simulated robot through a World along a MotionPlan, starting at the world's start
// pose, and hands every rig frame (at frame_rate_hz, the first at time 0) to a callback.
class Simulation {
 public:
  Simulation(const World& world, const CameraRig& rig, const SensorOptions& sensor,
             const DifferentialDriveOptions& robot, const SimulationOptions& options);

  SimulationSummary run(const MotionPlan& plan,
                        const std::function<void(const SimulatedFrame&)>& on_frame);

 private:
  const World& world_;
  CameraRig rig_;
  SensorOptions sensor_;
  DifferentialDriveOptions robot_;
  SimulationOptions options_;
};

}  // namespace stereonav
