#pragma once

#include <string>
#include <vector>

#include "simulator/number_list.h"
#include "simulator/surface_texture.h"

namespace stereonav {

// An axis-aligned rectangle on the floor plane.
struct FloorExtent {
  double x_min, y_min, x_max, y_max;
};

// A solid standing on (or floating above) the floor: an upright box turned by `yaw`, or an
// upright cylinder, spanning heights [z_min, z_max]. Every obstacle of an indoor floor is built
// from these (walls are thin boxes, a table is a thin box at table height on four cylinders), so
// one pair of analytic ray intersections and one pair of footprint tests cover the whole world.
struct Solid {
  enum class Shape { kBox, kCylinder };

  static Solid box(double x, double y, double size_x, double size_y, double yaw, double z_min,
                   double z_max, int texture);
  static Solid cylinder(double x, double y, double radius, double z_min, double z_max, int texture);

  // The smallest axis-aligned rectangle containing the solid's footprint.
  FloorExtent floorExtent() const;

  Shape shape = Shape::kBox;
  double x = 0.0;  // centre on the floor plane, world metres
  double y = 0.0;
  double half_x = 0.5;  // kBox: half sizes along the box's own axes
  double half_y = 0.5;
  double cos_yaw = 1.0;  // kBox: orientation of the box's x axis in the world
  double sin_yaw = 0.0;
  double radius = 0.5;  // kCylinder
  double z_min = 0.0;
  double z_max = 1.0;
  int texture = 0;             // index into World::textures
  // Shifts the texture's noise pattern (not stripes or poster frames), so that equal solids with
  // the same texture do not look identical.
  double texture_offset = 0.0;
};

// A solid following a closed polyline of waypoints at constant speed (a box pushed around, a
// person walking): the dynamic obstacles the paper's linear map update is meant to forget
// (section 3.4). A simulation moves it with MovingTraffic, which makes it wait for the robot.
struct MovingObstacle {
  std::string name;  // its world file section, e.g. "moving.person"
  Solid solid;       // placed at path[0]
  std::vector<Point2> path;
  double speed_mps = 0.5;

  // `solid` moved to where it is at `time_s` (seconds from the start of the simulation).
  Solid at(double time_s) const;
};

// The simulated indoor floor: textured solids, a floor plane at z = 0, an optional ceiling, and a
// light level that may change over time. Built by loadWorld() (world_loader.h).
struct World {
  std::vector<SurfaceTexture> textures;
  std::vector<std::string> texture_names;  // per texture, its [texture.<name>]
  std::vector<Solid> solids;  // static
  // Per static solid, the world file section it came from ("wall.w15"; a table's top and legs
  // share theirs): what a collision report names.
  std::vector<std::string> solid_sections;
  std::vector<MovingObstacle> moving_obstacles;
  int floor_texture = 0;
  double ceiling_height = 0.0;  // 0: no ceiling, rays going up see nothing (infinitely far)
  int ceiling_texture = 0;
  // Brightness gain 1 + lighting_change * sin(2 pi t / lighting_period_s): time-varying light
  // sources are one of the paper's causes of mismatches (section 4.1).
  double lighting_change = 0.0;
  double lighting_period_s = 4.0;
  // The region the ground-truth map covers: x_min, y_min, x_max, y_max.
  double bounds[4] = {0.0, 0.0, 0.0, 0.0};
  // Where a robot starts unless told otherwise: x, y (metres), heading (radians).
  double start_pose[3] = {0.0, 0.0, 0.0};

  double lightingGain(double time_s) const;
};

}  // namespace stereonav
