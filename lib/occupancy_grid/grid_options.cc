#include "occupancy_grid/grid_options.h"

#include <string>

namespace stereonav {

namespace {

[[noreturn]] void fail(const IniSection& section, const std::string& key, const std::string& why) {
  throw ConfigError("[" + section.name() + "] " + key + ": " + why);
}

}  // namespace

GridLimits loadGridLimits(IniSection& section) {
  GridLimits limits;
  limits.min_x = section.getDouble("min_x", limits.min_x);
  limits.max_x = section.getDouble("max_x", limits.max_x);
  limits.min_y = section.getDouble("min_y", limits.min_y);
  limits.max_y = section.getDouble("max_y", limits.max_y);
  limits.resolution = section.getDouble("resolution", limits.resolution);
  limits.growth_margin_m = section.getDouble("growth_margin_m", limits.growth_margin_m);
  if (!(limits.resolution > 0.0)) fail(section, "resolution", "must be positive (metres per cell)");
  if (!(limits.max_x > limits.min_x)) fail(section, "max_x", "must be greater than min_x");
  if (!(limits.max_y > limits.min_y)) fail(section, "max_y", "must be greater than min_y");
  if (!(limits.growth_margin_m >= 0.0)) fail(section, "growth_margin_m", "must not be negative");
  return limits;
}

GridUpdateOptions loadGridUpdateOptions(IniSection& section) {
  GridUpdateOptions options;
  OccupancyScale& scale = options.scale;
  options.update_step = section.getInt("update_step", options.update_step);
  scale.g_min = section.getInt("g_min", scale.g_min);
  scale.g_max = section.getInt("g_max", scale.g_max);
  scale.free_below = section.getInt("free_below", scale.free_below);
  scale.occupied_above = section.getInt("occupied_above", scale.occupied_above);
  options.accuracy_preservation =
      section.getBool("accuracy_preservation", options.accuracy_preservation);
  options.free_preservation_range_m =
      section.getDouble("free_preservation_range_m", options.free_preservation_range_m);
  if (!(options.free_preservation_range_m >= 0.0)) {
    fail(section, "free_preservation_range_m", "must not be negative (0 = off)");
  }
  if (scale.g_min < 0 || scale.g_min >= 255) fail(section, "g_min", "must be in 0..254");
  if (scale.g_max <= scale.g_min || scale.g_max > 255) {
    fail(section, "g_max", "must be in g_min+1..255");
  }
  if (options.update_step < 1 || options.update_step > scale.g_max - scale.g_min) {
    fail(section, "update_step", "must be in 1..(g_max - g_min)");
  }
  if (scale.free_below < scale.g_min || scale.free_below > scale.unknown()) {
    fail(section, "free_below", "must be in g_min..unknown (the midpoint of g_min..g_max)");
  }
  if (scale.occupied_above < scale.unknown() || scale.occupied_above > scale.g_max) {
    fail(section, "occupied_above", "must be in unknown..g_max (unknown = midpoint)");
  }
  return options;
}

}  // namespace stereonav
