#include "sensor_model/sensor_model_options.h"

namespace stereonav {

SensorModelOptions loadSensorModelOptions(IniSection& section) {
  SensorModelOptions options;
  options.max_range_m = section.getDouble("max_range_m", options.max_range_m);
  options.clear_invalid_columns_to_m =
      section.getDouble("clear_invalid_columns_to_m", options.clear_invalid_columns_to_m);
  options.disparity_uncertainty_px =
      section.getPositive("disparity_uncertainty_px", options.disparity_uncertainty_px);
  options.keep_obstacle_borders =
      section.getBool("keep_obstacle_borders", options.keep_obstacle_borders);
  const auto fail = [&](const std::string& key, const std::string& why) {
    throw ConfigError("[" + section.name() + "] " + key + ": " + why);
  };
  if (!(options.max_range_m > 0.0)) fail("max_range_m", "must be positive");
  if (!(options.clear_invalid_columns_to_m >= 0.0)) {
    fail("clear_invalid_columns_to_m", "must be 0 (off) or a positive depth in metres");
  }
  return options;
}

}  // namespace stereonav
