#include "explorer/cost_to_go_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stereonav {
namespace {

// One row of cells: traversable (NavigationGrid::fits) and the step weight, through pointers the
// byte stores cannot alias and without traps (CMakeLists.txt), so that the loop runs four cells at
// a time: it runs over every free cell's box for every plan. Built for AVX2 as well (chosen at
// load time); not with FMA, whose fused rounding would change the weights from one machine to
// another.
__attribute__((target_clones("avx2", "default")))
void traversableRow(const float* __restrict clearance, const float* __restrict distance, int width,
                    double body_radius, double repulsion_distance, double repulsion_weight, bool repelled,
                    uint8_t* __restrict traversable, float* __restrict weight) {
  for (int col = 0; col < width; ++col) {
    const bool fits = clearance[col] + 1e-6 >= body_radius;
    traversable[col] = fits ? 1 : 0;
    // Steps are taken between traversable cells only.
    const double beyond = distance[col] - body_radius;
    const double s = std::min(1.0, std::max(0.0, 1.0 - beyond / repulsion_distance));
    const float repelling = static_cast<float>(1.0 + repulsion_weight * s * s);
    weight[col] = fits && repelled ? repelling : 1.0f;
  }
}

}  // namespace

CostToGoField::CostToGoField(const NavigationGrid& grid, const CostToGoOptions& options)
    : grid_(grid),
      box_(grid.freeCells()),
      // The weight 1 + repulsion_weight * s^2 for s in [0, 1].
      min_weight_(1.0 + std::min(0.0, options.repulsion_weight)),
      max_weight_(1.0 + std::max(0.0, options.repulsion_weight)),
      // Every cell is written below.
      traversable_(box_.size()),
      step_weight_(box_.size()) {
  if (!(min_weight_ > 0.0)) throw std::invalid_argument("cost-to-go: repulsion_weight must be above -1");
  if (box_.empty()) return;
  const cv::Mat1f clearances = grid.clearances()(box_), distances = grid.obstacleDistances()(box_);
  for (int row = 0; row < box_.height; ++row) {
    traversableRow(clearances[row], distances[row], box_.width, options.body_radius_m, options.repulsion_distance_m,
                   options.repulsion_weight, options.repulsion_distance_m > 0.0, traversable_[row], step_weight_[row]);
  }
}

// The open cells of the wavefront, lowest (cost, index) first: the cell index breaks ties as
// std::pair orders them, so cells leave in exactly the order a priority queue of pairs gives.
// Costs leave in rising order and every step adds at least `min_step`, so the cells wait in
// buckets half that wide: a cell reached from the bucket being emptied lands in a later one, at
// most `max_step` beyond, which a ring of buckets covers, and the bucket being emptied is sorted
// once and read in order. A cell whose cost is lowered leaves its old entry behind, skipped as
// stale (its cost is no longer the cell's). The goals' seeds, at any cost, wait in a sorted list
// and join when their bucket comes up.
class CostToGoField::OpenCells {
 public:
  OpenCells(double min_step, double max_step)
      : bucket_width_(0.5 * min_step), ring_(static_cast<size_t>(std::ceil(max_step / bucket_width_)) + 2) {}

  // Before the first pop.
  void seed(int index, double cost) { seeds_.push_back({cost, index}); }

  // While popping: a cell reached from the one popped last, at a higher cost.
  void push(int index, double cost) {
    ring_[static_cast<size_t>(bucketOf(cost)) % ring_.size()].push_back({cost, index});
    ++waiting_;
  }

  // The next open cell (`costs`: each cell's cost now), or -1 when none is left.
  int pop(const double* costs) {
    while (true) {
      while (next_ < current_.size()) {
        const Entry& entry = current_[next_++];
        if (entry.cost == costs[entry.index]) return entry.index;
      }
      if (!advance()) return -1;
    }
  }

 private:
  struct Entry {
    double cost;
    int index;
    bool operator<(const Entry& other) const {
      return cost < other.cost || (cost == other.cost && index < other.index);
    }
  };

