#include "localization/wall_position_filter.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

constexpr Eigen::Index kScale = 2;
constexpr Eigen::Index kHeadingError = 3;
constexpr Eigen::Index kFirstWall = 4;

Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

// A wall line's direction: its normal turned a quarter turn counterclockwise.
Eigen::Vector2d along(double normal_rad) { return unit(normal_rad + M_PI / 2); }

}  // namespace

WallPositionFilter::WallPositionFilter(const WallPositionOptions& options,
                                       const WallHeadingOptions& heading_options, const Eigen::Vector2d& start)
    : options_(options),
      gate_sigmas_(heading_options.gate_sigmas),
      max_direction_rad_(mrpt::DEG2RAD(heading_options.max_correction_deg)),
      state_(Eigen::Vector4d(start.x(), start.y(), 1.0, 0.0)),
      covariance_(Eigen::Matrix4d::Zero()) {
  covariance_(kScale, kScale) = mrpt::square(options.distance_scale_sigma);
}

Eigen::Vector2d WallPositionFilter::update(const Eigen::Vector2d& displacement, double previous_heading,
                                           const HeadingEstimate& predicted, const HeadingEstimate& heading,
                                           const std::vector<double>& directions,
                                           const std::vector<WallSegment>& segments) {
  predict(displacement, previous_heading);
  followHeading(0.0, predicted.variance);
  followHeading(mrpt::math::wrapToPi(heading.heading - predicted.heading), heading.variance);
  frame_corrections_ = 0;
  if (!options_.enabled) return position();
  const Eigen::Rotation2Dd turn(heading.heading);
  for (const WallSegment& segment : segments) {
    const double seen = segment.normal_rad + heading.heading;
    double snap = M_PI;
    for (const double direction : directions) {
      const double difference = perpendicularPairDifference(seen, direction);
      if (std::abs(difference) < std::abs(snap)) snap = difference;
    }
    if (std::abs(snap) > max_direction_rad_) continue;
    const double normal = mrpt::math::wrapToPi(seen - snap);
    // The wall's direction is known, so its offset is the centroid's distance along the known
    // normal, not the fitted line's at the foot of its own normal: that one carries the fit's
    // tilt over the lever from the centroid to the robot (office seed 2: a cabinet's end and a
    // door jamb fitted as one line 5 degrees askew read 0.1 m off). The heading's error moves
    // the centroid's distance by the lever too.
    const Eigen::Vector2d centroid(segment.centroid.x, segment.centroid.y);
    const double normal_on_robot = normal - heading.heading;
    const double offset_m = unit(normal_on_robot).dot(centroid);
    const double lever_m = along(normal_on_robot).dot(centroid);
    const double variance = mrpt::square(std::max(segment.centroid_sigma_m, options_.min_offset_sigma_m)) +
                            mrpt::square(lever_m) * heading.variance;
    // The stretch's ends along the line, from the position as corrected by the frame so far.
    const Eigen::Vector2d robot = position();
    const Eigen::Vector2d t = along(normal);
    const double a = t.dot(robot + turn * Eigen::Vector2d(segment.first.x, segment.first.y));
    const double b = t.dot(robot + turn * Eigen::Vector2d(segment.last.x, segment.last.y));
    const size_t wall = associate(normal, offset_m, variance, std::min(a, b), std::max(a, b));
    if (wall == walls_.size()) {
      addWall(normal, offset_m, variance, std::min(a, b), std::max(a, b));
      continue;
    }
    turnWall(wall, normal);
    correct(innovation(wall, offset_m, variance));
    // The stretch as seen from the corrected position.
    const Eigen::Vector2d shift = position() - robot;
    walls_[wall].along_min = std::min(walls_[wall].along_min, std::min(a, b) + t.dot(shift));
    walls_[wall].along_max = std::max(walls_[wall].along_max, std::max(a, b) + t.dot(shift));
    ++frame_corrections_;
  }
  return position();
}

void WallPositionFilter::predict(const Eigen::Vector2d& displacement, double previous_heading) {
  // The heading filter keeps the heading: the error it leaves is new every frame, measured from it.
  state_(kHeadingError) = 0.0;
  const Eigen::Vector2d moved = Eigen::Rotation2Dd(previous_heading) * displacement;
  state_.head<2>() += state_(kScale) * moved;
  // F = I but for d position / d scale = moved and d position / d heading = moved turned a quarter
  // turn, times the scale. F P F^T by rows, then by columns.
  const Eigen::Vector2d sideways = state_(kScale) * Eigen::Vector2d(-moved.y(), moved.x());
  for (const Eigen::Index axis : {0, 1}) {
    covariance_.row(axis) += moved(axis) * covariance_.row(kScale) + sideways(axis) * covariance_.row(kHeadingError);
  }
  for (const Eigen::Index axis : {0, 1}) {
    covariance_.col(axis) += moved(axis) * covariance_.col(kScale) + sideways(axis) * covariance_.col(kHeadingError);
  }
  covariance_.topLeftCorner<2, 2>() +=
      mrpt::square(options_.position_noise_per_m * moved.norm()) * Eigen::Matrix2d::Identity();
}

