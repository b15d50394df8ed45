#include "column_projection/projection_options.h"

#include <string>

namespace stereonav {

ProjectionOptions loadProjectionOptions(IniSection& section) {
  ProjectionOptions options;
  options.floor_clearance_m = section.getDouble("floor_clearance_m", options.floor_clearance_m, -100.0, 100.0);
  options.robot_height_m = section.getDouble("robot_height_m", options.robot_height_m, -100.0, 100.0);
  options.surface_band_px = section.getNonNegative("surface_band_px", options.surface_band_px, 1e4);
  options.surface_band_scan_only = section.getBool("surface_band_scan_only", options.surface_band_scan_only);
  options.max_depth_m = section.getDouble("max_depth_m", options.max_depth_m, 0.0, 1e4);
  options.floor_end_max_depth_m =
      section.getDouble("floor_end_max_depth_m", options.floor_end_max_depth_m, 0.0, 1e4);
  options.floor_end_clear_max_depth_m =
      section.getDouble("floor_end_clear_max_depth_m", options.floor_end_clear_max_depth_m, 0.0, 1e4);
  options.near_floor_m = section.getDouble("near_floor_m", options.near_floor_m, 0.0, 1e4);
  options.scan_max_range_m = section.getPositive("scan_max_range_m", options.scan_max_range_m, 1e4);
  const auto fail = [&](const std::string& key, const std::string& why) {
    throw ConfigError("[" + section.name() + "] " + key + ": " + why);
  };
  if (!(options.robot_height_m > options.floor_clearance_m)) {
    fail("robot_height_m", "must be above floor_clearance_m");
  }
  return options;
}

}  // namespace stereonav
