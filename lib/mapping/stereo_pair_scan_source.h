#pragma once

#include <mutex>

#include "observations/frame_rectifier.h"
#include <optional>
#include <string>

#include "mapping/disparity_scanner.h"
#include "mapping/mapping_options.h"
#include "occupancy_grid/disparity_scan_source.h"

namespace stereonav {

// Lets CStereoOccupancyGridMap take raw stereo pairs: turns a
// mrpt::obs::CObservationStereoImages into its disparity scan with the front half of the
// pipeline (DisparityScanner). A pair alone is a binocular rig (its reference camera and the first
// secondary, see observations/rig_observations.h); the extra cameras of a trinocular frame travel
// as separate observations a map cannot combine, so use StereoMapper for those.
//
//   auto map = std::make_shared<CStereoOccupancyGridMap>(options.grid.stereo);
//   map->addDisparityScanSource(std::make_shared<StereoPairScanSource>(options));
//   map->insertObservation(stereo_pair, robot_pose);
//
// The rig is the [rig] section (its first secondary only) merged with the first pair's
// calibration; later pairs must have the same image size.
class StereoPairScanSource : public DisparityScanSource {
 public:
  // `images_directory`: where externally stored images of the pairs live ("" for embedded).
  explicit StereoPairScanSource(const MappingOptions& options, std::string images_directory = "");

  // nullptr for anything but a CObservationStereoImages. Throws ObservationRejected for a pair
  // that cannot be rectified (an unrectified one is rectified, frame_rectifier.h) and std::invalid_argument for one of another image size.
  CObservationDisparityScan::Ptr toDisparityScan(
      const mrpt::obs::CObservation& observation) const override;

 private:
  MappingOptions options_;
  std::string images_directory_;
  mutable FrameRectifier rectifier_;
  // The map calls a const source; the scanner's buffers are its cache. Guarded so that maps
  // sharing a source may be updated from several threads.
  mutable std::mutex mutex_;
  mutable std::optional<DisparityScanner> scanner_;
  mutable DisparityScanCamera camera_;
  mutable StageTimes times_;
};

}  // namespace stereonav
