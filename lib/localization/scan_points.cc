#include "localization/scan_points.h"

#include <mrpt/poses/CPose2D.h>

#include <cmath>

namespace stereonav {

std::vector<ScanReadingPoint> scanPointsWithin(const mrpt::obs::CObservation2DRangeScan& scan,
                                               double max_range_m) {
  std::vector<ScanReadingPoint> points;
  const mrpt::poses::CPose2D sensor(scan.sensorPose);
  for (size_t ray = 0; ray < scan.getScanSize(); ++ray) {
    if (!scan.getScanRangeValidity(ray)) continue;
    const double range = scan.getScanRange(ray);
    if (!(range > 0.0 && range <= max_range_m)) continue;
    const double angle = scan.getScanAngle(ray);
    const mrpt::poses::CPose2D point =
        sensor + mrpt::poses::CPose2D(range * std::cos(angle), range * std::sin(angle), 0.0);
    if (!points.empty() && points.back().x == point.x() && points.back().y == point.y()) continue;
    points.push_back({point.x(), point.y(), range});
  }
  return points;
}

}  // namespace stereonav
