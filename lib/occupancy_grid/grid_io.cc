#include "occupancy_grid/grid_io.h"

#include <mrpt/serialization/CArchive.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "common/atomic_file.h"
#include "occupancy_grid/grid_conversion.h"

namespace stereonav {

namespace {

cv::Mat1b gridPicture(const DisparityTaggedGrid& grid) {
  cv::Mat1b picture(grid.height(), grid.width());
  for (int row = 0; row < grid.height(); ++row) {
    const uint8_t* occupancy = grid.occupancyRow(row);
    uint8_t* pixels = picture.ptr<uint8_t>(grid.height() - 1 - row);
    for (int col = 0; col < grid.width(); ++col) pixels[col] = 255 - occupancy[col];
  }
  return picture;
}

std::string withoutExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
  return path.substr(0, dot);
}

std::string fileName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

void saveMrptGridmap(const DisparityTaggedGrid& grid, const std::string& path) {
  const mrpt::maps::COccupancyGridMap2D mrpt_grid = toMrptOccupancyGrid(grid);
  writeGzArchiveAtomically(path, [&](mrpt::serialization::CArchive& archive) { archive << mrpt_grid; });
}

void saveGridImage(const DisparityTaggedGrid& grid, const std::string& path) {
  writeImageAtomically(path, gridPicture(grid));
}

void saveRosMapServer(const DisparityTaggedGrid& grid, const std::string& yaml_path) {
  const std::string image_path = withoutExtension(yaml_path) + ".pgm";
  writeImageAtomically(image_path, gridPicture(grid));

  const OccupancyScale& scale = grid.scale();
  std::ostringstream yaml;
  yaml << std::setprecision(17);
  yaml << "image: " << fileName(image_path) << "\n"
       << "resolution: " << grid.resolution() << "\n"
       << "origin: [" << grid.minX() << ", " << grid.minY() << ", 0.0]\n"
       << "negate: 0\n"
       << "occupied_thresh: " << (scale.occupied_above + 0.5) / 255.0 << "\n"
       << "free_thresh: " << (scale.free_below - 0.5) / 255.0 << "\n"
       << "mode: trinary\n";
  writeStringAtomically(yaml_path, yaml.str());
}

}  // namespace stereonav
