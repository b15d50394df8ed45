#include "explorer/seen_free_memory.h"

#include <cmath>

#include "explorer/line_of_sight.h"

namespace stereonav {

void SeenFreeMemory::update(const DisparityTaggedGrid& grid, const mrpt::poses::CPose2D& pose) {
  int robot_col = 0, robot_row = 0;
  if (!grid.cellAt(pose.x(), pose.y(), robot_col, robot_row)) return;
  lattice_.anchor(grid.frame());
  const OccupancyScale& scale = grid.scale();
  const double r = grid.resolution();
  const int reach = static_cast<int>(std::ceil(options_.range_m / r));
  // Which cells of the square the loop below looks at (and a ring around it) are free, looked up
  // once: each cell is read by its neighbours' tests and by many lines of sight.
  const cv::Rect window(robot_col - reach - 1, robot_row - reach - 1, 2 * reach + 3, 2 * reach + 3);
  cv::Mat1b free_cells(window.size());
  for (int row = 0; row < window.height; ++row) {
    uint8_t* free_row = free_cells[row];
    for (int col = 0; col < window.width; ++col) {
      const int grid_col = window.x + col, grid_row = window.y + row;
      free_row[col] = grid.containsCell(grid_col, grid_row) &&
                      scale.classify(grid.occupancy(grid_col, grid_row)) == CellClass::kFree;
    }
  }
  const auto is_free = [&](int col, int row) { return free_cells(row - window.y, col - window.x) != 0; };
  const auto amid_free = [&](int col, int row) {
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if (!is_free(col + dc, row + dr)) return false;
      }
    }
    return true;
  };
  // The cameras never see the floor under the body: the line may start across it.
  const double body_cells_sq = std::pow(options_.body_radius_m / r, 2);
  const auto passes = [&](int col, int row) {
    const double dc = col - robot_col, dr = row - robot_row;
    return dc * dc + dr * dr <= body_cells_sq || is_free(col, row);
  };
  const double half_view = options_.field_of_view_deg * M_PI / 360.0;
  for (int row = robot_row - reach; row <= robot_row + reach; ++row) {
    for (int col = robot_col - reach; col <= robot_col + reach; ++col) {
      if (!amid_free(col, row)) continue;
      const double x = grid.minX() + (col + 0.5) * r, y = grid.minY() + (row + 0.5) * r;
      if (withinView(pose, x, y, options_.range_m, half_view) &&
          alongStraightLine(cv::Point(robot_col, robot_row), cv::Point(col, row), passes)) {
        const WorldCellLattice::Cell cell = lattice_.cellAt(x, y);
        uint8_t& remembered = cells_.at(cell);
        if (!remembered) centres_.push_back(lattice_.centre(cell));
        remembered = 1;
      }
    }
  }
}

}  // namespace stereonav
