#pragma once

#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

#include "occupancy_grid/ros_map.h"

namespace stereonav {

struct MapScoreOptions {
  // Obstacle boundaries are compared with this tolerance, in ground-truth cells (Chebyshev
  // distance): a stereo map quantises a 1-cell wall by a disparity step, so an occupied cell next
  // to a true obstacle is not counted as wrong (nor a true obstacle next to a mapped one as missed).
  int tolerance_cells = 1;
  // The run's true poses. When given, recall and false free count only the obstacle cells in
  // view of the camera from them (obstacleCellsInView with view_fov_deg, view_range_m), and
  // coverage starts from the first pose unless `start` says otherwise. Without them every
  // ground-truth obstacle counts.
  std::vector<mrpt::poses::CPose2D> poses;
  double view_fov_deg = 90.0;
  double view_range_m = 5.0;
  // Where reachable free space starts (world x, y). Without it and without poses, coverage is
  // over all free cells of the ground truth.
  std::optional<std::pair<double, double>> start;
};

// Cell counts of a map against the ground truth, over the cells of the ground truth that lie
// inside its bounds (known cells); the map is read at the centre of each of them, so the two maps
// may differ in origin, extent and resolution.
struct MapScore {
  int tolerance_cells = 1;
  bool obstacles_in_view_only = false;  // recall/false free over obstacles in view of the poses
  bool coverage_from_start = false;     // coverage over free cells reachable from a start

  size_t map_occupied = 0;          // cells the map calls occupied
  size_t map_occupied_correct = 0;  // ... with a true obstacle within the tolerance
  size_t truth_obstacles = 0;       // true obstacle cells (in view, if poses were given)
  size_t truth_obstacles_found = 0; // ... with a map-occupied cell within the tolerance
  size_t truth_obstacles_free = 0;  // ... the map calls free (exactly that cell): the dangerous error
  size_t reachable_free = 0;        // true free cells (reachable, if a start was given)
  size_t reachable_free_mapped_free = 0;  // ... the map calls free

  // Ratios; 0 when there is nothing to count (a map with no occupied cell has precision 0).
  double precision() const;
  double recall() const;
  double falseFree() const;
  double coverage() const;

  // Human-readable lines saying what was counted and how; and the same numbers as JSON.
  std::string toText() const;
  std::string toJson() const;
};

// Scores `map` against `truth` (see MapScoreOptions). Throws std::invalid_argument if the start
// is not free in the truth or the tolerance is negative.
MapScore scoreMap(const RosMap& map, const RosMap& truth, const MapScoreOptions& options);

}  // namespace stereonav
