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
// The unresolved regions (8-connected labels over `window`, 0 on resolved cells) and, per label,
// its cell count over the whole grid and whether it is an opening rather than a seam.
struct OpeningRegions {
  cv::Rect window;
  cv::Mat1i labels;
  std::vector<int> areas;
  std::vector<uint8_t> is_opening;
};

// Only the resolved cells' box and a ring of two unknown cells around it are labelled: each side
// of the ring is one region with the unknown cells beyond it, which are neither resolved nor next
// to a resolved cell nor to an obstacle, so they change no label's kind and only add their count
// to the ring's label. Beyond a side there are no cells where the ring meets the grid's edge.
OpeningRegions openingRegions(const NavigationGrid& grid) {
  const cv::Mat1b& all_classes = grid.cellClasses();
  OpeningRegions regions;
  const cv::Rect& resolved = grid.resolvedCells();
  regions.window = (resolved - cv::Point(2, 2) + cv::Size(4, 4)) & cv::Rect(cv::Point(), all_classes.size());
  const cv::Mat1b classes = all_classes(regions.window);
  cv::Mat1b unresolved;
  cv::inRange(classes, NavigationGrid::kUnknown, NavigationGrid::kImprecise, unresolved);
  const int count = cv::connectedComponents(unresolved, regions.labels, 8, CV_32S);
  // The cells with no resolved 8-neighbour (the grid's edge does not count as resolved, nor do the
  // unknown cells beyond the window), and those with a precise obstacle among their 8 neighbours
  // (nothing beyond the edge or the window).
  cv::Mat1b interior, beside_obstacle;
  cv::erode(unresolved, interior, cv::Mat());
  cv::dilate(classes == NavigationGrid::kOccupied, beside_obstacle, cv::Mat());
  regions.areas.assign(static_cast<size_t>(count), 0);
  std::vector<uint8_t> thin(static_cast<size_t>(count), 1), touches_obstacle(static_cast<size_t>(count), 0);
  // Run by run of one label: a count per cell would wait on the store before it (the same
  // label's count, cell after cell), and each flag is looked for only until it is found.
  int* areas = regions.areas.data();
  for (int row = 0; row < classes.rows; ++row) {
    const int* label_row = regions.labels[row];
    const uint8_t* interior_row = interior[row];
    const uint8_t* beside_row = beside_obstacle[row];
    for (int col = 0; col < classes.cols;) {
      const int label = label_row[col];
      int end = col + 1;
      while (end < classes.cols && label_row[end] == label) ++end;
      areas[label] += end - col;
      const auto any_set = [&](const uint8_t* cells) {
        return std::any_of(cells + col, cells + end, [](uint8_t cell) { return cell != 0; });
      };
      if (label != 0 && thin[label] && any_set(interior_row)) thin[label] = 0;
      if (label != 0 && !touches_obstacle[label] && any_set(beside_row)) touches_obstacle[label] = 1;
      col = end;
    }
  }
  // The cells beyond the window: the columns left and right of it at every row, and the rows
  // below and above it within its columns, each part added to the label of the ring beside it.
  // Parts that touch (a side part and an end part) are one region and the ring's sides one label.
  const cv::Rect& w = regions.window;
  const int grid_cols = all_classes.cols, grid_rows = all_classes.rows;
  const int last_col = w.width - 1, last_row = w.height - 1;
  regions.areas[regions.labels(0, 0)] += w.x * grid_rows;
  regions.areas[regions.labels(0, last_col)] += (grid_cols - w.x - w.width) * grid_rows;
  regions.areas[regions.labels(0, 0)] += w.y * w.width;
  regions.areas[regions.labels(last_row, 0)] += (grid_rows - w.y - w.height) * w.width;
  regions.is_opening.assign(static_cast<size_t>(count), 0);
  for (int label = 1; label < count; ++label) regions.is_opening[label] = !(thin[label] && touches_obstacle[label]);
  return regions;
}

}  // namespace

std::vector<Frontier> findFrontiers(const NavigationGrid& grid, int min_cells) {
  // A free cell is a frontier cell when one of its 4-neighbours belongs to an opening: per cell,
  // the largest area (cells) of the openings among them, and whether one of them is an unknown
  // cell rather than an obstacle seen from far. Per grid cell first, its own opening's area and
  // whether it is unknown; then the most of these over each cell's cross of neighbours (itself
  // resolved, so adding nothing). Only free cells border anything, so only their bounding box is
  // taken, grown by the cells its crosses reach.
  const cv::Rect& free_cells = grid.freeCells();
  if (free_cells.empty()) return {};
  const OpeningRegions regions = openingRegions(grid);
  const cv::Mat1b& classes = grid.cellClasses();
  const cv::Rect reach = (free_cells - cv::Point(1, 1) + cv::Size(2, 2)) & cv::Rect(cv::Point(), classes.size());
  cv::Mat1f opening_area(reach.size());
  cv::Mat1b unknown_opening(reach.size());
  for (int row = 0; row < reach.height; ++row) {
    const int* label_row = regions.labels[reach.y - regions.window.y + row] + reach.x - regions.window.x;
    const uint8_t* class_row = classes[reach.y + row] + reach.x;
    float* area_row = opening_area[row];
    uint8_t* unknown_row = unknown_opening[row];
    for (int col = 0; col < reach.width; ++col) {
      const auto label = static_cast<size_t>(label_row[col]);
      const bool opening = regions.is_opening[label] != 0;
      area_row[col] = opening ? static_cast<float>(regions.areas[label]) : 0.0f;
      unknown_row[col] = opening && class_row[col] == NavigationGrid::kUnknown ? 1 : 0;
    }
  }
  // Beyond the grid's edge nothing is bordered: dilate's default border adds nothing.
  const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3));
  cv::dilate(opening_area, opening_area, cross);
  cv::dilate(unknown_opening, unknown_opening, cross);
  const cv::Rect inner(free_cells.tl() - reach.tl(), free_cells.size());
  const cv::Mat1b is_free = classes(free_cells) == NavigationGrid::kFree;
  cv::Mat1f bordered(free_cells.size(), 0.0f);
  opening_area(inner).copyTo(bordered, is_free);
  cv::Mat1b faces_unknown(free_cells.size(), uint8_t{0});
  unknown_opening(inner).copyTo(faces_unknown, is_free);
  cv::Mat1b is_frontier = bordered > 0;
  const double cell_area = grid.resolution() * grid.resolution();
  std::vector<Frontier> frontiers;
  std::vector<cv::Point> stack;  // cells in the box's coordinates
  for (int row = 0; row < is_frontier.rows; ++row) {
    const uint8_t* frontier_row = is_frontier[row];
    for (int col = 0; col < is_frontier.cols; ++col) {
      if (!frontier_row[col]) continue;
      Frontier frontier;
      is_frontier(row, col) = 0;
      stack.assign(1, cv::Point(col, row));
      while (!stack.empty()) {
        const cv::Point cell = stack.back();
        stack.pop_back();
        frontier.cells.push_back(cell + free_cells.tl());
        frontier.unseen_area_m2 = std::max(frontier.unseen_area_m2, bordered(cell.y, cell.x) * cell_area);
        frontier.borders_unknown = frontier.borders_unknown || faces_unknown(cell.y, cell.x);
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const int c = cell.x + dc, r = cell.y + dr;
            if (c >= 0 && r >= 0 && c < is_frontier.cols && r < is_frontier.rows && is_frontier(r, c)) {
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
