#include "explorer/frontier_memory.h"

#include <algorithm>
#include <cmath>

#include "explorer/line_of_sight.h"

namespace stereonav {

FrontierMemory::FrontierMemory(const ExplorerOptions& options) : options_(options) {}

FrontierMemory::WorldCell FrontierMemory::worldCell(const NavigationGrid& grid, int col, int row) const {
  return lattice_.cellAt(grid.centreX(col), grid.centreY(row));
}

void FrontierMemory::countCloseViews(const NavigationGrid& grid, const std::vector<Frontier>& frontiers,
                                     const mrpt::poses::CPose2D& pose) {
  int robot_col = 0, robot_row = 0;
  if (!grid.cellAt(pose.x(), pose.y(), robot_col, robot_row)) return;
  const double range = options_.looked_at_range_m;
  const double half_view = options_.field_of_view_deg * M_PI / 360.0;
  const auto in_plain_sight = [&](const cv::Point& cell) {
    if (!withinView(pose, grid.centreX(cell.x), grid.centreY(cell.y), range, half_view)) return false;
    // An obstacle or unseen space between hides the cell.
    return alongStraightLine(cv::Point(robot_col, robot_row), cell,
                             [&](int col, int row) { return grid.cellClass(col, row) == NavigationGrid::kFree; });
  };
  for (const Frontier& frontier : frontiers) {
    for (const cv::Point& cell : frontier.cells) {
      if (in_plain_sight(cell)) ++close_views_.at(worldCell(grid, cell.x, cell.y));
    }
  }
}

void FrontierMemory::dropSurfaced(const NavigationGrid& grid, const std::vector<Frontier>& frontiers,
                                  const std::vector<mrpt::math::TPoint2D>& scan, const mrpt::poses::CPose2D& pose) {
  std::set<std::pair<int, int>> surfaced;
  for (const mrpt::math::TPoint2D& point : scan) {
    int col = 0, row = 0;
    if (std::hypot(point.x - pose.x(), point.y - pose.y()) <= options_.seen_free_range_m &&
        grid.cellAt(point.x, point.y, col, row)) {
      surfaced.emplace(col, row);
    }
  }
  if (surfaced.empty()) return;
  const cv::Rect inside(0, 0, grid.cellClasses().cols, grid.cellClasses().rows);
  for (const Frontier& frontier : frontiers) {
    for (const cv::Point& cell : frontier.cells) {
      int unresolved = 0, seen = 0;
      for (const cv::Point& step : {cv::Point(1, 0), cv::Point(-1, 0), cv::Point(0, 1), cv::Point(0, -1)}) {
        const cv::Point next = cell + step;
        if (!inside.contains(next)) continue;
        const uint8_t kind = grid.cellClass(next.x, next.y);
        if (kind != NavigationGrid::kUnknown && kind != NavigationGrid::kImprecise) continue;
        ++unresolved;
        seen += surfaced.count({next.x, next.y}) > 0 ? 1 : 0;
      }
      if (unresolved > 0 && seen == unresolved) drop(grid, cell);
    }
  }
}

bool FrontierMemory::beginSecondPass() {
  if (second_pass_ || (dropped_.empty() && looked_from_.empty() && close_views_.empty())) return false;
  second_pass_ = true;
  dropped_.clear();
  looked_from_.clear();
  close_views_.clear();
  return true;
}

bool FrontierMemory::isDropped(const NavigationGrid& grid, int col, int row) const {
  const double x = grid.centreX(col), y = grid.centreY(row);
  const double half_view = options_.field_of_view_deg * M_PI / 360.0;
  for (const mrpt::poses::CPose2D& pose : looked_from_) {
    if (withinView(pose, x, y, options_.looked_at_range_m, half_view)) return true;
  }
  const WorldCell key = worldCell(grid, col, row);
  if (dropped_.get(key) != 0) return true;
  const int views = close_views_.get(key);
  return views > 0 && views >= options_.resolving_views;
}

std::vector<Frontier> FrontierMemory::withoutDropped(const NavigationGrid& grid, std::vector<Frontier> frontiers) const {
  for (Frontier& frontier : frontiers) {
    frontier.cells.erase(std::remove_if(frontier.cells.begin(), frontier.cells.end(),
                                        [&](const cv::Point& cell) { return isDropped(grid, cell.x, cell.y); }),
                         frontier.cells.end());
  }
  frontiers.erase(std::remove_if(frontiers.begin(), frontiers.end(),
                                 [&](const Frontier& frontier) {
                                   return static_cast<int>(frontier.cells.size()) < options_.min_frontier_cells;
                                 }),
                  frontiers.end());
  return frontiers;
}

}  // namespace stereonav
