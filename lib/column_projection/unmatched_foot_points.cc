#include "column_projection/unmatched_foot_points.h"

namespace stereonav {

std::vector<mrpt::math::TPoint2D> unmatchedFootPoints(const DisparityScan& scan, const CameraRig& rig) {
  std::vector<mrpt::math::TPoint2D> points;
  for (int column = 0; column < scan.columns(); ++column) {
    if (!scan.endsClear(column)) continue;
    // The foot's row, not its disparity: the floor plane fixes where the ray through it lands.
    if (const auto foot = rig.floorPointOnRobot(column, scan.column_clear_end_row[column])) points.push_back(*foot);
  }
  return points;
}

}  // namespace stereonav
