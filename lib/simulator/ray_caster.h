#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "simulator/ray_intersection.h"
#include "simulator/world.h"

namespace stereonav {

// The centre rays of the pixels of a pinhole image: pixel (x, y) looks from `origin` along
// forward + (y - cy) * down + (x - cx) * right. `right` and `down` (one pixel's step) must be
// orthogonal to `forward`; with a unit `forward`, a ray's t is the depth Z of the point it reaches.
struct PixelRays {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d forward = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d right = Eigen::Vector3d::UnitX();
  Eigen::Vector3d down = Eigen::Vector3d::UnitY();
  int width = 1;
  int height = 1;
  double cx = 0.0;
  double cy = 0.0;

  // The direction of pixel (x, y) is rowStart(y) + x * right.
  Eigen::Vector3d rowStart(int y) const { return forward + (y - cy) * down - cx * right; }
  Ray ray(int x, int y) const { return {origin, rowStart(y) + x * right}; }
};

// The nearest surface a ray meets, and what it is.
struct RayHit {
  double t = kNoHit;
  SurfacePoint surface;
  int texture = 0;
  double texture_offset = 0.0;  // Solid::texture_offset of the surface hit
};

// What the pixels of one image row see, as arrays that vector loops read: the depth of every
// pixel's nearest hit, and for the pixels that see a surface, in column order, where and what it
// is (RayHit's fields, one array each).
struct RowSurfaces {
  std::vector<double> t;  // every pixel of the row; kNoHit where it sees nothing
  size_t count = 0;       // the pixels that see a surface; the arrays below hold them first
  std::vector<int> column;
  std::vector<double> x, y, z;
  std::vector<double> normal_x, normal_y, normal_z;
  std::vector<double> u, v;
  std::vector<int> texture;
  std::vector<double> texture_offset;

  void resize(size_t width);
};

// Finds the first surface along the centre ray of every pixel of an image: the floor, the
// optional ceiling, and the solids, static and moving. Like a z-buffer, it visits the solids
// rather than the rays: each solid's exact ray test runs only on the pixels its silhouette covers
// (the projection of its corners, widened by a pixel), nearest solid first, and not where the
// pixel already holds a hit nearer than the solid's nearest corner. Hits nearer than
// kNearPlaneT are not seen (a camera never stands that close to a surface).
class RayCaster {
 public:
  explicit RayCaster(const World& world);

  // The moving obstacles where they are now (MovingTraffic::solids).
  void setMovingSolids(const std::vector<Solid>& moving_solids) { moving_ = moving_solids; }

  // Finds the first hit of every pixel's ray; hit() then reads them.
  void cast(const PixelRays& rays);
  // The nearest hit with t > 0 of pixel (x, y) of the last cast(), or t = kNoHit.
  RayHit hit(int x, int y) const;
  // hit() of every pixel of row y, bit for bit. A row's pixels see few surfaces, one after
  // another: what differs from surface to surface is decided once per run of pixels on one
  // face, and the loops within a run have no branches (rendering a generated office: 7% less
  // time than building each pixel's RayHit).
  void rowSurfaces(int y, RowSurfaces& row) const;

  static constexpr double kNearPlaneT = 1e-6;

 private:
  // What a pixel's ray meets first: kNothing, kFloor, kCeiling, or an index into the cast's
  // solids (the world's static ones, then the moving ones).
  static constexpr int kNothing = -1;
  static constexpr int kFloor = -2;
  static constexpr int kCeiling = -3;
  struct PixelHit {
    double t;
    int32_t source;
    int32_t face;
  };

  const Solid& solid(int index) const;
  // Tests solid `index` on the pixels its silhouette covers whose hits are farther than
  // `nearest_t`; `corners`: its bounding prism's corners in view coordinates (ray_caster.cc).
  void drawSolid(int index, double nearest_t, const std::array<Eigen::Vector3d, 8>& corners);
  // drawSolid's tests of a box on the pixels begin..end of a row.
  void drawBoxOnRow(const Solid& box, int index, double nearest_t, const Eigen::Vector3d& row_start, int begin,
                    int end, PixelHit* row);
  // Widens the row spans of the silhouette being drawn by the segment a-b (pixel coordinates).
  void addSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

  const World& world_;
  std::vector<Solid> moving_;
  PixelRays rays_;
  std::vector<PixelHit> hits_;
  // A row's hits on the floor and on the ceiling (kNoHit where there is none or no such plane).
  std::vector<double> floor_t_, ceiling_t_;
  // The silhouette being drawn: the x range to test on each row, and the rows it reaches.
  std::vector<double> span_begin_;
  std::vector<double> span_end_;
  int first_row_ = 0;
  int last_row_ = -1;
};

// Inline: the renderer reads every pixel's hit.
inline const Solid& RayCaster::solid(int index) const {
  const int static_count = static_cast<int>(world_.solids.size());
  return index < static_count ? world_.solids[index] : moving_[index - static_count];
}

inline RayHit RayCaster::hit(int x, int y) const {
  const PixelHit& pixel = hits_[static_cast<size_t>(y) * rays_.width + x];
  const Ray ray = rays_.ray(x, y);
  RayHit hit;
  hit.t = pixel.t;
  switch (pixel.source) {
    case kNothing:
      break;
    case kFloor:
    case kCeiling:
      hit.surface.position = ray.origin + pixel.t * ray.direction;
      hit.surface.normal = Eigen::Vector3d(0.0, 0.0, pixel.source == kFloor ? 1.0 : -1.0);
      hit.surface.u = hit.surface.position.x();
      hit.surface.v = hit.surface.position.y();
      hit.texture = pixel.source == kFloor ? world_.floor_texture : world_.ceiling_texture;
      break;
    default: {
      const Solid& hit_solid = solid(pixel.source);
      hit.surface = surfaceOfSolid(hit_solid, pixel.face, ray, pixel.t);
      hit.texture = hit_solid.texture;
      hit.texture_offset = hit_solid.texture_offset;
      break;
    }
  }
  return hit;
}

}  // namespace stereonav
