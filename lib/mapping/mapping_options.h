#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <optional>
#include <string>

#include "column_projection/projection_options.h"
#include "disparity/stereo_options.h"
#include "localization/localization_options.h"
#include "observations/camera_image_pairing.h"
#include "observations/camera_rig_merge.h"
#include "rectification/rig_calibration.h"
#include "occupancy_grid/grid_map_factory.h"
#include "rig/camera_rig.h"
#include "spike_removal/spike_removal_options.h"

namespace stereonav {

// What the mapper itself adds to the stages' options (section [mapping]).
struct MapperOptions {
  // Build the virtual CObservation2DRangeScan of every frame even when the grid does not need it
  // (the linear model takes the disparity scan itself), e.g. to record them for icp-slam.
  bool virtual_scans = false;
  // The debug panel's top-down view: how far ahead of the camera it shows, metres.
  double panel_range_m = 5.0;
};

// Everything the mapping pipeline is configured with, read from one ini file:
//   [rig]            optional; the ini's calibration overrides the rawlog's (camera_rig_merge.h)
//   [rawlog]         sensor_label to follow ("" or absent: the first stereo pair found), the
//                    calibration tolerances, camera_labels + pairing_tolerance_s for cameras
//                    recorded as separate images (camera_image_pairing.h), and calibration: a
//                    calibration file (or several, space-separated; calibration_files.h) that
//                    replaces the recorded one; the writer's keys are accepted, as the simulator
//                    writes them in the same section
//   [stereo]         disparity engine (paper section 2.2)
//   [spike_removal]  section 4.2
//   [projection]     body volume, section 3.3
//   [grid]           model, limits, update rule, sensor model (sections 3.2, 3.4, 4.3)
//   [mapping]        MapperOptions
//   [localization]   scan matching against the map when mapping with localized poses
// Every section is read by its stage's own loader and rejects keys nobody reads.
struct MappingOptions {
  std::optional<CameraRig> rig;
  std::string sensor_label;
  CalibrationTolerance calibration_tolerance;
  ImagePairingOptions pairing;
  std::optional<RigCalibration> calibration;
  StereoOptions stereo;
  SpikeRemovalOptions spike_removal;
  ProjectionOptions projection;
  GridMapOptions grid;
  MapperOptions mapper;
  LocalizationOptions localization;
};

// Throws ConfigError "[section] key: why" for a bad or unknown key.
MappingOptions loadMappingOptions(const mrpt::config::CConfigFileBase& config);

// Reads `path` (throws std::runtime_error naming it if it cannot be read) and loads it.
MappingOptions loadMappingOptionsFile(const std::string& path);

}  // namespace stereonav
