#pragma once

#include <mrpt/config/CConfigFile.h>

#include <string>

#include "disparity/stereo_options.h"

namespace stereonav::testing {

// The [stereo] section of one of the example configurations in ini/.
inline StereoOptions shippedStereoOptions(const std::string& file) {
  const mrpt::config::CConfigFile config(std::string(STEREONAV_TEST_DATA_DIR) + "/../../ini/" + file);
  IniSection section(config, "stereo");
  const StereoOptions options = loadStereoOptions(section);
  section.rejectUnknownKeys();
  return options;
}

}  // namespace stereonav::testing
