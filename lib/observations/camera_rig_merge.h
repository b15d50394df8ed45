#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/ini_section.h"
#include "rig/camera_rig.h"

namespace stereonav {

// How far the ini's rig may differ from the one recorded in the observations before the
// difference is worth telling the user (beyond rounding in either source).
struct CalibrationTolerance {
  double focal_px = 0.5;
  double principal_point_px = 0.5;
  double baseline_m = 0.001;
  double position_m = 0.01;  // camera mount, and each secondary camera's place
  double angle_deg = 0.5;    // camera mount orientation
};

// Keys (all optional, defaults above): tolerance_focal_px, tolerance_principal_point_px,
// tolerance_baseline_m, tolerance_position_m, tolerance_angle_deg. Throws ConfigError on a
// negative value.
CalibrationTolerance loadCalibrationTolerance(IniSection& section);

struct MergedCameraRig {
  CameraRig rig;
  // One line per quantity on which the two sources disagree beyond the tolerance, naming both
  // values and which was used.
  std::vector<std::string> warnings;
};

// The rig to map with, from the [rig] ini section and/or the cameras recorded in the rawlog. The
// ini wins when both are given (the user's measurement overrides what the recorder stored); every
// disagreement is reported. Throws std::invalid_argument if neither is given.
MergedCameraRig mergeCameraRigs(const std::optional<CameraRig>& from_ini,
                                const std::optional<CameraRig>& observed,
                                const CalibrationTolerance& tolerance);

}  // namespace stereonav
