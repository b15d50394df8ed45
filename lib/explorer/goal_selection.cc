#include "explorer/goal_selection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

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
  // Without a distance cost a frontier's discs all stamp its seed cost, and a cell the disc of the
  // frontier's cell before covered holds that cost or less already: a cell next to the one before
  // stamps only the part of its disc the other's missed. The frontier finder's depth-first flood
  // gives a frontier's cells mostly one step apart: 23 cells of a 377-cell disc at 5 cm for a step
  // along a row or a column.
  const bool flat = distance_cost == 0.0;
  const auto halfWidth = [&](int dr) {
    for (const Run& run : disc) {
      if (run.dr == dr) return run.half_width;
    }
    return -1;
  };
  struct Piece {
    int dr, first_dc, last_dc;
  };
  // By the step (dx, dy) from the cell before, at [(dy + 1) * 3 + dx + 1]: the disc's cells that
  // the disc one step back does not hold.
  std::array<std::vector<Piece>, 9> crescents;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      std::vector<Piece>& pieces = crescents[static_cast<size_t>((dy + 1) * 3 + dx + 1)];
      for (const Run& run : disc) {
        const int behind = halfWidth(run.dr + dy);
        if (behind < 0) {
          pieces.push_back({run.dr, -run.half_width, run.half_width});
          continue;
        }
        const int held_first = -behind - dx, held_last = behind - dx;
        if (-run.half_width < held_first) pieces.push_back({run.dr, -run.half_width, std::min(run.half_width, held_first - 1)});
        if (run.half_width > held_last) pieces.push_back({run.dr, std::max(-run.half_width, held_last + 1), run.half_width});
      }
    }
  }
  // Per cell within reach of a frontier, inside the free cells' box where every traversable cell
  // lies, the cheapest seed and its frontier: goals of overlapping frontiers are not repeated.
  const cv::Rect& box = field.box();
  cv::Rect reached;
  for (const Frontier& frontier : frontiers) {
    for (const cv::Point& cell : frontier.cells) reached |= cv::Rect(cell.x - reach, cell.y - reach, 2 * reach + 1, 2 * reach + 1);
  }
  reached &= box;
  if (reached.empty()) return {};
  const cv::Mat1b traversable = field.traversableCells()(reached - box.tl());
  // A cell's seed is read only once it has a label: the seeds are not filled first (a box of
  // doubles per plan).
  cv::Mat1d seed(reached.size());
  cv::Mat1i label(reached.size(), -1);
  const auto stamp = [&](const cv::Point& cell, int dr, int first_dc, int last_dc, double seed_cost,
                         const double* costs, int frontier) {
    const int r = cell.y + dr - reached.y;
    if (r < 0 || r >= reached.height) return;
    const int first = cell.x + first_dc - reached.x;
    const int begin = std::max(0, first), end = std::min(reached.width, cell.x + last_dc + 1 - reached.x);
    const uint8_t* traversable_row = traversable[r];
    double* seed_row = seed[r];
    int* label_row = label[r];
    for (int c = begin; c < end; ++c) {
      if (!traversable_row[c]) continue;
      const double cost = seed_cost + costs[c - first];
      if (label_row[c] < 0 || cost < seed_row[c]) {
        seed_row[c] = cost;
        label_row[c] = frontier;
      }
    }
  };
  const std::vector<double> no_costs(static_cast<size_t>(2 * reach + 1), 0.0);
  for (size_t i = 0; i < frontiers.size(); ++i) {
    const bool waits = frontiers[i].unseen_area_m2 < options_.pocket_area_m2 || !frontiers[i].borders_unknown;
    const double seed_cost = (isTarget(grid, frontiers[i], goal_radius, memory) ? 0.0 : options_.target_switch_penalty_m) +
                             (waits ? options_.pocket_penalty_m : 0.0);
    const int index = static_cast<int>(i);
    std::optional<cv::Point> before;
    for (const cv::Point& cell : frontiers[i].cells) {
      const cv::Point step = before ? cell - *before : cv::Point(2, 2);
      before = cell;
      if (flat && std::abs(step.x) <= 1 && std::abs(step.y) <= 1) {
        for (const Piece& piece : crescents[static_cast<size_t>((step.y + 1) * 3 + step.x + 1)]) {
          stamp(cell, piece.dr, piece.first_dc, piece.last_dc, seed_cost, no_costs.data(), index);
        }
        continue;
      }
      for (const Run& run : disc) stamp(cell, run.dr, -run.half_width, run.half_width, seed_cost, run.costs.data(), index);
    }
  }
  std::vector<GoalCell> goals;
  for (int row = 0; row < reached.height; ++row) {
    for (int col = 0; col < reached.width; ++col) {
      if (label(row, col) >= 0) goals.push_back({reached.x + col, reached.y + row, seed(row, col), label(row, col)});
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
