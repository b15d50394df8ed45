#include "simulator/world.h"

#include <algorithm>
#include <cmath>

namespace stereonav {

Solid Solid::box(double x, double y, double size_x, double size_y, double yaw, double z_min,
                 double z_max, int texture) {
  Solid solid;
  solid.shape = Shape::kBox;
  solid.x = x;
  solid.y = y;
  solid.half_x = size_x / 2.0;
  solid.half_y = size_y / 2.0;
  solid.cos_yaw = std::cos(yaw);
  solid.sin_yaw = std::sin(yaw);
  solid.z_min = z_min;
  solid.z_max = z_max;
  solid.texture = texture;
  return solid;
}

Solid Solid::cylinder(double x, double y, double radius, double z_min, double z_max, int texture) {
  Solid solid;
  solid.shape = Shape::kCylinder;
  solid.x = x;
  solid.y = y;
  solid.radius = radius;
  solid.z_min = z_min;
  solid.z_max = z_max;
  solid.texture = texture;
  return solid;
}

FloorExtent Solid::floorExtent() const {
  double ex = radius;
  double ey = radius;
  if (shape == Shape::kBox) {
    ex = std::abs(cos_yaw) * half_x + std::abs(sin_yaw) * half_y;
    ey = std::abs(sin_yaw) * half_x + std::abs(cos_yaw) * half_y;
  }
  return {x - ex, y - ey, x + ex, y + ey};
}

Solid MovingObstacle::at(double time_s) const {
  Solid placed = solid;
  if (path.size() < 2 || speed_mps <= 0.0) return placed;
  double loop_length = 0.0;
  for (size_t i = 0; i < path.size(); ++i) {
    const Point2& a = path[i];
    const Point2& b = path[(i + 1) % path.size()];
    loop_length += std::hypot(b.x - a.x, b.y - a.y);
  }
  if (loop_length <= 0.0) return placed;
  double travelled = std::fmod(speed_mps * std::max(time_s, 0.0), loop_length);
  for (size_t i = 0; i < path.size(); ++i) {
    const Point2& a = path[i];
    const Point2& b = path[(i + 1) % path.size()];
    const double leg = std::hypot(b.x - a.x, b.y - a.y);
    if (travelled <= leg && leg > 0.0) {
      placed.x = a.x + (b.x - a.x) * travelled / leg;
      placed.y = a.y + (b.y - a.y) * travelled / leg;
      return placed;
    }
    travelled -= leg;
  }
  placed.x = path.front().x;
  placed.y = path.front().y;
  return placed;
}

double World::lightingGain(double time_s) const {
  return 1.0 + lighting_change * std::sin(2.0 * M_PI * time_s / lighting_period_s);
}

}  // namespace stereonav
