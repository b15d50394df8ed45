#pragma once

#include <vector>

#include "disparity/disparity_image.h"
#include "rig/camera_rig.h"

namespace stereonav {

// The paper's "stereo scan" (section 3.3, figure 5c): for each column of the reference image,
// the largest valid disparity among the pixels whose 3D point lies inside the robot's body
// volume, i.e. the closest obstacle seen through that column; kInvalidDisparity where the column
// saw none.
struct DisparityScan {
  std::vector<float> column_disparity;
  // The image row of the pixel that gave column_disparity (-1 where invalid). A tilted camera sees
  // the same disparity at different distances and bearings in different rows, so turning the scan
  // into floor-plane geometry (a virtual laser scan) needs it. Empty when the scan was not made
  // by ColumnProjector.
  std::vector<int> column_row;
  // Per column, 1 where it saw (almost) nothing of the nearest floor the camera can see
  // (ProjectionOptions::near_floor_m): whatever stands in front of the robot there, nearer than
  // that floor, the matcher could not see. Empty when not checked.
  std::vector<unsigned char> column_blind;
  // Per column, the disparity and image row of the floor's end where it is the foot of a surface
  // that matched nothing, nearer than the column's reading if it has one (ProjectionOptions::
  // floor_end_clear_max_depth_m): the floor up to it was seen, what lies beyond it was not, so a
  // reading's CLEAR stops there, and a guard stops short of it (unmatched_foot_points.h).
  // kInvalidDisparity where none; empty when not checked.
  std::vector<float> column_clear_end;
  std::vector<int> column_clear_end_row;
  // Per column, where its nearest surface lies when the reading above is kept as that surface's
  // nearest point (ProjectionOptions::surface_band_scan_only): the median of the surface's
  // disparities, or the floor's end where that is the reading (kInvalidDisparity, -1 where none).
  // The largest of tens of noisy pixels reads a wall 2-5 cm too near at 2-4 m, by an amount that
  // changes with range; a map and a guard keep clear of that nearest point, a scan matcher aligns
  // the walls where they lie. Empty otherwise.
  std::vector<float> column_surface;
  std::vector<int> column_surface_row;
  // The largest disparity the matcher searched (kInvalidDisparity when not known). A surface
  // nearer than the search range matches best at its top, so a column read there saw something
  // at least that near, but not where: its depth is a bound, not a measurement.
  float range_top = kInvalidDisparity;

  int columns() const { return static_cast<int>(column_disparity.size()); }
  bool valid(int column) const { return isValidDisparity(column_disparity[column]); }
  bool blind(int column) const { return !column_blind.empty() && column_blind[column] != 0; }
  bool atRangeTop(int column) const {
    return isValidDisparity(range_top) && valid(column) && column_disparity[column] >= range_top;
  }
  bool endsClear(int column) const {
    return column_clear_end.size() == column_disparity.size() &&
           column_clear_end_row.size() == column_clear_end.size() &&
           isValidDisparity(column_clear_end[column]);
  }
};

// The scan a scan matcher reads: every column's surface (DisparityScan::column_surface) where
// the projection found them, else the scan itself.
inline DisparityScan surfaceReadings(const DisparityScan& scan) {
  DisparityScan surfaces = scan;
  if (scan.column_surface.size() == scan.column_disparity.size() &&
      scan.column_surface_row.size() == scan.column_row.size()) {
    surfaces.column_disparity = scan.column_surface;
    surfaces.column_row = scan.column_surface_row;
  }
  return surfaces;
}

// Figure 5d: depth along the optical axis, Z = f B / d, per column; +inf where the column saw no
// obstacle (like the disparity's invalid marker, "nothing there", never 0).
inline std::vector<float> columnDepths(const DisparityScan& scan, const CameraRig& rig) {
  std::vector<float> depths(scan.column_disparity.size(), kInvalidDisparity);
  for (int column = 0; column < scan.columns(); ++column) {
    if (scan.valid(column)) {
      depths[column] = static_cast<float>(rig.depthForDisparity(scan.column_disparity[column]));
    }
  }
  return depths;
}

}  // namespace stereonav
