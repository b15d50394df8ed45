#include "sensor_model/sensor_model_options.h"

namespace stereonav {

SensorModelOptions loadSensorModelOptions(IniSection& section) {
  SensorModelOptions options;
  options.max_range_m = section.getPositive("max_range_m", options.max_range_m, 1e4);
  options.clear_invalid_columns_to_m =
      section.getDouble("clear_invalid_columns_to_m", options.clear_invalid_columns_to_m, 0.0, 1e4);
  options.disparity_uncertainty_px =
      section.getPositive("disparity_uncertainty_px", options.disparity_uncertainty_px, 1e3);
  options.keep_obstacle_borders =
      section.getBool("keep_obstacle_borders", options.keep_obstacle_borders);
  return options;
}

}  // namespace stereonav
