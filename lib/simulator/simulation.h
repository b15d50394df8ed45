#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <string>
#include <vector>

#include "common/ini_section.h"
#include "observations/rig_frame.h"
#include "rig/camera_rig.h"
#include "simulator/differential_drive_robot.h"
#include "simulator/motion_plan.h"
#include "simulator/moving_traffic.h"
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

// A run's time as a timestamp: 2000-01-01T00:00:00Z plus `time_s`, so runs are reproducible.
mrpt::Clock::time_point simulationTimestamp(double time_s);

// The frame as the rig would deliver it to the mapping pipeline or a rawlog: images, odometry and
// simulationTimestamp(frame.time_s).
RigFrame rigFrameOf(const SimulatedFrame& frame, const CameraRig& rig);

// A contact the simulator counted: when, where (true pose) and with what.
struct CollisionEvent {
  double time_s = 0.0;
  double x = 0.0;
  double y = 0.0;
  double speed_mps = 0.0;  // the robot's speed just before
  // What was touched: a moving obstacle's section ("moving.person"), or a static solid's with
  // its texture ("wall.w15 (paint_1)"); "static" if nothing lies within a centimetre of the body.
  std::string with;
};

struct SimulationSummary {
  size_t frames = 0;
  double duration_s = 0.0;
  double distance_m = 0.0;
  int collisions = 0;
  bool plan_completed = false;  // false: stopped at max_duration_s
};

// Drives a simulated robot through a World, from its start pose (or another), with moving
// traffic: every control period (1 / control_rate_hz) the robot takes a velocity command, and at
// frame_rate_hz (the first frame at time 0) the rig renders a frame. run() drives it along a
// MotionPlan; a closed loop (closed_loop/exploration_run.h) steps it itself:
//   while (true) { if (frameDue()) use(renderFrame()); if (timeUp(limit)) break; step(command); }
class Simulation {
 public:
  Simulation(const World& world, const CameraRig& rig, const SensorOptions& sensor,
             const DifferentialDriveOptions& robot, const SimulationOptions& options);
  Simulation(const World& world, const CameraRig& rig, const SensorOptions& sensor,
             const DifferentialDriveOptions& robot, const SimulationOptions& options,
             const mrpt::poses::CPose2D& start);

  // Follows `plan` until it is completed or max_duration_s, handing every frame to `on_frame`.
  SimulationSummary run(const MotionPlan& plan, const std::function<void(const SimulatedFrame&)>& on_frame);

  // The next frame's time has come.
  bool frameDue() const;
  // Renders the frame of now.
  SimulatedFrame renderFrame();
  // The simulation clock has reached `limit_s`.
  bool timeUp(double limit_s) const;
  // One control period with this command: the traffic moves, then the robot (stopped by what it
  // touches); contacts are recorded.
  void step(double speed, double turn_rate);

  double time() const { return time_; }
  const DifferentialDriveRobot& robot() const { return robot_; }
  size_t frames() const { return frames_; }
  double distance() const { return distance_m_; }
  double topSpeed() const { return top_speed_mps_; }
  const std::vector<CollisionEvent>& collisionEvents() const { return collision_events_; }

 private:
  void recordCollision(double time_s, double speed_before);

  const World& world_;
  DifferentialDriveOptions robot_options_;
  SimulationOptions options_;
  DifferentialDriveRobot robot_;
  RigRenderer renderer_;
  MovingTraffic traffic_;
  double time_ = 0.0;
  size_t steps_ = 0;
  size_t frames_ = 0;
  double distance_m_ = 0.0;
  double top_speed_mps_ = 0.0;
  std::vector<CollisionEvent> collision_events_;
};

}  // namespace stereonav
