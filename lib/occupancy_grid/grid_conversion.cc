#include "occupancy_grid/grid_conversion.h"

#include <stdexcept>

namespace stereonav {

mrpt::maps::COccupancyGridMap2D toMrptOccupancyGrid(const DisparityTaggedGrid& grid) {
  mrpt::maps::COccupancyGridMap2D mrpt_grid;
  // MRPT snaps its limits to multiples of the resolution, as DisparityTaggedGrid does, so the
  // cell indices coincide.
  mrpt_grid.setSize(static_cast<float>(grid.minX()), static_cast<float>(grid.maxX()),
                    static_cast<float>(grid.minY()), static_cast<float>(grid.maxY()),
                    static_cast<float>(grid.resolution()));
  if (static_cast<int>(mrpt_grid.getSizeX()) != grid.width() ||
      static_cast<int>(mrpt_grid.getSizeY()) != grid.height()) {
    throw std::logic_error("toMrptOccupancyGrid: MRPT grid size differs from ours");
  }
  for (int row = 0; row < grid.height(); ++row) {
    const uint8_t* occupancy = grid.occupancyRow(row);
    for (int col = 0; col < grid.width(); ++col) {
      mrpt_grid.setCell(col, row,
                        static_cast<float>(1.0 - OccupancyScale::occupiedProbability(occupancy[col])));
    }
  }
  return mrpt_grid;
}

}  // namespace stereonav
