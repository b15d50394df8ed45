#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "simulator/ground_truth_map.h"
#include "simulator/world_generator.h"
#include "simulator/world_loader.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav generate --seed N --out PREFIX\n"
    "Generates a varied indoor floor from a seed (the same on every machine): an apartment, an\n"
    "office or a hall, 3-12 rooms and corridors, doors of 0.8-1.2 m, 20-40% of the walls in flat\n"
    "paint, furniture, thin poles and plants, in some a walking person. Writes PREFIX.ini, an\n"
    "ordinary world file for 'stereonav simulate' and 'stereonav explore' (docs/worlds.md), and\n"
    "PREFIX.truth.yaml + .pgm, its ground-truth map for a robot 1 m tall.\n";

}  // namespace

int runGenerateCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const int seed = command_line.intValue("seed").value_or(-1);
  const std::string prefix = command_line.required("out");
  command_line.rejectUnknown();
  if (seed < 0) throw UsageError("--seed: a number 0 or more is required");

  const GeneratedWorld world = generateWorld(static_cast<unsigned>(seed));
  writeStringAtomically(prefix + ".ini", world.ini_text);
  GroundTruthMap(loadWorld(prefix + ".ini"), GroundTruthMapOptions{}).writeRosMap(prefix + ".truth.yaml");
  std::cerr << "stereonav generate: seed " << seed << ", " << world.kind << " of "
            << world.footprint.width() << " x " << world.footprint.depth() << " m, "
            << world.rooms.size() << " rooms and corridors, " << world.doors.size() << " doors, "
            << world.flat_wall_sections << " of " << world.wall_sections << " wall sections flat, "
            << world.furniture << " pieces of furniture" << (world.moving_person ? ", a walking person" : "")
            << ": wrote " << prefix << ".ini and " << prefix << ".truth.yaml\n";
  return 0;
}

}  // namespace stereonav::app
