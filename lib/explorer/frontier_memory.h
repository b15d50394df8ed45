#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <vector>

#include "explorer/explorer_options.h"
#include "explorer/frontier_finder.h"
#include "explorer/navigation_grid.h"
#include "explorer/world_cell_lattice.h"

namespace stereonav {

// What the explorer has learnt about frontier cells that looking does not resolve (unknown behind
// something stereo cannot see: under a table top, a textureless wall). Cells are named on a
// lattice fixed at the first map (world_cell_lattice.h), so the memory holds while the grid grows.
// A cell is dropped, until the second pass, when
//   - a look from up close did not resolve it: it lies within looked_at_range_m and the field of
//     view of a pose the robot looked from (as the map changes the frontier may move by a cell or
//     two without becoming any more resolvable);
//   - it was given up explicitly (the faced cell of a look, every cell of an unreachable frontier);
//   - it was in plain sight within looked_at_range_m in resolving_views maps;
//   - every unresolved cell beside it holds a point of a scan read within seen_free_range_m: a
//     surface was seen there, as at a wall stereo cannot match, whose foot the scan reports while
//     the map, which takes no obstacle from a foot, keeps the wall's cells unknown.
// Each rule gives cells up on indirect evidence (a stereo mismatch on open floor reads as a
// surface, a person in a doorway hides what is beyond it, a door given up from one side may be
// seen open from another), so before the run ends for want of frontiers all of it is forgotten
// once: the second pass tries every frontier again, from where the robot is then, under the
// same rules.
class FrontierMemory {
 public:
  using WorldCell = WorldCellLattice::Cell;

  explicit FrontierMemory(const ExplorerOptions& options);

  // Fixes the lattice at the first map's frame (later calls do nothing).
  void anchor(const GridFrame& frame) { lattice_.anchor(frame); }
  WorldCell worldCell(const NavigationGrid& grid, int col, int row) const;

  // A new map is a new view: the cells of `frontiers` the robot at `pose` has in plain sight
  // (over known free cells) within looked_at_range_m count one more view.
  void countCloseViews(const NavigationGrid& grid, const std::vector<Frontier>& frontiers,
                       const mrpt::poses::CPose2D& pose);
  // The cells of `frontiers` whose unresolved 4-neighbours all hold a point of `scan` (map
  // frame) within seen_free_range_m of `pose`.
  void dropSurfaced(const NavigationGrid& grid, const std::vector<Frontier>& frontiers,
                    const std::vector<mrpt::math::TPoint2D>& scan, const mrpt::poses::CPose2D& pose);
  // Forgets every cell given up, look and view; false, forgetting nothing, if the second pass has
  // begun already or nothing was ever given up.
  bool beginSecondPass();
  bool inSecondPass() const { return second_pass_; }
  bool isDropped(const NavigationGrid& grid, int col, int row) const;
  // `frontiers` without their dropped cells, and without the ones left under min_frontier_cells.
  std::vector<Frontier> withoutDropped(const NavigationGrid& grid, std::vector<Frontier> frontiers) const;

  // The robot looked from `pose` without resolving what it faced.
  void lookedFrom(const mrpt::poses::CPose2D& pose) { looked_from_.push_back(pose); }
  void drop(const NavigationGrid& grid, const cv::Point& cell) { dropped_.at(worldCell(grid, cell.x, cell.y)) = 1; }
  size_t looks() const { return looked_from_.size(); }

 private:
  ExplorerOptions options_;
  WorldCellLattice lattice_;
  std::vector<mrpt::poses::CPose2D> looked_from_;
  WorldCellMap<uint8_t> dropped_;
  WorldCellMap<int> close_views_;  // per cell: the maps in which it was in plain sight up close
  bool second_pass_ = false;
};

}  // namespace stereonav
