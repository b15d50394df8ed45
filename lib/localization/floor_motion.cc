#include "localization/floor_motion.h"

#include <mrpt/math/wrap2pi.h>
#include <opencv2/imgproc.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

// Where the reference camera sees a floor point (X, Y) of the robot frame: the camera
// coordinates are A (X, Y, 1), a homography of the floor plane.
struct FloorProjection {
  Eigen::Matrix3d a;
  double focal, cx, cy;

  explicit FloorProjection(const CameraRig& rig)
      : focal(rig.reference.focal_px), cx(rig.reference.cx), cy(rig.reference.cy) {
    const auto rotation = rig.pose_on_robot.getRotationMatrix();
    Eigen::Matrix3d r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r(i, j) = rotation(i, j);
    const Eigen::Vector3d t(rig.pose_on_robot.x(), rig.pose_on_robot.y(), rig.pose_on_robot.z());
    a.col(0) = r.transpose().col(0);
    a.col(1) = r.transpose().col(1);
    a.col(2) = -r.transpose() * t;
  }

  // The pixel, and its derivatives by X and Y; false behind the camera.
  bool project(double x, double y, Eigen::Vector2d& pixel, Eigen::Matrix2d& by_floor) const {
    const Eigen::Vector3d c = a * Eigen::Vector3d(x, y, 1.0);
    if (c.z() <= 1e-3) return false;
    const double inverse = 1.0 / c.z();
    pixel = Eigen::Vector2d(focal * c.x() * inverse + cx, focal * c.y() * inverse + cy);
    for (int k = 0; k < 2; ++k) {
      by_floor(0, k) = focal * (a(0, k) * c.z() - c.x() * a(2, k)) * inverse * inverse;
      by_floor(1, k) = focal * (a(1, k) * c.z() - c.y() * a(2, k)) * inverse * inverse;
    }
    return true;
  }
};

float bilinear(const cv::Mat1f& image, double u, double v) {
  const int x0 = static_cast<int>(u), y0 = static_cast<int>(v);
  const float a = static_cast<float>(u - x0), b = static_cast<float>(v - y0);
  const float* row0 = image.ptr<float>(y0);
  const float* row1 = image.ptr<float>(y0 + 1);
  return (1 - b) * ((1 - a) * row0[x0] + a * row0[x0 + 1]) + b * ((1 - a) * row1[x0] + a * row1[x0 + 1]);
}

}  // namespace

cv::Mat1f smoothedForFloor(const cv::Mat1b& grey) {
  cv::Mat1f smoothed;
  grey.convertTo(smoothed, CV_32F);
  cv::GaussianBlur(smoothed, smoothed, cv::Size(5, 5), 1.0);
  return smoothed;
}

FloorPixels floorPixels(const CameraRig& rig, const cv::Mat1f& smoothed, const cv::Mat1f& disparity,
                        const FloorMotionOptions& options) {
  FloorPixels floor;
  const int step = std::max(1, options.pixel_step);
  for (int y = 0; y < smoothed.rows; y += step) {
    const float* disparity_row = disparity.ptr<float>(y);
    for (int x = 0; x < smoothed.cols; x += step) {
      const float measured = disparity_row[x];
      if (measured == kInvalidDisparity) continue;
      const auto point = rig.floorPointOnRobot(x, y);
      if (!point) continue;
      const double range = std::hypot(point->x, point->y);
      if (range < options.min_range_m || range > options.max_range_m) continue;
      mrpt::math::TPoint3D camera;
      rig.pose_on_robot.inverseComposePoint(mrpt::math::TPoint3D(point->x, point->y, 0.0), camera);
      if (!(std::abs(measured - rig.disparityForDepth(camera.z)) <= options.disparity_tolerance_px)) continue;
      floor.on_robot.emplace_back(point->x, point->y);
      floor.brightness.push_back(smoothed(y, x));
    }
  }
  return floor;
}

