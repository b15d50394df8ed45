#include "localization/obstacle_distance_field.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace stereonav {

ObstacleDistanceField::ObstacleDistanceField(const DisparityTaggedGrid& grid,
                                             double max_distance_m)
    : frame_(grid.frame()), max_distance_m_(max_distance_m) {
  cv::Mat1b not_occupied(grid.height(), grid.width(), uint8_t{255});
  for (int row = 0; row < grid.height(); ++row) {
    const uint8_t* cells = grid.occupancyRow(row);
    uint8_t* out = not_occupied[row];
    for (int col = 0; col < grid.width(); ++col) {
      if (grid.scale().classify(cells[col]) == CellClass::kOccupied) {
        out[col] = 0;
        has_obstacles_ = true;
      }
    }
  }
  if (!has_obstacles_ || not_occupied.empty()) {
    distance_m_ = cv::Mat1f(std::max(grid.height(), 1), std::max(grid.width(), 1),
                            static_cast<float>(max_distance_m));
    return;
  }
  cv::distanceTransform(not_occupied, distance_m_, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  distance_m_ *= frame_.resolution;
  cv::min(distance_m_, max_distance_m, distance_m_);
}

double ObstacleDistanceField::distance(double x, double y) const {
  const double u = (x - frame_.origin_x) / frame_.resolution - 0.5;
  const double v = (y - frame_.origin_y) / frame_.resolution - 0.5;
  if (!(u >= 0.0 && v >= 0.0 && u <= distance_m_.cols - 1 && v <= distance_m_.rows - 1)) {
    return max_distance_m_;
  }
  const int col = static_cast<int>(u);
  const int row = static_cast<int>(v);
  const int col1 = std::min(col + 1, distance_m_.cols - 1);
  const int row1 = std::min(row + 1, distance_m_.rows - 1);
  const double fu = u - col, fv = v - row;
  const float* r0 = distance_m_[row];
  const float* r1 = distance_m_[row1];
  return (1 - fv) * ((1 - fu) * r0[col] + fu * r0[col1]) + fv * ((1 - fu) * r1[col] + fu * r1[col1]);
}

}  // namespace stereonav
