#pragma once

#include <Eigen/Core>

#include <cmath>
#include <limits>

#include "simulator/world.h"

namespace stereonav {

// A ray origin + t * direction, t >= 0. The direction need not be unit length: the renderer uses
// camera-frame directions ((x - cx)/f, (y - cy)/f, 1), so that t is the depth Z of the hit.
struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;
};

constexpr double kNoHit = std::numeric_limits<double>::infinity();
// Below this a hit is taken to be at the ray's own origin (a surface the ray starts on).
constexpr double kMinimumHitT = 1e-9;

// Which face of a solid a ray hit. Boxes: 0..5 = +x, -x, +y, -y (the box's own axes), top,
// bottom. Cylinders: 0 = side, 4 = top, 5 = bottom.
enum SolidFace : int { kFacePlusX = 0, kFaceMinusX, kFacePlusY, kFaceMinusY, kFaceTop, kFaceBottom };

// The smallest t in (0, t_max) where the ray enters the solid from outside, or kNoHit (also when
// the origin is inside the solid: a camera never looks out of an obstacle). Sets *face on a hit.
double intersectSolid(const Solid& solid, const Ray& ray, double t_max, int* face);

// t where the ray crosses the horizontal plane at height z, in (0, t_max), or kNoHit. Inline:
// every pixel's ray meets the floor and the ceiling.
inline double intersectHorizontalPlane(double z, const Ray& ray, double t_max) {
  if (ray.direction.z() == 0.0) return kNoHit;
  const double t = (z - ray.origin.z()) / ray.direction.z();
  return t > kMinimumHitT && t < t_max ? t : kNoHit;
}

// What the renderer needs to know about a hit point.
struct SurfacePoint {
  Eigen::Vector3d position;
  Eigen::Vector3d normal;  // unit, facing out of the solid
  double u = 0.0;          // surface coordinates, metres (vertical faces: v is the height)
  double v = 0.0;
};

// Surface coordinates are fixed to the solid, so a moving obstacle carries its texture along.
// Side faces: v is the height above the floor and u the horizontal distance from the middle of the
// face, increasing to the right as seen from the front (box faces), or the arc length
// counter-clockwise from the solid's +x direction (cylinders). Top and bottom faces: u, v are
// x, y relative to the solid's centre, along the world axes. The reference for
// RayCaster::rowSurfaces (ray_caster.cc), which computes the same for a run of pixels on one face:
// a change here must be made there too, or the caster's tests of rows against hit() fail.
inline SurfacePoint surfaceOfSolid(const Solid& solid, int face, const Ray& ray, double t) {
  SurfacePoint point;
  point.position = ray.origin + t * ray.direction;
  const double px = point.position.x() - solid.x;
  const double py = point.position.y() - solid.y;
  if (face == kFaceTop || face == kFaceBottom) {
    point.normal = Eigen::Vector3d(0.0, 0.0, face == kFaceTop ? 1.0 : -1.0);
    point.u = px;
    point.v = py;
    return point;
  }
  point.v = point.position.z();
  if (solid.shape == Solid::Shape::kCylinder) {
    point.normal = Eigen::Vector3d(px / solid.radius, py / solid.radius, 0.0);
    point.u = solid.radius * std::atan2(py, px);
    return point;
  }
  const double local_x = solid.cos_yaw * px + solid.sin_yaw * py;
  const double local_y = -solid.sin_yaw * px + solid.cos_yaw * py;
  const Eigen::Vector3d axis_x(solid.cos_yaw, solid.sin_yaw, 0.0);
  const Eigen::Vector3d axis_y(-solid.sin_yaw, solid.cos_yaw, 0.0);
  switch (face) {
    case kFacePlusX:
      point.normal = axis_x;
      point.u = local_y;
      break;
    case kFaceMinusX:
      point.normal = -axis_x;
      point.u = -local_y;
      break;
    case kFacePlusY:
      point.normal = axis_y;
      point.u = -local_x;
      break;
    default:
      point.normal = -axis_y;
      point.u = local_x;
      break;
  }
  return point;
}

}  // namespace stereonav
