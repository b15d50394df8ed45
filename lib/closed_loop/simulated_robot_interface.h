#pragma once

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/nav/reactive/CRobot2NavInterface.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "mapping/rawlog_mapping.h"
#include "rig/camera_rig.h"
#include "simulator/simulation.h"

namespace stereonav {

// The simulated robot behind MRPT's robot-to-navigator interface, so that the explorer drives it
// exactly as it would drive a real base's driver. As MRPT defines it, the pose is the
// localization's and the odometry is the raw dead reckoning. The pose comes per MapPoseSource:
// dead reckoning, as the paper maps and navigates (section 5; it names localization an open
// problem, section 6.1), odometry corrected by scan matching, or the simulator's true pose (a
// perfect localization). Time is the simulation's clock. Velocity commands are held until the
// simulation steps the robot (commandedSpeed / commandedTurnRate).
class CSimulatedRobotInterface : public mrpt::nav::CRobot2NavInterface {
 public:
  // The robot and the clock of `simulation`, read on every call.
  CSimulatedRobotInterface(const Simulation& simulation, MapPoseSource pose_source);

  // The pose the navigator gets (and the map must be built at). Localized: the localizer's last
  // pose carried forward by the odometry since, as a localization module between its updates.
  mrpt::poses::CPose2D pose() const;

  // Localized only: the localizer put the robot at `pose` when its odometry read `odometry`.
  void setLocalizedPose(const mrpt::poses::CPose2D& pose, const mrpt::poses::CPose2D& odometry);

  // What the driver of a robot carrying the stereo head reports (senseObstacles) from the newest
  // disparity scan, taken with the robot at pose() == `pose`, until the next one: the virtual
  // laser scan's obstacles within max_range_m (column_projection/virtual_range_scan.h) and what
  // its readings miss: the blind columns' points for a body of radius body_radius_m
  // (blind_column_points.h) and the feet of surfaces that matched nothing (unmatched_foot_points.h).
  void setSensedScan(const DisparityScan& scan, const CameraRig& rig, double body_radius_m, double max_range_m,
                     mrpt::system::TTimeStamp timestamp, const mrpt::poses::CPose2D& pose);

  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity_global,
                               mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
                               std::string& frame_id) override;
  // Accepts mrpt::kinematics::CVehicleVelCmd_DiffDriven only (false for anything else).
  bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& command) override;
  bool stop(bool is_emergency_stop) override;
  mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override;
  mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override;
  // The newest scan's obstacle points in the robot's current frame (moved by the motion since the
  // scan was taken), stamped with the scan's time; false before the first scan.
  bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& timestamp) override;
  // The navigator found the robot not moving though told to (it reverses out); counted.
  void sendApparentCollisionEvent() override { ++apparent_collisions_; }
  double getNavigationTime() override { return simulation_.time(); }
  void resetNavigationTimer() override {}

  double commandedSpeed() const { return speed_; }
  double commandedTurnRate() const { return turn_rate_; }
  int apparentCollisions() const { return apparent_collisions_; }

 private:
  const Simulation& simulation_;
  MapPoseSource pose_source_;
  // Until the first localization, pose() is the odometry.
  mrpt::poses::CPose2D localized_pose_;
  mrpt::poses::CPose2D localized_at_odometry_;
  double speed_ = 0.0;
  double turn_rate_ = 0.0;
  int apparent_collisions_ = 0;
  bool has_scan_ = false;
  mrpt::maps::CSimplePointsMap scan_points_;  // robot frame at scan_pose_
  mrpt::poses::CPose2D scan_pose_;
  mrpt::system::TTimeStamp scan_time_;
};

}  // namespace stereonav
