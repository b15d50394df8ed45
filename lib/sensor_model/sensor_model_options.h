#pragma once

#include "common/ini_section.h"

namespace stereonav {

// How one disparity reading becomes OCC and CLEAR regions (paper section 3.2). Read from the
// [grid] section (next to the update rule's keys) by loadSensorModelOptions.
struct SensorModelOptions {
  // The region of uncertainty ends at this depth at the latest: equation 1 puts the obstacle out
  // to infinity when d - disparity_uncertainty_px <= 0, and kilometres away just above (a
  // reading of d = 0.51 px at fB = 8 px m would be an OCC region 800 m deep). The CLEAR
  // triangle is not affected.
  double max_range_m = 10.0;
  // A column with no valid disparity saw nothing: by default it changes nothing. A positive
  // value clears that column's wedge out to this depth, as laser insertion does for "no echo".
  double clear_invalid_columns_to_m = 0.0;
  // Half-width u of the disparity interval a reading's obstacle may lie in: OCC spans depths
  // Z(d + u) to Z(d - u) and CLEAR ends at Z(d + u). 0.5 is equation 1, the quantisation of
  // whole-pixel disparities; sub-pixel disparities are better than that (the paper cites
  // standard deviations well below a pixel, section 3.2).
  double disparity_uncertainty_px = 0.5;
  // true: a scan does not clear the cells that touch one of its own OCC regions (a corner of
  // the cell lies in it). Cells are taken by their centres, and an obstacle is known only to
  // within its region: a column that looks past an obstacle seen edge-on (a chair's side) would
  // clear the cell the obstacle reaches into by a centimetre, an obstacle cell for a planner
  // (and for the simulator's true maps). false: every cell whose centre lies in CLEAR.
  bool keep_obstacle_borders = false;
};

// Keys: max_range_m, clear_invalid_columns_to_m (0 = off), disparity_uncertainty_px,
// keep_obstacle_borders. Throws ConfigError on bad values.
SensorModelOptions loadSensorModelOptions(IniSection& section);

}  // namespace stereonav
