#include "simulator/ray_caster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace stereonav {
namespace {

// The axes of a view scaled so that a point's coordinates along them are (a, b, c) with
// point - origin = c * forward + a * right + b * down: the point lies on the ray of pixel
// (cx + a/c, cy + b/c) at t = c.
struct ViewAxes {
  Eigen::Vector3d origin, right, down, forward;
  explicit ViewAxes(const PixelRays& rays)
      : origin(rays.origin),
        right(rays.right / rays.right.squaredNorm()),
        down(rays.down / rays.down.squaredNorm()),
        forward(rays.forward / rays.forward.squaredNorm()) {}
};

// The corners of a solid's bounding prism in view coordinates (a, b, c). Boxes: their own
// corners; cylinders: the square prism around them.
using ViewCorners = std::array<Eigen::Vector3d, 8>;

ViewCorners viewCorners(const Solid& solid, const ViewAxes& view) {
  const bool box = solid.shape == Solid::Shape::kBox;
  const double cos_yaw = box ? solid.cos_yaw : 1.0;
  const double sin_yaw = box ? solid.sin_yaw : 0.0;
  const double half_x = box ? solid.half_x : solid.radius;
  const double half_y = box ? solid.half_y : solid.radius;
  ViewCorners corners;
  for (int i = 0; i < 8; ++i) {
    const double along_x = (i & 1) ? half_x : -half_x;
    const double along_y = (i & 2) ? half_y : -half_y;
    const Eigen::Vector3d corner(solid.x + along_x * cos_yaw - along_y * sin_yaw,
                                 solid.y + along_x * sin_yaw + along_y * cos_yaw, (i & 4) ? solid.z_max : solid.z_min);
    const Eigen::Vector3d relative = corner - view.origin;
    corners[i] = Eigen::Vector3d(relative.dot(view.right), relative.dot(view.down), relative.dot(view.forward));
  }
  return corners;
}

// Corner pairs that differ along one axis: the prism's edges.
constexpr std::array<std::array<int, 2>, 12> kEdges{{{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                                     {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// intersectHorizontalPlane for the rays of a row of pixels, whose directions rise by `step_z` from
// `row_z` pixel by pixel: as a vector loop, the planes being met by every ray of the image.
__attribute__((target_clones("avx2", "default")))
void planeHits(double height, double origin_z, double row_z, double step_z, int width, double* t) {
  const double rise = height - origin_z;
  for (int x = 0; x < width; ++x) {
    // A ray parallel to the plane divides by zero: infinite or NaN, no hit.
    const double hit = rise / (row_z + x * step_z);
    t[x] = hit > kMinimumHitT && hit < kNoHit ? hit : kNoHit;
  }
}

}  // namespace

RayCaster::RayCaster(const World& world) : world_(world) {}

void RayCaster::cast(const PixelRays& rays) {
  rays_ = rays;
  hits_.resize(static_cast<size_t>(rays.width) * rays.height);
  const bool above_floor = rays.origin.z() > 0.0;
  const bool below_ceiling = world_.ceiling_height > 0.0 && rays.origin.z() < world_.ceiling_height;
  floor_t_.assign(rays.width, kNoHit);
  ceiling_t_.assign(rays.width, kNoHit);
  for (int y = 0; y < rays.height; ++y) {
    const Eigen::Vector3d row_start = rays.rowStart(y);
    if (above_floor) planeHits(0.0, rays.origin.z(), row_start.z(), rays.right.z(), rays.width, floor_t_.data());
    if (below_ceiling) {
      planeHits(world_.ceiling_height, rays.origin.z(), row_start.z(), rays.right.z(), rays.width, ceiling_t_.data());
    }
    PixelHit* row = &hits_[static_cast<size_t>(y) * rays.width];
    for (int x = 0; x < rays.width; ++x) {
      row[x] = {floor_t_[x], floor_t_[x] < kNoHit ? kFloor : kNothing, 0};
      if (ceiling_t_[x] < row[x].t) row[x] = {ceiling_t_[x], kCeiling, 0};
    }
  }

  // Nearest first, so that most pixels of a hidden solid are passed over by one comparison.
  const ViewAxes view(rays);
  const int solid_count = static_cast<int>(world_.solids.size() + moving_.size());
  std::vector<ViewCorners> corners(static_cast<size_t>(solid_count));
  std::vector<std::pair<double, int>> order;
  for (int i = 0; i < solid_count; ++i) {
    corners[i] = viewCorners(solid(i), view);
    double nearest = kNoHit;
    double farthest = -kNoHit;
    for (const auto& corner : corners[i]) {
      nearest = std::min(nearest, corner.z());
      farthest = std::max(farthest, corner.z());
    }
    if (farthest >= kNearPlaneT) order.emplace_back(nearest, i);
  }
  std::sort(order.begin(), order.end());
  span_begin_.assign(rays.height, kNoHit);
  span_end_.assign(rays.height, -kNoHit);
  for (const auto& [nearest, index] : order) drawSolid(index, nearest, corners[index]);
}

void RayCaster::drawSolid(int index, double nearest_t, const std::array<Eigen::Vector3d, 8>& corners) {
  const auto project = [&](const Eigen::Vector3d& corner) {
    return Eigen::Vector2d(rays_.cx + corner.x() / corner.z(), rays_.cy + corner.y() / corner.z());
  };
  // The silhouette of the prism cut off at the near plane: its outline lies on the projections of
  // the edges' parts in front of the plane and of the cut face, whose corners are the cut points.
  first_row_ = rays_.height;
  last_row_ = -1;
  std::array<Eigen::Vector2d, kEdges.size()> cuts;
  size_t cut_count = 0;
  for (const auto& edge : kEdges) {
    const Eigen::Vector3d& p = corners[edge[0]];
    const Eigen::Vector3d& q = corners[edge[1]];
    const bool p_in_front = p.z() >= kNearPlaneT;
    const bool q_in_front = q.z() >= kNearPlaneT;
    if (p_in_front && q_in_front) {
      addSegment(project(p), project(q));
    } else if (p_in_front || q_in_front) {
      Eigen::Vector3d cut = p + (kNearPlaneT - p.z()) / (q.z() - p.z()) * (q - p);
      cut.z() = kNearPlaneT;
      cuts[cut_count] = project(cut);
      addSegment(project(p_in_front ? p : q), cuts[cut_count]);
      ++cut_count;
    }
  }
  for (size_t i = 0; i < cut_count; ++i) {
    for (size_t j = i + 1; j < cut_count; ++j) addSegment(cuts[i], cuts[j]);
  }

  const Solid& tested = solid(index);
  const bool box = tested.shape == Solid::Shape::kBox;
  Ray ray{rays_.origin, Eigen::Vector3d::Zero()};
  for (int y = first_row_; y <= last_row_; ++y) {
    // Half a pixel of margin beside the outline: rounding must never lose a pixel it covers.
    const double begin = std::max(0.0, std::ceil(span_begin_[y] - 0.5));
    const double end = std::min(rays_.width - 1.0, std::floor(span_end_[y] + 0.5));
    span_begin_[y] = kNoHit;
    span_end_[y] = -kNoHit;
    if (begin > end) continue;
    const Eigen::Vector3d row_start = rays_.rowStart(y);
    PixelHit* row = &hits_[static_cast<size_t>(y) * rays_.width];
    if (box) {
      drawBoxOnRow(tested, index, nearest_t, row_start, static_cast<int>(begin), static_cast<int>(end), row);
      continue;
    }
    for (int x = static_cast<int>(begin); x <= static_cast<int>(end); ++x) {
      PixelHit& pixel = row[x];
      if (pixel.t <= nearest_t) continue;
      ray.direction = row_start + x * rays_.right;
      int face = 0;
      const double t = intersectSolid(tested, ray, pixel.t, &face);
      if (t < pixel.t) pixel = {t, index, face};
    }
  }
}

namespace {

// Four pixels' rays side by side, and lane masks (all bits set where true).
using Lanes = double __attribute__((vector_size(32)));
using LaneMasks = int64_t __attribute__((vector_size(32)));

// ray_intersection.cc's clipSlab for four rays at once, bit for bit: the same operations in the
// same order, its early exits as lane masks. A lane already `missed` may take any values.
[[gnu::always_inline]] inline void clipSlabLanes(double origin, Lanes direction, double low, double high,
                                                 int64_t entry_face, Lanes& t_near, Lanes& t_far,
                                                 LaneMasks& near_face, LaneMasks& missed) {
  const LaneMasks parallel = direction == 0.0;
  const Lanes inverse = 1.0 / direction;
  const Lanes t_low = (low - origin) * inverse;
  const Lanes t_high = (high - origin) * inverse;
  // Entering through the low side means crossing the face whose normal points to -axis.
  const LaneMasks swapped = t_low > t_high;
  const Lanes entry = swapped ? t_high : t_low;
  const Lanes exit = swapped ? t_low : t_high;
  const LaneMasks face = swapped ? LaneMasks{} + entry_face : LaneMasks{} + (entry_face + 1);
  const LaneMasks later_entry = ~parallel & (entry > t_near);
  t_near = later_entry ? entry : t_near;
  near_face = later_entry ? face : near_face;
  t_far = (~parallel & (exit < t_far)) ? exit : t_far;
  const int64_t outside_slab = origin >= low && origin <= high ? 0 : -1;
  missed |= parallel ? LaneMasks{} + outside_slab : ~(t_near <= t_far);
}

}  // namespace

// Built for AVX2 as well (chosen at load time), without FMA: the same hits on every machine.
__attribute__((target_clones("avx2", "default")))
void RayCaster::drawBoxOnRow(const Solid& box, int index, double nearest_t, const Eigen::Vector3d& row_start,
                             int begin, int end, PixelHit* row) {
  // intersectSolid's box test (ray_intersection.cc), four pixels at a time: the ray origin in the
  // box frame is the same for all, the directions step by `right` along the row.
  const double px = rays_.origin.x() - box.x;
  const double py = rays_.origin.y() - box.y;
  const double local_ox = box.cos_yaw * px + box.sin_yaw * py;
  const double local_oy = -box.sin_yaw * px + box.cos_yaw * py;
  const Lanes lane_offsets{0.0, 1.0, 2.0, 3.0};
  for (int x = begin; x <= end; x += 4) {
    Lanes t_max;
    for (int lane = 0; lane < 4; ++lane) t_max[lane] = x + lane <= end ? row[x + lane].t : -kNoHit;
    // Pixels already nearer than the box's nearest corner (or past the span) are not tested:
    // behind a nearer wall or desk, most of a box's silhouette.
    LaneMasks missed = t_max <= nearest_t;
    if (!(missed[0] == 0 || missed[1] == 0 || missed[2] == 0 || missed[3] == 0)) continue;
    const Lanes column = static_cast<double>(x) + lane_offsets;
    const Lanes dx = row_start.x() + column * rays_.right.x();
    const Lanes dy = row_start.y() + column * rays_.right.y();
    const Lanes dz = row_start.z() + column * rays_.right.z();
    const Lanes local_dx = box.cos_yaw * dx + box.sin_yaw * dy;
    const Lanes local_dy = -box.sin_yaw * dx + box.cos_yaw * dy;
    Lanes t_near = Lanes{} - kNoHit;
    Lanes t_far = t_max;
    LaneMasks near_face = LaneMasks{} - 1;
    clipSlabLanes(local_ox, local_dx, -box.half_x, box.half_x, kFacePlusX, t_near, t_far, near_face, missed);
    clipSlabLanes(local_oy, local_dy, -box.half_y, box.half_y, kFacePlusY, t_near, t_far, near_face, missed);
    clipSlabLanes(rays_.origin.z(), dz, box.z_min, box.z_max, kFaceTop, t_near, t_far, near_face, missed);
    const LaneMasks hit = ~missed & ~(t_near <= kMinimumHitT) & (near_face >= 0) & (t_near < t_max);
    for (int lane = 0; lane < 4; ++lane) {
      if (hit[lane]) row[x + lane] = {t_near[lane], index, static_cast<int32_t>(near_face[lane])};
    }
  }
}

void RowSurfaces::resize(size_t width) {
  for (auto* values : {&t, &x, &y, &z, &normal_x, &normal_y, &normal_z, &u, &v, &texture_offset}) {
    values->resize(width);
  }
  column.resize(width);
  texture.resize(width);
}

void RayCaster::rowSurfaces(int y, RowSurfaces& row) const {
  const int width = rays_.width;
  row.resize(static_cast<size_t>(width));
  const PixelHit* hits = &hits_[static_cast<size_t>(y) * width];
  // Ray::direction and SurfacePoint::position as hit() computes them, component by component.
  const Eigen::Vector3d row_start = rays_.rowStart(y);
  const Eigen::Vector3d& origin = rays_.origin;
  const Eigen::Vector3d& right = rays_.right;
  size_t count = 0;
  for (int begin = 0; begin < width;) {
    const int source = hits[begin].source;
    const int face = hits[begin].face;
    int end = begin + 1;
    while (end < width && hits[end].source == source && hits[end].face == face) ++end;
    for (int x = begin; x < end; ++x) row.t[x] = hits[x].t;
    if (source == kNothing) {
      begin = end;
      continue;
    }
    const size_t first = count;
    for (int x = begin; x < end; ++x, ++count) {
      const double t = hits[x].t;
      const double column = x;
      row.column[count] = x;
      row.x[count] = origin.x() + t * (row_start.x() + column * right.x());
      row.y[count] = origin.y() + t * (row_start.y() + column * right.y());
      row.z[count] = origin.z() + t * (row_start.z() + column * right.z());
    }
    const auto fill = [&](std::vector<double>& values, double value) {
      std::fill(values.begin() + first, values.begin() + count, value);
    };
    const auto setNormal = [&](double nx, double ny, double nz) {
      fill(row.normal_x, nx);
      fill(row.normal_y, ny);
      fill(row.normal_z, nz);
    };
    if (source == kFloor || source == kCeiling) {
      setNormal(0.0, 0.0, source == kFloor ? 1.0 : -1.0);
      std::copy(row.x.begin() + first, row.x.begin() + count, row.u.begin() + first);
      std::copy(row.y.begin() + first, row.y.begin() + count, row.v.begin() + first);
      std::fill(row.texture.begin() + first, row.texture.begin() + count,
                source == kFloor ? world_.floor_texture : world_.ceiling_texture);
      fill(row.texture_offset, 0.0);
      begin = end;
      continue;
    }
    // surfaceOfSolid (ray_intersection.h) with the face's branches taken once for the run.
    const Solid& hit_solid = solid(source);
    std::fill(row.texture.begin() + first, row.texture.begin() + count, hit_solid.texture);
    fill(row.texture_offset, hit_solid.texture_offset);
    if (face == kFaceTop || face == kFaceBottom) {
      setNormal(0.0, 0.0, face == kFaceTop ? 1.0 : -1.0);
      for (size_t i = first; i < count; ++i) {
        row.u[i] = row.x[i] - hit_solid.x;
        row.v[i] = row.y[i] - hit_solid.y;
      }
    } else if (hit_solid.shape == Solid::Shape::kCylinder) {
      fill(row.normal_z, 0.0);
      for (size_t i = first; i < count; ++i) {
        const double px = row.x[i] - hit_solid.x;
        const double py = row.y[i] - hit_solid.y;
        row.normal_x[i] = px / hit_solid.radius;
        row.normal_y[i] = py / hit_solid.radius;
        row.u[i] = hit_solid.radius * std::atan2(py, px);
        row.v[i] = row.z[i];
      }
    } else {
      // The face's outward normal, and u along the face: +-local_y on the x faces, -+local_x on
      // the y faces.
      const double cos_yaw = hit_solid.cos_yaw, sin_yaw = hit_solid.sin_yaw;
      const bool x_face = face == kFacePlusX || face == kFaceMinusX;
      const bool plus_face = face == kFacePlusX || face == kFacePlusY;
      if (x_face) {
        setNormal(plus_face ? cos_yaw : -cos_yaw, plus_face ? sin_yaw : -sin_yaw, plus_face ? 0.0 : -0.0);
      } else {
        setNormal(plus_face ? -sin_yaw : sin_yaw, plus_face ? cos_yaw : -cos_yaw, plus_face ? 0.0 : -0.0);
      }
      // u = sign * (x faces: local_y; y faces: local_x), local_* as surfaceOfSolid rotates them.
      const double sign = x_face == plus_face ? 1.0 : -1.0;
      const double along_x = x_face ? -sin_yaw : cos_yaw;
      const double along_y = x_face ? cos_yaw : sin_yaw;
      for (size_t i = first; i < count; ++i) {
        const double px = row.x[i] - hit_solid.x;
        const double py = row.y[i] - hit_solid.y;
        row.u[i] = sign * (along_x * px + along_y * py);
        row.v[i] = row.z[i];
      }
    }
    begin = end;
  }
  row.count = count;
}

void RayCaster::addSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d& top = a.y() <= b.y() ? a : b;
  const Eigen::Vector2d& bottom = a.y() <= b.y() ? b : a;
  // A row's span takes the segment's x over the rows either side of it: a pixel of margin.
  const int row_begin = static_cast<int>(std::max(0.0, std::ceil(top.y() - 1.0)));
  const int row_end = static_cast<int>(std::min(rays_.height - 1.0, std::floor(bottom.y() + 1.0)));
  if (row_begin > row_end) return;
  const double rise = bottom.y() - top.y();
  const double slope = rise > 1e-9 ? (bottom.x() - top.x()) / rise : 0.0;
  for (int y = row_begin; y <= row_end; ++y) {
    double x0 = top.x();
    double x1 = bottom.x();
    if (rise > 1e-9) {
      x0 = top.x() + slope * (std::max(top.y(), y - 1.0) - top.y());
      x1 = top.x() + slope * (std::min(bottom.y(), y + 1.0) - top.y());
    }
    span_begin_[y] = std::min(span_begin_[y], std::min(x0, x1));
    span_end_[y] = std::max(span_end_[y], std::max(x0, x1));
  }
  first_row_ = std::min(first_row_, row_begin);
  last_row_ = std::max(last_row_, row_end);
}

}  // namespace stereonav