FloorAlignment alignFloor(const CameraRig& rig, const FloorPixels& current, const cv::Mat1f& previous_smoothed,
                          const mrpt::poses::CPose2D& guess) {
  const FloorProjection projection(rig);
  cv::Mat1f gradient_x, gradient_y;
  cv::Sobel(previous_smoothed, gradient_x, CV_32F, 1, 0, 3, 1.0 / 8.0);
  cv::Sobel(previous_smoothed, gradient_y, CV_32F, 0, 1, 3, 1.0 / 8.0);
  // Parameters: the motion (x, y, phi) and the brightness gain and offset of the previous image.
  Eigen::Matrix<double, 5, 1> p;
  p << guess.x(), guess.y(), guess.phi(), 0.0, 0.0;
  FloorAlignment result;
  std::vector<double> residuals;
  residuals.reserve(current.on_robot.size());
  double huber = 1e9;  // the first pass weighs every pixel alike
  constexpr int kMaxIterations = 30;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double c = std::cos(p(2)), s = std::sin(p(2));
    Eigen::Matrix<double, 5, 5> normal = Eigen::Matrix<double, 5, 5>::Zero();
    Eigen::Matrix<double, 5, 1> gradient = Eigen::Matrix<double, 5, 1>::Zero();
    residuals.clear();
    for (size_t i = 0; i < current.on_robot.size(); ++i) {
      const cv::Point2d& q = current.on_robot[i];
      const double x = p(0) + c * q.x - s * q.y, y = p(1) + s * q.x + c * q.y;
      Eigen::Vector2d pixel;
      Eigen::Matrix2d by_floor;
      if (!projection.project(x, y, pixel, by_floor)) continue;
      // Written so that a NaN pixel (a diverged motion) is outside too.
      if (!(pixel.x() >= 1.0 && pixel.y() >= 1.0 && pixel.x() <= previous_smoothed.cols - 3.0 &&
            pixel.y() <= previous_smoothed.rows - 3.0)) {
        continue;
      }
      const double seen = bilinear(previous_smoothed, pixel.x(), pixel.y());
      const double residual = (1.0 + p(3)) * seen + p(4) - current.brightness[i];
      const Eigen::RowVector2d image_gradient(bilinear(gradient_x, pixel.x(), pixel.y()),
                                              bilinear(gradient_y, pixel.x(), pixel.y()));
      Eigen::Matrix<double, 2, 3> by_motion;
      by_motion << 1.0, 0.0, -(y - p(1)), 0.0, 1.0, x - p(0);
      Eigen::Matrix<double, 1, 5> jacobian;
      jacobian.head<3>() = (1.0 + p(3)) * image_gradient * by_floor * by_motion;
      jacobian(3) = seen;
      jacobian(4) = 1.0;
      const double weight = std::abs(residual) <= huber ? 1.0 : huber / std::abs(residual);
      normal += weight * jacobian.transpose() * jacobian;
      gradient += weight * jacobian.transpose() * residual;
      residuals.push_back(std::abs(residual));
    }
    result.pixels = static_cast<int>(residuals.size());
    if (residuals.size() < 10) return result;
    // The next pass's Huber threshold: 1.5 robust sigmas of this pass's residuals.
    std::nth_element(residuals.begin(), residuals.begin() + residuals.size() / 2, residuals.end());
    huber = std::max(1.0, 1.5 * 1.4826 * residuals[residuals.size() / 2]);
    const Eigen::Matrix<double, 5, 1> delta = normal.ldlt().solve(-gradient);
    if (!delta.allFinite()) return result;
    p += delta;
    if (std::hypot(delta(0), delta(1)) < 1e-5 && std::abs(delta(2)) < 1e-6) {
      result.converged = true;
      break;
    }
  }
  result.motion = mrpt::poses::CPose2D(p(0), p(1), mrpt::math::wrapToPi(p(2)));
  return result;
}

FloorOdometry::FloorOdometry(const CameraRig& rig, const FloorMotionOptions& options)
    : rig_(rig), options_(options) {}

