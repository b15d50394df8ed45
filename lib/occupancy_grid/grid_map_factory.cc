#include "occupancy_grid/grid_map_factory.h"

#include <mrpt/maps/COccupancyGridMap2D.h>

namespace stereonav {

GridMapOptions loadGridMapOptions(IniSection& section) {
  GridMapOptions options;
  const std::string model = section.getString("model", "linear");
  if (model == "linear") {
    options.model = GridModel::kLinear;
  } else if (model == "mrpt_bayes") {
    options.model = GridModel::kMrptBayes;
  } else {
    throw ConfigError("[" + section.name() + "] model: expected linear or mrpt_bayes, got '" +
                      model + "'");
  }
  options.stereo.limits = loadGridLimits(section);
  options.stereo.update = loadGridUpdateOptions(section);
  options.stereo.sensor_model = loadSensorModelOptions(section);
  section.rejectUnknownKeys();
  return options;
}

mrpt::maps::CMetricMap::Ptr createGridMap(const GridMapOptions& options) {
  if (options.model == GridModel::kLinear) {
    return std::make_shared<CStereoOccupancyGridMap>(options.stereo);
  }
  const GridLimits& limits = options.stereo.limits;
  auto grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>(
      static_cast<float>(limits.min_x), static_cast<float>(limits.max_x),
      static_cast<float>(limits.min_y), static_cast<float>(limits.max_y),
      static_cast<float>(limits.resolution));
  grid->insertionOptions.maxDistanceInsertion =
      static_cast<float>(options.stereo.sensor_model.max_range_m);
  grid->insertionOptions.considerInvalidRangesAsFreeSpace =
      options.stereo.sensor_model.clear_invalid_columns_to_m > 0.0;
  return grid;
}

}  // namespace stereonav
