#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

// A map built by StereoMapper as the paper's grid: the linear model's own grid, or MRPT's
// COccupancyGridMap2D with G = 255 (1 - p_free) rounded, untagged (256 levels are finer than
// MRPT's 8-bit log-odds cells near the middle of the scale). Throws std::invalid_argument for
// any other map type.
DisparityTaggedGrid gridOfMap(const mrpt::maps::CMetricMap& map, const OccupancyScale& scale);
// The map's own grid when it is a CStereoOccupancyGridMap (no copy), else nullptr.
const DisparityTaggedGrid* ownGridOf(const mrpt::maps::CMetricMap& map);

// Writes, each atomically:
//   <prefix>.gridmap   MRPT's serialised COccupancyGridMap2D, gzip-compressed (grid_io.h)
//   <prefix>.png       white free, black occupied, grey unknown (grid_io.h)
//   <prefix>.yaml/.pgm ROS map_server map (grid_io.h)
//   <prefix>.3Dscene   mrpt::opengl::COpenGLScene with the map, the robot's path (red line) and
//                      the robot at its last pose, for SceneViewer3D
// An output that cannot be written does not stop the others; then std::runtime_error names it.
void saveMapOutputs(const mrpt::maps::CMetricMap& map, const OccupancyScale& scale,
                    const std::vector<mrpt::poses::CPose2D>& robot_path, const std::string& prefix);

}  // namespace stereonav
