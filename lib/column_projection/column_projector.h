#pragma once

#include <opencv2/core.hpp>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "column_projection/projection_options.h"
#include "rig/camera_rig.h"

namespace stereonav {

// Projects a disparity image onto the floor plane column by column (paper section 3.3, figure
// 5c): per column, the largest valid disparity whose 3D point lies inside the robot's body volume,
// or the median of the nearest surface's (ProjectionOptions::surface_band_px; kept apart for the
// virtual scan, DisparityScan::column_surface, with surface_band_scan_only); with
// ProjectionOptions::floor_end_max_depth_m, the foot of an unmatched surface where the floor ends
// in front of it; with ProjectionOptions::near_floor_m, which columns see nothing of the nearest
// floor (DisparityScan::column_blind).
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
  // The floor's end in column x, matched from the bottom up, if it is the foot of a surface that
  // matched nothing: its disparity on the floor plane and its row; false otherwise.
  // Feet at a smaller disparity than min_disparity are not looked for.
  bool unmatchedFoot(const cv::Mat1f& disparity, int x, double min_disparity, float& foot_disparity,
                     int& foot_row) const;
  // Whether column x matches nothing in most of its near-floor rows.
  bool blind(const cv::Mat1f& disparity, int x) const;

  // Inside the body volume iff lowest_ <= d <= highest_ (an empty interval has lowest_ > highest_;
  // highest_ is finite, so the invalid +inf never passes, and lowest_ > 0, so neither does a point
  // at infinity).
  cv::Mat1f lowest_;
  cv::Mat1f highest_;
  // Height above the camera of pixel (x, y)'s point is height_factor_(y, x) / d.
  cv::Mat1f height_factor_;
  double mount_z_;
  double floor_clearance_;
  // Floor ends at a smaller disparity (deeper than floor_end_max_depth_m) are no feet; 0 = off.
  double floor_end_min_disparity_;
  // Likewise for feet that end a farther reading's CLEAR; 0 = off.
  double clear_end_min_disparity_;
  // Per column, the top row of the nearest floor it sees (rows near_floor_top_row_[x] .. the
  // bottom); empty when near_floor_m is off.
  std::vector<int> near_floor_top_row_;
  double surface_band_px_;
  bool surface_band_scan_only_;
  // Readings below this disparity are deeper than max_depth_m (0: no limit).
  double min_reading_disparity_;
};

}  // namespace stereonav
