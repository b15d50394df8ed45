#pragma once

#include <mrpt/poses/CPose2D.h>

#include <opencv2/core.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

struct NavigationGridOptions {
  // Cells under a disc of this radius around each visited robot position are free unless the map
  // says occupied: the body stood there (the cameras never see the floor under the robot, so
  // without this the start is unknown).
  double body_radius_m = 0.3;
  // Islands of at most this many unknown cells whose every neighbour is free are free: inside
  // observed free space such a cell is not unobserved but holds mixed evidence (a stereo spike's
  // OCC not yet cleared away), and it would otherwise be a frontier and a wall.
  int max_hole_cells = 0;
  // Occupied cells whose disparity tag is below this (pixels) were only seen from far away,
  // where one disparity step spans metres of depth (paper section 3.2): the obstacle is somewhere
  // in a deep trapezoid. They block the robot like any obstacle, but looking closer resolves
  // them, so free cells next to them are frontiers. 0: every occupied cell is precise.
  float precise_min_disparity = 0.0f;
  // Occupancy values G at or above this hold obstacle evidence from several readings (each adds
  // K, paper section 3.4): mapHoldsObstacle.
  int sure_obstacle_g = 200;
  // clearance and obstacleDistance are exact at free cells up to this distance (metres) and at
  // least this beyond it: nothing that reads them looks farther. The obstacle distances then need
  // only the free floor's surroundings instead of the whole map, and a grid made after another of
  // the same cells takes again only the distances near cells whose class changed.
  double distance_horizon_m = std::numeric_limits<double>::infinity();
};

// The stereo grid as the planner sees it: each cell free, unknown, occupied only by imprecise
// far readings, or occupied (the paper's conservative thresholds, OccupancyScale::classify), and
// how far each cell is from trouble. Same cells as the DisparityTaggedGrid it was made from
// (row 0 at min y).
class NavigationGrid {
 public:
  static constexpr uint8_t kFree = 0;
  static constexpr uint8_t kUnknown = 1;
  static constexpr uint8_t kImprecise = 2;
  static constexpr uint8_t kOccupied = 3;

  // `visited` are robot positions (odometry frame, the map's). `contacts` are points where the
  // robot found itself blocked by something the map does not show (a table top seen edge-on,
  // paper section 6.1): their cells are occupied, as a bumper would report them.
  // `seen_free` are points the robot has seen free from up close (seen_free_memory.h): their
  // cells are free where the map holds them unknown or imprecise. `previous`: the grid made from
  // the map before (e.g. a frame earlier), whose distances are kept where they still hold, and
  // whose `visited` and `seen_free` were the first of these (both lists only grow); it is used
  // up (what it drew moves here rather than being copied, a map's worth each frame).
  NavigationGrid(const DisparityTaggedGrid& grid, const std::vector<mrpt::poses::CPose2D>& visited,
                 const NavigationGridOptions& options, const std::vector<cv::Point2d>& contacts = {},
                 const std::vector<cv::Point2d>& seen_free = {}, std::unique_ptr<NavigationGrid> previous = nullptr);

  int width() const { return cell_class_.cols; }
  int height() const { return cell_class_.rows; }
  double resolution() const { return frame_.resolution; }
  bool contains(int col, int row) const { return col >= 0 && row >= 0 && col < width() && row < height(); }
  bool cellAt(double x, double y, int& col, int& row) const {
    col = static_cast<int>(std::floor((x - frame_.origin_x) / frame_.resolution));
    row = static_cast<int>(std::floor((y - frame_.origin_y) / frame_.resolution));
    return contains(col, row);
  }
  double centreX(int col) const { return frame_.origin_x + (col + 0.5) * frame_.resolution; }
  double centreY(int row) const { return frame_.origin_y + (row + 0.5) * frame_.resolution; }

