#include "closed_loop/simulated_robot_interface.h"

#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>

#include <cmath>

#include "column_projection/blind_column_points.h"
#include "column_projection/unmatched_foot_points.h"
#include "column_projection/virtual_range_scan.h"

namespace stereonav {

CSimulatedRobotInterface::CSimulatedRobotInterface(const Simulation& simulation, MapPoseSource pose_source)
    : simulation_(simulation), pose_source_(pose_source) {}

mrpt::poses::CPose2D CSimulatedRobotInterface::pose() const {
  const DifferentialDriveRobot& robot = simulation_.robot();
  switch (pose_source_) {
    case MapPoseSource::kOdometry:
      return robot.odometry();
    case MapPoseSource::kLocalized:
      return localized_pose_ + (robot.odometry() - localized_at_odometry_);
    case MapPoseSource::kGroundTruth:
      break;
  }
  return robot.pose();
}

void CSimulatedRobotInterface::setLocalizedPose(const mrpt::poses::CPose2D& pose,
                                                const mrpt::poses::CPose2D& odometry) {
  localized_pose_ = pose;
  localized_at_odometry_ = odometry;
}

bool CSimulatedRobotInterface::getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose,
                                                       mrpt::math::TTwist2D& velocity_global,
                                                       mrpt::system::TTimeStamp& timestamp,
                                                       mrpt::math::TPose2D& odometry, std::string& frame_id) {
  const DifferentialDriveRobot& robot = simulation_.robot();
  odometry = robot.odometry().asTPose();
  pose = this->pose().asTPose();
  velocity_global.vx = robot.speed() * std::cos(pose.phi);
  velocity_global.vy = robot.speed() * std::sin(pose.phi);
  velocity_global.omega = robot.turnRate();
  timestamp = simulationTimestamp(simulation_.time());
  frame_id = "odom";
  return true;
}

bool CSimulatedRobotInterface::changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& command) {
  const auto* differential = dynamic_cast<const mrpt::kinematics::CVehicleVelCmd_DiffDriven*>(&command);
  if (differential == nullptr) return false;
  speed_ = differential->lin_vel;
  turn_rate_ = differential->ang_vel;
  return true;
}

bool CSimulatedRobotInterface::stop(bool /*is_emergency_stop*/) {
  speed_ = 0.0;
  turn_rate_ = 0.0;
  return true;
}

void CSimulatedRobotInterface::setSensedScan(const DisparityScan& scan, const CameraRig& rig, double body_radius_m,
                                             double max_range_m, mrpt::system::TTimeStamp timestamp,
                                             const mrpt::poses::CPose2D& pose) {
  scan_points_.clear();
  const mrpt::obs::CObservation2DRangeScan range_scan = makeVirtualRangeScan(scan, rig, max_range_m);
  scan_points_.loadFromRangeScan(range_scan);
  for (const auto& points : {blindColumnPoints(scan, rig, body_radius_m), unmatchedFootPoints(scan, rig)}) {
    for (const mrpt::math::TPoint2D& point : points) {
      scan_points_.insertPoint(static_cast<float>(point.x), static_cast<float>(point.y), 0.0f);
    }
  }
  scan_pose_ = pose;
  scan_time_ = timestamp;
  has_scan_ = true;
}

bool CSimulatedRobotInterface::senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
                                              mrpt::system::TTimeStamp& timestamp) {
  if (!has_scan_) return false;
  obstacles.clear();
  const mrpt::poses::CPose2D scan_in_current = scan_pose_ - pose();
  for (size_t i = 0; i < scan_points_.size(); ++i) {
    float x = 0.0f, y = 0.0f, z = 0.0f;
    scan_points_.getPoint(i, x, y, z);
    double current_x = 0.0, current_y = 0.0;
    scan_in_current.composePoint(x, y, current_x, current_y);
    obstacles.insertPoint(static_cast<float>(current_x), static_cast<float>(current_y), 0.0f);
  }
  timestamp = scan_time_;
  return true;
}

mrpt::kinematics::CVehicleVelCmd::Ptr CSimulatedRobotInterface::getEmergencyStopCmd() { return getStopCmd(); }

mrpt::kinematics::CVehicleVelCmd::Ptr CSimulatedRobotInterface::getStopCmd() {
  return std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
}

}  // namespace stereonav