void WallPositionFilter::followHeading(double shift, double variance) {
  const double prior = covariance_(kHeadingError, kHeadingError);
  if (variance >= prior) {  // odometry's turn: the error grew, independently of the rest
    covariance_(kHeadingError, kHeadingError) = variance;
    return;
  }
  // The walls' directions measured the heading's error: a Kalman update by a measurement of it
  // alone whose noise takes its variance from prior to `variance`, and its mean by `shift`. What
  // was driven on that error moves with it.
  const Eigen::VectorXd column = covariance_.col(kHeadingError);
  state_ += column * (shift / prior);
  covariance_ -= column * column.transpose() * ((prior - variance) / (prior * prior));
  state_(kHeadingError) = 0.0;
}

WallPositionFilter::Innovation WallPositionFilter::innovation(size_t wall, double offset_m, double variance) const {
  const Eigen::Vector2d n = unit(walls_[wall].normal_rad);
  const Eigen::Index w = kFirstWall + static_cast<Eigen::Index>(wall);
  // The offset predicted from the state is wall offset - n . position: H = [-n 0 0 .. 1 ..].
  Innovation result;
  result.value = offset_m - (state_(w) - n.dot(state_.head<2>()));
  result.h_covariance = covariance_.row(w) - n.x() * covariance_.row(0) - n.y() * covariance_.row(1);
  result.variance = result.h_covariance(w) - n.x() * result.h_covariance(0) - n.y() * result.h_covariance(1) + variance;
  return result;
}

size_t WallPositionFilter::associate(double normal_rad, double offset_m, double variance, double along_min,
                                     double along_max) const {
  size_t best = walls_.size();
  double best_distance = mrpt::square(gate_sigmas_);
  for (size_t i = 0; i < walls_.size(); ++i) {
    const WallLine& wall = walls_[i];
    if (std::abs(mrpt::math::wrapToPi(wall.normal_rad - normal_rad)) > max_direction_rad_) continue;
    if (along_min - wall.along_max > options_.max_join_gap_m || wall.along_min - along_max > options_.max_join_gap_m) {
      continue;
    }
    const Innovation candidate = innovation(i, offset_m, variance);
    const double distance = candidate.value * candidate.value / candidate.variance;
    if (distance < best_distance) {
      best_distance = distance;
      best = i;
    }
  }
  return best;
}

void WallPositionFilter::correct(const Innovation& innovation) {
  const Eigen::VectorXd gain = innovation.h_covariance.transpose() / innovation.variance;
  state_ += gain * innovation.value;
  covariance_ -= gain * innovation.h_covariance;
}

void WallPositionFilter::addWall(double normal_rad, double offset_m, double variance, double along_min,
                                 double along_max) {
  const Eigen::Vector2d n = unit(normal_rad);
  const Eigen::Index size = state_.size();
  // Measured from the position, the wall's offset shares its error, plus its own.
  const Eigen::RowVectorXd from_position = n.x() * covariance_.row(0) + n.y() * covariance_.row(1);
  state_.conservativeResize(size + 1);
  state_(size) = n.dot(state_.head<2>()) + offset_m;
  covariance_.conservativeResize(size + 1, size + 1);
  covariance_.row(size).head(size) = from_position;
  covariance_.col(size).head(size) = from_position.transpose();
  covariance_(size, size) = n.x() * from_position(0) + n.y() * from_position(1) + variance;
  walls_.push_back({normal_rad, along_min, along_max});
}

void WallPositionFilter::turnWall(size_t wall, double normal_rad) {
  WallLine& line = walls_[wall];
  if (line.normal_rad == normal_rad) return;
  const Eigen::Index w = kFirstWall + static_cast<Eigen::Index>(wall);
  const double middle = 0.5 * (line.along_min + line.along_max);
  const Eigen::Vector2d pivot = state_(w) * unit(line.normal_rad) + middle * along(line.normal_rad);
  state_(w) = unit(normal_rad).dot(pivot);
  const double new_middle = along(normal_rad).dot(pivot);
  line.along_min += new_middle - middle;
  line.along_max += new_middle - middle;
  line.normal_rad = normal_rad;
}

}  // namespace stereonav
