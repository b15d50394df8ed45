// libFuzzer target: the ini option loaders (map and simulate configurations) on arbitrary text.
// Every input must load or throw ConfigError (no crash, no undefined behaviour, no hang).
#include <mrpt/config/CConfigFileMemory.h>

#include <cstdint>
#include <string>

#include "common/ini_section.h"
#include "mapping/mapping_options.h"
#include "simulator/simulator_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  mrpt::config::CConfigFileMemory config(text);
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
