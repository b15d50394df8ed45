#include "explorer/navigation_grid.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace stereonav {
namespace {

// Metres from each cell centre in `window` to the near edge of the nearest cell whose class is
// not below `clear_below`, -half a cell outside the window (as at a blocked cell). The cells
// around the window count as blocked, as does the grid's border, so nothing plans off the map.
cv::Mat1f distanceToBlocked(const cv::Mat1b& classes, uint8_t clear_below, const cv::Rect& window,
                            double resolution) {
  const double cell_m = static_cast<float>(resolution);
  cv::Mat1f metres(classes.size(), static_cast<float>(-0.5 * cell_m));
  if (!window.empty()) {
    cv::Mat1b padded;
    cv::copyMakeBorder(classes(window) < clear_below, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::Mat1f cells;
    cv::distanceTransform(padded, cells, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    cells(cv::Rect(1, 1, window.width, window.height)).convertTo(metres(window), CV_32F, cell_m, -0.5 * cell_m);
  }
  return metres;
}

// One row's cells from `first` to `end` of the map classified (`classes`) and marked sure
// obstacles or not (`sure`), through restrict pointers so that the loop runs many cells at a
// time: a table's loads, a branch on the occupied class and the reloads of a bound the byte
// stores might alias took about 3% of an office's exploration, cell by cell. Built for AVX2 as
// well (chosen at load time).
__attribute__((target_clones("avx2", "default")))
void classifyRow(const uint8_t* __restrict g, const float* __restrict tag, int first, int end, OccupancyScale scale,
                 int sure_obstacle_g, float precise_min_disparity, uint8_t* __restrict classes,
                 uint8_t* __restrict sure) {
  for (int col = first; col < end; ++col) {
    const CellClass cell_class = scale.classify(g[col]);
    const bool imprecise = tag[col] != DisparityTaggedGrid::kNoTag && tag[col] < precise_min_disparity;
    const uint8_t occupied_class = imprecise ? NavigationGrid::kImprecise : NavigationGrid::kOccupied;
    classes[col] = cell_class == CellClass::kFree      ? NavigationGrid::kFree
                   : cell_class == CellClass::kOccupied ? occupied_class
                                                        : NavigationGrid::kUnknown;
    sure[col] = g[col] >= sure_obstacle_g ? 1 : 0;
  }
}

// `box` grown by `cells` on every side, within a grid of `size`; empty if `box` is.
cv::Rect grownInside(const cv::Rect& box, int cells, const cv::Size& size) {
  if (box.empty()) return cv::Rect();
  return (box - cv::Point(cells, cells) + cv::Size(2 * cells, 2 * cells)) & cv::Rect(cv::Point(), size);
}

}  // namespace

NavigationGrid::NavigationGrid(const DisparityTaggedGrid& grid, const std::vector<mrpt::poses::CPose2D>& visited,
                               const NavigationGridOptions& options, const std::vector<cv::Point2d>& contacts,
                               const std::vector<cv::Point2d>& seen_free, std::unique_ptr<NavigationGrid> previous)
    : frame_(grid.frame()),
      distance_horizon_m_(options.distance_horizon_m),
      body_radius_m_(options.body_radius_m),
      cell_class_(grid.height(), grid.width()),
      sure_obstacle_(grid.height(), grid.width()) {
  const bool same_cells = previous != nullptr && previous->cell_class_.size() == cell_class_.size() &&
                          previous->frame_.origin_x == frame_.origin_x && previous->frame_.origin_y == frame_.origin_y &&
                          previous->frame_.resolution == frame_.resolution;
  // Cells the map never wrote are unknown and no sure obstacle: only its written cells are
  // classified, and the cells stamped below widen the box of resolved cells.
  cell_class_.setTo(kUnknown);
  sure_obstacle_.setTo(0);
  const CellWindow& written = grid.writtenCells();
  const OccupancyScale& scale = grid.scale();
  for (int row = written.row_begin; row < written.row_end; ++row) {
    classifyRow(grid.occupancyRow(row), grid.tagRow(row), written.col_begin, written.col_end, scale,
                options.sure_obstacle_g, options.precise_min_disparity, cell_class_[row], sure_obstacle_[row]);
  }
  resolved_cells_ = cv::Rect(written.col_begin, written.row_begin, written.col_end - written.col_begin,
                             written.row_end - written.row_begin);
  // The cells seen free and under the body that the previous grid drew are kept; only the points
  // added since are drawn.
  if (same_cells && previous->body_radius_m_ == body_radius_m_ && previous->seen_free_points_ <= seen_free.size() &&
      previous->body_positions_ <= visited.size()) {
    stamps_ = std::move(previous->stamps_);
    stamps_box_ = previous->stamps_box_;
    seen_free_points_ = previous->seen_free_points_;
    body_positions_ = previous->body_positions_;
  } else {
    stamps_ = cv::Mat1b::zeros(cell_class_.size());
  }
  for (; seen_free_points_ < seen_free.size(); ++seen_free_points_) {
    const cv::Point2d& point = seen_free[seen_free_points_];
    int col = 0, row = 0;
    if (!cellAt(point.x, point.y, col, row)) continue;
    stamps_(row, col) |= kSeenFreeStamp;
    stamps_box_ |= cv::Rect(col, row, 1, 1);
  }
  const int reach = static_cast<int>(std::ceil(body_radius_m_ / frame_.resolution));
  for (; body_positions_ < visited.size(); ++body_positions_) {
    const mrpt::poses::CPose2D& pose = visited[body_positions_];
    int centre_col = 0, centre_row = 0;
    if (!cellAt(pose.x(), pose.y(), centre_col, centre_row)) continue;
    const int first_col = std::max(0, centre_col - reach), last_col = std::min(width() - 1, centre_col + reach);
    const int first_row = std::max(0, centre_row - reach), last_row = std::min(height() - 1, centre_row + reach);
    for (int row = first_row; row <= last_row; ++row) {
      uint8_t* stamps = stamps_[row];
      for (int col = first_col; col <= last_col; ++col) {
        if (std::hypot(centreX(col) - pose.x(), centreY(row) - pose.y()) <= body_radius_m_) stamps[col] |= kBodyStamp;
      }
    }
    stamps_box_ |= cv::Rect(first_col, first_row, last_col - first_col + 1, last_row - first_row + 1);
  }
  // Seen free unless the map holds a precise obstacle; then free under the body if unknown.
  for (int row = stamps_box_.y; row < stamps_box_.y + stamps_box_.height; ++row) {
    const uint8_t* stamps = stamps_[row];
    uint8_t* classes = cell_class_[row];
    for (int col = stamps_box_.x; col < stamps_box_.x + stamps_box_.width; ++col) {
      uint8_t cell_class = classes[col];
      cell_class = (stamps[col] & kSeenFreeStamp) != 0 && cell_class != kOccupied ? kFree : cell_class;
      cell_class = (stamps[col] & kBodyStamp) != 0 && cell_class == kUnknown ? kFree : cell_class;
      classes[col] = cell_class;
    }
  }
  resolved_cells_ |= stamps_box_;
  for (const cv::Point2d& contact : contacts) {
    int col = 0, row = 0;
    if (cellAt(contact.x, contact.y, col, row)) {
      cell_class_(row, col) = kOccupied;
      resolved_cells_ |= cv::Rect(col, row, 1, 1);
    }
  }
  if (!resolved_cells_.empty()) {
    const cv::Rect free_cells = cv::boundingRect(cell_class_(resolved_cells_) == kFree);
    if (!free_cells.empty()) free_cells_ = free_cells + resolved_cells_.tl();
  }
  if (options.max_hole_cells > 0) freeIslands(kUnknown, kUnknown, 4, options.max_hole_cells);
  if (same_cells && previous->distance_horizon_m_ == distance_horizon_m_ && horizonCells() > 0) {
    clearance_m_ = std::move(previous->clearance_m_);
    obstacle_distance_m_ = std::move(previous->obstacle_distance_m_);
    updateDistances(previous->cell_class_, previous->resolved_cells_);
  } else {
    computeDistances();
  }
}

void NavigationGrid::freeSpecks(int max_cells, const std::vector<cv::Point2d>& keep) {
  const cv::Mat1b classes_before = cell_class_.clone();
  std::vector<cv::Point> kept_cells;
  for (const cv::Point2d& point : keep) {
    int col = 0, row = 0;
    if (cellAt(point.x, point.y, col, row)) kept_cells.emplace_back(col, row);
  }
  freeIslands(kImprecise, kOccupied, 8, max_cells, kept_cells);
  if (horizonCells() > 0) {
    updateDistances(classes_before, resolved_cells_);
  } else {
    computeDistances();
  }
}

int NavigationGrid::horizonCells() const {
  return std::isfinite(distance_horizon_m_) ? static_cast<int>(std::ceil(distance_horizon_m_ / frame_.resolution)) : 0;
}

void NavigationGrid::computeDistances() {
  // Only over the free cells' bounding box, whose blocked ring is no nearer than a cell's nearest
  // blocked cell: the free floor is often a small part of a map that far readings have stretched.
  clearance_m_ = distanceToBlocked(cell_class_, kUnknown, free_cells_, frame_.resolution);
  // Obstacle distances are wanted at free cells and up to the horizon only, so the box grows by
  // the horizon: a nearer obstacle lies inside it, and its ring is farther than the horizon.
  const int reach = horizonCells() > 0 ? horizonCells() : std::max(width(), height());
  const cv::Rect near_free = grownInside(free_cells_, reach, cell_class_.size());
  obstacle_distance_m_ = distanceToBlocked(cell_class_, kImprecise, near_free, frame_.resolution);
}

void NavigationGrid::updateDistances(const cv::Mat1b& classes_before, const cv::Rect& resolved_before) {
  // A cell farther than the horizon from every changed cell keeps its distances: a nearer
  // blocked cell it had is still there, and any new one is beyond the horizon. The cells within
  // it are taken again in a window grown by the horizon once more, so that their nearer blocked
  // cells lie inside and its blocked ring lies beyond the horizon.
  // Outside both grids' resolved cells every cell is unknown in both.
  const cv::Rect compared = resolved_cells_ | resolved_before;
  if (compared.empty()) return;
  const cv::Rect changed = cv::boundingRect(cell_class_(compared) != classes_before(compared)) + compared.tl();
  if (changed.empty()) return;
  const int reach = horizonCells();
  const cv::Rect updated = grownInside(changed, reach, cell_class_.size());
  const cv::Rect window = grownInside(changed, 2 * reach, cell_class_.size());
  const cv::Rect in_window = updated - window.tl();
  distanceToBlocked(cell_class_(window), kUnknown, cv::Rect(cv::Point(), window.size()), frame_.resolution)(in_window)
      .copyTo(clearance_m_(updated));
  distanceToBlocked(cell_class_(window), kImprecise, cv::Rect(cv::Point(), window.size()), frame_.resolution)(in_window)
      .copyTo(obstacle_distance_m_(updated));
}

void NavigationGrid::freeIslands(uint8_t lowest_class, uint8_t highest_class, int connectivity, int max_cells,
                                 const std::vector<cv::Point>& kept_cells) {
  // An island borders free cells only, so it lies inside the free cells' bounding box, and a
  // region that reaches the box's edge is none (its neighbour beyond is not free): only the box
  // is labelled, and freeing islands leaves the box as it was.
  const cv::Rect& box = free_cells_;
  if (box.empty()) return;
  cv::Mat1b is_island;
  cv::inRange(cell_class_(box), lowest_class, highest_class, is_island);
  cv::Mat1i labels;
  const int count = cv::connectedComponents(is_island, labels, connectivity, CV_32S);
  // Per label its area and the box of its cells: only the islands' boxes are looked at again.
  std::vector<int> areas(static_cast<size_t>(count), 0);
  std::vector<cv::Rect> extents(static_cast<size_t>(count));
  for (int row = 0; row < box.height; ++row) {
    const int* label_row = labels[row];
    // Run by run of one label: a count per cell would wait on the store before it.
    for (int col = 0; col < box.width;) {
      const int label = label_row[col];
      int end = col + 1;
      while (end < box.width && label_row[end] == label) ++end;
      areas[label] += end - col;
      extents[label] |= cv::Rect(col, row, end - col, 1);
      col = end;
    }
  }
  std::vector<uint8_t> frees(static_cast<size_t>(count), 0);
  for (int label = 1; label < count; ++label) frees[label] = areas[label] <= max_cells;
  for (const cv::Point& cell : kept_cells) {
    if (box.contains(cell)) frees[labels(cell.y - box.y, cell.x - box.x)] = 0;
  }
  static const int kNeighbours[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  cv::Mat1b classes = cell_class_(box);  // a view: the islands are freed through it
  for (int label = 1; label < count; ++label) {
    if (!frees[label]) continue;
    const cv::Rect& extent = extents[label];
    for (int row = extent.y; row < extent.y + extent.height && frees[label]; ++row) {
      for (int col = extent.x; col < extent.x + extent.width; ++col) {
        if (labels(row, col) != label) continue;
        for (int i = 0; i < connectivity; ++i) {
          const int c = col + kNeighbours[i][0], r = row + kNeighbours[i][1];
          const bool inside = c >= 0 && r >= 0 && c < box.width && r < box.height;
          if (!inside || (classes(r, c) != kFree && labels(r, c) != label)) frees[label] = 0;
        }
      }
    }
  }
  for (int label = 1; label < count; ++label) {
    if (!frees[label]) continue;
    const cv::Rect& extent = extents[label];
    for (int row = extent.y; row < extent.y + extent.height; ++row) {
      for (int col = extent.x; col < extent.x + extent.width; ++col) {
        if (labels(row, col) == label) classes(row, col) = kFree;
      }
    }
  }
}

bool NavigationGrid::mapHoldsObstacle(double x, double y) const {
  int col = 0, row = 0;
  return cellAt(x, y, col, row) && sure_obstacle_(row, col) != 0;
}

double NavigationGrid::clearanceAt(double x, double y, double search_m) const {
  int centre_col = 0, centre_row = 0;
  cellAt(x, y, centre_col, centre_row);
  const int reach = static_cast<int>(std::ceil(search_m / frame_.resolution)) + 1;
  const double half = 0.5 * frame_.resolution;
  double nearest = search_m;
  for (int row = centre_row - reach; row <= centre_row + reach; ++row) {
    for (int col = centre_col - reach; col <= centre_col + reach; ++col) {
      if (contains(col, row) && cell_class_(row, col) == kFree) continue;
      const double dx = std::max(0.0, std::abs(x - centreX(col)) - half);
      const double dy = std::max(0.0, std::abs(y - centreY(row)) - half);
      nearest = std::min(nearest, std::hypot(dx, dy));
    }
  }
  return nearest;
}

}  // namespace stereonav
