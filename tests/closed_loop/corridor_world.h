#pragma once

#include <mrpt/config/CConfigFileMemory.h>

#include <string>

#include "simulator/world.h"
#include "simulator/world_loader.h"

namespace stereonav::testing {

// A corridor 1.6 m wide whose textured walls run east from x = 0 to an end wall at x = 5 (its face
// at x = 4.95, half the default 0.1 m thickness short of its line), the robot starting at
// (start_x, 0.8) looking east. end_texture: "flat" (paint, nothing for stereo to match) or
// "rough" (a plaster-like noise).
constexpr double kCorridorEndWallFace = 4.95;

inline World corridorWorld(double start_x, const std::string& end_texture) {
  const std::string corridor = "[world]\nstart_pose = " + std::to_string(start_x) + R"( 0.8 0
ceiling_height = 2.5
[texture.flat]
type = paint
mean = 0.8
[texture.rough]
type = noise
mean = 0.6
contrast = 0.25
scales_m = 0.5 0.12 0.03
[wall.sides]
points = 5 0; 0 0; 0 1.6; 5 1.6
[wall.end]
points = 5 0; 5 1.6
texture = )" + end_texture + "\n";
  return loadWorld(mrpt::config::CConfigFileMemory(corridor), "corridor.ini");
}

}  // namespace stereonav::testing
