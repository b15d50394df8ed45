#pragma once

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace stereonav {

// std::lround(x) for |x| < 2^52, inline (a call into libm per sample was most of a line's cost):
// there the truncation is exact, and so is the fraction it leaves.
inline long roundHalfAwayFromZero(double x) {
  const long whole = static_cast<long>(x);
  const double fraction = x - static_cast<double>(whole);
  return whole + (fraction >= 0.5 ? 1 : 0) - (fraction <= -0.5 ? 1 : 0);
}

// Whether `passes(col, row)` holds for every cell the straight line from cell `from` to cell `to`
// crosses between them (sampled every half cell; the end cells themselves are not tested).
template <typename CellTest>
bool alongStraightLine(const cv::Point& from, const cv::Point& to, const CellTest& passes) {
  const int steps = 2 * std::max(std::abs(to.x - from.x), std::abs(to.y - from.y));
  for (int step = 1; step < steps; ++step) {
    const double t = step / static_cast<double>(steps);
    if (!passes(static_cast<int>(roundHalfAwayFromZero(from.x + (to.x - from.x) * t)),
                static_cast<int>(roundHalfAwayFromZero(from.y + (to.y - from.y) * t)))) {
      return false;
    }
  }
  return true;
}

// Whether point (x, y) lies within `range_m` of the camera at `pose` and inside its field of view
// (`half_view_rad` either side of the heading), boundaries included.
inline bool withinView(const mrpt::poses::CPose2D& pose, double x, double y, double range_m, double half_view_rad) {
  const double dx = x - pose.x(), dy = y - pose.y();
  return dx * dx + dy * dy <= range_m * range_m &&
         std::abs(mrpt::math::wrapToPi(std::atan2(dy, dx) - pose.phi())) <= half_view_rad;
}

}  // namespace stereonav
