#pragma once

#include <mrpt/poses/CPose2D.h>

#include <optional>

#include "localization/floor_motion.h"
#include "localization/localization_options.h"
#include "localization/scan_localizer.h"
#include "mapping/stereo_mapper.h"
#include "occupancy_grid/disparity_tagged_grid.h"
#include "rig/camera_rig.h"

namespace stereonav {

// Localizes the frames of a StereoMapper, as `map --poses localized` and `explore` on localized
// poses both do: the step since the last frame measured on the floor's texture (with
// [localization] floor_motion) or read from the wheels, then corrected by ScanLocalizer.
//
//   FrameLocalizer localizer(options.localization, rig);
//   for each frame: mapper.observe(frame);
//                   pose = localizer.update(wheel_odometry, mapper, map_so_far).pose;
class FrameLocalizer {
 public:
  FrameLocalizer(const LocalizationOptions& options, const CameraRig& rig);

  // The last frame `mapper` observed, at the wheels' `odometry`, against the map before it.
  const ScanMatch& update(const mrpt::poses::CPose2D& odometry, const StereoMapper& mapper,
                          const DisparityTaggedGrid& map);
  // Frames whose step the floor measured (0 without floor_motion): the rest are the wheels'.
  int floorMeasuredSteps() const { return floor_odometry_ ? floor_odometry_->measuredSteps() : 0; }

 private:
  ScanLocalizer scan_localizer_;
  std::optional<FloorOdometry> floor_odometry_;  // with floor_motion
};

}  // namespace stereonav
