#pragma once

#include <opencv2/core.hpp>

#include <optional>
#include <set>
#include <vector>

#include "explorer/cost_to_go_field.h"
#include "explorer/explorer_options.h"
#include "explorer/frontier_finder.h"
#include "explorer/frontier_memory.h"
#include "explorer/navigation_grid.h"

namespace stereonav {

// Which frontier the robot heads for (paper section 5: the nearest reachable one, by path). Goals
// are the traversable cells within goal_distance_m of a frontier's cells, seeded into one
// cost-to-go field for all frontiers at once; a goal's seed cost is its penalty in metres of path:
//   - target_switch_penalty_m on every frontier but the current target's (stickiness: the robot
//     does not dither between two frontiers at similar distances);
//   - pocket_penalty_m on frontiers that border only a pocket of unseen space smaller than
//     pocket_area_m2 or only obstacles seen from far: the rest of the building comes first.
// Owns the target: where the current path ends, its frontier, and that frontier's cells.
class GoalSelection {
 public:
  explicit GoalSelection(const ExplorerOptions& options);

  // Before a new map replaces `grid` and `frontiers`: remembers the target frontier's cells by
  // name, so that the new map's frontier sharing one is still the target.
  void carryTargetOver(const NavigationGrid& grid, const std::vector<Frontier>& frontiers,
                       const FrontierMemory& memory);

  // The goal cells of every frontier (label = index into `frontiers`) for a body of
  // `body_radius_m`, each cell with the cheapest seed cost of the frontiers it is near.
  // `look_from_m` > 0: every traversable cell within that distance of a frontier is a goal too,
  // its distance to the frontier added to its seed, so that the nearest place the body reaches
  // is preferred (look_from_afar_m).
  std::vector<GoalCell> goals(const NavigationGrid& grid, const CostToGoField& field,
                              const std::vector<Frontier>& frontiers, double body_radius_m,
                              const FrontierMemory& memory, double look_from_m = 0.0) const;

  // The path now ends at `goal`, near frontier `label`.
  void aimAt(const cv::Point2d& goal, int label);
  // No target: the next plan chooses afresh.
  void clear();
  const std::optional<cv::Point2d>& target() const { return target_; }

 private:
  // The frontier still near the target, or still holding some of its cells, is the target's: a
  // wall resolved look by look keeps the robot working along it, not jumping across the room
  // each time the part nearest the goal is resolved.
  bool isTarget(const NavigationGrid& grid, const Frontier& frontier, double goal_radius,
                const FrontierMemory& memory) const;

  ExplorerOptions options_;
  std::optional<cv::Point2d> target_;
  int target_label_ = -1;
  std::set<FrontierMemory::WorldCell> target_cells_;
};

}  // namespace stereonav