  uint8_t cellClass(int col, int row) const { return cell_class_(row, col); }
  // Obstacle islands (occupied or imprecise, 8-connected) of at most `max_cells` cells whose
  // every neighbour is free become free: as a rule a stereo mismatch that repeated rather than a
  // post. The explorer passes them only when nothing else is reachable, with the reactive guard
  // judging them from the scans; an island holding a point of `keep` stays (a post the guard has
  // stopped the robot at is no mismatch).
  void freeSpecks(int max_cells, const std::vector<cv::Point2d>& keep = {});
  // Whether the stereo map itself is sure of an obstacle at (x, y): its occupancy value is at
  // least sure_obstacle_g (the `contacts` the planner adds do not count).
  bool mapHoldsObstacle(double x, double y) const;
  const cv::Mat1b& cellClasses() const { return cell_class_; }
  // The free cells' bounding box: no cell outside it is free, so whatever only free cells have
  // (frontiers, clearance, traversability) is looked for inside it.
  const cv::Rect& freeCells() const { return free_cells_; }
  // The box outside which every cell is unknown (the map's written cells and the cells the
  // robot's own positions and memories stamped): what looks for resolved cells, or for the
  // unknown regions they border, looks inside it.
  const cv::Rect& resolvedCells() const { return resolved_cells_; }
  // Distance from the cell's centre to the nearest cell that is not free (or to the grid's edge),
  // counted to that cell's near edge: a disc of this radius at the centre overlaps free cells only.
  // Exact up to the options' distance_horizon_m, at least that beyond; -half a cell at cells that
  // are not free.
  float clearance(int col, int row) const { return clearance_m_(row, col); }
  // Whether a disc of `radius_m` at the cell's centre overlaps free cells only. Clearances are
  // whole cells less half a cell, held as floats (4 x 0.1 - 0.05 comes out a few parts in a
  // billion below 0.35): a body that fits a gap exactly is not refused by that rounding.
  bool fits(int col, int row, double radius_m) const { return clearance(col, row) + 1e-6 >= radius_m; }
  // The same from the point (x, y) itself, not its cell's centre, looked for up to `search_m`
  // (which it returns when nothing is nearer); cells off the grid count as not free.
  double clearanceAt(double x, double y, double search_m) const;
  // The same to the nearest occupied or imprecise cell only (the potential field's repulsion). At
  // free cells it is exact up to the options' distance_horizon_m and at least that beyond; at
  // occupied and imprecise cells it is -half a cell.
  float obstacleDistance(int col, int row) const { return obstacle_distance_m_(row, col); }
  // Every cell's clearance and obstacleDistance, for loops over many cells.
  const cv::Mat1f& clearances() const { return clearance_m_; }
  const cv::Mat1f& obstacleDistances() const { return obstacle_distance_m_; }

 private:
  // Islands of cells whose class is from `lowest_class` to `highest_class` (`connectivity` 4 or
  // 8) of at most `max_cells` cells, bordered by free cells only (not by other cells or the
  // grid's edge), become free, unless one holds a cell of `kept_cells`.
  void freeIslands(uint8_t lowest_class, uint8_t highest_class, int connectivity, int max_cells,
                   const std::vector<cv::Point>& kept_cells = {});
  // Takes every distance afresh.
  void computeDistances();
  // Takes again the distances near cells whose class differs from `classes_before` (whose cells
  // outside `resolved_before` are unknown), for which the distances held now were taken (with the
  // same horizon).
  void updateDistances(const cv::Mat1b& classes_before, const cv::Rect& resolved_before);
  // Cells within the distance horizon; 0 if it is infinite (or 0): then every distance is taken
  // afresh and exactly.
  int horizonCells() const;

  GridFrame frame_;
  double distance_horizon_m_;
  double body_radius_m_;
  // Per cell, whether one of the first seen_free_points_ seen-free points lies in it and whether
  // the body's disc at one of the first body_positions_ visited positions covers it, within
  // stamps_box_. Both lists only grow, by a few points a frame; drawing them all every frame
  // took a quarter of the grid's own time after half an hour.
  static constexpr uint8_t kSeenFreeStamp = 1;
  static constexpr uint8_t kBodyStamp = 2;
  cv::Mat1b stamps_;
  cv::Rect stamps_box_;
  size_t seen_free_points_ = 0;
  size_t body_positions_ = 0;
  cv::Mat1b cell_class_;
  cv::Mat1b sure_obstacle_;
  cv::Rect resolved_cells_;
  cv::Rect free_cells_;
  cv::Mat1f clearance_m_;
  cv::Mat1f obstacle_distance_m_;
};

}  // namespace stereonav
