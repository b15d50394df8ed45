#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>

#include "occupancy_grid/observation_disparity_scan.h"
#include "occupancy_grid/stereo_occupancy_grid_map.h"

// MRPT finds serialisable classes by name (reading rawlogs, .simplemap files, CMultiMetricMap
// serialisations) only once they are registered; MRPT's own libraries do it when they are
// loaded, and so does this one.
MRPT_INITIALIZER(registerStereonavOccupancyGridClasses) {
  mrpt::rtti::registerClass(CLASS_ID(stereonav::CObservationDisparityScan));
  mrpt::rtti::registerClass(CLASS_ID(stereonav::CStereoOccupancyGridMap));
}
