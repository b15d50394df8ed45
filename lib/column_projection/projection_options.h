#pragma once

#include "common/ini_section.h"

namespace stereonav {

// The robot's body volume (paper section 3.3): points higher than floor_clearance_m above the
// floor and no higher than robot_height_m are obstacles; the floor itself (texture the matcher
// happily finds) and whatever the robot passes under are not.
struct ProjectionOptions {
  double floor_clearance_m = 0.05;
  double robot_height_m = 1.0;
  // The virtual laser scan's maxRange: obstacles farther than this are left out of it.
  double scan_max_range_m = 10.0;
};

// Section [projection]. Keys: floor_clearance_m, robot_height_m, scan_max_range_m.
// Throws ConfigError on bad values.
ProjectionOptions loadProjectionOptions(IniSection& section);

}  // namespace stereonav
