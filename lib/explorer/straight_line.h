#pragma once

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace stereonav {

// Whether `passes(col, row)` holds for every cell the straight line from cell `from` to cell `to`
// crosses between them (sampled every half cell; the end cells themselves are not tested).
template <typename CellTest>
bool alongStraightLine(const cv::Point& from, const cv::Point& to, const CellTest& passes) {
  const int steps = 2 * std::max(std::abs(to.x - from.x), std::abs(to.y - from.y));
  for (int step = 1; step < steps; ++step) {
    const double t = step / static_cast<double>(steps);
    if (!passes(static_cast<int>(std::lround(from.x + (to.x - from.x) * t)),
                static_cast<int>(std::lround(from.y + (to.y - from.y) * t)))) {
      return false;
    }
  }
  return true;
}

}  // namespace stereonav
