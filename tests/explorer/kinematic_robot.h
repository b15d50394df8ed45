#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/nav/reactive/CRobot2NavInterface.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <string>
#include <vector>

namespace stereonav::testing {

// A robot behind MRPT's navigator interface that moves exactly as commanded (no map of its own),
// so the tests see what the explorer asks of any robot driver.
class KinematicRobot : public mrpt::nav::CRobot2NavInterface {
 public:
  explicit KinematicRobot(const mrpt::math::TPose2D& pose) : pose_(pose) {}

  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity,
                               mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
                               std::string& /*frame_id*/) override {
    pose = pose_;
    odometry = pose_;
    velocity = mrpt::math::TTwist2D(speed_ * std::cos(pose_.phi), speed_ * std::sin(pose_.phi), turn_rate_);
    timestamp = mrpt::Clock::fromDouble(time_);
    return true;
  }
  bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& command) override {
    const auto& differential = dynamic_cast<const mrpt::kinematics::CVehicleVelCmd_DiffDriven&>(command);
    speed_ = differential.lin_vel;
    turn_rate_ = differential.ang_vel;
    return true;
  }
  bool stop(bool /*is_emergency_stop*/) override {
    speed_ = turn_rate_ = 0.0;
    ++stops_;
    return true;
  }
  mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override { return getStopCmd(); }
  mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override {
    return std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  }
  // `sensed_` (map frame) in the robot frame, as a new scan every 0.2 s.
  bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& stamp) override {
    if (sensed_.empty()) return false;
    obstacles.clear();
    const mrpt::poses::CPose2D robot(pose_);
    for (const mrpt::math::TPoint2D& point : sensed_) {
      double x = 0.0, y = 0.0;
      robot.inverseComposePoint(point.x, point.y, x, y);
      obstacles.insertPoint(static_cast<float>(x), static_cast<float>(y), 0.0f);
    }
    stamp = mrpt::Clock::fromDouble(std::floor(time_ / 0.2) * 0.2);
    return true;
  }
  double getNavigationTime() override { return time_; }
  void resetNavigationTimer() override {}

  void step(double dt) {
    pose_.x += speed_ * std::cos(pose_.phi) * dt;
    pose_.y += speed_ * std::sin(pose_.phi) * dt;
    pose_.phi = mrpt::math::wrapToPi(pose_.phi + turn_rate_ * dt);
    turned_ += std::abs(turn_rate_ * dt);
    time_ += dt;
  }

  mrpt::math::TPose2D pose_;
  std::vector<mrpt::math::TPoint2D> sensed_;  // what its sensor sees, map frame
  double speed_ = 0.0;
  double turn_rate_ = 0.0;
  double time_ = 0.0;
  double turned_ = 0.0;
  int stops_ = 0;
};

}  // namespace stereonav::testing
