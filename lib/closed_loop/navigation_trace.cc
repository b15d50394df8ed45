#include "closed_loop/navigation_trace.h"

#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>

#include <cmath>
#include <iomanip>

#include "common/atomic_file.h"

namespace stereonav {
namespace {

// One frame as MRPT's reactive navigators log it (reactive_nav_log.h).
mrpt::nav::CLogFileRecord navigationRecord(mrpt::system::TTimeStamp stamp, const mrpt::poses::CPose2D& map_pose,
                                           const DifferentialDriveRobot& robot,
                                           CSimulatedRobotInterface& robot_interface, const ExplorerStatus& status,
                                           double robot_radius_m) {
  mrpt::nav::CLogFileRecord record;
  record.timestamps["tim_start_iteration"] = stamp;
  record.robotPoseLocalization = map_pose.asTPose();
  record.robotPoseOdometry = robot.odometry().asTPose();
  mrpt::system::TTimeStamp sensed_stamp;
  robot_interface.senseObstacles(record.WS_Obstacles, sensed_stamp);
  record.WS_Obstacles_original = record.WS_Obstacles;
  if (status.has_target) {
    const mrpt::math::TPoint2D target = map_pose.inverseComposePoint(mrpt::math::TPoint2D(status.target_x, status.target_y));
    record.WS_targets_relative.emplace_back(target.x, target.y, 0.0);
  }
  auto command = std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  command->lin_vel = status.speed_command;
  command->ang_vel = status.turn_rate_command;
  record.cmd_vel = command;
  record.cur_vel_local = mrpt::math::TTwist2D(robot.speed(), 0.0, robot.turnRate());
  record.cur_vel = record.cur_vel_local;
  record.cur_vel.rotate(map_pose.phi());
  record.robotShape_radius = robot_radius_m;
  record.values["frontiers"] = static_cast<double>(status.frontiers);
  record.values["cost_to_go_m"] = status.cost_to_go;
  record.values["free_travel_m"] = status.free_travel_m;
  record.values["collisions"] = robot.collisionCount();
  record.additional_debug_msgs["phase"] = phaseName(status.phase);
  return record;
}

}  // namespace

NavigationTrace::NavigationTrace()
    : navlog_({"t", "odometry_x", "odometry_y", "odometry_phi", "true_x", "true_y", "true_phi", "speed", "turn_rate",
               "phase", "frontiers", "target_x", "target_y", "cost_to_go", "speed_command", "turn_rate_command",
               "free_travel", "collisions"}) {
  path_text_ << std::setprecision(9);
  truth_text_ << std::setprecision(9);
}

void NavigationTrace::append(const SimulatedFrame& frame, const mrpt::poses::CPose2D& map_pose,
                             const DifferentialDriveRobot& robot, CSimulatedRobotInterface& robot_interface,
                             const ExplorerStatus& status, double robot_radius_m) {
  const double t = frame.time_s;
  path_text_ << t << " " << map_pose.x() << " " << map_pose.y() << " " << map_pose.phi() << "\n";
  truth_text_ << t << " " << frame.true_pose.x() << " " << frame.true_pose.y() << " " << frame.true_pose.phi() << "\n";
  reactive_navlog_.append(
      navigationRecord(simulationTimestamp(t), map_pose, robot, robot_interface, status, robot_radius_m));
  navlog_.add(t).add(frame.odometry.x()).add(frame.odometry.y()).add(frame.odometry.phi());
  navlog_.add(frame.true_pose.x()).add(frame.true_pose.y()).add(frame.true_pose.phi());
  navlog_.add(robot.speed()).add(robot.turnRate()).add(phaseName(status.phase)).add(status.frontiers);
  navlog_.add(status.has_target ? status.target_x : NAN).add(status.has_target ? status.target_y : NAN);
  navlog_.add(status.cost_to_go).add(status.speed_command).add(status.turn_rate_command).add(status.free_travel_m);
  navlog_.add(robot.collisionCount());
  navlog_.endRow();
}

void NavigationTrace::save(const std::string& prefix) const {
  writeStringAtomically(prefix + ".path.txt", path_text_.str());
  writeStringAtomically(prefix + ".truth.txt", truth_text_.str());
  writeStringAtomically(prefix + ".navlog.csv", navlog_.str());
  reactive_navlog_.save(prefix + ".reactivenavlog");
}

}  // namespace stereonav
