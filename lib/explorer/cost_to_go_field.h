#pragma once

#include <opencv2/core.hpp>

#include <limits>
#include <memory>
#include <vector>

#include "explorer/navigation_grid.h"

namespace stereonav {

struct CostToGoOptions {
  // A cell is traversable when a disc of this radius around its centre covers free cells only:
  // obstacles and unknown space inflated by the robot (plus margin).
  double body_radius_m = 0.35;
  double repulsion_distance_m = 0.6;
  double repulsion_weight = 4.0;
};

// A goal of the wavefront: a traversable cell, the cost it starts with (metres of path; lower
// goals are preferred), and a label the cells that lead to it inherit (e.g. a frontier's index).
struct GoalCell {
  int col = 0;
  int row = 0;
  double seed_cost = 0.0;
  int label = 0;
};

// The paper's planner, "a mixture of shortest path and potential field methods" (section 5): a
// Dijkstra wavefront from the goals over the traversable cells (8-connected, no corner cutting),
// where stepping through a cell costs its length times 1 + repulsion_weight * s^2, s growing
// from 0 at repulsion_distance_m beyond the inflated obstacles to 1 at their edge. Descending
// the cost-to-go from any reachable cell is the shortest such path to the cheapest goal: like a
// potential field it gives a direction everywhere at once and keeps clear of obstacles, but it
// has no local minima.
//
// MRPT's PlannerSimple2D is a plain wavefront without the repulsive term, and its reactive
// navigator expects PTG configurations for a known robot shape; this is the one piece of the
// navigation stack written here.
//
// The wavefront spreads only as far as the queries need: a query settles its cell first, so the
// explorer, which asks about the cells around the robot between two maps, pays for the cells
// cheaper than the robot's and not for the rest of the building. The cells leave the wavefront
// in the same order whenever it pauses, so every answer is the one a whole wavefront gives. So a
// query changes the field's state: one thread at a time.
class CostToGoField {
 public:
  CostToGoField(const NavigationGrid& grid, const CostToGoOptions& options);
  ~CostToGoField();

  // Starts the field afresh from `goals` (non-traversable goals are ignored).
  void compute(const std::vector<GoalCell>& goals);

  bool traversable(int col, int row) const { return inBox(col, row) && traversable_(row - box_.y, col - box_.x) != 0; }
  // The cells the field covers (the grid's free cells' box; nothing outside is traversable), and
  // per cell of it whether it is traversable (1) or not (0), indexed from the box's corner.
  const cv::Rect& box() const { return box_; }
  const cv::Mat1b& traversableCells() const { return traversable_; }
  bool reachable(int col, int row) const { return inBox(col, row) && parent_[0][settledIndex(col, row)] >= 0; }
  double cost(int col, int row) const {
    return inBox(col, row) ? cost_[0][settledIndex(col, row)] : std::numeric_limits<double>::infinity();
  }
  // The label of the goal that the path from this cell ends at (-1 if unreachable).
  int label(int col, int row) const { return inBox(col, row) ? label_[0][settledIndex(col, row)] : -1; }
  // The cells from (col, row) to its goal, both included; empty if unreachable.
  std::vector<cv::Point> pathFrom(int col, int row) const;

 private:
  class OpenCells;

  bool inBox(int col, int row) const { return box_.contains(cv::Point(col, row)); }
  // The cell's index in the box (the maps are continuous), once the wavefront has settled it or
  // found it unreachable.
  int settledIndex(int col, int row) const;

  const NavigationGrid& grid_;
  // Only free cells can be traversable, so the field covers the free cells' box (the grid's
  // NavigationGrid::freeCells) and its maps are indexed from the box's corner.
  cv::Rect box_;
  double min_weight_;  // the bounds of the step weights
  double max_weight_;
  cv::Mat1b traversable_;
  cv::Mat1f step_weight_;
  // The wavefront's state, advanced by queries (settledIndex).
  mutable cv::Mat1d cost_;
  mutable cv::Mat1i parent_;  // row * width + col (in the box) of the next cell towards the goal; itself at a goal
  mutable cv::Mat1i label_;
  mutable cv::Mat1b settled_;
  mutable std::unique_ptr<OpenCells> open_;
};

// A path between two points through traversable cells (the wavefront from `goal`), as cell
// centres from start to goal; empty when either end is not traversable or no path exists.
std::vector<cv::Point2d> planPath(const NavigationGrid& grid, const CostToGoOptions& options, double start_x,
                                  double start_y, double goal_x, double goal_y);

}  // namespace stereonav
