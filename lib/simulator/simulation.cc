#include "simulator/simulation.h"

#include <mrpt/math/wrap2pi.h>

#include "simulator/footprint_overlap.h"

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

// Event times are compared with this slack, so that frame and command times that are exact in
// decimal are not missed by a rounding error of the step clock.
constexpr double kTimeSlack = 1e-9;

struct Velocity {
  double speed = 0.0;
  double turn_rate = 0.0;
};

// Head for the waypoint, slowing down as the heading error grows and turning on the spot when it
// is more than 60 degrees off; and slow down in time (with the robot's deceleration) to take the
// turn onto the next leg, or to stop on the final waypoint.
Velocity steerTowards(const mrpt::poses::CPose2D& pose, const std::vector<Point2>& waypoints, size_t target,
                      double deceleration, const SimulationOptions& options) {
  const Point2& goal = waypoints[target];
  const double bearing = std::atan2(goal.y - pose.y(), goal.x - pose.x());
  const double error = mrpt::math::wrapToPi(bearing - pose.phi());
  const double alignment = std::cos(error);
  double speed = alignment > 0.5 ? options.cruise_speed_mps * alignment : 0.0;
  double speed_at_goal = 0.0;
  if (target + 1 < waypoints.size()) {
    const Point2& next = waypoints[target + 1];
    const double turn = std::cos(mrpt::math::wrapToPi(std::atan2(next.y - goal.y, next.x - goal.x) - bearing));
    speed_at_goal = turn > 0.5 ? options.cruise_speed_mps * turn : 0.0;
  }
  const double distance = std::hypot(goal.x - pose.x(), goal.y - pose.y());
  speed = std::min(speed, std::sqrt(speed_at_goal * speed_at_goal + 2.0 * deceleration * distance));
  return {speed, options.heading_gain * error};
}

}  // namespace

SimulationOptions loadSimulationOptions(IniSection& section) {
  SimulationOptions options;
  options.frame_rate_hz = section.getPositive("frame_rate_hz", options.frame_rate_hz, 1000.0);
  options.control_rate_hz = section.getPositive("control_rate_hz", options.control_rate_hz, 10000.0);
  options.cruise_speed_mps = section.getPositive("cruise_speed_mps", options.cruise_speed_mps, 100.0);
  options.waypoint_tolerance_m = section.getPositive("waypoint_tolerance_m", options.waypoint_tolerance_m, 1000.0);
  options.heading_gain = section.getPositive("heading_gain", options.heading_gain, 1000.0);
  options.max_duration_s = section.getPositive("max_duration_s", options.max_duration_s, 86400.0);
  if (options.control_rate_hz < options.frame_rate_hz) {
    throw ConfigError("[" + section.name() + "] control_rate_hz: must be at least frame_rate_hz");
  }
  return options;
}

mrpt::Clock::time_point simulationTimestamp(double time_s) {
  constexpr double kRunEpoch = 946684800.0;  // 2000-01-01T00:00:00Z, seconds since 1970
  return mrpt::Clock::fromDouble(kRunEpoch + time_s);
}

RigFrame rigFrameOf(const SimulatedFrame& frame, const CameraRig& rig) {
  RigFrame rig_frame;
  rig_frame.timestamp = simulationTimestamp(frame.time_s);
  rig_frame.reference = frame.images.reference;
  rig_frame.secondaries.assign(frame.images.secondaries.begin(), frame.images.secondaries.end());
  rig_frame.rig = rig;
  rig_frame.odometry = frame.odometry;
  return rig_frame;
}

Simulation::Simulation(const World& world, const CameraRig& rig, const SensorOptions& sensor,
                       const DifferentialDriveOptions& robot, const SimulationOptions& options)
    : Simulation(world, rig, sensor, robot, options,
                 mrpt::poses::CPose2D(world.start_pose[0], world.start_pose[1], world.start_pose[2])) {}

Simulation::Simulation(const World& world, const CameraRig& rig, const SensorOptions& sensor,
                       const DifferentialDriveOptions& robot, const SimulationOptions& options,
                       const mrpt::poses::CPose2D& start)
    : world_(world),
      robot_options_(robot),
      options_(options),
      robot_(world, robot, start),
      renderer_(world, rig, sensor),
      traffic_(world) {}

