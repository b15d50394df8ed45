#include "simulator/footprint_overlap.h"

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

// (x, y) in the box's own frame.
void toBoxFrame(const Solid& box, double x, double y, double* local_x, double* local_y) {
  const double px = x - box.x;
  const double py = y - box.y;
  *local_x = box.cos_yaw * px + box.sin_yaw * py;
  *local_y = -box.sin_yaw * px + box.cos_yaw * py;
}

// Separating-axis test of two convex polygons given by their corners (4 each). Overlap of
// interiors only: intervals that merely touch separate.
bool rectanglesOverlap(const double (&a)[4][2], const double (&b)[4][2]) {
  for (const auto* polygon : {&a, &b}) {
    for (int i = 0; i < 4; ++i) {
      const double* p = (*polygon)[i];
      const double* q = (*polygon)[(i + 1) % 4];
      const double nx = q[1] - p[1];
      const double ny = p[0] - q[0];
      double a_min = INFINITY, a_max = -INFINITY, b_min = INFINITY, b_max = -INFINITY;
      for (int k = 0; k < 4; ++k) {
        const double pa = a[k][0] * nx + a[k][1] * ny;
        const double pb = b[k][0] * nx + b[k][1] * ny;
        a_min = std::min(a_min, pa);
        a_max = std::max(a_max, pa);
        b_min = std::min(b_min, pb);
        b_max = std::max(b_max, pb);
      }
      const double tolerance = 1e-9 * std::hypot(nx, ny);  // a nanometre
      if (a_max <= b_min + tolerance || b_max <= a_min + tolerance) return false;
    }
  }
  return true;
}

}  // namespace

bool solidInHeightBand(const Solid& solid, double z_low, double z_high) {
  return solid.z_min < z_high && solid.z_max > z_low;
}

bool solidOverlapsDisc(const Solid& solid, double x, double y, double radius) {
  if (solid.shape == Solid::Shape::kCylinder) {
    return std::hypot(x - solid.x, y - solid.y) < solid.radius + radius;
  }
  double local_x = 0.0;
  double local_y = 0.0;
  toBoxFrame(solid, x, y, &local_x, &local_y);
  const double nearest_x = std::clamp(local_x, -solid.half_x, solid.half_x);
  const double nearest_y = std::clamp(local_y, -solid.half_y, solid.half_y);
  return std::hypot(local_x - nearest_x, local_y - nearest_y) < radius ||
         (std::abs(local_x) < solid.half_x && std::abs(local_y) < solid.half_y);
}

bool solidOverlapsCell(const Solid& solid, double x_min, double y_min, double size) {
  const double x_max = x_min + size;
  const double y_max = y_min + size;
  if (solid.shape == Solid::Shape::kCylinder) {
    const double nearest_x = std::clamp(solid.x, x_min, x_max);
    const double nearest_y = std::clamp(solid.y, y_min, y_max);
    return std::hypot(solid.x - nearest_x, solid.y - nearest_y) < solid.radius;
  }
  const double cell[4][2] = {{x_min, y_min}, {x_max, y_min}, {x_max, y_max}, {x_min, y_max}};
  double box[4][2];
  const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k) {
    const double lx = corners[k][0] * solid.half_x;
    const double ly = corners[k][1] * solid.half_y;
    box[k][0] = solid.x + solid.cos_yaw * lx - solid.sin_yaw * ly;
    box[k][1] = solid.y + solid.sin_yaw * lx + solid.cos_yaw * ly;
  }
  return rectanglesOverlap(cell, box);
}

}  // namespace stereonav
