#include "explorer/plan_image.h"

namespace stereonav {

cv::Mat3b drawPlan(const NavigationGrid& grid, const CostToGoField& field, const std::vector<Frontier>& frontiers,
                   const std::vector<cv::Point2d>& remembered_obstacles) {
  cv::Mat3b image(grid.height(), grid.width());
  const auto pixel = [&](int col, int row) -> cv::Vec3b& { return image(grid.height() - 1 - row, col); };
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      switch (grid.cellClass(col, row)) {
        case NavigationGrid::kFree:
          pixel(col, row) = field.traversable(col, row) ? cv::Vec3b(200, 255, 200) : cv::Vec3b(255, 255, 255);
          break;
        case NavigationGrid::kUnknown: pixel(col, row) = cv::Vec3b(128, 128, 128); break;
        case NavigationGrid::kImprecise: pixel(col, row) = cv::Vec3b(64, 64, 64); break;
        default: pixel(col, row) = cv::Vec3b(0, 0, 0); break;
      }
    }
  }
  for (const Frontier& frontier : frontiers) {
    for (const cv::Point& cell : frontier.cells) pixel(cell.x, cell.y) = cv::Vec3b(255, 0, 0);
  }
  for (const cv::Point2d& point : remembered_obstacles) {
    int col = 0, row = 0;
    if (grid.cellAt(point.x, point.y, col, row)) pixel(col, row) = cv::Vec3b(0, 0, 255);
  }
  return image;
}

}  // namespace stereonav
