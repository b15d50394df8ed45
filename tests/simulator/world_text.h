#pragma once

#include <mrpt/config/CConfigFileMemory.h>

#include <string>

#include "simulator/world_loader.h"

namespace stereonav {

// Builds a World from ini text, as if it had been read from a file named "test.ini".
inline World worldFromText(const std::string& text) {
  const mrpt::config::CConfigFileMemory config(text);
  return loadWorld(config, "test.ini");
}

inline std::string worldsDirectory() { return std::string(STEREONAV_TEST_DATA_DIR) + "/../../ini/worlds"; }

}  // namespace stereonav
