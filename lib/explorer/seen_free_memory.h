#pragma once

#include <mrpt/poses/CPose2D.h>
#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

#include "explorer/world_cell_lattice.h"
#include "occupancy_grid/disparity_tagged_grid.h"

namespace stereonav {

struct SeenFreeMemoryOptions {
  // Cells the map holds free within this distance of the robot, in view, are remembered. Up
  // close one disparity step is a few centimetres deep (Z^2 / (f B), paper section 3.2), so the
  // free space in front of a reading there is certain.
  double range_m = 2.0;
  double field_of_view_deg = 90.0;
  // The robot's body: the cameras never see the floor under it.
  double body_radius_m = 0.3;
};

// Floor the robot has seen free from up close, kept for the planner. The paper's accuracy
// preservation (section 4.3) keeps far readings from smearing obstacles seen up close, but not
// free space: a far reading a disparity step off, or a ghost match on a repetitive texture
// (section 4.1), paints its uncertainty region over floor seen free a moment ago. Such bands
// close corridors and doors behind the robot, and every band is a new frontier: the robot
// would tour finished rooms. The planner takes a remembered cell as free while the map holds it
// unknown or imprecise; an obstacle the map holds precisely still wins, and the reactive guard
// still brakes for whatever the newest scans show.
class SeenFreeMemory {
 public:
  explicit SeenFreeMemory(const SeenFreeMemoryOptions& options) : options_(options) {}

  // Remembers the cells the robot at `pose` (the map's frame) sees free in `grid`: within
  // range_m, inside the field of view, with free cells all round (not at a wall's edge or a door
  // jamb seen edge-on, where a cell may be part floor and part wall, nor at the edge of what was
  // seen), and reached from the robot's cell by a straight
  // line over free cells (an obstacle or unseen space between hides them). A remembered cell is
  // kept for good: where the map holds it occupied the map wins anyway, and a moving obstacle's
  // trail would otherwise reopen as frontiers every time it passes.
  void update(const DisparityTaggedGrid& grid, const mrpt::poses::CPose2D& pose);

  // Centres of the remembered cells (map frame), in the order they were first seen.
  const std::vector<cv::Point2d>& cells() const { return centres_; }
  size_t size() const { return centres_.size(); }

 private:
  SeenFreeMemoryOptions options_;
  WorldCellLattice lattice_;
  WorldCellMap<uint8_t> cells_;  // 1 at the remembered cells
  // The planner reads every remembered cell every frame: a list, kept as cells are added (none
  // is ever removed), instead of a walk over the set, whose nodes grow with the floor explored.
  std::vector<cv::Point2d> centres_;
};

}  // namespace stereonav
