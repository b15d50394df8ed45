#pragma once

#include <mrpt/nav/reactive/CRobot2NavInterface.h>

#include "simulator/differential_drive_robot.h"

namespace stereonav {

// The simulated robot behind MRPT's robot-to-navigator interface, so that the explorer drives it
// exactly as it would drive a real base's driver. Pose and odometry are both the robot's dead
// reckoning (the paper maps and navigates with it, section 5; the true pose stays with the
// simulator). Time is the simulation's clock. Velocity commands are held until the simulation
// steps the robot (commandedSpeed / commandedTurnRate).
class CSimulatedRobotInterface : public mrpt::nav::CRobot2NavInterface {
 public:
  // `time_s` is the simulation clock, read on every call.
  CSimulatedRobotInterface(const DifferentialDriveRobot& robot, const double& time_s);

  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity_global,
                               mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
                               std::string& frame_id) override;
  // Accepts mrpt::kinematics::CVehicleVelCmd_DiffDriven only (false for anything else).
  bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& command) override;
  bool stop(bool is_emergency_stop) override;
  mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override;
  mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override;
  // The explorer's obstacles come from the stereo map, not from a sensor of the base: false.
  bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& timestamp) override;
  double getNavigationTime() override { return time_s_; }
  void resetNavigationTimer() override {}

  double commandedSpeed() const { return speed_; }
  double commandedTurnRate() const { return turn_rate_; }

 private:
  const DifferentialDriveRobot& robot_;
  const double& time_s_;
  double speed_ = 0.0;
  double turn_rate_ = 0.0;
};

}  // namespace stereonav
