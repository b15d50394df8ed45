#include "simulator/ground_truth_map.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "common/atomic_file.h"
#include "common/ini_section.h"
#include "simulator/footprint_overlap.h"

namespace stereonav {

GroundTruthMapOptions loadGroundTruthMapOptions(IniSection& section) {
  GroundTruthMapOptions options;
  options.resolution_m = section.getDouble("resolution_m", options.resolution_m, 1e-3, 100.0);
  options.margin_m = section.getNonNegative("margin_m", options.margin_m, 1000.0);
  options.max_cells = section.getInt("max_cells", options.max_cells, 1, std::numeric_limits<int>::max());
  return options;
}

GroundTruthMap::GroundTruthMap(const World& world, const GroundTruthMapOptions& options)
    : resolution_(options.resolution_m) {
  if (!(options.resolution_m > 0.0)) throw ConfigError("ground-truth map: resolution must be positive");
  const double* bounds = world.bounds;
  x_min_ = bounds[0] - options.margin_m;
  y_min_ = bounds[1] - options.margin_m;
  const double cols = std::ceil((bounds[2] + options.margin_m - x_min_) / resolution_);
  const double rows = std::ceil((bounds[3] + options.margin_m - y_min_) / resolution_);
  if (!(cols * rows <= options.max_cells)) {
    char why[200];
    std::snprintf(why, sizeof why,
                  "[ground_truth_map] max_cells: the world's map needs %.0f x %.0f cells, more than %d; "
                  "raise max_cells or resolution_m",
                  cols, rows, options.max_cells);
    throw ConfigError(why);
  }
  const int width = static_cast<int>(cols);
  const int height = static_cast<int>(rows);
  cells_ = cv::Mat1b(std::max(height, 1), std::max(width, 1), kUnknown);
  for (int iy = 0; iy < cells_.rows; ++iy) {
    for (int ix = 0; ix < cells_.cols; ++ix) {
      const double cx = x_min_ + (ix + 0.5) * resolution_;
      const double cy = y_min_ + (iy + 0.5) * resolution_;
      if (cx > bounds[0] && cx < bounds[2] && cy > bounds[1] && cy < bounds[3]) cells_(iy, ix) = kFree;
    }
  }
  for (const auto& solid : world.solids) {
    if (!solidInHeightBand(solid, options.band_min_z, options.band_max_z)) continue;
    const FloorExtent extent = solid.floorExtent();
    const int x0 = std::max(0, static_cast<int>(std::floor((extent.x_min - x_min_) / resolution_)));
    const int y0 = std::max(0, static_cast<int>(std::floor((extent.y_min - y_min_) / resolution_)));
    const int x1 = std::min(cells_.cols - 1, static_cast<int>(std::floor((extent.x_max - x_min_) / resolution_)));
    const int y1 = std::min(cells_.rows - 1, static_cast<int>(std::floor((extent.y_max - y_min_) / resolution_)));
    for (int iy = y0; iy <= y1; ++iy) {
      for (int ix = x0; ix <= x1; ++ix) {
        if (solidOverlapsCell(solid, x_min_ + ix * resolution_, y_min_ + iy * resolution_, resolution_)) {
          cells_(iy, ix) = kOccupied;
        }
      }
    }
  }
}

void GroundTruthMap::writeRosMap(const std::string& yaml_path) const {
  const size_t dot = yaml_path.find_last_of('.');
  const size_t slash = yaml_path.find_last_of('/');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string image_path = (has_extension ? yaml_path.substr(0, dot) : yaml_path) + ".pgm";
  const std::string image_name = slash == std::string::npos ? image_path : image_path.substr(slash + 1);

  cv::Mat1b image;
  cv::flip(cells_, image, 0);  // image row 0 is the top of the map (largest y)
  writeImageAtomically(image_path, image);
  std::ostringstream yaml;
  yaml << std::setprecision(10);
  yaml << "image: " << image_name << "\n"
       << "resolution: " << resolution_ << "\n"
       << "origin: [" << x_min_ << ", " << y_min_ << ", 0.0]\n"
       << "negate: 0\n"
       << "occupied_thresh: 0.65\n"
       << "free_thresh: 0.196\n";
  writeStringAtomically(yaml_path, yaml.str());
}

}  // namespace stereonav
