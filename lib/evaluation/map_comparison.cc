#include "evaluation/map_comparison.h"

#include <opencv2/imgproc.hpp>

#include <stdexcept>

#include "evaluation/truth_regions.h"

namespace stereonav {
namespace {

// Cells within `tolerance` (Chebyshev) of a set cell of `mask`.
cv::Mat1b withinTolerance(const cv::Mat1b& mask, int tolerance) {
  if (tolerance == 0) return mask.clone();
  cv::Mat1b grown;
  cv::dilate(mask, grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * tolerance + 1, 2 * tolerance + 1)));
  return grown;
}

}  // namespace

MapComparison compareOnTruthCells(const RosMap& map, const RosMap& truth, const MapScoreOptions& options) {
  if (options.tolerance_cells < 0) throw std::invalid_argument("tolerance must be >= 0 cells");
  const int width = truth.width(), height = truth.height();
  const double r = truth.resolution();

  MapComparison comparison;
  cv::Mat1b inside(height, width);
  comparison.truth_occupied.create(height, width);
  comparison.map_occupied.create(height, width);
  comparison.map_free.create(height, width);
  for (int iy = 0; iy < height; ++iy) {
    for (int ix = 0; ix < width; ++ix) {
      const CellClass truth_class = truth.cell(ix, iy);
      const CellClass map_class = map.at(truth.xMin() + (ix + 0.5) * r, truth.yMin() + (iy + 0.5) * r);
      const bool known = truth_class != CellClass::kUnknown;
      inside(iy, ix) = known ? 255 : 0;
      comparison.truth_occupied(iy, ix) = truth_class == CellClass::kOccupied ? 255 : 0;
      comparison.map_occupied(iy, ix) = known && map_class == CellClass::kOccupied ? 255 : 0;
      comparison.map_free(iy, ix) = known && map_class == CellClass::kFree ? 255 : 0;
    }
  }

  comparison.scored_obstacles =
      options.poses.empty() ? comparison.truth_occupied
                            : obstacleCellsInView(truth, options.poses, options.view_fov_deg, options.view_range_m);
  comparison.near_truth_obstacle = withinTolerance(comparison.truth_occupied, options.tolerance_cells);
  comparison.near_map_obstacle = withinTolerance(comparison.map_occupied, options.tolerance_cells);

  if (options.start || !options.poses.empty()) {
    const double x = options.start ? options.start->first : options.poses.front().x();
    const double y = options.start ? options.start->second : options.poses.front().y();
    comparison.free_space = reachableFreeCells(truth, x, y);
    comparison.coverage_from_start = true;
  } else {
    comparison.free_space = inside & ~comparison.truth_occupied;
  }
  return comparison;
}

}  // namespace stereonav
