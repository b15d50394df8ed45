#include "column_projection/unmatched_foot_points.h"

namespace stereonav {

std::vector<mrpt::math::TPoint2D> unmatchedFootPoints(const DisparityScan& scan, const CameraRig& rig) {
  std::vector<mrpt::math::TPoint2D> points;
  const auto sensor = rig.pose_on_robot.translation();
  for (int column = 0; column < scan.columns(); ++column) {
    if (!scan.endsClear(column)) continue;
    // The foot's row, not its disparity: the floor plane fixes where the ray through it lands.
    const mrpt::math::TVector3D ray = rig.rayOnRobot(column, scan.column_clear_end_row[column]);
    if (ray.z >= 0.0 || sensor.z <= 0.0) continue;  // it meets no floor
    const double depth = -sensor.z / ray.z;
    points.emplace_back(sensor.x + depth * ray.x, sensor.y + depth * ray.y);
  }
  return points;
}

}  // namespace stereonav
