#include "explorer/near_obstacle_memory.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stereonav {
namespace {

// Calls `visit` on every cell of `cells` (keyed by lround(coordinate / cell_m)) whose point may lie
// within `radius` of (x, y), in the map's order; `visit` returns the iterator to go on from, so it
// may erase. A cell's point lies within half a cell of its key: keys one beyond the square of
// `radius` hold every point within it.
template <typename Cells, typename Visit>
void walkCellsNear(Cells& cells, double cell_m, double x, double y, double radius, const Visit& visit) {
  const long first_row = std::lround((y - radius) / cell_m) - 1, last_row = std::lround((y + radius) / cell_m) + 1;
  const long last_col = std::lround((x + radius) / cell_m) + 1;
  for (long col = std::lround((x - radius) / cell_m) - 1; col <= last_col; ++col) {
    const auto end = cells.upper_bound({col, last_row});
    for (auto it = cells.lower_bound({col, first_row}); it != end;) it = visit(it);
  }
}

}  // namespace

void NearObstacleMemory::update(const std::vector<mrpt::math::TPoint2D>& sensed, const mrpt::poses::CPose2D& pose,
                                const std::function<bool(double x, double y)>& confirmed) {
  // The scan by bearing: per bin of bearing_window_rad the nearest range and the count.
  const int bins = std::max(1, static_cast<int>(std::ceil(2.0 * M_PI / options_.bearing_window_rad)));
  const double bin_width = 2.0 * M_PI / bins;
  std::vector<double> nearest(static_cast<size_t>(bins), std::numeric_limits<double>::infinity());
  std::vector<int> count(static_cast<size_t>(bins), 0);
  const auto binOf = [&](double bearing) {
    const int bin = static_cast<int>(std::floor((bearing + M_PI) / bin_width));
    return ((bin % bins) + bins) % bins;
  };
  for (const mrpt::math::TPoint2D& point : sensed) {
    const int bin = binOf(std::atan2(point.y, point.x));
    nearest[bin] = std::min(nearest[bin], std::hypot(point.x, point.y));
    ++count[bin];
  }

  const auto seenPast = [&](const mrpt::math::TPoint2D& point) {
    double x = 0.0, y = 0.0;
    pose.inverseComposePoint(point.x, point.y, x, y);
    const double range = std::hypot(x, y);
    if (range < options_.judge_beyond_m || range > options_.remember_within_m) return false;
    // The bin of the point and its neighbours on both sides: the window around its bearing.
    const int centre = binOf(std::atan2(y, x));
    int points = 0;
    double closest = std::numeric_limits<double>::infinity();
    for (int offset = -1; offset <= 1; ++offset) {
      const int bin = ((centre + offset) % bins + bins) % bins;
      points += count[bin];
      closest = std::min(closest, nearest[bin]);
    }
    return points >= 2 && closest > range + options_.see_through_margin_m;
  };
  // Only points within remember_within_m are judged: the cells around the robot, not the whole
  // memory, which grows with the building.
  walkCellsNear(remembered_, options_.cell_m, pose.x(), pose.y(), options_.remember_within_m,
                [&](auto it) { return seenPast(points_[it->second]) ? forget(it) : std::next(it); });
  walkCellsNear(candidates_, options_.cell_m, pose.x(), pose.y(), options_.remember_within_m,
                [&](auto it) { return seenPast(it->second.point) ? candidates_.erase(it) : std::next(it); });

  for (const mrpt::math::TPoint2D& point : sensed) {
    if (std::hypot(point.x, point.y) > options_.remember_within_m) continue;
    double x = 0.0, y = 0.0;
    pose.composePoint(point.x, point.y, x, y);
    if (!confirmed(x, y)) continue;
    const mrpt::math::TPoint2D view(pose.x(), pose.y());
    const Key key = keyOf(x, y);
    if (const auto known = remembered_.find(key); known != remembered_.end()) {
      points_[known->second] = mrpt::math::TPoint2D(x, y);
      continue;
    }
    const auto [it, inserted] = candidates_.try_emplace(key, Candidate{mrpt::math::TPoint2D(x, y), view});
    if (inserted) continue;
    it->second.point = mrpt::math::TPoint2D(x, y);
    if (std::hypot(view.x - it->second.first_view.x, view.y - it->second.first_view.y) >= options_.distinct_views_m) {
      rememberCell(key, it->second.point);
      candidates_.erase(it);
    }
  }
}

void NearObstacleMemory::remember(const std::vector<mrpt::math::TPoint2D>& points) {
  for (const mrpt::math::TPoint2D& point : points) {
    const Key key = keyOf(point.x, point.y);
    candidates_.erase(key);
    rememberCell(key, point);
  }
}

void NearObstacleMemory::rememberCell(const Key& key, const mrpt::math::TPoint2D& point) {
  const auto [it, inserted] = remembered_.try_emplace(key, points_.size());
  if (inserted) {
    points_.push_back(point);
    keys_.push_back(key);
    return;
  }
  points_[it->second] = point;
}

std::map<NearObstacleMemory::Key, size_t>::iterator NearObstacleMemory::forget(std::map<Key, size_t>::iterator it) {
  const size_t slot = it->second;
  if (slot + 1 != points_.size()) {
    points_[slot] = points_.back();
    keys_[slot] = keys_.back();
    remembered_.find(keys_[slot])->second = slot;
  }
  points_.pop_back();
  keys_.pop_back();
  return remembered_.erase(it);
}

NearObstacleMemory::Key NearObstacleMemory::keyOf(double x, double y) const {
  return {std::lround(x / options_.cell_m), std::lround(y / options_.cell_m)};
}

size_t NearObstacleMemory::forgetUnconfirmed(const std::function<bool(double x, double y)>& confirmed) {
  size_t forgotten = 0;
  for (auto it = remembered_.begin(); it != remembered_.end();) {
    const mrpt::math::TPoint2D& point = points_[it->second];
    if (confirmed(point.x, point.y)) {
      ++it;
      continue;
    }
    ++forgotten;
    it = forget(it);
  }
  for (auto it = candidates_.begin(); it != candidates_.end();) {
    it = confirmed(it->second.point.x, it->second.point.y) ? std::next(it) : candidates_.erase(it);
  }
  return forgotten;
}

std::vector<mrpt::math::TPoint2D> NearObstacleMemory::pointsNear(double x, double y, double radius) const {
  std::vector<mrpt::math::TPoint2D> points;
  walkCellsNear(remembered_, options_.cell_m, x, y, radius, [&](auto it) {
    points.push_back(points_[it->second]);
    return std::next(it);
  });
  return points;
}

size_t NearObstacleMemory::size() const { return remembered_.size(); }

}  // namespace stereonav
