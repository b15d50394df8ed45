#pragma once

#include <string>

namespace stereonav::testing {

// The closed-loop tests' configuration: the shipped 160x120 exploration config, as users run it.
inline std::string shippedExplorationConfigPath() {
  return std::string(STEREONAV_TEST_DATA_DIR) + "/../../ini/explore_160x120.ini";
}

}  // namespace stereonav::testing
