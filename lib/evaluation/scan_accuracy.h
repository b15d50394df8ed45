#pragma once

#include <cstddef>
#include <limits>
#include <string>

#include "column_projection/disparity_scan.h"
#include "rig/camera_rig.h"

namespace stereonav {

// What a stereo scan (paper section 3.3) tells the map and the safety guard, against the scan the
// exact disparity gives. A column that reads an obstacle nearer than anything its pixels see is a
// phantom the robot brakes for or plans around: a window matcher fattens a near surface over what
// lies beside and below it, and a camera of the head that does not see a point (section 6.1)
// still votes on its disparity. A column that reads nothing, or farther, where an obstacle stands
// near is one the robot may drive into.
struct ScanAccuracyOptions {
  double agree_px = 1.0;       // a reading within this of the truth's agrees
  double wrong_px = 1.5;       // nearer (farther) than the truth by more than this: a phantom (a miss)
  double close_range_m = 2.0;  // on the floor from the robot's centre: where the guard and the
                               // obstacle memory act, counted apart
  // The largest disparity the matcher searches: a column whose truth is nearer cannot be read,
  // and is counted as too near rather than as a miss.
  double max_disparity = std::numeric_limits<double>::infinity();
};

struct ScanAccuracy {
  size_t frames = 0;
  size_t columns = 0;          // of all frames
  size_t read = 0;             // columns with a reading
  size_t agreeing = 0;         // read, within agree_px of the truth's column
  double agreeing_error_sum = 0.0;     // px (reading minus truth), summed over the agreeing columns
  double agreeing_square_error = 0.0;  // px², summed over the agreeing columns
  size_t phantoms = 0;         // read nearer than the truth's column, or where it sees nothing
  size_t close_phantoms = 0;   // of them, read within close_range_m
  size_t too_near = 0;         // columns whose truth is nearer than max_disparity reaches
  size_t close_obstacles = 0;  // columns whose truth is an obstacle within close_range_m, not too near
  size_t close_misses = 0;     // of them, read farther than the truth, or not at all

  ScanAccuracy& operator+=(const ScanAccuracy& other);
  // The bias and the precision of the agreeing columns (px): what wall offsets and scan matching
  // inherit. A positive bias reads surfaces too near.
  double agreeingMeanError() const;
  double agreeingRmsError() const;
  std::string toText() const;
  std::string toJson() const;
};

// `measured` and `truth` are one frame's scans by one ColumnProjector, `truth` of the renderer's
// exact disparity. Throws std::invalid_argument if their column counts differ.
ScanAccuracy compareScans(const DisparityScan& measured, const DisparityScan& truth, const CameraRig& rig,
                          const ScanAccuracyOptions& options);

}  // namespace stereonav
