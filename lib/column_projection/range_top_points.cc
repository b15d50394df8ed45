#include "column_projection/range_top_points.h"

namespace stereonav {

std::vector<mrpt::math::TPoint2D> rangeTopPoints(const DisparityScan& scan, const CameraRig& rig) {
  std::vector<mrpt::math::TPoint2D> points;
  if (scan.column_row.size() != scan.column_disparity.size()) return points;
  for (int column = 0; column < scan.columns(); ++column) {
    if (scan.atRangeTop(column)) {
      points.push_back(rig.readingOnRobot(column, scan.column_row[column], scan.column_disparity[column]));
    }
  }
  return points;
}

}  // namespace stereonav
