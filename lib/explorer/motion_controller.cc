#include "explorer/motion_controller.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

double clampAbs(double value, double limit) { return std::max(-limit, std::min(limit, value)); }

}  // namespace

MotionController::MotionController(const ExplorerOptions& options) : options_(options) {}

double MotionController::headingError(const mrpt::poses::CPose2D& pose, double x, double y) const {
  return mrpt::math::wrapToPi(std::atan2(y - pose.y(), x - pose.x()) - pose.phi());
}

VelocityCommand MotionController::turnTowards(const mrpt::poses::CPose2D& pose, double x, double y) const {
  const double error = headingError(pose, x, y);
  // A proportional law would creep through the last half radian, and the robot turns on the
  // spot a few hundred times an exploration.
  const double turn_rate = std::max(
      options_.min_turn_rate, std::min(options_.max_turn_rate, std::sqrt(2.0 * options_.turn_braking * std::abs(error))));
  return {0.0, std::copysign(turn_rate, error)};
}

bool MotionController::faces(const mrpt::poses::CPose2D& pose, double x, double y) const {
  return std::abs(headingError(pose, x, y)) <= options_.facing_tolerance_rad;
}

MotionController::Drive MotionController::drive(const mrpt::poses::CPose2D& pose, const std::vector<cv::Point>& path,
                                                const NavigationGrid& grid, bool driving) const {
  // Carrot: the first path cell at least lookahead_m along the path; and the whole path length.
  double along = 0.0, remaining = 0.0;
  cv::Point2d carrot(grid.centreX(path.back().x), grid.centreY(path.back().y));
  bool carrot_set = false;
  for (size_t i = 1; i < path.size(); ++i) {
    const double step = std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y) * grid.resolution();
    remaining += step;
    along += step;
    if (!carrot_set && along >= options_.lookahead_m) {
      carrot = cv::Point2d(grid.centreX(path[i].x), grid.centreY(path[i].y));
      carrot_set = true;
    }
  }
  const double error = headingError(pose, carrot.x, carrot.y);
  if (!driving && std::abs(error) > options_.facing_tolerance_rad) {
    return {turnTowards(pose, carrot.x, carrot.y), false, remaining};
  }
  if (std::abs(error) > options_.turn_in_place_rad) return {turnTowards(pose, carrot.x, carrot.y), false, remaining};
  int col = 0, row = 0;
  grid.cellAt(pose.x(), pose.y(), col, row);
  const double body_radius = options_.robot_radius_m + options_.safety_margin_m;
  const double room = grid.obstacleDistance(col, row) - body_radius;
  // Down to 0.3 of full speed where the path runs close to obstacles.
  const double room_factor = std::max(0.3, std::min(1.0, room / (options_.repulsion_distance_m + 1e-9)));
  // Slower with the square of the heading error, down to 0.3 of full speed at the turn-in-place
  // angle: the carrot on a grid path swings 5-15 degrees from cell to cell, which a proportional
  // slow-down would pay for on every straight.
  const double heading_share = error / options_.turn_in_place_rad;
  double speed = options_.max_speed_mps * room_factor * (1.0 - 0.7 * heading_share * heading_share);
  speed = std::min(speed, std::sqrt(2.0 * options_.braking_deceleration * remaining));
  return {{speed, clampAbs(options_.heading_gain * error, options_.max_turn_rate)}, true, remaining};
}

std::optional<VelocityCommand> MotionController::lookAround(const mrpt::poses::CPose2D& pose, bool continuing) {
  if (continuing && last_phi_) {
    turned_rad_ += std::abs(mrpt::math::wrapToPi(pose.phi() - *last_phi_));
  } else {
    turned_rad_ = 0.0;
  }
  last_phi_ = pose.phi();
  if (turned_rad_ >= 2.0 * M_PI) {
    looked_around_here_ = true;
    look_around_x_ = pose.x();
    look_around_y_ = pose.y();
    return std::nullopt;
  }
  return VelocityCommand{0.0, options_.look_around_turn_rate};
}

void MotionController::forgetLookAroundIfMoved(const mrpt::poses::CPose2D& pose) {
  if (looked_around_here_ &&
      std::hypot(pose.x() - look_around_x_, pose.y() - look_around_y_) > options_.look_around_spacing_m) {
    looked_around_here_ = false;
  }
}

VelocityCommand MotionController::approach(const mrpt::poses::CPose2D& pose, const cv::Point2d& point) const {
  const double error = headingError(pose, point.x, point.y);
  if (std::abs(error) > options_.facing_tolerance_rad * 2.0) return turnTowards(pose, point.x, point.y);
  return {options_.escape_speed_mps, clampAbs(options_.heading_gain * error, options_.max_turn_rate)};
}

bool MotionController::roomBehind(const mrpt::poses::CPose2D& pose, const NavigationGrid& grid) const {
  const double back = options_.back_off_speed_mps * options_.back_off_s;
  for (double along = grid.resolution(); along <= back + 1e-9; along += grid.resolution()) {
    const double x = pose.x() - along * std::cos(pose.phi()), y = pose.y() - along * std::sin(pose.phi());
    int col = 0, row = 0;
    if (!grid.cellAt(x, y, col, row) || !grid.fits(col, row, options_.robot_radius_m)) return false;
  }
  return true;
}

}  // namespace stereonav
