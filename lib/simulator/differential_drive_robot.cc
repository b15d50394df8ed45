#include "simulator/differential_drive_robot.h"

#include <algorithm>
#include <cmath>

#include "simulator/footprint_overlap.h"

namespace stereonav {
namespace {

// The pose change of driving `distance` along an arc that turns by `turn` (exact for constant
// wheel speeds).
mrpt::poses::CPose2D arcIncrement(double distance, double turn) {
  if (std::abs(turn) < 1e-9) return {distance, 0.0, turn};
  return {distance * std::sin(turn) / turn, distance * (1.0 - std::cos(turn)) / turn, turn};
}

double towards(double current, double target, double max_change) {
  return current + std::clamp(target - current, -max_change, max_change);
}

// Contact is located to this fraction of a step.
constexpr int kContactBisections = 20;

}  // namespace

DifferentialDriveOptions loadDifferentialDriveOptions(IniSection& section) {
  DifferentialDriveOptions options;
  options.max_speed_mps = section.getPositive("max_speed_mps", options.max_speed_mps, 100.0);
  options.max_turn_rate = section.getPositive("max_turn_rate", options.max_turn_rate, 100.0);
  options.max_acceleration = section.getPositive("max_acceleration", options.max_acceleration, 1000.0);
  options.max_turn_acceleration = section.getPositive("max_turn_acceleration", options.max_turn_acceleration, 1000.0);
  options.radius_m = section.getPositive("radius_m", options.radius_m, 100.0);
  options.height_m = section.getPositive("height_m", options.height_m, 100.0);
  options.odometry_distance_noise = section.getNonNegative("odometry_distance_noise", options.odometry_distance_noise, 10.0);
  options.odometry_turn_noise = section.getNonNegative("odometry_turn_noise", options.odometry_turn_noise, 10.0);
  options.odometry_drift_rad_per_m = section.getNonNegative("odometry_drift_rad_per_m", options.odometry_drift_rad_per_m, 10.0);
  options.odometry_distance_bias = section.getDouble("odometry_distance_bias", options.odometry_distance_bias, -0.5, 0.5);
  options.odometry_turn_bias = section.getDouble("odometry_turn_bias", options.odometry_turn_bias, -0.5, 0.5);
  options.seed = section.getInt("seed", options.seed);
  return options;
}

DifferentialDriveRobot::DifferentialDriveRobot(const World& world, DifferentialDriveOptions options,
                                               const mrpt::poses::CPose2D& start)
    : options_(options),
      pose_(start),
      odometry_(start),
      random_(static_cast<std::mt19937::result_type>(options.seed)) {
  for (const auto& solid : world.solids) {
    if (solidInHeightBand(solid, 0.0, options_.height_m)) static_in_band_.push_back(solid);
  }
}

bool DifferentialDriveRobot::footprintCollides(double x, double y, const std::vector<Solid>& moving_solids) const {
  for (const auto& solid : static_in_band_) {
    if (solidOverlapsDisc(solid, x, y, options_.radius_m)) return true;
  }
  for (const auto& solid : moving_solids) {
    if (solidInHeightBand(solid, 0.0, options_.height_m) && solidOverlapsDisc(solid, x, y, options_.radius_m)) {
      return true;
    }
  }
  return false;
}

double DifferentialDriveRobot::freeFractionOfArc(double distance, double turn,
                                                 const std::vector<Solid>& moving_solids,
                                                 bool* blocked) const {
  const auto collidesAt = [&](double fraction) {
    const mrpt::poses::CPose2D there = pose_ + arcIncrement(fraction * distance, fraction * turn);
    return footprintCollides(there.x(), there.y(), moving_solids);
  };
  if (collidesAt(0.0)) {
    // Something moved into the robot: it may only drive out of it.
    *blocked = collidesAt(1.0);
    return *blocked ? 0.0 : 1.0;
  }
  // Check the arc in pieces shorter than half the radius, so no thin wall is jumped over; then
  // bisect between the last free and the first blocked piece to stop at contact.
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(distance) / (options_.radius_m / 2))));
  for (int k = 1; k <= pieces; ++k) {
    const double fraction = static_cast<double>(k) / pieces;
    if (!collidesAt(fraction)) continue;
    double low = static_cast<double>(k - 1) / pieces;
    double high = fraction;
    for (int i = 0; i < kContactBisections; ++i) {
      const double middle = (low + high) / 2;
      (collidesAt(middle) ? high : low) = middle;
    }
    *blocked = true;
    return low;
  }
  *blocked = false;
  return 1.0;
}

void DifferentialDriveRobot::measureOdometry(double travelled, double turned) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const double measured_distance =
      travelled * (1.0 + options_.odometry_distance_bias) +
      unit(random_) * options_.odometry_distance_noise * std::abs(travelled);
  const double measured_turn =
      turned * (1.0 + options_.odometry_turn_bias) +
      unit(random_) * (options_.odometry_turn_noise * std::abs(turned) +
                       options_.odometry_drift_rad_per_m * std::abs(travelled));
  odometry_ = odometry_ + arcIncrement(measured_distance, measured_turn);
  odometry_.normalizePhi();
}

bool DifferentialDriveRobot::step(double commanded_speed, double commanded_turn_rate, double dt,
                                  const std::vector<Solid>& moving_solids) {
  const double target_speed = std::clamp(commanded_speed, -options_.max_speed_mps, options_.max_speed_mps);
  const double target_turn = std::clamp(commanded_turn_rate, -options_.max_turn_rate, options_.max_turn_rate);
  speed_ = towards(speed_, target_speed, options_.max_acceleration * dt);
  turn_rate_ = towards(turn_rate_, target_turn, options_.max_turn_acceleration * dt);

  const double distance = speed_ * dt;
  const double turn = turn_rate_ * dt;
  bool blocked = false;
  const double free_fraction = freeFractionOfArc(distance, turn, moving_solids, &blocked);

  // Blocked, the robot still finishes the step's turn on the spot: a disc turning in place
  // cannot hit anything, and it lets a controller steer away from what it touches.
  const double travelled = free_fraction * distance;
  pose_ = pose_ + arcIncrement(travelled, free_fraction * turn) +
          mrpt::poses::CPose2D(0.0, 0.0, (1.0 - free_fraction) * turn);
  pose_.normalizePhi();
  measureOdometry(travelled, turn);

  if (blocked) {
    speed_ = 0.0;
    if (!in_contact_) ++collisions_;
  }
  in_contact_ = blocked;
  return !blocked;
}

}  // namespace stereonav
