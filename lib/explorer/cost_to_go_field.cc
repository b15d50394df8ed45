#include "explorer/cost_to_go_field.h"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace stereonav {

CostToGoField::CostToGoField(const NavigationGrid& grid, const CostToGoOptions& options)
    : grid_(grid),
      traversable_(grid.height(), grid.width(), uint8_t{0}),
      step_weight_(grid.height(), grid.width(), 1.0f) {
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      traversable_(row, col) = grid.clearance(col, row) >= options.body_radius_m ? 1 : 0;
      // Steps are taken between traversable cells only.
      if (!traversable_(row, col) || options.repulsion_distance_m <= 0.0) continue;
      const double beyond = grid.obstacleDistance(col, row) - options.body_radius_m;
      const double s = std::max(0.0, 1.0 - beyond / options.repulsion_distance_m);
      step_weight_(row, col) = static_cast<float>(1.0 + options.repulsion_weight * std::min(1.0, s) * std::min(1.0, s));
    }
  }
}

void CostToGoField::compute(const std::vector<GoalCell>& goals) {
  const int width = grid_.width();
  cost_.create(grid_.height(), width);
  cost_.setTo(std::numeric_limits<double>::infinity());
  parent_.create(grid_.height(), width);
  parent_.setTo(-1);
  label_.create(grid_.height(), width);
  label_.setTo(-1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (const GoalCell& goal : goals) {
    if (!grid_.contains(goal.col, goal.row) || !traversable(goal.col, goal.row)) continue;
    if (goal.seed_cost >= cost_(goal.row, goal.col)) continue;
    cost_(goal.row, goal.col) = goal.seed_cost;
    parent_(goal.row, goal.col) = goal.row * width + goal.col;
    label_(goal.row, goal.col) = goal.label;
    open.emplace(goal.seed_cost, goal.row * width + goal.col);
  }
  const double resolution = grid_.resolution();
  while (!open.empty()) {
    const auto [cost, index] = open.top();
    open.pop();
    const int row = index / width, col = index % width;
    if (cost > cost_(row, col)) continue;
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if (dr == 0 && dc == 0) continue;
        const int r = row + dr, c = col + dc;
        if (!grid_.contains(c, r) || !traversable(c, r)) continue;
        // A diagonal step must not cut the corner of a blocked cell.
        if (dr != 0 && dc != 0 && (!traversable(col + dc, row) || !traversable(col, row + dr))) continue;
        const double length = (dr != 0 && dc != 0 ? M_SQRT2 : 1.0) * resolution;
        const double next = cost + length * 0.5 * (step_weight_(row, col) + step_weight_(r, c));
        if (next < cost_(r, c)) {
          cost_(r, c) = next;
          parent_(r, c) = index;
          label_(r, c) = label_(row, col);
          open.emplace(next, r * width + c);
        }
      }
    }
  }
}

std::vector<cv::Point> CostToGoField::pathFrom(int col, int row) const {
  std::vector<cv::Point> path;
  if (!grid_.contains(col, row) || !reachable(col, row)) return path;
  const int width = grid_.width();
  int index = row * width + col;
  while (true) {
    path.emplace_back(index % width, index / width);
    const int next = parent_(index / width, index % width);
    if (next == index) return path;
    index = next;
  }
}

std::vector<cv::Point2d> planPath(const NavigationGrid& grid, const CostToGoOptions& options, double start_x,
                                  double start_y, double goal_x, double goal_y) {
  std::vector<cv::Point2d> path;
  int start_col = 0, start_row = 0, goal_col = 0, goal_row = 0;
  if (!grid.cellAt(start_x, start_y, start_col, start_row) || !grid.cellAt(goal_x, goal_y, goal_col, goal_row)) {
    return path;
  }
  CostToGoField field(grid, options);
  field.compute({GoalCell{goal_col, goal_row, 0.0, 0}});
  for (const cv::Point& cell : field.pathFrom(start_col, start_row)) {
    path.emplace_back(grid.centreX(cell.x), grid.centreY(cell.y));
  }
  return path;
}

}  // namespace stereonav
