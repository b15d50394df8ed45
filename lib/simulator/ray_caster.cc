#include "simulator/ray_caster.h"

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

// Whether the ray's floor projection (as an infinite line) comes within the solid's bounding
// radius: a cheap rejection before the exact test.
bool floorProjectionPasses(const Solid& solid, const Ray& ray) {
  const double px = solid.x - ray.origin.x();
  const double py = solid.y - ray.origin.y();
  const double dx = ray.direction.x();
  const double dy = ray.direction.y();
  const double cross = px * dy - py * dx;
  const double radius_squared = solid.shape == Solid::Shape::kBox
                                    ? solid.half_x * solid.half_x + solid.half_y * solid.half_y
                                    : solid.radius * solid.radius;
  return cross * cross <= radius_squared * (dx * dx + dy * dy);
}

// Rounding at cell borders must never drop a solid from a cell its surface reaches.
constexpr double kCellPadding = 1e-6;
constexpr int kMaxCellsPerAxis = 1024;

}  // namespace

RayCaster::RayCaster(const World& world, double cell_size_m)
    : world_(world), cell_size_(cell_size_m), tested_by_ray_(world.solids.size(), 0) {
  if (world.solids.empty()) return;
  FloorExtent all = world.solids.front().floorExtent();
  solids_top_z_ = world.solids.front().z_max;
  for (const auto& solid : world.solids) {
    const FloorExtent e = solid.floorExtent();
    all = {std::min(all.x_min, e.x_min), std::min(all.y_min, e.y_min), std::max(all.x_max, e.x_max),
           std::max(all.y_max, e.y_max)};
    solids_top_z_ = std::max(solids_top_z_, solid.z_max);
  }
  const double span = std::max(all.x_max - all.x_min, all.y_max - all.y_min);
  cell_size_ = std::max(cell_size_, span / kMaxCellsPerAxis);
  grid_x_min_ = all.x_min - kCellPadding;
  grid_y_min_ = all.y_min - kCellPadding;
  cells_x_ = static_cast<int>(std::ceil((all.x_max - all.x_min + 2 * kCellPadding) / cell_size_));
  cells_y_ = static_cast<int>(std::ceil((all.y_max - all.y_min + 2 * kCellPadding) / cell_size_));
  cells_x_ = std::max(cells_x_, 1);
  cells_y_ = std::max(cells_y_, 1);

  std::vector<std::vector<int>> per_cell(static_cast<size_t>(cells_x_) * cells_y_);
  const auto cellIndex = [&](double coordinate, double origin, int count) {
    return std::clamp(static_cast<int>(std::floor((coordinate - origin) / cell_size_)), 0, count - 1);
  };
  for (size_t i = 0; i < world.solids.size(); ++i) {
    const FloorExtent e = world.solids[i].floorExtent();
    const int x0 = cellIndex(e.x_min - kCellPadding, grid_x_min_, cells_x_);
    const int x1 = cellIndex(e.x_max + kCellPadding, grid_x_min_, cells_x_);
    const int y0 = cellIndex(e.y_min - kCellPadding, grid_y_min_, cells_y_);
    const int y1 = cellIndex(e.y_max + kCellPadding, grid_y_min_, cells_y_);
    for (int cy = y0; cy <= y1; ++cy) {
      for (int cx = x0; cx <= x1; ++cx) per_cell[static_cast<size_t>(cy) * cells_x_ + cx].push_back(static_cast<int>(i));
    }
  }
  cell_begin_.reserve(per_cell.size() + 1);
  cell_begin_.push_back(0);
  for (const auto& cell : per_cell) {
    cell_solids_.insert(cell_solids_.end(), cell.begin(), cell.end());
    cell_begin_.push_back(static_cast<int>(cell_solids_.size()));
  }
}

RayHit RayCaster::cast(const Ray& ray, double t_max) {
  enum class Source { kNothing, kFloor, kCeiling, kStatic, kMoving };
  Source source = Source::kNothing;
  double best_t = t_max;
  int best_solid = -1;
  int best_face = 0;

  if (ray.origin.z() > 0.0) {
    const double t = intersectHorizontalPlane(0.0, ray, best_t);
    if (t < best_t) {
      best_t = t;
      source = Source::kFloor;
    }
  }
  if (world_.ceiling_height > 0.0 && ray.origin.z() < world_.ceiling_height) {
    const double t = intersectHorizontalPlane(world_.ceiling_height, ray, best_t);
    if (t < best_t) {
      best_t = t;
      source = Source::kCeiling;
    }
  }
  int moving_solid = -1;
  for (size_t i = 0; i < moving_.size(); ++i) {
    if (!floorProjectionPasses(moving_[i], ray)) continue;
    int face = 0;
    const double t = intersectSolid(moving_[i], ray, best_t, &face);
    if (t < best_t) {
      best_t = t;
      moving_solid = static_cast<int>(i);
      best_face = face;
      source = Source::kMoving;
    }
  }
  castThroughGrid(ray, &best_t, &best_solid, &best_face);
  if (best_solid >= 0) source = Source::kStatic;

  RayHit hit;
  hit.t = best_t;
  switch (source) {
    case Source::kNothing:
      hit.t = kNoHit;
      break;
    case Source::kFloor:
    case Source::kCeiling: {
      hit.surface.position = ray.origin + best_t * ray.direction;
      hit.surface.normal = Eigen::Vector3d(0.0, 0.0, source == Source::kFloor ? 1.0 : -1.0);
      hit.surface.u = hit.surface.position.x();
      hit.surface.v = hit.surface.position.y();
      hit.texture = source == Source::kFloor ? world_.floor_texture : world_.ceiling_texture;
      break;
    }
    case Source::kStatic:
      hit.surface = surfaceOfSolid(world_.solids[best_solid], best_face, ray, best_t);
      hit.texture = world_.solids[best_solid].texture;
      hit.texture_offset = world_.solids[best_solid].texture_offset;
      break;
    case Source::kMoving:
      hit.surface = surfaceOfSolid(moving_[moving_solid], best_face, ray, best_t);
      hit.texture = moving_[moving_solid].texture;
      hit.texture_offset = moving_[moving_solid].texture_offset;
      break;
  }
  return hit;
}

