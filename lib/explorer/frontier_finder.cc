#include "explorer/frontier_finder.h"

#include <algorithm>

namespace stereonav {
namespace {

bool isFrontierCell(const NavigationGrid& grid, int col, int row) {
  if (grid.cellClass(col, row) != NavigationGrid::kFree) return false;
  static const int kNeighbours[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& offset : kNeighbours) {
    const int c = col + offset[0], r = row + offset[1];
    if (!grid.contains(c, r)) continue;
    const uint8_t neighbour = grid.cellClass(c, r);
    if (neighbour == NavigationGrid::kUnknown || neighbour == NavigationGrid::kImprecise) return true;
  }
  return false;
}

}  // namespace

std::vector<Frontier> findFrontiers(const NavigationGrid& grid, int min_cells) {
  cv::Mat1b is_frontier(grid.height(), grid.width(), uint8_t{0});
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) is_frontier(row, col) = isFrontierCell(grid, col, row) ? 1 : 0;
  }
  std::vector<Frontier> frontiers;
  std::vector<cv::Point> stack;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (!is_frontier(row, col)) continue;
      Frontier frontier;
      is_frontier(row, col) = 0;
      stack.assign(1, cv::Point(col, row));
      while (!stack.empty()) {
        const cv::Point cell = stack.back();
        stack.pop_back();
        frontier.cells.push_back(cell);
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const int c = cell.x + dc, r = cell.y + dr;
            if (grid.contains(c, r) && is_frontier(r, c)) {
              is_frontier(r, c) = 0;
              stack.emplace_back(c, r);
            }
          }
        }
      }
      if (static_cast<int>(frontier.cells.size()) < min_cells) continue;
      for (const cv::Point& cell : frontier.cells) {
        frontier.centroid_x += grid.centreX(cell.x);
        frontier.centroid_y += grid.centreY(cell.y);
      }
      frontier.centroid_x /= static_cast<double>(frontier.cells.size());
      frontier.centroid_y /= static_cast<double>(frontier.cells.size());
      frontiers.push_back(std::move(frontier));
    }
  }
  std::stable_sort(frontiers.begin(), frontiers.end(),
                   [](const Frontier& a, const Frontier& b) { return a.cells.size() > b.cells.size(); });
  return frontiers;
}

}  // namespace stereonav
