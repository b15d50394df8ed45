#include "explorer/escape_search.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>

namespace stereonav {

std::optional<cv::Point2d> findEscape(const NavigationGrid& grid, const CostToGoField& field, int col, int row,
                                      double search_m, const std::vector<cv::Point2d>& failed, double failed_m) {
  const int reach = static_cast<int>(std::ceil(search_m / grid.resolution()));
  const auto failed_before = [&](const cv::Point2d& centre) {
    return std::any_of(failed.begin(), failed.end(), [&](const cv::Point2d& escape) {
      return std::hypot(escape.x - centre.x, escape.y - centre.y) < failed_m;
    });
  };
  std::deque<cv::Point> queue{cv::Point(col, row)};
  cv::Mat1b seen(grid.height(), grid.width(), uint8_t{0});
  seen(row, col) = 1;
  static const int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  while (!queue.empty()) {
    const cv::Point cell = queue.front();
    queue.pop_front();
    for (const auto& step : kSteps) {
      const int c = cell.x + step[0], r = cell.y + step[1];
      if (!grid.contains(c, r) || seen(r, c) || std::abs(c - col) > reach || std::abs(r - row) > reach) continue;
      seen(r, c) = 1;
      if (grid.cellClass(c, r) != NavigationGrid::kFree) continue;
      const cv::Point2d centre(grid.centreX(c), grid.centreY(r));
      if (field.traversable(c, r) && !failed_before(centre)) return centre;
      queue.emplace_back(c, r);
    }
  }
  return std::nullopt;
}

}  // namespace stereonav
