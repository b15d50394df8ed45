#include "column_projection/virtual_range_scan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace stereonav {
namespace {

// Directions in the sensor's floor frame (x along the camera's heading, y to its left).
class FloorBearings {
 public:
  explicit FloorBearings(const CameraRig& rig) : rig_(rig) {
    const auto rotation = rig.pose_on_robot.getRotationMatrix();
    heading_ = std::atan2(rotation(1, 2), rotation(0, 2));  // of the optical axis
  }

  double heading() const { return heading_; }

  // Horizontal part of the camera ray through image point (x, y), per unit of camera depth Z.
  void horizontalRay(double x, double y, double& forward, double& left) const {
    const mrpt::math::TVector3D ray = rig_.rayOnRobot(x, y);
    forward = std::cos(heading_) * ray.x + std::sin(heading_) * ray.y;
    left = -std::sin(heading_) * ray.x + std::cos(heading_) * ray.y;
  }

  double bearing(double x, double y) const {
    double forward, left;
    horizontalRay(x, y, forward, left);
    return std::atan2(left, forward);
  }

 private:
  const CameraRig& rig_;
  double heading_;
};

}  // namespace

mrpt::obs::CObservation2DRangeScan makeVirtualRangeScan(const DisparityScan& scan,
                                                         const CameraRig& rig,
                                                         double max_range_m) {
  const PinholeCamera& camera = rig.reference;
  if (scan.columns() != camera.width ||
      scan.column_row.size() != scan.column_disparity.size()) {
    throw std::invalid_argument(
        "makeVirtualRangeScan: the scan needs one disparity and one row per image column (" +
        std::to_string(camera.width) + ")");
  }
  const FloorBearings bearings(rig);
  double half_aperture = 0.0;
  for (const double x : {-0.5, camera.width - 0.5}) {
    for (const double y : {-0.5, camera.height - 0.5}) {
      half_aperture = std::max(half_aperture, std::abs(bearings.bearing(x, y)));
    }
  }

  mrpt::obs::CObservation2DRangeScan observation;
  const auto rays = static_cast<size_t>(camera.width);
  observation.aperture = static_cast<float>(2.0 * half_aperture);
  observation.rightToLeft = true;
  observation.maxRange = static_cast<float>(max_range_m);
  const auto centre = rig.pose_on_robot.translation();
  observation.sensorPose = mrpt::poses::CPose3D(centre.x, centre.y, 0.0, bearings.heading(), 0, 0);
  observation.resizeScanAndAssign(rays, observation.maxRange, false);
  if (rays < 2) return observation;
  const double ray_spacing = 2.0 * half_aperture / (rays - 1);

  for (int column = 0; column < scan.columns(); ++column) {
    if (!scan.valid(column)) continue;
    const double row = scan.column_row[column];
    double forward, left;
    bearings.horizontalRay(column, row, forward, left);
    const double depth = rig.depthForDisparity(scan.column_disparity[column]);
    const double range = depth * std::hypot(forward, left);
    if (!(range <= max_range_m)) continue;
    // Image x grows to the right, bearings to the left: the right edge has the smaller bearing.
    const double first = (bearings.bearing(column + 0.5, row) + half_aperture) / ray_spacing;
    const double last = (bearings.bearing(column - 0.5, row) + half_aperture) / ray_spacing;
    const long first_ray = std::max(0L, static_cast<long>(std::ceil(first)));
    const long last_ray = std::min(static_cast<long>(rays) - 1, static_cast<long>(std::floor(last)));
    for (long ray = first_ray; ray <= last_ray; ++ray) {
      const auto index = static_cast<size_t>(ray);
      if (observation.getScanRangeValidity(index) && observation.getScanRange(index) <= range) {
        continue;
      }
      observation.setScanRange(index, static_cast<float>(range));
      observation.setScanRangeValidity(index, true);
    }
  }
  return observation;
}

}  // namespace stereonav
