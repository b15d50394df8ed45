#include "mapping/frame_localizer.h"

namespace stereonav {

FrameLocalizer::FrameLocalizer(const LocalizationOptions& options, const CameraRig& rig)
    : scan_localizer_(options, rig.reference.focal_px * rig.baseline_m) {
  if (options.floor.enabled) floor_odometry_.emplace(rig, options.floor);
}

const ScanMatch& FrameLocalizer::update(const mrpt::poses::CPose2D& odometry, const StereoMapper& mapper,
                                        const DisparityTaggedGrid& map) {
  if (!floor_odometry_) return scan_localizer_.update(odometry, *mapper.virtualScan(), map);
  const DisparityScanner& scanner = mapper.scanner();
  const mrpt::poses::CPose2D& measured =
      floor_odometry_->update(odometry, scanner.referenceGrey(), scanner.disparity());
  return scan_localizer_.update(measured, *mapper.virtualScan(), map, floor_odometry_->lastTurnDoubt());
}

}  // namespace stereonav
