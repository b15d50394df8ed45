#pragma once

#include <string>
#include <vector>

namespace stereonav {

// An axis-aligned rectangle on the floor, metres.
struct FloorRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double depth() const { return y1 - y0; }
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// A gap in a wall: its centre on the wall's centre line and its clear width (between the slabs'
// faces), along x for a wall at constant y (`along_x`), else along y.
struct GeneratedDoor {
  double x = 0, y = 0;
  bool along_x = true;
  double clear_width_m = 0;
};

// An indoor floor made from a seed by generateWorld(): what it holds, for the benchmark's table
// and the tests, and the world file itself.
struct GeneratedWorld {
  unsigned seed = 0;
  std::string kind;               // "apartment", "office" or "hall"
  FloorRect footprint;            // the outer walls' centre lines
  std::vector<FloorRect> rooms;   // rooms and corridors (between wall centre lines)
  std::vector<GeneratedDoor> doors;
  size_t wall_sections = 0;
  size_t flat_wall_sections = 0;  // in flat paint: walls stereo cannot match
  size_t furniture = 0;           // tables, desks, chairs, sofas, beds, cabinets, poles, plants
  bool moving_person = false;
  double start_x = 0, start_y = 0;
  std::string ini_text;           // the world file (docs/worlds.md), loadable as it is
};

// Bounds of what generateWorld() makes.
constexpr double kGeneratedDoorMinWidthM = 0.8;
constexpr double kGeneratedDoorMaxWidthM = 1.2;
// Every room is reachable for a round robot of this radius (the shipped robot is 0.6 m wide).
constexpr double kGeneratedRobotRadiusM = 0.3;

// A varied indoor floor, the same for the same seed on every machine: an apartment (8-14 m a
// side, rooms off each other), an office (16-30 m x 10-20 m, a corridor with rooms on both
// sides) or a hall (a large room with side rooms and pillars); 3-12 rooms and corridors, doors of
// 0.8-1.2 m clear width, 20-40% of the wall sections in flat paint and some in stripes or posters,
// furniture (tables and desks with tops at 0.4-0.8 m, chairs, sofas, beds, cabinets, thin poles
// of 2-5 cm, plants) and in some a person walking. Furniture that would cut a room off from the
// start for a robot of kGeneratedRobotRadiusM is left out.
GeneratedWorld generateWorld(unsigned seed);

}  // namespace stereonav
