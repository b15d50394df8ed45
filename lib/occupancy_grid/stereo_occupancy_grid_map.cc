#include "occupancy_grid/stereo_occupancy_grid_map.h"

#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <ostream>

#include "common/ini_section.h"
#include "occupancy_grid/grid_conversion.h"
#include "occupancy_grid/grid_io.h"

IMPLEMENTS_SERIALIZABLE(CStereoOccupancyGridMap, CMetricMap, stereonav)

// The class name MRPT's registry is searched with (CLASS_ID's name) and the short name used for
// "<name>_count" in CMultiMetricMap ini definitions.
MAP_DEFINITION_REGISTER("stereonav::CStereoOccupancyGridMap,stereoOccupancyGrid",
                        stereonav::CStereoOccupancyGridMap)

namespace stereonav {

CStereoOccupancyGridMap::CStereoOccupancyGridMap(const StereoGridMapOptions& options)
    : options_(options),
      grid_(options.limits, options.update.scale),
      inserter_(options.sensor_model, options.update, options.limits.growth_margin_m) {}

void CStereoOccupancyGridMap::addDisparityScanSource(
    std::shared_ptr<const DisparityScanSource> source) {
  sources_.push_back(std::move(source));
}

void CStereoOccupancyGridMap::internal_clear() {
  grid_.reset(options_.limits);
  is_empty_ = true;
}

bool CStereoOccupancyGridMap::internal_insertObservation(
    const mrpt::obs::CObservation& observation,
    const std::optional<const mrpt::poses::CPose3D>& robot_pose) {
  const mrpt::poses::CPose2D pose = robot_pose ? mrpt::poses::CPose2D(*robot_pose)
                                               : mrpt::poses::CPose2D();
  CObservationDisparityScan::Ptr converted;
  const auto* scan = dynamic_cast<const CObservationDisparityScan*>(&observation);
  for (size_t i = 0; scan == nullptr && i < sources_.size(); ++i) {
    converted = sources_[i]->toDisparityScan(observation);
    scan = converted.get();
  }
  if (scan == nullptr) return false;
  inserter_.insert(scan->scan, scan->camera, pose, grid_);
  is_empty_ = false;
  return true;
}

double CStereoOccupancyGridMap::internal_computeObservationLikelihood(
    const mrpt::obs::CObservation&, const mrpt::poses::CPose3D&) const {
  return 0.0;
}

bool CStereoOccupancyGridMap::internal_canComputeObservationLikelihood(
    const mrpt::obs::CObservation&) const {
  return false;
}

void CStereoOccupancyGridMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
  saveGridImage(grid_, prefix + ".png");
  saveRosMapServer(grid_, prefix + ".yaml");
}

std::string CStereoOccupancyGridMap::asString() const {
  return mrpt::format(
      "Stereo occupancy grid (Murray & Little linear update, K=%d), from (%f,%f) to (%f,%f), "
      "cell size=%f",
      options_.update.update_step, grid_.minX(), grid_.minY(), grid_.maxX(), grid_.maxY(),
      grid_.resolution());
}

void CStereoOccupancyGridMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
  if (!genericMapParams.enableSaveAs3DObject) return;
  toMrptOccupancyGrid(grid_).getVisualizationInto(o);
}

// Version 1 adds the sensor model's disparity_uncertainty_px and keep_obstacle_borders; version 2
// free_preservation_range_m and the close-free layer (older maps load with it off and empty).
uint8_t CStereoOccupancyGridMap::serializeGetVersion() const { return 2; }

void CStereoOccupancyGridMap::serializeTo(mrpt::serialization::CArchive& out) const {
  const GridLimits& limits = options_.limits;
  const GridUpdateOptions& update = options_.update;
  out << limits.min_x << limits.max_x << limits.min_y << limits.max_y << limits.resolution
      << limits.growth_margin_m;
  out.WriteAs<int32_t>(update.scale.g_min).WriteAs<int32_t>(update.scale.g_max);
  out.WriteAs<int32_t>(update.scale.free_below).WriteAs<int32_t>(update.scale.occupied_above);
  out.WriteAs<int32_t>(update.update_step) << update.accuracy_preservation;
  out << options_.sensor_model.max_range_m << options_.sensor_model.clear_invalid_columns_to_m
      << options_.sensor_model.disparity_uncertainty_px << options_.sensor_model.keep_obstacle_borders;
  const GridFrame& frame = grid_.frame();
  out << frame.origin_x << frame.origin_y << frame.resolution;
  out.WriteAs<int32_t>(grid_.width()).WriteAs<int32_t>(grid_.height());
  out.WriteBuffer(grid_.occupancyLayer().data(), grid_.occupancyLayer().size());
  out.WriteBufferFixEndianness(grid_.tagLayer().data(), grid_.tagLayer().size());
  out << is_empty_;
  out << update.free_preservation_range_m;
  out.WriteBuffer(grid_.closeFreeLayer().data(), grid_.closeFreeLayer().size());
}

void CStereoOccupancyGridMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
  switch (version) {
    case 0:
    case 1:
    case 2: {
      StereoGridMapOptions options;
      GridLimits& limits = options.limits;
      GridUpdateOptions& update = options.update;
      in >> limits.min_x >> limits.max_x >> limits.min_y >> limits.max_y >> limits.resolution >>
          limits.growth_margin_m;
      update.scale.g_min = in.ReadAs<int32_t>();
      update.scale.g_max = in.ReadAs<int32_t>();
      update.scale.free_below = in.ReadAs<int32_t>();
      update.scale.occupied_above = in.ReadAs<int32_t>();
      update.update_step = in.ReadAs<int32_t>();
      in >> update.accuracy_preservation;
      in >> options.sensor_model.max_range_m >> options.sensor_model.clear_invalid_columns_to_m;
      if (version >= 1) {
        in >> options.sensor_model.disparity_uncertainty_px >> options.sensor_model.keep_obstacle_borders;
      }
      GridFrame frame;
      in >> frame.origin_x >> frame.origin_y >> frame.resolution;
      const int width = in.ReadAs<int32_t>();
      const int height = in.ReadAs<int32_t>();
      if (width <= 0 || height <= 0) THROW_EXCEPTION("corrupt CStereoOccupancyGridMap size");
      std::vector<uint8_t> occupancy(static_cast<size_t>(width) * height);
      std::vector<float> tags(occupancy.size());
      in.ReadBuffer(occupancy.data(), occupancy.size());
      in.ReadBufferFixEndianness(tags.data(), tags.size());
      in >> is_empty_;
      std::vector<uint8_t> close_free(occupancy.size(), 0);
      if (version >= 2) {
        in >> update.free_preservation_range_m;
        in.ReadBuffer(close_free.data(), close_free.size());
      }
      options_ = options;
      grid_ = DisparityTaggedGrid(options.limits, options.update.scale);
      grid_.assign(frame, width, height, std::move(occupancy), std::move(tags),
                   std::move(close_free));
      inserter_ = DisparityScanInserter(options.sensor_model, options.update,
                                        options.limits.growth_margin_m);
      break;
    }
    default:
      MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  }
}

CStereoOccupancyGridMap::TMapDefinition::TMapDefinition() = default;

void CStereoOccupancyGridMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& section_prefix) {
  IniSection creation(source, section_prefix + "_creationOpts");
  options.limits = loadGridLimits(creation);
  IniSection insertion(source, section_prefix + "_insertOpts");
  options.update = loadGridUpdateOptions(insertion);
  options.sensor_model = loadSensorModelOptions(insertion);
  insertion.rejectUnknownKeys();
}

void CStereoOccupancyGridMap::TMapDefinition::dumpToTextStream_map_specific(
    std::ostream& out) const {
  const GridLimits& l = options.limits;
  const GridUpdateOptions& u = options.update;
  out << "min_x=" << l.min_x << " max_x=" << l.max_x << " min_y=" << l.min_y
      << " max_y=" << l.max_y << " resolution=" << l.resolution
      << " growth_margin_m=" << l.growth_margin_m << "\n"
      << "update_step=" << u.update_step << " g_min=" << u.scale.g_min << " g_max=" << u.scale.g_max
      << " free_below=" << u.scale.free_below << " occupied_above=" << u.scale.occupied_above
      << " accuracy_preservation=" << u.accuracy_preservation
      << " free_preservation_range_m=" << u.free_preservation_range_m << "\n"
      << "max_range_m=" << options.sensor_model.max_range_m
      << " clear_invalid_columns_to_m=" << options.sensor_model.clear_invalid_columns_to_m
      << " disparity_uncertainty_px=" << options.sensor_model.disparity_uncertainty_px
      << " keep_obstacle_borders=" << options.sensor_model.keep_obstacle_borders << "\n";
}

mrpt::maps::CMetricMap* CStereoOccupancyGridMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& definition) {
  const auto& own = dynamic_cast<const CStereoOccupancyGridMap::TMapDefinition&>(definition);
  return new CStereoOccupancyGridMap(own.options);
}

}  // namespace stereonav
