#pragma once

#include <string>

#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

// Outputs of a DisparityTaggedGrid. Every file is written atomically (writeFileAtomically).

// MRPT's binary grid map: the serialised mrpt::maps::COccupancyGridMap2D (toMrptOccupancyGrid)
// in a gzip stream, as MRPT's apps write and read it (image2gridmap, grid-matching, navigation
// demos load "*.gridmap.gz" or "*.gridmap" through CFileGZInputStream). Use ".gridmap.gz".
void saveMrptGridmap(const DisparityTaggedGrid& grid, const std::string& path);

// An image with one pixel per cell, value 255 - G (white free, black occupied, grey unknown;
// continuous, so evidence strength shows), first image row = top of the map (max y), as MRPT's
// grid viewers and COccupancyGridMap2D::saveAsBitmapFile show it. Format from the extension.
void saveGridImage(const DisparityTaggedGrid& grid, const std::string& path);

// A ROS map_server map: `yaml_path` and, next to it, the same name with ".pgm" holding the
// saveGridImage() picture. With negate 0 map_server reads occupancy = (255 - pixel) / 255 =
// G / 255, and the thresholds are written half a level outside the grid's own (occupied_thresh =
// (occupied_above + 0.5) / 255, free_thresh = (free_below - 0.5) / 255), so map_server, MRPT's
// loadFromROSMapServerYAML and OccupancyScale::classify agree on every cell. mode: trinary.
void saveRosMapServer(const DisparityTaggedGrid& grid, const std::string& yaml_path);

}  // namespace stereonav
