#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

// The same cells as an MRPT occupancy grid (same limits, resolution and cell indices). MRPT
// stores per cell the probability of being FREE, so each cell gets 1 - G/255 (see
// OccupancyScale: p_occ = G/255), quantised by MRPT's 8-bit log-odds.
mrpt::maps::COccupancyGridMap2D toMrptOccupancyGrid(const DisparityTaggedGrid& grid);

}  // namespace stereonav
