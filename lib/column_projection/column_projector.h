#pragma once

#include <opencv2/core.hpp>

#include "column_projection/disparity_scan.h"
#include "column_projection/projection_options.h"
#include "rig/camera_rig.h"

namespace stereonav {

// Projects a disparity image onto the floor plane column by column (paper section 3.3, figure
// 5c): per column, the largest valid disparity whose 3D point lies inside the robot's body volume,
// or the median of the nearest surface's (ProjectionOptions::surface_band_px).
//
// A pixel (x, y) at disparity d is the camera-frame point (B/d) (x - cx, y - cy, f), so its height
// on the robot is mount_z + k(x, y) / d with k fixed by the rig. The body volume is therefore one
// disparity interval per pixel, worked out once here; projecting a frame is then a single pass of
// two comparisons per pixel.
class ColumnProjector {
 public:
  ColumnProjector(const CameraRig& rig, const ProjectionOptions& options);

  // `disparity` must have the rig's image size (throws std::invalid_argument otherwise).
  DisparityScan project(const cv::Mat1f& disparity) const;

 private:
  // Inside the body volume iff lowest_ <= d <= highest_ (an empty interval has lowest_ > highest_;
  // highest_ is finite, so the invalid +inf never passes, and lowest_ > 0, so neither does a point
  // at infinity).
  cv::Mat1f lowest_;
  cv::Mat1f highest_;
  double surface_band_px_;
  // Readings below this disparity are deeper than max_depth_m (0: no limit).
  double min_reading_disparity_;
};

}  // namespace stereonav
