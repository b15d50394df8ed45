#include "occupancy_grid/disparity_tagged_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stereonav {

DisparityTaggedGrid::DisparityTaggedGrid(const GridLimits& limits, const OccupancyScale& scale)
    : scale_(scale) {
  reset(limits);
}

namespace {

// Cell boundaries sit on multiples of the resolution (as in MRPT's COccupancyGridMap2D, which
// snaps its limits the same way), so grids of equal resolution share cells. The tolerance keeps
// -10 / 0.05 = -200.0000001 on cell -200.
constexpr double kLatticeTolerance = 1e-6;

double latticeBelow(double coordinate, double resolution) {
  return std::floor(coordinate / resolution + kLatticeTolerance);
}
double latticeAbove(double coordinate, double resolution) {
  return std::ceil(coordinate / resolution - kLatticeTolerance);
}

}  // namespace

void DisparityTaggedGrid::reset(const GridLimits& limits) {
  const double r = limits.resolution;
  max_cells_ = limits.max_cells;
  reached_cell_limit_ = false;
  const double first_col = latticeBelow(limits.min_x, r);
  const double first_row = latticeBelow(limits.min_y, r);
  frame_ = {first_col * r, first_row * r, r};
  const double width = std::max(1.0, latticeAbove(limits.max_x, r) - first_col);
  const double height = std::max(1.0, latticeAbove(limits.max_y, r) - first_row);
  if (!(width * height <= static_cast<double>(limits.max_cells) && width < CellWindow::kIndexRange &&
        height < CellWindow::kIndexRange)) {
    throw std::invalid_argument("grid of " + std::to_string(width) + " x " + std::to_string(height) +
                                " cells exceeds max_cells");
  }
  width_ = static_cast<int>(width);
  height_ = static_cast<int>(height);
  occupancy_.assign(static_cast<size_t>(width_) * height_, scale_.unknown());
  tags_.assign(occupancy_.size(), kNoTag);
  close_free_.assign(occupancy_.size(), 0);
  written_ = {0, 0, 0, 0};
}

bool DisparityTaggedGrid::cellAt(double x, double y, int& col, int& row) const {
  const double u = std::floor((x - frame_.origin_x) / frame_.resolution);
  const double v = std::floor((y - frame_.origin_y) / frame_.resolution);
  if (!(u >= 0 && v >= 0 && u < width_ && v < height_)) return false;
  col = static_cast<int>(u);
  row = static_cast<int>(v);
  return true;
}

void DisparityTaggedGrid::growToInclude(const WorldBounds& bounds, double margin_m) {
  const double r = frame_.resolution;
  // Whole cells wanted on each side (zero when the bounds are already inside), in double: bounds
  // from far readings can be kilometres away.
  // No side can usefully grow by more than max_cells, which keeps the scale below in range.
  const auto cells = [&](double outside_by) {
    return outside_by > 0.0 ? std::min(std::ceil((outside_by + margin_m) / r), static_cast<double>(max_cells_)) : 0.0;
  };
  double grow_left = cells(minX() - bounds.min_x);
  double grow_right = cells(bounds.max_x - maxX());
  double grow_down = cells(minY() - bounds.min_y);
  double grow_up = cells(bounds.max_y - maxY());
  if (!(grow_left + grow_right + grow_down + grow_up > 0.0)) return;
  // Bounded by max_cells: the growth on every side is scaled down by the largest factor that
  // fits (found by bisection); regions beyond the capped grid are clipped by the rasteriser.
  const auto fits = [&](double scale) {
    const double w = width_ + std::floor(scale * grow_left) + std::floor(scale * grow_right);
    const double h = height_ + std::floor(scale * grow_down) + std::floor(scale * grow_up);
    return w * h <= static_cast<double>(max_cells_) && w < CellWindow::kIndexRange &&
           h < CellWindow::kIndexRange;
  };
  if (!fits(1.0)) {
    reached_cell_limit_ = true;
    double low = 0.0, high = 1.0;
    for (int i = 0; i < 60; ++i) {
      const double middle = 0.5 * (low + high);
      (fits(middle) ? low : high) = middle;
    }
    grow_left = std::floor(low * grow_left);
    grow_right = std::floor(low * grow_right);
    grow_down = std::floor(low * grow_down);
    grow_up = std::floor(low * grow_up);
    if (grow_left + grow_right + grow_down + grow_up == 0.0) return;
  }
  const int new_width = width_ + static_cast<int>(grow_left) + static_cast<int>(grow_right);
  const int new_height = height_ + static_cast<int>(grow_down) + static_cast<int>(grow_up);
  std::vector<uint8_t> occupancy(static_cast<size_t>(new_width) * new_height, scale_.unknown());
  std::vector<float> tags(occupancy.size(), kNoTag);
  std::vector<uint8_t> close_free(occupancy.size(), 0);
  for (int row = 0; row < height_; ++row) {
    const size_t to = static_cast<size_t>(row + grow_down) * new_width + static_cast<size_t>(grow_left);
    const size_t from = index(0, row);
    std::copy_n(occupancy_.begin() + from, width_, occupancy.begin() + to);
    std::copy_n(tags_.begin() + from, width_, tags.begin() + to);
    std::copy_n(close_free_.begin() + from, width_, close_free.begin() + to);
  }
  if (written_.col_begin < written_.col_end) {
    const int right = static_cast<int>(grow_left), up = static_cast<int>(grow_down);
    written_ = {written_.col_begin + right, written_.col_end + right, written_.row_begin + up, written_.row_end + up};
  }
  frame_.origin_x -= grow_left * r;
  frame_.origin_y -= grow_down * r;
  width_ = new_width;
  height_ = new_height;
  occupancy_ = std::move(occupancy);
  tags_ = std::move(tags);
  close_free_ = std::move(close_free);
}

void DisparityTaggedGrid::assign(const GridFrame& frame, int width, int height,
                                 std::vector<uint8_t> occupancy, std::vector<float> tags,
                                 std::vector<uint8_t> close_free) {
  const size_t cells = static_cast<size_t>(width) * static_cast<size_t>(height);
  if (width <= 0 || height <= 0 || occupancy.size() != cells || tags.size() != cells ||
      close_free.size() != cells) {
    throw std::invalid_argument("DisparityTaggedGrid::assign: layer sizes do not match the grid");
  }
  frame_ = frame;
  width_ = width;
  height_ = height;
  occupancy_ = std::move(occupancy);
  tags_ = std::move(tags);
  close_free_ = std::move(close_free);
  written_ = {0, width_, 0, height_};
}

}  // namespace stereonav
