#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace stereonav {

// A reading of a range scan as a point in the robot frame.
struct ScanReadingPoint {
  double x = 0.0;
  double y = 0.0;
  double range_m = 0.0;
};

// The scan's valid readings nearer than max_range_m, in ray order, through the scan's sensor
// pose. Neighbouring rays that share one column's reading (a virtual scan has more rays than
// columns) give one point.
std::vector<ScanReadingPoint> scanPointsWithin(const mrpt::obs::CObservation2DRangeScan& scan,
                                               double max_range_m);

}  // namespace stereonav
