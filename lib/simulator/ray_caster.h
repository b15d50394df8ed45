#pragma once

#include <cstdint>
#include <vector>

#include "simulator/ray_intersection.h"
#include "simulator/world.h"

namespace stereonav {

// The nearest surface a ray meets, and what it is.
struct RayHit {
  double t = kNoHit;
  SurfacePoint surface;
  int texture = 0;
  double texture_offset = 0.0;  // Solid::texture_offset of the surface hit
};

// Finds the first surface along rays through a World: the floor, the optional ceiling, static
// solids through a uniform 2D grid on the floor plane (a ray visits only the cells its floor
// projection crosses, nearest first, and stops once a hit is closer than the next cell), and the
// few moving obstacles directly.
class RayCaster {
 public:
  explicit RayCaster(const World& world, double cell_size_m = 0.5);

  // The moving obstacles where they are now (MovingTraffic::solids).
  void setMovingSolids(const std::vector<Solid>& moving_solids) { moving_ = moving_solids; }

  // The nearest hit with t in (0, t_max), or t = kNoHit.
  RayHit cast(const Ray& ray, double t_max = kNoHit);

 private:
  void castThroughGrid(const Ray& ray, double* best_t, int* best_solid, int* best_face);

  const World& world_;
  std::vector<Solid> moving_;
  double cell_size_;
  double grid_x_min_ = 0.0;
  double grid_y_min_ = 0.0;
  int cells_x_ = 0;
  int cells_y_ = 0;
  double solids_top_z_ = 0.0;
  // Compressed rows: the solids of cell c are cell_solids_[cell_begin_[c] .. cell_begin_[c+1]).
  std::vector<int> cell_begin_;
  std::vector<int> cell_solids_;
  // A solid spanning several cells is tested once per ray: it is stamped with the ray's number.
  std::vector<uint32_t> tested_by_ray_;
  uint32_t ray_number_ = 0;
};

}  // namespace stereonav
