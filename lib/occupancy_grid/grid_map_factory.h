#pragma once

#include <mrpt/maps/CMetricMap.h>

#include "common/ini_section.h"
#include "occupancy_grid/stereo_occupancy_grid_map.h"

namespace stereonav {

// Which occupancy model maps the scans:
//   linear     - the paper's grid (CStereoOccupancyGridMap: trapezoid/triangle regions, G += K)
//   mrpt_bayes - MRPT's own COccupancyGridMap2D (Bayesian log-odds) fed the virtual range scan
enum class GridModel { kLinear, kMrptBayes };

struct GridMapOptions {
  GridModel model = GridModel::kLinear;
  StereoGridMapOptions stereo;
};

// The whole [grid] section: model, the GridLimits, GridUpdateOptions and SensorModelOptions
// keys; rejects unknown keys. mrpt_bayes uses the limits, max_range_m (as MRPT's
// maxDistanceInsertion) and clear_invalid_columns_to_m > 0 (as considerInvalidRangesAsFreeSpace).
GridMapOptions loadGridMapOptions(IniSection& section);

// The chosen map behind MRPT's common interface. Insert a CSensoryFrame holding both the
// CObservationDisparityScan and its virtual CObservation2DRangeScan (column_projection) with
// CSensoryFrame::insertObservationsInto: each model takes the observation it understands, so the
// caller does not care which one it got.
mrpt::maps::CMetricMap::Ptr createGridMap(const GridMapOptions& options);

}  // namespace stereonav