  long bucketOf(double cost) const { return static_cast<long>(std::floor(cost / bucket_width_)); }

  // Makes the next bucket that may hold cells the current one; false when no cell waits.
  bool advance() {
    if (!seeds_sorted_) {
      std::sort(seeds_.begin(), seeds_.end());
      seeds_sorted_ = true;
    }
    if (waiting_ == 0) {
      if (next_seed_ == seeds_.size()) return false;
      bucket_ = bucketOf(seeds_[next_seed_].cost);
    } else {
      ++bucket_;
    }
    current_.clear();
    next_ = 0;
    std::vector<Entry>& slot = ring_[static_cast<size_t>(bucket_) % ring_.size()];
    waiting_ -= slot.size();
    current_.swap(slot);
    while (next_seed_ < seeds_.size() && bucketOf(seeds_[next_seed_].cost) == bucket_) {
      current_.push_back(seeds_[next_seed_++]);
    }
    std::sort(current_.begin(), current_.end());
    return true;
  }

  double bucket_width_;
  std::vector<std::vector<Entry>> ring_;
  size_t waiting_ = 0;  // entries in the ring
  std::vector<Entry> seeds_;
  bool seeds_sorted_ = false;
  size_t next_seed_ = 0;
  long bucket_ = 0;
  std::vector<Entry> current_;
  size_t next_ = 0;
};

CostToGoField::~CostToGoField() = default;

void CostToGoField::compute(const std::vector<GoalCell>& goals) {
  const int width = box_.width, height = box_.height;
  cost_.create(height, width);
  cost_.setTo(std::numeric_limits<double>::infinity());
  parent_.create(height, width);
  parent_.setTo(-1);
  label_.create(height, width);
  label_.setTo(-1);
  settled_.create(height, width);
  settled_.setTo(0);
  // The cheapest step is a straight one between the lightest cells, the dearest a diagonal one
  // between the heaviest (settledIndex).
  const double resolution = grid_.resolution();
  open_ = std::make_unique<OpenCells>(resolution * min_weight_, M_SQRT2 * resolution * max_weight_);
  double* const cost = cost_[0];
  for (const GoalCell& goal : goals) {
    if (!this->traversable(goal.col, goal.row)) continue;
    const int index = (goal.row - box_.y) * width + goal.col - box_.x;
    if (goal.seed_cost >= cost[index]) continue;
    cost[index] = goal.seed_cost;
    parent_[0][index] = index;
    label_[0][index] = goal.label;
    open_->seed(index, goal.seed_cost);
  }
}

int CostToGoField::settledIndex(int col, int row) const {
  const int width = box_.width;
  const int wanted = (row - box_.y) * width + col - box_.x;
  if (!open_) return wanted;
  // The maps are continuous (created whole), so a cell's index in the box addresses each of them.
  // Cells are ordered by index as by (row, col), in the box as in the grid.
  double* const cost = cost_[0];
  int* const parent = parent_[0];
  int* const label = label_[0];
  uint8_t* const settled = settled_[0];
  const uint8_t* const traversable = traversable_[0];
  const float* const weight = step_weight_[0];
  // Steps cost a cell's length (diagonal: sqrt(2) times) times the mean weight of its two cells.
  const double resolution = grid_.resolution();
  const double lengths[2] = {resolution, M_SQRT2 * resolution};
  while (!settled[wanted]) {
    const int index = open_->pop(cost);
    if (index < 0) {
      open_.reset();  // every reachable cell is settled
      break;
    }
    settled[index] = 1;
    const int cell_row = index / width, cell_col = index % width;
    const double here = cost[index];
    for (int dr = -1; dr <= 1; ++dr) {
      const int r = cell_row + dr;
      if (r < 0 || r >= box_.height) continue;
      for (int dc = -1; dc <= 1; ++dc) {
        const int c = cell_col + dc;
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
          open_->push(next_index, next);
        }
      }
    }
  }
  return wanted;
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
