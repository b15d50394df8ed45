#include "evaluation/truth_regions.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace stereonav {

cv::Mat1b reachableFreeCells(const RosMap& truth, double start_x, double start_y) {
  const int ix = static_cast<int>(std::floor((start_x - truth.xMin()) / truth.resolution()));
  const int iy = static_cast<int>(std::floor((start_y - truth.yMin()) / truth.resolution()));
  if (truth.at(start_x, start_y) != CellClass::kFree) {
    throw std::invalid_argument("start " + std::to_string(start_x) + "," + std::to_string(start_y) +
                                " is not on a free cell of the ground truth");
  }
  cv::Mat1b free_cells(truth.height(), truth.width());
  for (int y = 0; y < truth.height(); ++y) {
    for (int x = 0; x < truth.width(); ++x) free_cells(y, x) = truth.cell(x, y) == CellClass::kFree ? 255 : 0;
  }
  // Fill the start's component with 128: exactly the reachable cells end up at 128.
  cv::floodFill(free_cells, cv::Point(ix, iy), cv::Scalar(128), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
  cv::Mat1b reachable = free_cells == 128;
  return reachable;
}

cv::Mat1b obstacleCellsInView(const RosMap& truth, const std::vector<mrpt::poses::CPose2D>& poses,
                              double fov_deg, double range_m) {
  cv::Mat1b seen = cv::Mat1b::zeros(truth.height(), truth.width());
  const double r = truth.resolution();
  // A quarter cell along the ray cannot step over the corner of a cell; rays half a cell apart at
  // full range leave no cell between them unvisited.
  const double step = r / 4.0;
  const double fov = fov_deg * M_PI / 180.0;
  const int rays = std::max(2, static_cast<int>(std::ceil(fov * range_m / (r / 2.0))) + 1);
  for (const mrpt::poses::CPose2D& pose : poses) {
    for (int k = 0; k < rays; ++k) {
      const double angle = pose.phi() - fov / 2.0 + fov * k / (rays - 1);
      const double dx = std::cos(angle), dy = std::sin(angle);
      for (double t = 0.0; t <= range_m; t += step) {
        const double fx = std::floor((pose.x() + t * dx - truth.xMin()) / r);
        const double fy = std::floor((pose.y() + t * dy - truth.yMin()) / r);
        if (fx < 0 || fy < 0 || fx >= truth.width() || fy >= truth.height()) break;
        const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
        if (truth.cell(ix, iy) == CellClass::kOccupied) {
          seen(iy, ix) = 255;
          break;
        }
      }
    }
  }
  return seen;
}

}  // namespace stereonav
