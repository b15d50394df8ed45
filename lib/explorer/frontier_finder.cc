#include "explorer/frontier_finder.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace stereonav {
namespace {

// Unresolved (unknown or imprecise) cells that form a thin seam along an obstacle the map has
// pinned down are not an opening: a wall's cells eroded by grazing rays, the band between a wall
// and the region of uncertainty of its far readings. Looking again does not open them, and as
// far views keep redrawing such bands the robot would tour finished rooms. A seam: a connected
// region of unresolved cells each of which has a resolved cell among its 8 neighbours (none is
// farther than 1.5 cells from one), touching a precise obstacle.
//
// Per cell: the label of the unresolved region of an opening it is in, 0 otherwise (resolved, or
// in a seam); `areas` gets each label's cell count.
cv::Mat1i openingRegions(const NavigationGrid& grid, std::vector<int>& areas) {
  const cv::Mat1b& classes = grid.cellClasses();
  const cv::Mat1b unresolved = (classes == NavigationGrid::kUnknown) | (classes == NavigationGrid::kImprecise);
  cv::Mat1i labels;
  cv::Mat stats, centroids;
  const int count = cv::connectedComponentsWithStats(unresolved, labels, stats, centroids, 8, CV_32S);
  areas.assign(static_cast<size_t>(count), 0);
  for (int label = 1; label < count; ++label) areas[label] = stats.at<int>(label, cv::CC_STAT_AREA);
  // The cells with no resolved 8-neighbour (the grid's edge does not count as resolved), and
  // those with a precise obstacle among their 8 neighbours (nothing beyond the edge).
  cv::Mat1b interior, beside_obstacle;
  cv::erode(unresolved, interior, cv::Mat());
  cv::dilate(classes == NavigationGrid::kOccupied, beside_obstacle, cv::Mat());
  std::vector<uint8_t> thin(static_cast<size_t>(count), 1), touches_obstacle(static_cast<size_t>(count), 0);
  for (int row = 0; row < classes.rows; ++row) {
    const int* label_row = labels[row];
    const uint8_t* interior_row = interior[row];
    const uint8_t* beside_row = beside_obstacle[row];
    for (int col = 0; col < classes.cols; ++col) {
      const int label = label_row[col];
      if (interior_row[col]) thin[label] = 0;
      if (beside_row[col]) touches_obstacle[label] = 1;
    }
  }
  for (int row = 0; row < classes.rows; ++row) {
    for (int col = 0; col < classes.cols; ++col) {
      const int label = labels(row, col);
      if (label != 0 && thin[label] && touches_obstacle[label]) labels(row, col) = 0;
    }
  }
  return labels;
}

// What a free cell borders through its 4-neighbours: the largest area (cells) of the opening
// regions among them (0 if none: then it is no frontier cell), and whether one of them is an
// unknown cell rather than an obstacle seen from far.
struct OpeningBorder {
  int area = 0;
  bool unknown = false;
};

OpeningBorder openingBorder(const NavigationGrid& grid, const cv::Mat1i& regions, const std::vector<int>& areas,
                            int col, int row) {
  OpeningBorder border;
  if (grid.cellClass(col, row) != NavigationGrid::kFree) return border;
  static const int kNeighbours[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& offset : kNeighbours) {
    const int c = col + offset[0], r = row + offset[1];
    if (!grid.contains(c, r) || regions(r, c) == 0) continue;
    border.area = std::max(border.area, areas[static_cast<size_t>(regions(r, c))]);
    border.unknown = border.unknown || grid.cellClass(c, r) == NavigationGrid::kUnknown;
  }
  return border;
}

}  // namespace

std::vector<Frontier> findFrontiers(const NavigationGrid& grid, int min_cells) {
  std::vector<int> areas;
  const cv::Mat1i regions = openingRegions(grid, areas);
  // Per cell: the area it borders (0 if it is no frontier cell) and whether it faces unknown.
  // Only free cells border anything.
  cv::Mat1i bordered(grid.height(), grid.width(), 0);
  cv::Mat1b faces_unknown(grid.height(), grid.width(), uint8_t{0});
  const cv::Rect free_cells = cv::boundingRect(grid.cellClasses() == NavigationGrid::kFree);
  for (int row = free_cells.y; row < free_cells.y + free_cells.height; ++row) {
    for (int col = free_cells.x; col < free_cells.x + free_cells.width; ++col) {
      const OpeningBorder border = openingBorder(grid, regions, areas, col, row);
      bordered(row, col) = border.area;
      faces_unknown(row, col) = border.unknown;
    }
  }
  cv::Mat1b is_frontier = bordered > 0;
  const double cell_area = grid.resolution() * grid.resolution();
  std::vector<Frontier> frontiers;
  std::vector<cv::Point> stack;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (!is_frontier(row, col)) continue;
      Frontier frontier;
      is_frontier(row, col) = 0;
      stack.assign(1, cv::Point(col, row));
      while (!stack.empty()) {
        const cv::Point cell = stack.back();
        stack.pop_back();
        frontier.cells.push_back(cell);
        frontier.unseen_area_m2 = std::max(frontier.unseen_area_m2, bordered(cell.y, cell.x) * cell_area);
        frontier.borders_unknown = frontier.borders_unknown || faces_unknown(cell.y, cell.x);
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const int c = cell.x + dc, r = cell.y + dr;
            if (grid.contains(c, r) && is_frontier(r, c)) {
              is_frontier(r, c) = 0;
              stack.emplace_back(c, r);
            }
          }
        }
      }
      if (static_cast<int>(frontier.cells.size()) < min_cells) continue;
      for (const cv::Point& cell : frontier.cells) {
        frontier.centroid_x += grid.centreX(cell.x);
        frontier.centroid_y += grid.centreY(cell.y);
      }
      frontier.centroid_x /= static_cast<double>(frontier.cells.size());
      frontier.centroid_y /= static_cast<double>(frontier.cells.size());
      frontiers.push_back(std::move(frontier));
    }
  }
  std::stable_sort(frontiers.begin(), frontiers.end(),
                   [](const Frontier& a, const Frontier& b) { return a.cells.size() > b.cells.size(); });
  return frontiers;
}

}  // namespace stereonav
