#include "column_projection/range_top_points.h"

namespace stereonav {

std::vector<mrpt::math::TPoint2D> rangeTopPoints(const DisparityScan& scan, const CameraRig& rig) {
  std::vector<mrpt::math::TPoint2D> points;
  if (scan.column_row.size() != scan.column_disparity.size()) return points;
  const auto camera = rig.pose_on_robot.translation();
  for (int column = 0; column < scan.columns(); ++column) {
    if (!scan.atRangeTop(column)) continue;
    const double depth = rig.depthForDisparity(scan.column_disparity[column]);
    const mrpt::math::TVector3D ray = rig.rayOnRobot(column, scan.column_row[column]);
    points.emplace_back(camera.x + depth * ray.x, camera.y + depth * ray.y);
  }
  return points;
}

}  // namespace stereonav
