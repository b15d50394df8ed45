#include "occupancy_grid/grid_options.h"

#include "sensor_model/polygon_rasterizer.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace stereonav {

namespace {

[[noreturn]] void fail(const IniSection& section, const std::string& key, const std::string& why) {
  throw ConfigError("[" + section.name() + "] " + key + ": " + why);
}

}  // namespace

GridLimits loadGridLimits(IniSection& section) {
  GridLimits limits;
  constexpr double kMax = kMaxGridCoordinate;
  limits.min_x = section.getDouble("min_x", limits.min_x, -kMax, kMax);
  limits.max_x = section.getDouble("max_x", limits.max_x, -kMax, kMax);
  limits.min_y = section.getDouble("min_y", limits.min_y, -kMax, kMax);
  limits.max_y = section.getDouble("max_y", limits.max_y, -kMax, kMax);
  limits.resolution = section.getDouble("resolution", limits.resolution, 1e-3, 100.0);
  limits.growth_margin_m = section.getDouble("growth_margin_m", limits.growth_margin_m, 0.0, 1000.0);
  limits.max_cells = section.getInt("max_cells", static_cast<int>(limits.max_cells), 1,
                                    std::numeric_limits<int>::max());
  if (!(limits.max_x > limits.min_x)) fail(section, "max_x", "must be greater than min_x");
  if (!(limits.max_y > limits.min_y)) fail(section, "max_y", "must be greater than min_y");
  const double cells = std::ceil((limits.max_x - limits.min_x) / limits.resolution) *
                       std::ceil((limits.max_y - limits.min_y) / limits.resolution);
  if (cells > static_cast<double>(limits.max_cells) ||
      (limits.max_x - limits.min_x) / limits.resolution >= CellWindow::kIndexRange ||
      (limits.max_y - limits.min_y) / limits.resolution >= CellWindow::kIndexRange) {
    char why[200];
    std::snprintf(why, sizeof why,
                  "%lld, but the initial grid (min_x..max_x, min_y..max_y at resolution) has %.3g cells "
                  "(or a side over 2^20); raise max_cells, coarsen resolution or shrink the limits",
                  static_cast<long long>(limits.max_cells), cells);
    fail(section, "max_cells", why);
  }
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
      section.getDouble("free_preservation_range_m", options.free_preservation_range_m, 0.0, 1000.0);
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
