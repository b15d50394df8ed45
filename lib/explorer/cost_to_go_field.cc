#include "explorer/cost_to_go_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stereonav {

CostToGoField::CostToGoField(const NavigationGrid& grid, const CostToGoOptions& options)
    : grid_(grid),
      box_(grid.freeCells()),
      traversable_(box_.size(), uint8_t{0}),
      step_weight_(box_.size(), 1.0f) {
  for (int row = 0; row < box_.height; ++row) {
    for (int col = 0; col < box_.width; ++col) {
      const int grid_col = box_.x + col, grid_row = box_.y + row;
      traversable_(row, col) = grid.clearance(grid_col, grid_row) >= options.body_radius_m ? 1 : 0;
      // Steps are taken between traversable cells only.
      if (!traversable_(row, col) || options.repulsion_distance_m <= 0.0) continue;
      const double beyond = grid.obstacleDistance(grid_col, grid_row) - options.body_radius_m;
      const double s = std::max(0.0, 1.0 - beyond / options.repulsion_distance_m);
      step_weight_(row, col) = static_cast<float>(1.0 + options.repulsion_weight * std::min(1.0, s) * std::min(1.0, s));
    }
  }
}

namespace {

// The open cells of the wavefront, lowest (cost, index) first: a 4-ary heap that lowers a cell's
// cost in place, so each cell is in it at most once (a std::priority_queue keeps every stale
// entry). Pairs are ordered as std::pair orders them, the cell index breaking ties, so cells
// leave in exactly the order a priority queue of pairs gives.
class OpenCells {
 public:
  explicit OpenCells(size_t cells) : position_(cells, kAbsent) {}

  bool empty() const { return heap_.empty(); }

  // Adds `index` at `cost`, or lowers its cost if it is open already.
  void lower(int index, double cost) {
    size_t at = position_[static_cast<size_t>(index)];
    if (at == kAbsent) {
      at = heap_.size();
      heap_.push_back({cost, index});
    } else {
      heap_[at].cost = cost;
    }
    siftUp(at);
  }

  // Removes and returns the lowest cell.
  int pop() {
    const int index = heap_.front().index;
    position_[static_cast<size_t>(index)] = kAbsent;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      heap_.front() = last;
      siftDown(0);
    }
    return index;
  }

 private:
  struct Entry {
    double cost;
    int index;
    bool operator<(const Entry& other) const {
      return cost < other.cost || (cost == other.cost && index < other.index);
    }
  };
  static constexpr size_t kAbsent = static_cast<size_t>(-1);
  static constexpr size_t kArity = 4;

  void place(size_t at, const Entry& entry) {
    heap_[at] = entry;
    position_[static_cast<size_t>(entry.index)] = at;
  }
  void siftUp(size_t at) {
    const Entry entry = heap_[at];
    while (at > 0) {
      const size_t parent = (at - 1) / kArity;
      if (!(entry < heap_[parent])) break;
      place(at, heap_[parent]);
      at = parent;
    }
    place(at, entry);
  }
  void siftDown(size_t at) {
    const Entry entry = heap_[at];
    const size_t size = heap_.size();
    while (true) {
      const size_t first = at * kArity + 1;
      if (first >= size) break;
      size_t lowest = first;
      for (size_t child = first + 1; child < std::min(first + kArity, size); ++child) {
        if (heap_[child] < heap_[lowest]) lowest = child;
      }
      if (!(heap_[lowest] < entry)) break;
      place(at, heap_[lowest]);
      at = lowest;
    }
    place(at, entry);
  }

  std::vector<Entry> heap_;
  std::vector<size_t> position_;
};

}  // namespace

void CostToGoField::compute(const std::vector<GoalCell>& goals) {
  const int width = box_.width, height = box_.height;
  cost_.create(height, width);
  cost_.setTo(std::numeric_limits<double>::infinity());
  parent_.create(height, width);
  parent_.setTo(-1);
  label_.create(height, width);
  label_.setTo(-1);
  // The maps are continuous (created whole), so a cell's index in the box addresses each of them.
  // Cells are ordered by index as by (row, col), in the box as in the grid.
  double* const cost = cost_[0];
  int* const parent = parent_[0];
  int* const label = label_[0];
  const uint8_t* const traversable = traversable_[0];
  const float* const weight = step_weight_[0];
  OpenCells open(static_cast<size_t>(width) * height);
  for (const GoalCell& goal : goals) {
    if (!this->traversable(goal.col, goal.row)) continue;
    const int index = (goal.row - box_.y) * width + goal.col - box_.x;
    if (goal.seed_cost >= cost[index]) continue;
    cost[index] = goal.seed_cost;
    parent[index] = index;
    label[index] = goal.label;
    open.lower(index, goal.seed_cost);
  }
  const double resolution = grid_.resolution();
  const double lengths[2] = {resolution, M_SQRT2 * resolution};
  while (!open.empty()) {
    const int index = open.pop();
    const int row = index / width, col = index % width;
    const double here = cost[index];
    for (int dr = -1; dr <= 1; ++dr) {
      const int r = row + dr;
      if (r < 0 || r >= height) continue;
      for (int dc = -1; dc <= 1; ++dc) {
        const int c = col + dc;
        if ((dr == 0 && dc == 0) || c < 0 || c >= width) continue;
        const int next_index = r * width + c;
        if (!traversable[next_index]) continue;
        const bool diagonal = dr != 0 && dc != 0;
        // A diagonal step must not cut the corner of a blocked cell.
        if (diagonal && (!traversable[index + dc] || !traversable[index + dr * width])) continue;
        const double next = here + lengths[diagonal] * 0.5 * (weight[index] + weight[next_index]);
        if (next < cost[next_index]) {
          cost[next_index] = next;
          parent[next_index] = index;
          label[next_index] = label[index];
          open.lower(next_index, next);
        }
      }
    }
  }
}

std::vector<cv::Point> CostToGoField::pathFrom(int col, int row) const {
  std::vector<cv::Point> path;
  if (!reachable(col, row)) return path;
  const int width = box_.width;
  int index = (row - box_.y) * width + col - box_.x;
  while (true) {
    path.emplace_back(box_.x + index % width, box_.y + index / width);
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
