#include "localization/wall_segments.h"

#include <algorithm>
#include <cmath>

#include "localization/scan_points.h"

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
WallSegment fitLine(const std::vector<Point>& points, size_t begin, size_t end, int correlated_readings) {
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
  // The residuals' variance, times the readings that share one error: n readings count as
  // n / correlated_readings independent ones.
  const double residual_variance = across_sq / std::max(n - 2.0, 1.0) * std::max(correlated_readings, 1);
  WallSegment segment;
  segment.direction_rad = direction >= M_PI / 2 ? direction - M_PI : direction;
  // The slope's standard error: residual variance over the spread along the line.
  segment.sigma_rad = along_sq > 0.0 ? std::sqrt(residual_variance / along_sq) : M_PI;
  segment.length_m = along_max - along_min;
  // The normal toward the line, signed so that the centroid lies ahead along it.
  double nx = -s, ny = c;
  if (nx * mx + ny * my < 0.0) {
    nx = -nx;
    ny = -ny;
  }
  segment.normal_rad = std::atan2(ny, nx);
  segment.centroid = mrpt::math::TPoint2D(mx, my);
  segment.centroid_sigma_m = std::sqrt(residual_variance / n);
  const auto ontoLine = [&](const Point& p) {
    const double along = c * (p.x - mx) + s * (p.y - my);
    return mrpt::math::TPoint2D(mx + along * c, my + along * s);
  };
  segment.first = ontoLine(points[begin]);
  segment.last = ontoLine(points[end - 1]);
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
  const WallSegment segment = fitLine(points, begin, end, options.correlated_readings);
  if (segment.length_m >= options.min_length_m) segments.push_back(segment);
}

}  // namespace

std::vector<WallSegment> wallSegments(const mrpt::obs::CObservation2DRangeScan& scan,
                                      const WallSegmentOptions& options) {
  std::vector<Point> points;
  for (const ScanReadingPoint& reading : scanPointsWithin(scan, options.max_range_m)) {
    points.push_back({reading.x, reading.y});
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
