#pragma once

#include <string>
#include <vector>

#include "occupancy_grid/ros_map.h"

namespace stereonav {

// A small map drawn as text, top row first as in the image: '#' occupied, '.' free, '?' unknown.
inline RosMap drawnMap(const std::vector<std::string>& rows, double resolution = 1.0, double x_min = 0.0,
                       double y_min = 0.0) {
  const int height = static_cast<int>(rows.size());
  cv::Mat1b classes(height, static_cast<int>(rows.front().size()));
  for (int row = 0; row < height; ++row) {
    for (int x = 0; x < classes.cols; ++x) {
      const char c = rows[row][x];
      classes(height - 1 - row, x) = static_cast<uint8_t>(c == '#'   ? CellClass::kOccupied
                                                          : c == '.' ? CellClass::kFree
                                                                     : CellClass::kUnknown);
    }
  }
  return RosMap(resolution, x_min, y_min, classes);
}

}  // namespace stereonav
