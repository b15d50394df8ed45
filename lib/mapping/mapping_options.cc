#include "mapping/mapping_options.h"


#include <iterator>
#include <sstream>
#include <stdexcept>

#include "common/ini_section.h"
#include "observations/rawlog_writer.h"
#include "rectification/calibration_files.h"

namespace stereonav {
namespace {

MapperOptions loadMapperOptions(IniSection& section) {
  MapperOptions options;
  options.virtual_scans = section.getBool("virtual_scans", options.virtual_scans);
  options.panel_range_m = section.getPositive("panel_range_m", options.panel_range_m, 1e3);
  return options;
}

}  // namespace

MappingOptions loadMappingOptions(const mrpt::config::CConfigFileBase& config) {
  MappingOptions options;
  if (config.sectionExists("rig")) options.rig = loadIniSection(config, "rig", loadCameraRig);
  {
    IniSection rawlog(config, "rawlog");
    const bool follow_named_pair = rawlog.has("sensor_label");
    const RawlogWriterOptions writer = loadRawlogWriterOptions(rawlog);
    if (follow_named_pair) options.sensor_label = writer.sensor_label;
    options.calibration_tolerance = loadCalibrationTolerance(rawlog);
    options.pairing = loadImagePairingOptions(rawlog);
    std::istringstream calibration_files(rawlog.getString("calibration", ""));
    const std::vector<std::string> paths{std::istream_iterator<std::string>(calibration_files), {}};
    if (!paths.empty()) {
      try {
        options.calibration = loadRigCalibration(paths);
      } catch (const RectificationError& error) {
        throw ConfigError("[rawlog] calibration: " + std::string(error.what()));
      }
    }
    rawlog.rejectUnknownKeys();
  }
  options.stereo = loadIniSection(config, "stereo", loadStereoOptions);
  options.spike_removal = loadIniSection(config, "spike_removal", loadSpikeRemovalOptions);
  options.projection = loadIniSection(config, "projection", loadProjectionOptions);
  {
    IniSection grid(config, "grid");
    options.grid = loadGridMapOptions(grid);
  }
  options.mapper = loadIniSection(config, "mapping", loadMapperOptions);
  options.localization = loadIniSection(config, "localization", loadLocalizationOptions);
  // The scan's readings come one per column, and neighbouring columns' disparities share most of
  // their SAD window, so their errors too.
  options.localization.walls.segments.correlated_readings = options.stereo.window;
  if (options.rig && options.stereo.backend != StereoBackend::kSad && options.rig->secondaries.size() != 1) {
    throw ConfigError(std::string("[stereo] backend: ") + toString(options.stereo.backend) +
                      " (OpenCV) takes exactly one secondary camera; [rig] secondary_cameras has " +
                      std::to_string(options.rig->secondaries.size()));
  }
  return options;
}

MappingOptions loadMappingOptionsFile(const std::string& path) {
  const mrpt::config::CConfigFileMemory config = readConfigFile(path);
  try {
    return loadMappingOptions(config);
  } catch (const ConfigError& error) {
    throw ConfigError(path + ": " + error.what());
  }
}

}  // namespace stereonav
