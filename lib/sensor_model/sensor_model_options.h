#pragma once

#include "common/ini_section.h"

namespace stereonav {

// How one disparity reading becomes OCC and CLEAR regions (paper section 3.2). Read from the
// [grid] section (next to the update rule's keys) by loadSensorModelOptions.
struct SensorModelOptions {
  // The region of uncertainty ends at this depth at the latest: equation 1 puts the obstacle out
  // to infinity when d - 0.5 <= 0, and kilometres away just above (a reading of d = 0.51 px at
  // fB = 8 px m would be an OCC region 800 m deep). The CLEAR triangle is not affected.
  double max_range_m = 10.0;
  // A column with no valid disparity saw nothing: by default it changes nothing. A positive
  // value clears that column's wedge out to this depth, as laser insertion does for "no echo".
  double clear_invalid_columns_to_m = 0.0;
};

// Keys: max_range_m, clear_invalid_columns_to_m (0 = off). Throws ConfigError on bad values.
SensorModelOptions loadSensorModelOptions(IniSection& section);

}  // namespace stereonav
