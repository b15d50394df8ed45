#include "column_projection/blind_column_points.h"

#include <algorithm>
#include <cmath>

namespace stereonav {

std::vector<mrpt::math::TPoint2D> blindColumnPoints(const DisparityScan& scan, const CameraRig& rig,
                                                    double body_radius_m) {
  std::vector<mrpt::math::TPoint2D> points;
  if (scan.column_blind.empty()) return points;
  // Inside the body by this much, so that the guard reads the point as under the body, not
  // beside it.
  constexpr double kInsideBody = 0.02;
  const double radius = std::max(0.0, body_radius_m - kInsideBody);
  const auto sensor = rig.pose_on_robot.translation();
  int ahead = 0;
  for (int column = 0; column < scan.columns(); ++column) {
    // The ray through the column's bottom pixel, the one that meets the nearest floor.
    const auto floor = rig.floorPointOnRobot(column, rig.reference.height - 1);
    if (!floor || std::abs(floor->y) > body_radius_m) continue;
    ++ahead;
    if (!scan.blind(column)) continue;
    // The floor point's bearing from the sensor is the ray's.
    double dx = floor->x - sensor.x, dy = floor->y - sensor.y;
    const double norm = std::hypot(dx, dy);
    if (norm == 0.0) continue;
    dx /= norm;
    dy /= norm;
    // Where that direction, from the sensor, leaves the circle of `radius` (the sensor itself if
    // it is outside).
    const double along = sensor.x * dx + sensor.y * dy;
    const double outside = sensor.x * sensor.x + sensor.y * sensor.y - radius * radius;
    const double t = outside >= 0.0 ? 0.0 : -along + std::sqrt(along * along - outside);
    points.emplace_back(sensor.x + t * dx, sensor.y + t * dy);
  }
  // A few blind columns are a door jamb or a table leg close beside the path, which the scan
  // and the map handle; the robot cannot see where it is going only when most are.
  if (2 * points.size() <= static_cast<size_t>(ahead)) points.clear();
  return points;
}

}  // namespace stereonav
