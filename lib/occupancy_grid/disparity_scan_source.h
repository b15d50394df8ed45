#pragma once

#include <mrpt/obs/CObservation.h>

#include "occupancy_grid/observation_disparity_scan.h"

namespace stereonav {

// Turns an observation that CStereoOccupancyGridMap does not take natively into the disparity
// scan it stands for. This is how raw stereo observations (mrpt::obs::CObservationStereoImages)
// reach the map: the full pipeline (matching, spike removal, column projection) implements a
// source for them and registers it with CStereoOccupancyGridMap::addDisparityScanSource.
class DisparityScanSource {
 public:
  virtual ~DisparityScanSource() = default;
  // nullptr when this source does not handle `observation`.
  virtual CObservationDisparityScan::Ptr toDisparityScan(
      const mrpt::obs::CObservation& observation) const = 0;
};

}  // namespace stereonav
