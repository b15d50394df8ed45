#include "simulator/simulation.h"

#include <mrpt/math/wrap2pi.h>

#include "simulator/moving_traffic.h"

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

Simulation::Simulation(const World& world, const CameraRig& rig, const SensorOptions& sensor,
                       const DifferentialDriveOptions& robot, const SimulationOptions& options)
    : world_(world), rig_(rig), sensor_(sensor), robot_(robot), options_(options) {}

SimulationSummary Simulation::run(const MotionPlan& plan,
                                  const std::function<void(const SimulatedFrame&)>& on_frame) {
  const mrpt::poses::CPose2D start(world_.start_pose[0], world_.start_pose[1], world_.start_pose[2]);
  DifferentialDriveRobot robot(world_, robot_, start);
  RigRenderer renderer(world_, rig_, sensor_);
  MovingTraffic traffic(world_);
  SimulationSummary summary;
  const double dt = 1.0 / options_.control_rate_hz;
  size_t step = 0;
  size_t next_waypoint = 0;
  size_t active_command = 0;
  double time = 0.0;

  const auto emitFrame = [&] {
    SimulatedFrame frame;
    frame.time_s = time;
    frame.images = renderer.render(robot.pose(), time, traffic.solids());
    frame.true_pose = robot.pose();
    frame.odometry = robot.odometry();
    frame.collisions = robot.collisionCount();
    on_frame(frame);
    ++summary.frames;
  };
  emitFrame();
  while (true) {
    Velocity command;
    if (!plan.commands.empty()) {
      if (time >= plan.commands.back().time_s - kTimeSlack) {
        summary.plan_completed = true;
        break;
      }
      while (time >= plan.commands[active_command + 1].time_s - kTimeSlack) ++active_command;
      command = {plan.commands[active_command].speed_mps, plan.commands[active_command].turn_rate};
    } else {
      while (next_waypoint < plan.waypoints.size() &&
             std::hypot(plan.waypoints[next_waypoint].x - robot.pose().x(),
                        plan.waypoints[next_waypoint].y - robot.pose().y()) < options_.waypoint_tolerance_m) {
        ++next_waypoint;
      }
      if (next_waypoint == plan.waypoints.size()) {
        if (robot.speed() == 0.0 && robot.turnRate() == 0.0) {
          summary.plan_completed = true;
          break;
        }
      } else {
        command = steerTowards(robot.pose(), plan.waypoints, next_waypoint, robot_.max_acceleration, options_);
      }
    }
    if (time >= options_.max_duration_s - kTimeSlack) break;

    const mrpt::poses::CPose2D before = robot.pose();
    traffic.advance(dt, robot.pose(), robot.speed(), robot_.radius_m);
    robot.step(command.speed, command.turn_rate, dt, traffic.solids());
    summary.distance_m += std::hypot(robot.pose().x() - before.x(), robot.pose().y() - before.y());
    time = static_cast<double>(++step) * dt;
    if (time >= static_cast<double>(summary.frames) / options_.frame_rate_hz - kTimeSlack) emitFrame();
  }
  summary.duration_s = time;
  summary.collisions = robot.collisionCount();
  return summary;
}

}  // namespace stereonav
