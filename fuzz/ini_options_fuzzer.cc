// libFuzzer target: the ini option loaders (map and simulate configurations) on arbitrary text.
// Every input must load or throw ConfigError (no crash, no undefined behaviour, no hang).
#include <mrpt/config/CConfigFileMemory.h>

#include <cstdint>
#include <optional>
#include <string>

#include "common/ini_section.h"
#include "mapping/mapping_options.h"
#include "simulator/simulator_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<mrpt::config::CConfigFileMemory> parsed;
  try {
    parsed.emplace(stereonav::parseConfigText(text, "fuzz.ini"));
  } catch (const stereonav::ConfigError&) {
    return 0;
  }
  const mrpt::config::CConfigFileMemory& config = *parsed;
  try {
    stereonav::loadMappingOptions(config);
  } catch (const stereonav::ConfigError&) {
  }
  try {
    stereonav::loadSimulatorConfig(config, "fuzz.ini");
  } catch (const stereonav::ConfigError&) {
  }
  return 0;
}
