#include "configuration/accepted_keys.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "closed_loop/exploration_config.h"
#include "mapping/mapping_options.h"
#include "occupancy_grid/stereo_occupancy_grid_map.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

// One object of each kind with only its required keys: loading it asks for all the others.
constexpr const char* kProbeWorld = R"([world]
[texture.<name>]
[wall.<name>]
points = 0 0; 1 0
[box.<name>]
center = 2 2
size = 1 1
[cylinder.<name>]
center = 4 4
[table.<name>]
center = 6 6
size = 1 1
[picket_fence.<name>]
from = 8 8
to = 9 8
[moving.<name>]
path = 10 10
)";

// loadExplorationConfig reads a file (the `stereonav explore` configuration: the simulator's,
// the mapping pipeline's and the explorer's sections), so it gets an empty one.
void loadEmptyExplorationConfig() {
  std::string path = (std::filesystem::temp_directory_path() / "stereonav_keys_XXXXXX").string();
  const int descriptor = mkstemp(path.data());
  if (descriptor < 0) throw std::runtime_error(path + ": cannot create a temporary file");
  close(descriptor);
  try {
    loadExplorationConfig(path);
  } catch (...) {
    std::filesystem::remove(path);
    throw;
  }
  std::filesystem::remove(path);
}

// A floor plan needs its map file: a one-cell free map in a temporary folder.
void loadProbeFloorPlan() {
  std::string folder = (std::filesystem::temp_directory_path() / "stereonav_plan_XXXXXX").string();
  if (mkdtemp(folder.data()) == nullptr) throw std::runtime_error(folder + ": cannot create a temporary folder");
  try {
    std::ofstream(folder + "/plan.pgm", std::ios::binary) << "P5\n1 1\n255\n" << '\xfe';
    std::ofstream(folder + "/plan.yaml") << "image: plan.pgm\nresolution: 1\norigin: [0, 0, 0]\n";
    loadWorld(mrpt::config::CConfigFileMemory("[floor_plan.<name>]\nmap = " + folder + "/plan.yaml\n"),
              "the probe floor plan");
  } catch (...) {
    std::filesystem::remove_all(folder);
    throw;
  }
  std::filesystem::remove_all(folder);
}

}  // namespace

IniKeyRecorder::Sections acceptedConfigKeys() {
  IniKeyRecorder recorder;
  loadEmptyExplorationConfig();
  mrpt::config::CConfigFileMemory empty;
  loadMappingOptions(empty);
  CStereoOccupancyGridMap::TMapDefinition map_definition;
  map_definition.loadFromConfigFile(empty, "<map>");
  loadWorld(mrpt::config::CConfigFileMemory(kProbeWorld), "the probe world");
  loadProbeFloorPlan();
  return recorder.sections();
}

std::string configurationSkeleton(const IniKeyRecorder::Sections& sections) {
  std::ostringstream text;
  for (const auto& [section, keys] : sections) {
    text << "### [" << section << "]\n\n"
         << "| key | type | default | range | meaning |\n"
         << "|---|---|---|---|---|\n";
    for (const auto& [key, read] : keys) {
      text << "| `" << key << "` | " << read.type << " | "
           << (read.default_value.empty() ? "" : "`" + read.default_value + "`") << " |  |  |\n";
    }
    text << "\n";
  }
  return text.str();
}

}  // namespace stereonav