namespace {

// Narrows [t_begin, t_end] to where origin + t * direction lies in [low, high]; false when empty.
bool clipToSlab(double origin, double direction, double inverse, double low, double high, double& t_begin,
                double& t_end) {
  if (direction == 0.0) return origin >= low && origin <= high;
  double ta = (low - origin) * inverse;
  double tb = (high - origin) * inverse;
  if (ta > tb) std::swap(ta, tb);
  t_begin = std::max(t_begin, ta);
  t_end = std::min(t_end, tb);
  return t_begin <= t_end;
}

}  // namespace

void RayCaster::castThroughGrid(const Ray& ray, double* best_t, int* best_solid, int* best_face) {
  if (cells_x_ == 0) return;
  const double ox = ray.origin.x();
  const double oy = ray.origin.y();
  const double dx = ray.direction.x();
  const double dy = ray.direction.y();
  const double dz = ray.direction.z();
  // Above every solid and rising: nothing to meet.
  double t_end = *best_t;
  if (dz > 0.0) {
    if (ray.origin.z() >= solids_top_z_) return;
    t_end = std::min(t_end, (solids_top_z_ - ray.origin.z()) / dz);
  }
  // Clip the ray's floor projection to the grid. Divisions are few: this runs once per pixel.
  const double inverse_dx = dx != 0.0 ? 1.0 / dx : 0.0;
  const double inverse_dy = dy != 0.0 ? 1.0 / dy : 0.0;
  double t_begin = 0.0;
  if (!clipToSlab(ox, dx, inverse_dx, grid_x_min_, grid_x_min_ + cells_x_ * cell_size_, t_begin, t_end) ||
      !clipToSlab(oy, dy, inverse_dy, grid_y_min_, grid_y_min_ + cells_y_ * cell_size_, t_begin, t_end)) {
    return;
  }

  // The entry point is inside the grid (or on its border), so truncation is the floor here.
  const double inverse_cell = 1.0 / cell_size_;
  int ix = std::clamp(static_cast<int>((ox + dx * t_begin - grid_x_min_) * inverse_cell), 0, cells_x_ - 1);
  int iy = std::clamp(static_cast<int>((oy + dy * t_begin - grid_y_min_) * inverse_cell), 0, cells_y_ - 1);
  const int step_x = dx > 0.0 ? 1 : -1;
  const int step_y = dy > 0.0 ? 1 : -1;
  const double t_delta_x = dx != 0.0 ? cell_size_ * std::abs(inverse_dx) : kNoHit;
  const double t_delta_y = dy != 0.0 ? cell_size_ * std::abs(inverse_dy) : kNoHit;
  double t_next_x = dx != 0.0 ? (grid_x_min_ + (ix + (dx > 0.0)) * cell_size_ - ox) * inverse_dx : kNoHit;
  double t_next_y = dy != 0.0 ? (grid_y_min_ + (iy + (dy > 0.0)) * cell_size_ - oy) * inverse_dy : kNoHit;

  if (++ray_number_ == 0) {
    std::fill(tested_by_ray_.begin(), tested_by_ray_.end(), 0);
    ray_number_ = 1;
  }
  while (true) {
    const int cell = iy * cells_x_ + ix;
    for (int k = cell_begin_[cell]; k < cell_begin_[cell + 1]; ++k) {
      const int index = cell_solids_[k];
      if (tested_by_ray_[index] == ray_number_) continue;
      tested_by_ray_[index] = ray_number_;
      int face = 0;
      const double t = intersectSolid(world_.solids[index], ray, *best_t, &face);
      if (t < *best_t) {
        *best_t = t;
        *best_solid = index;
        *best_face = face;
      }
    }
    const double cell_exit = std::min(t_next_x, t_next_y);
    if (*best_t <= cell_exit || cell_exit > t_end) return;
    if (t_next_x < t_next_y) {
      ix += step_x;
      if (ix < 0 || ix >= cells_x_) return;
      t_next_x += t_delta_x;
    } else {
      iy += step_y;
      if (iy < 0 || iy >= cells_y_) return;
      t_next_y += t_delta_y;
    }
  }
}

}  // namespace stereonav
