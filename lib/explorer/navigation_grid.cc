#include "explorer/navigation_grid.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace stereonav {
namespace {

// Metres from each cell centre to the near edge of the nearest cell where `is_clear` is 0; the
// grid's border counts as not clear, so nothing plans off the map.
cv::Mat1f distanceToBlocked(const cv::Mat1b& is_clear, double resolution) {
  cv::Mat1b padded;
  cv::copyMakeBorder(is_clear, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat1f cells;
  cv::distanceTransform(padded, cells, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::Mat1f metres = cells(cv::Rect(1, 1, is_clear.cols, is_clear.rows)).clone();
  metres = (metres - 0.5f) * static_cast<float>(resolution);
  return metres;
}

}  // namespace

NavigationGrid::NavigationGrid(const DisparityTaggedGrid& grid, const std::vector<mrpt::poses::CPose2D>& visited,
                               double body_radius_m)
    : frame_(grid.frame()), cell_class_(grid.height(), grid.width()) {
  const OccupancyScale& scale = grid.scale();
  for (int row = 0; row < grid.height(); ++row) {
    const uint8_t* g = grid.occupancyRow(row);
    uint8_t* out = cell_class_[row];
    for (int col = 0; col < grid.width(); ++col) {
      switch (scale.classify(g[col])) {
        case CellClass::kFree: out[col] = kFree; break;
        case CellClass::kUnknown: out[col] = kUnknown; break;
        case CellClass::kOccupied: out[col] = kOccupied; break;
      }
    }
  }
  const int reach = static_cast<int>(std::ceil(body_radius_m / frame_.resolution));
  for (const mrpt::poses::CPose2D& pose : visited) {
    int centre_col = 0, centre_row = 0;
    if (!cellAt(pose.x(), pose.y(), centre_col, centre_row)) continue;
    for (int row = centre_row - reach; row <= centre_row + reach; ++row) {
      for (int col = centre_col - reach; col <= centre_col + reach; ++col) {
        if (!contains(col, row) || cell_class_(row, col) != kUnknown) continue;
        if (std::hypot(centreX(col) - pose.x(), centreY(row) - pose.y()) <= body_radius_m) {
          cell_class_(row, col) = kFree;
        }
      }
    }
  }
  clearance_m_ = distanceToBlocked(cell_class_ == kFree, frame_.resolution);
  obstacle_distance_m_ = distanceToBlocked(cell_class_ != kOccupied, frame_.resolution);
}

bool NavigationGrid::cellAt(double x, double y, int& col, int& row) const {
  col = static_cast<int>(std::floor((x - frame_.origin_x) / frame_.resolution));
  row = static_cast<int>(std::floor((y - frame_.origin_y) / frame_.resolution));
  return contains(col, row);
}

}  // namespace stereonav
