#include "evaluation/exploration_coverage.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace stereonav {

ReachableFloor::ReachableFloor(const GroundTruthMap& truth, double robot_radius_m, double start_x, double start_y)
    : cell_area_m2_(truth.resolution() * truth.resolution()) {
  const double resolution = truth.resolution();
  cv::Mat1b free(truth.height(), truth.width());
  for (int iy = 0; iy < truth.height(); ++iy) {
    for (int ix = 0; ix < truth.width(); ++ix) free(iy, ix) = truth.cell(ix, iy) == GroundTruthMap::kFree ? 255 : 0;
  }
  // Where the body's centre may stand: free cells at least a radius from any other cell.
  cv::Mat1f clearance;
  cv::Mat1b padded;
  cv::copyMakeBorder(free, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::distanceTransform(padded, clearance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  clearance = clearance(cv::Rect(1, 1, free.cols, free.rows)).clone();
  cv::Mat1b centre_ok = (clearance - 0.5f) * static_cast<float>(resolution) >= robot_radius_m;
  // The connected part of it holding the start (flood fill marks it 128).
  const int start_ix = static_cast<int>(std::floor((start_x - truth.xMin()) / resolution));
  const int start_iy = static_cast<int>(std::floor((start_y - truth.yMin()) / resolution));
  if (start_ix < 0 || start_iy < 0 || start_ix >= free.cols || start_iy >= free.rows || !centre_ok(start_iy, start_ix)) {
    return;
  }
  cv::floodFill(centre_ok, cv::Point(start_ix, start_iy), cv::Scalar(128), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
  // Swept by the body: within a radius of a reachable centre.
  cv::Mat1b not_reached = centre_ok != 128;
  cv::Mat1f to_reached;
  cv::distanceTransform(not_reached, to_reached, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  for (int iy = 0; iy < free.rows; ++iy) {
    for (int ix = 0; ix < free.cols; ++ix) {
      if (!free(iy, ix) || to_reached(iy, ix) * resolution > robot_radius_m) continue;
      cell_centres_.emplace_back(truth.xMin() + (ix + 0.5) * resolution, truth.yMin() + (iy + 0.5) * resolution);
      area_m2_ += cell_area_m2_;
    }
  }
}

ExplorationCoverage ReachableFloor::measure(const DisparityTaggedGrid& map) const {
  ExplorationCoverage coverage;
  coverage.reachable_free_m2 = area_m2_;
  for (const cv::Point2d& centre : cell_centres_) {
    int col = 0, row = 0;
    if (!map.cellAt(centre.x, centre.y, col, row)) continue;
    const CellClass cell = map.scale().classify(map.occupancy(col, row));
    if (cell != CellClass::kUnknown) coverage.seen_m2 += cell_area_m2_;
    if (cell == CellClass::kFree) coverage.covered_m2 += cell_area_m2_;
  }
  if (coverage.reachable_free_m2 > 0.0) {
    coverage.coverage = coverage.covered_m2 / coverage.reachable_free_m2;
    coverage.seen_coverage = coverage.seen_m2 / coverage.reachable_free_m2;
  }
  const double map_cell_area = map.resolution() * map.resolution();
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      const CellClass cell = map.scale().classify(map.occupancy(col, row));
      if (cell != CellClass::kUnknown) coverage.known_area_m2 += map_cell_area;
      if (cell == CellClass::kFree) coverage.free_area_m2 += map_cell_area;
    }
  }
  return coverage;
}

}  // namespace stereonav