// The wheels' scales are used once the accepted steps add up to this much (squared: metres or
// radians, as a step of 0.3 m or 0.3 rad would): a few steps' noise is then well below 1%.
constexpr double kMinCalibrationSquares = 0.1;

double FloorOdometry::distanceScale() const {
  return distance_squares_ >= kMinCalibrationSquares ? distance_products_ / distance_squares_ : 1.0;
}

bool FloorOdometry::turnCalibrated() const { return turn_squares_ >= kMinCalibrationSquares; }

double FloorOdometry::turnScale() const {
  return turnCalibrated() ? turn_products_ / turn_squares_ : 1.0;
}

std::optional<mrpt::poses::CPose2D> FloorOdometry::floorStep(const cv::Mat1f& smoothed, const cv::Mat1f& disparity,
                                                             const mrpt::poses::CPose2D& predicted) const {
  const FloorPixels floor = floorPixels(rig_, smoothed, disparity, options_);
  if (static_cast<int>(floor.on_robot.size()) < options_.min_pixels) return std::nullopt;
  const FloorAlignment alignment = alignFloor(rig_, floor, previous_smoothed_, predicted);
  if (!alignment.converged || alignment.pixels < options_.min_pixels) return std::nullopt;
  const double allowed_m = options_.max_disagreement_m + options_.max_disagreement_fraction * predicted.norm();
  const double allowed_rad =
      mrpt::DEG2RAD(options_.max_disagreement_deg) + options_.max_disagreement_fraction * std::abs(predicted.phi());
  if (std::hypot(alignment.motion.x() - predicted.x(), alignment.motion.y() - predicted.y()) > allowed_m ||
      std::abs(mrpt::math::wrapToPi(alignment.motion.phi() - predicted.phi())) > allowed_rad) {
    return std::nullopt;
  }
  return alignment.motion;
}

const mrpt::poses::CPose2D& FloorOdometry::update(const mrpt::poses::CPose2D& wheels, const cv::Mat1b& grey,
                                                  const cv::Mat1f& disparity) {
  cv::Mat1f smoothed = smoothedForFloor(grey);
  if (!previous_wheels_) {
    pose_ = wheels;
  } else {
    const mrpt::poses::CPose2D wheel_step = wheels - *previous_wheels_;
    const mrpt::poses::CPose2D calibrated(distanceScale() * wheel_step.x(), distanceScale() * wheel_step.y(),
                                          turnScale() * wheel_step.phi());
    mrpt::poses::CPose2D step = calibrated;
    last_turn_doubt_ = TurnDoubt();
    if (const auto measured = floorStep(smoothed, disparity, calibrated)) {
      step = *measured;
      ++measured_steps_;
      distance_products_ += measured->x() * wheel_step.x();
      distance_squares_ += wheel_step.x() * wheel_step.x();
      turn_products_ += measured->phi() * wheel_step.phi();
      turn_squares_ += wheel_step.phi() * wheel_step.phi();
    } else {
      last_turn_doubt_.sigma_rad =
          std::hypot(options_.wheel_turn_noise_per_rad * wheel_step.phi(),
                     mrpt::DEG2RAD(options_.wheel_heading_noise_deg_per_m) * wheel_step.x());
      if (!turnCalibrated()) {
        last_turn_doubt_.scale_sigma_rad = options_.wheel_turn_scale_sigma * std::abs(wheel_step.phi());
        uncalibrated_turn_ += wheel_step.phi();
      }
    }
    // Once the wheels' turn scale is known, the wheel steps taken before it was are turned by it too.
    if (turnCalibrated() && uncalibrated_turn_ != 0.0) {
      step = step + mrpt::poses::CPose2D(0.0, 0.0, (turnScale() - 1.0) * uncalibrated_turn_);
      uncalibrated_turn_ = 0.0;
      last_turn_doubt_.earlier_turns_scale = turnScale();
    }
    ++steps_;
    pose_ = pose_ + step;
  }
  previous_wheels_ = wheels;
  previous_smoothed_ = std::move(smoothed);
  return pose_;
}

}  // namespace stereonav
