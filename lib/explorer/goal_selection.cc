#include "explorer/goal_selection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stereonav {

GoalSelection::GoalSelection(const ExplorerOptions& options) : options_(options) {}

void GoalSelection::carryTargetOver(const NavigationGrid& grid, const std::vector<Frontier>& frontiers,
                                    const FrontierMemory& memory) {
  target_cells_.clear();
  if (!target_ || target_label_ < 0 || target_label_ >= static_cast<int>(frontiers.size())) return;
  for (const cv::Point& cell : frontiers[static_cast<size_t>(target_label_)].cells) {
    target_cells_.insert(memory.worldCell(grid, cell.x, cell.y));
  }
}

bool GoalSelection::isTarget(const NavigationGrid& grid, const Frontier& frontier, double goal_radius,
                             const FrontierMemory& memory) const {
  if (!target_) return false;
  // The goal region's edge, plus a little for the frontier receding as it is resolved.
  const double near_target_sq = (goal_radius + 0.3) * (goal_radius + 0.3);
  for (const cv::Point& cell : frontier.cells) {
    const double dx = grid.centreX(cell.x) - target_->x, dy = grid.centreY(cell.y) - target_->y;
    if (dx * dx + dy * dy <= near_target_sq || target_cells_.count(memory.worldCell(grid, cell.x, cell.y)) > 0) {
      return true;
    }
  }
  return false;
}

std::vector<GoalCell> GoalSelection::goals(const NavigationGrid& grid, const CostToGoField& field,
                                           const std::vector<Frontier>& frontiers, double body_radius_m,
                                           const FrontierMemory& memory, double look_from_m) const {
  const double goal_radius = body_radius_m + options_.goal_distance_m;
  const double reach_m = std::max(goal_radius, look_from_m);
  const int reach = static_cast<int>(std::ceil(reach_m / grid.resolution()));
  const double reach_sq = reach_m * reach_m / (grid.resolution() * grid.resolution());
  // Looking from afar, a step nearer the frontier is worth more than any step of path costs
  // (at most 1 + repulsion_weight per metre): the nearest place the body reaches wins.
  const double distance_cost = look_from_m > 0.0 ? 2.0 * (1.0 + options_.repulsion_weight) : 0.0;
  // The cells within reach of a frontier cell, row by row: a row's cells form one run, with what
  // standing on each adds.
  struct Run {
    int dr, half_width;
    std::vector<double> costs;  // from dc = -half_width on
  };
  std::vector<Run> disc;
  for (int dr = -reach; dr <= reach; ++dr) {
    Run run{dr, -1, {}};
    for (int dc = -reach; dc <= reach; ++dc) {
      if (dc * dc + dr * dr > reach_sq) continue;
      run.half_width = std::abs(dc);
      run.costs.push_back(std::hypot(dc, dr) * grid.resolution() * distance_cost);
    }
    if (run.half_width >= 0) disc.push_back(std::move(run));
  }
  // Per cell of the free cells' box, where every traversable cell lies, the cheapest seed and its
  // frontier: goals of overlapping frontiers are not repeated.
  const cv::Rect& box = field.box();
  const cv::Mat1b& traversable = field.traversableCells();
  cv::Mat1d seed(box.size(), std::numeric_limits<double>::infinity());
  cv::Mat1i label(box.size(), -1);
  for (size_t i = 0; i < frontiers.size(); ++i) {
    const bool waits = frontiers[i].unseen_area_m2 < options_.pocket_area_m2 || !frontiers[i].borders_unknown;
    const double seed_cost = (isTarget(grid, frontiers[i], goal_radius, memory) ? 0.0 : options_.target_switch_penalty_m) +
                             (waits ? options_.pocket_penalty_m : 0.0);
    for (const cv::Point& cell : frontiers[i].cells) {
      for (const Run& run : disc) {
        const int r = cell.y + run.dr - box.y;
        if (r < 0 || r >= box.height) continue;
        const int first = cell.x - run.half_width - box.x;
        const int begin = std::max(0, first), end = std::min(box.width, cell.x + run.half_width + 1 - box.x);
        const uint8_t* traversable_row = traversable[r];
        double* seed_row = seed[r];
        int* label_row = label[r];
        for (int c = begin; c < end; ++c) {
          if (!traversable_row[c]) continue;
          const double cost = seed_cost + run.costs[static_cast<size_t>(c - first)];
          if (cost < seed_row[c]) {
            seed_row[c] = cost;
            label_row[c] = static_cast<int>(i);
          }
        }
      }
    }
  }
  std::vector<GoalCell> goals;
  for (int row = 0; row < box.height; ++row) {
    for (int col = 0; col < box.width; ++col) {
      if (label(row, col) >= 0) goals.push_back({box.x + col, box.y + row, seed(row, col), label(row, col)});
    }
  }
  return goals;
}

void GoalSelection::aimAt(const cv::Point2d& goal, int label) {
  target_ = goal;
  target_label_ = label;
}

void GoalSelection::clear() {
  target_.reset();
  target_label_ = -1;
  target_cells_.clear();
}

}  // namespace stereonav