bool Simulation::frameDue() const {
  return time_ >= static_cast<double>(frames_) / options_.frame_rate_hz - kTimeSlack;
}

SimulatedFrame Simulation::renderFrame() {
  SimulatedFrame frame;
  frame.time_s = time_;
  frame.images = renderer_.render(robot_.pose(), time_, traffic_.solids());
  frame.true_pose = robot_.pose();
  frame.odometry = robot_.odometry();
  frame.collisions = robot_.collisionCount();
  ++frames_;
  return frame;
}

bool Simulation::timeUp(double limit_s) const { return time_ >= limit_s - kTimeSlack; }

void Simulation::step(double speed, double turn_rate) {
  const double dt = 1.0 / options_.control_rate_hz;
  const mrpt::poses::CPose2D before = robot_.pose();
  const double speed_before = robot_.speed();
  const int collisions_before = robot_.collisionCount();
  traffic_.advance(dt, robot_.pose(), robot_.speed(), robot_options_.radius_m);
  robot_.step(speed, turn_rate, dt, traffic_.solids());
  if (robot_.collisionCount() > collisions_before) recordCollision(time_ + dt, speed_before);
  distance_m_ += std::hypot(robot_.pose().x() - before.x(), robot_.pose().y() - before.y());
  top_speed_mps_ = std::max(top_speed_mps_, std::abs(robot_.speed()));
  time_ = static_cast<double>(++steps_) * dt;
}

void Simulation::recordCollision(double time_s, double speed_before) {
  // What lies this close to the body is what the robot touched; a moving obstacle is named
  // before the static solids, which it may have pushed the robot against.
  constexpr double kContactSlackM = 0.01;
  const double x = robot_.pose().x(), y = robot_.pose().y(), reach = robot_options_.radius_m + kContactSlackM;
  CollisionEvent event{time_s, x, y, speed_before, ""};
  for (size_t i = 0; i < traffic_.solids().size() && event.with.empty(); ++i) {
    if (solidOverlapsDisc(traffic_.solids()[i], x, y, reach)) event.with = world_.moving_obstacles[i].name;
  }
  for (size_t i = 0; i < world_.solids.size() && event.with.empty(); ++i) {
    const Solid& solid = world_.solids[i];
    if (solidInHeightBand(solid, 0.0, robot_options_.height_m) && solidOverlapsDisc(solid, x, y, reach)) {
      event.with = world_.solid_sections[i] + " (" + world_.texture_names[static_cast<size_t>(solid.texture)] + ")";
    }
  }
  if (event.with.empty()) event.with = "static";
  collision_events_.push_back(event);
}

SimulationSummary Simulation::run(const MotionPlan& plan, const std::function<void(const SimulatedFrame&)>& on_frame) {
  SimulationSummary summary;
  size_t next_waypoint = 0;
  size_t active_command = 0;
  while (true) {
    if (frameDue()) on_frame(renderFrame());
    Velocity command;
    if (!plan.commands.empty()) {
      if (time_ >= plan.commands.back().time_s - kTimeSlack) {
        summary.plan_completed = true;
        break;
      }
      while (time_ >= plan.commands[active_command + 1].time_s - kTimeSlack) ++active_command;
      command = {plan.commands[active_command].speed_mps, plan.commands[active_command].turn_rate};
    } else {
      while (next_waypoint < plan.waypoints.size() &&
             std::hypot(plan.waypoints[next_waypoint].x - robot_.pose().x(),
                        plan.waypoints[next_waypoint].y - robot_.pose().y()) < options_.waypoint_tolerance_m) {
        ++next_waypoint;
      }
      if (next_waypoint == plan.waypoints.size()) {
        if (robot_.speed() == 0.0 && robot_.turnRate() == 0.0) {
          summary.plan_completed = true;
          break;
        }
      } else {
        command = steerTowards(robot_.pose(), plan.waypoints, next_waypoint, robot_options_.max_acceleration, options_);
      }
    }
    if (timeUp(options_.max_duration_s)) break;
    step(command.speed, command.turn_rate);
  }
  summary.frames = frames_;
  summary.duration_s = time_;
  summary.distance_m = distance_m_;
  summary.collisions = robot_.collisionCount();
  return summary;
}

}  // namespace stereonav
