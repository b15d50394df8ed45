// libFuzzer target: world files and motion plans on arbitrary text; a world that loads must give
// a ground-truth map within its max_cells, or a ConfigError.
#include <cstdint>
#include <string>

#include "common/ini_section.h"
#include "simulator/ground_truth_map.h"
#include "simulator/motion_plan.h"
#include "simulator/world_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const stereonav::World world = stereonav::loadWorld(stereonav::parseConfigText(text, "fuzz.ini"), "fuzz.ini");
    stereonav::GroundTruthMapOptions options;
    options.resolution_m = 0.25;  // keeps each run fast; the bound is max_cells either way
    stereonav::GroundTruthMap map(world, options);
  } catch (const stereonav::ConfigError&) {
  }
  try {
    stereonav::parseMotionPlan(text, "fuzz.txt");
  } catch (const stereonav::ConfigError&) {
  }
  return 0;
}
