#pragma once

#include <mrpt/poses/CPose2D.h>

#include <random>
#include <vector>

#include "common/ini_section.h"
#include "simulator/world.h"

namespace stereonav {

struct DifferentialDriveOptions {
  double max_speed_mps = 1.5;  // the paper's robot moves at 150 cm/s (abstract)
  double max_turn_rate = 2.0;  // rad/s
  double max_acceleration = 1.0;       // m/s^2
  double max_turn_acceleration = 4.0;  // rad/s^2
  double radius_m = 0.3;   // circular footprint (an RWI B-14 is about 0.6 m across)
  double height_m = 1.0;   // the body sweeps heights [0, height] (paper section 3.3)
  // Odometry error standard deviations: of the distance travelled per metre, of the heading per
  // radian turned, and of the heading per metre travelled.
  double odometry_distance_noise = 0.02;
  double odometry_turn_noise = 0.02;
  double odometry_drift_rad_per_m = 0.005;
  // Systematic errors, the same on every step as a real base's calibration error: the measured
  // distance is (1 + odometry_distance_bias) times the driven one (a wheel radius off by that
  // fraction), the measured turn (1 + odometry_turn_bias) times the turned one (the wheel base).
  double odometry_distance_bias = 0.0;
  double odometry_turn_bias = 0.0;
  int seed = 1;
};

// Section [sim_robot]: max_speed_mps, max_turn_rate, max_acceleration, max_turn_acceleration,
// radius_m, height_m, odometry_distance_noise, odometry_turn_noise, odometry_drift_rad_per_m,
// odometry_distance_bias, odometry_turn_bias, seed.
DifferentialDriveOptions loadDifferentialDriveOptions(IniSection& section);

// A differential-drive robot with a circular footprint driving through a World: velocity
// commands are limited in speed and acceleration, motion is an exact arc, and the body never
// passes through an obstacle in its height band — it stops at contact (still turning on the spot
// if told to) and the collision is counted. Odometry integrates the executed motion with seeded random errors, so it drifts from
// the true pose as a real robot's does (paper section 6.1).
class DifferentialDriveRobot {
 public:
  DifferentialDriveRobot(const World& world, DifferentialDriveOptions options,
                         const mrpt::poses::CPose2D& start);

  // Drives for dt seconds towards the commanded velocities among the moving obstacles where they
  // are at the end of the step (MovingTraffic::solids). Returns false if the robot hit something.
  bool step(double commanded_speed, double commanded_turn_rate, double dt, const std::vector<Solid>& moving_solids);

  const mrpt::poses::CPose2D& pose() const { return pose_; }
  const mrpt::poses::CPose2D& odometry() const { return odometry_; }
  double speed() const { return speed_; }
  double turnRate() const { return turn_rate_; }
  // Distinct contacts so far: pushing on against an obstacle one is already touching does not
  // count again.
  int collisionCount() const { return collisions_; }
  bool inContact() const { return in_contact_; }

 private:
  // Whether the footprint at (x, y) overlaps a solid of the world in the body's height band.
  bool footprintCollides(double x, double y, const std::vector<Solid>& moving_solids) const;
  // The share of the step's arc (distance, turn) driven before contact, and whether it stopped.
  double freeFractionOfArc(double distance, double turn, const std::vector<Solid>& moving_solids,
                           bool* blocked) const;
  void measureOdometry(double travelled, double turned);

  DifferentialDriveOptions options_;
  std::vector<Solid> static_in_band_;
  mrpt::poses::CPose2D pose_;
  mrpt::poses::CPose2D odometry_;
  double speed_ = 0.0;
  double turn_rate_ = 0.0;
  int collisions_ = 0;
  bool in_contact_ = false;
  std::mt19937 random_;
};

}  // namespace stereonav
