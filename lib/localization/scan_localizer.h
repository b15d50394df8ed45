#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

#include "localization/localization_options.h"
#include "localization/scan_matcher.h"
#include "localization/wall_heading_filter.h"
#include "localization/wall_position_filter.h"
#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

// Tracks the robot's pose in the map's frame from odometry corrected by the frame's stereo scan
// (its virtual CObservation2DRangeScan, column_projection/virtual_range_scan.h), in two steps:
//  1. the odometry motion since the previous frame, added to the last corrected pose, is matched
//     against the map built from the frames before it (matchScan; skipped when both windows are 0);
//  2. the heading is then kept by the directions of the walls the scan sees (WallHeadingFilter),
//     which does not drift as odometry and the match against a map built from drifting poses do;
//  3. and the position by the walls' offsets (WallPositionFilter), each wall seen again telling
//     how far the robot has drifted since it was first seen.
// The map's frame is the first frame's odometry frame.
//
//   ScanLocalizer localizer(options.localization, rig.reference.focal_px * rig.baseline_m);
//   for each frame:
//     const CPose2D pose = localizer.update(odometry, virtual_scan, map_so_far).pose;
//     insert the frame's scan into the map at `pose`
class ScanLocalizer {
 public:
  // `focal_baseline_px_m`: f B of the stereo head (readings' range errors, matchablePoints).
  ScanLocalizer(const LocalizationOptions& options, double focal_baseline_px_m);

  // `turn_doubt`: the doubt of odometry's turn since the last frame beyond what the options
  // say of odometry (FloorOdometry::lastTurnDoubt).
  const ScanMatch& update(const mrpt::poses::CPose2D& odometry,
                          const mrpt::obs::CObservation2DRangeScan& scan,
                          const DisparityTaggedGrid& map, const TurnDoubt& turn_doubt = {});

  // The last corrected pose (the origin before the first update).
  const mrpt::poses::CPose2D& pose() const { return last_match_.pose; }
  const ScanMatch& lastMatch() const { return last_match_; }

 private:
  LocalizationOptions options_;
  double focal_baseline_px_m_;
  double field_range_m_;  // distances beyond are all equally far for every reading
  std::optional<mrpt::poses::CPose2D> last_odometry_;
  ScanMatch last_match_;
  std::optional<WallHeadingFilter> wall_heading_;  // from the first frame on
  std::optional<WallPositionFilter> wall_position_;
};

}  // namespace stereonav
