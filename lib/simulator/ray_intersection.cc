#include "simulator/ray_intersection.h"

#include <cmath>

namespace stereonav {
namespace {

// Slab test on one axis: narrows [t_near, t_far]; returns false if the ray misses the slab.
bool clipSlab(double origin, double direction, double low, double high, int entry_face,
              double* t_near, double* t_far, int* near_face) {
  if (direction == 0.0) return origin >= low && origin <= high;
  const double inverse = 1.0 / direction;
  double t_low = (low - origin) * inverse;
  double t_high = (high - origin) * inverse;
  // Entering through the low side means crossing the face whose normal points to -axis.
  int face = entry_face + 1;
  if (t_low > t_high) {
    std::swap(t_low, t_high);
    face = entry_face;
  }
  if (t_low > *t_near) {
    *t_near = t_low;
    *near_face = face;
  }
  if (t_high < *t_far) *t_far = t_high;
  return *t_near <= *t_far;
}

// The reference for RayCaster::drawBoxOnRow (ray_caster.cc), which runs these same operations in
// the same order on four rays at once: a change here must be made there too, or the caster's
// tests against testing every solid for every pixel fail.
double intersectBox(const Solid& box, const Ray& ray, double t_max, int* face) {
  // Into the box frame: rotate by -yaw about the box centre.
  const double px = ray.origin.x() - box.x;
  const double py = ray.origin.y() - box.y;
  const double local_ox = box.cos_yaw * px + box.sin_yaw * py;
  const double local_oy = -box.sin_yaw * px + box.cos_yaw * py;
  const double local_dx = box.cos_yaw * ray.direction.x() + box.sin_yaw * ray.direction.y();
  const double local_dy = -box.sin_yaw * ray.direction.x() + box.cos_yaw * ray.direction.y();
  double t_near = -kNoHit;
  double t_far = t_max;
  int near_face = -1;
  if (!clipSlab(local_ox, local_dx, -box.half_x, box.half_x, kFacePlusX, &t_near, &t_far, &near_face) ||
      !clipSlab(local_oy, local_dy, -box.half_y, box.half_y, kFacePlusY, &t_near, &t_far, &near_face) ||
      !clipSlab(ray.origin.z(), ray.direction.z(), box.z_min, box.z_max, kFaceTop, &t_near, &t_far,
                &near_face)) {
    return kNoHit;
  }
  if (t_near <= kMinimumHitT || near_face < 0) return kNoHit;
  *face = near_face;
  return t_near;
}

double intersectCylinder(const Solid& cylinder, const Ray& ray, double t_max, int* face) {
  const double px = ray.origin.x() - cylinder.x;
  const double py = ray.origin.y() - cylinder.y;
  const double dx = ray.direction.x();
  const double dy = ray.direction.y();
  const double dz = ray.direction.z();
  const double r2 = cylinder.radius * cylinder.radius;
  double best = kNoHit;
  const double a = dx * dx + dy * dy;
  const double c = px * px + py * py - r2;
  if (a > 0.0) {
    const double b = px * dx + py * dy;  // half of the usual b
    const double discriminant = b * b - a * c;
    if (discriminant >= 0.0) {
      const double t = (-b - std::sqrt(discriminant)) / a;
      const double z = ray.origin.z() + t * dz;
      if (t > kMinimumHitT && t < t_max && z >= cylinder.z_min && z <= cylinder.z_max) {
        best = t;
        *face = kFacePlusX;
      }
    }
  }
  // The caps, entered from above (top) or below (bottom).
  const double cap_z = dz < 0.0 ? cylinder.z_max : cylinder.z_min;
  const bool outside_cap = dz < 0.0 ? ray.origin.z() > cylinder.z_max : ray.origin.z() < cylinder.z_min;
  if (dz != 0.0 && outside_cap) {
    const double t = (cap_z - ray.origin.z()) / dz;
    const double hx = px + t * dx;
    const double hy = py + t * dy;
    if (t > kMinimumHitT && t < std::min(best, t_max) && hx * hx + hy * hy <= r2) {
      best = t;
      *face = dz < 0.0 ? kFaceTop : kFaceBottom;
    }
  }
  return best;
}

}  // namespace

double intersectSolid(const Solid& solid, const Ray& ray, double t_max, int* face) {
  return solid.shape == Solid::Shape::kBox ? intersectBox(solid, ray, t_max, face)
                                           : intersectCylinder(solid, ray, t_max, face);
}

}  // namespace stereonav
