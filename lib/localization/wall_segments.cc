#include "localization/wall_segments.h"

#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cmath>

namespace stereonav {
namespace {

struct Point {
  double x = 0.0;
  double y = 0.0;
};

double distanceToChord(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length = std::hypot(dx, dy);
  if (length <= 0.0) return std::hypot(p.x - a.x, p.y - a.y);
  return std::abs((p.x - a.x) * dy - (p.y - a.y) * dx) / length;
}

// Total least squares: the line through the centroid along the scatter's major axis.
WallSegment fitLine(const std::vector<Point>& points, size_t begin, size_t end) {
  const double n = static_cast<double>(end - begin);
  double mx = 0.0, my = 0.0;
  for (size_t i = begin; i < end; ++i) {
    mx += points[i].x;
    my += points[i].y;
  }
  mx /= n;
  my /= n;
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (size_t i = begin; i < end; ++i) {
    const double dx = points[i].x - mx, dy = points[i].y - my;
    sxx += dx * dx;
    syy += dy * dy;
    sxy += dx * dy;
  }
  const double direction = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  const double c = std::cos(direction), s = std::sin(direction);
  double along_min = 0.0, along_max = 0.0, along_sq = 0.0, across_sq = 0.0;
  for (size_t i = begin; i < end; ++i) {
    const double dx = points[i].x - mx, dy = points[i].y - my;
    const double along = c * dx + s * dy, across = -s * dx + c * dy;
    along_min = std::min(along_min, along);
    along_max = std::max(along_max, along);
    along_sq += along * along;
    across_sq += across * across;
  }
  WallSegment segment;
  segment.direction_rad = direction >= M_PI / 2 ? direction - M_PI : direction;
  // The slope's standard error: residual variance over the spread along the line.
  segment.sigma_rad = along_sq > 0.0 ? std::sqrt(across_sq / std::max(n - 2.0, 1.0) / along_sq) : M_PI;
  segment.length_m = along_max - along_min;
  return segment;
}

void splitAndFit(const std::vector<Point>& points, size_t begin, size_t end,
                 const WallSegmentOptions& options, std::vector<WallSegment>& segments) {
  if (end - begin < static_cast<size_t>(std::max(options.min_points, 2))) return;
  size_t farthest = begin;
  double farthest_distance = 0.0;
  for (size_t i = begin + 1; i + 1 < end; ++i) {
    const double distance = distanceToChord(points[i], points[begin], points[end - 1]);
    if (distance > farthest_distance) {
      farthest_distance = distance;
      farthest = i;
    }
  }
  if (farthest_distance > options.split_tolerance_m) {
    splitAndFit(points, begin, farthest + 1, options, segments);
    splitAndFit(points, farthest, end, options, segments);
    return;
  }
  const WallSegment segment = fitLine(points, begin, end);
  if (segment.length_m >= options.min_length_m) segments.push_back(segment);
}

}  // namespace

std::vector<WallSegment> wallSegments(const mrpt::obs::CObservation2DRangeScan& scan,
                                      const WallSegmentOptions& options) {
  std::vector<Point> points;
  const mrpt::poses::CPose2D sensor(scan.sensorPose);
  for (size_t ray = 0; ray < scan.getScanSize(); ++ray) {
    if (!scan.getScanRangeValidity(ray)) continue;
    const double range = scan.getScanRange(ray);
    if (!(range > 0.0 && range <= options.max_range_m)) continue;
    const double angle = scan.getScanAngle(ray);
    const mrpt::poses::CPose2D point =
        sensor + mrpt::poses::CPose2D(range * std::cos(angle), range * std::sin(angle), 0.0);
    // Neighbouring rays that share one column's reading give the same point twice.
    if (!points.empty() && points.back().x == point.x() && points.back().y == point.y()) continue;
    points.push_back({point.x(), point.y()});
  }
  std::vector<WallSegment> segments;
  size_t run_begin = 0;
  for (size_t i = 1; i <= points.size(); ++i) {
    if (i == points.size() ||
        std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y) > options.max_gap_m) {
      splitAndFit(points, run_begin, i, options, segments);
      run_begin = i;
    }
  }
  return segments;
}

}  // namespace stereonav
