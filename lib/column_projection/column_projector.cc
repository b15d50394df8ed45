#include "column_projection/column_projector.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace stereonav {
namespace {

struct DisparityInterval {
  double lowest;
  double highest;
};

// The disparities d > 0 for which mount_z + k / d lies in (floor_clearance, robot_height].
DisparityInterval bodyVolumeInterval(double k, double mount_z, const ProjectionOptions& options) {
  const double clearance = options.floor_clearance_m;
  const double height = options.robot_height_m;
  constexpr DisparityInterval kEmpty{1.0, 0.0};
  DisparityInterval interval{std::numeric_limits<float>::min(), std::numeric_limits<float>::max()};
  if (k == 0.0) {
    // A ray parallel to the floor stays at the camera's height whatever the disparity.
    return clearance < mount_z && mount_z <= height ? interval : kEmpty;
  }
  if (k > 0.0) {
    // Looking up: the point comes down towards mount_z as d grows.
    if (height <= mount_z) return kEmpty;
    interval.lowest = std::max(interval.lowest, k / (height - mount_z));
    if (clearance >= mount_z) interval.highest = std::min(interval.highest, k / (clearance - mount_z));
  } else {
    // Looking down: the point rises towards mount_z as d grows.
    if (clearance >= mount_z) return kEmpty;
    interval.lowest = std::max(interval.lowest, -k / (mount_z - clearance));
    if (height < mount_z) interval.highest = std::min(interval.highest, -k / (mount_z - height));
  }
  return interval.lowest <= interval.highest ? interval : kEmpty;
}

// "Mostly matches nothing": three pixels in four, as spike removal leaves a few stray matches on
// a flat surface.
constexpr double kUnmatchedShare = 0.75;

}  // namespace

ColumnProjector::ColumnProjector(const CameraRig& rig, const ProjectionOptions& options)
    : mount_z_(rig.pose_on_robot.z()),
      floor_clearance_(options.floor_clearance_m),
      // A camera at or below the floor sees no floor to end.
      floor_end_min_disparity_(options.floor_end_max_depth_m > 0.0 && mount_z_ > 0.0
                                   ? rig.disparityForDepth(options.floor_end_max_depth_m)
                                   : 0.0),
      clear_end_min_disparity_(options.floor_end_clear_max_depth_m > 0.0 && mount_z_ > 0.0
                                   ? rig.disparityForDepth(options.floor_end_clear_max_depth_m)
                                   : 0.0),
      surface_band_px_(options.surface_band_px),
      surface_band_scan_only_(options.surface_band_scan_only),
      min_reading_disparity_(options.max_depth_m > 0.0 ? rig.disparityForDepth(options.max_depth_m)
                                                       : 0.0) {
  const PinholeCamera& camera = rig.reference;
  lowest_.create(camera.height, camera.width);
  highest_.create(camera.height, camera.width);
  height_factor_.create(camera.height, camera.width);
  const auto rotation = rig.pose_on_robot.getRotationMatrix();
  const double mount_z = mount_z_;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      // Height above the camera of the point (B/d)(x - cx, y - cy, f) is k / d.
      const double k = rig.baseline_m * (rotation(2, 0) * (x - camera.cx) +
                                         rotation(2, 1) * (y - camera.cy) +
                                         rotation(2, 2) * camera.focal_px);
      height_factor_(y, x) = static_cast<float>(k);
      const DisparityInterval interval = bodyVolumeInterval(k, mount_z, options);
      lowest_(y, x) = static_cast<float>(interval.lowest);
      highest_(y, x) = static_cast<float>(interval.highest);
    }
  }
  if (options.near_floor_m > 0.0 && mount_z > 0.0) {
    // The floor in row y lies at disparity -k / mount_z (where k < 0: the row looks down).
    const auto floor_depth = [&](int y, int x) { return rig.depthForDisparity(-height_factor_(y, x) / mount_z); };
    near_floor_top_row_.assign(camera.width, camera.height);
    const int bottom = camera.height - 1;
    for (int x = 0; x < camera.width; ++x) {
      if (height_factor_(bottom, x) >= 0.0f) continue;  // no floor in sight: no rows to check
      const double deepest = floor_depth(bottom, x) + options.near_floor_m;
      int top = bottom;
      while (top > 0 && height_factor_(top - 1, x) < 0.0f && floor_depth(top - 1, x) <= deepest) --top;
      near_floor_top_row_[x] = top;
    }
  }
}

DisparityScan ColumnProjector::project(const cv::Mat1f& disparity) const {
  if (disparity.size() != lowest_.size()) {
    throw std::invalid_argument(
        "ColumnProjector: disparity image is " + std::to_string(disparity.cols) + "x" +
        std::to_string(disparity.rows) + ", the rig's camera is " + std::to_string(lowest_.cols) +
        "x" + std::to_string(lowest_.rows));
  }
  const int width = disparity.cols;
  DisparityScan scan;
  // -1 is below every disparity, so the first pixel inside the volume always wins the max.
  scan.column_disparity.assign(width, -1.0f);
  scan.column_row.assign(width, -1);
  float* best = scan.column_disparity.data();
  int* best_row = scan.column_row.data();
  for (int y = 0; y < disparity.rows; ++y) {
    const float* row = disparity[y];
    const float* lowest = lowest_[y];
    const float* highest = highest_[y];
    for (int x = 0; x < width; ++x) {
      const float d = row[x];
      const bool closer = (d >= lowest[x]) & (d <= highest[x]) & (d > best[x]);
      best[x] = closer ? d : best[x];
      best_row[x] = closer ? y : best_row[x];
    }
  }
  if (surface_band_px_ > 0.0) {
    float* surface_disparity = best;
    int* surface_row = best_row;
    if (surface_band_scan_only_) {
      scan.column_surface.assign(width, -1.0f);
      scan.column_surface_row.assign(width, -1);
      surface_disparity = scan.column_surface.data();
      surface_row = scan.column_surface_row.data();
    }
    std::vector<std::pair<float, int>> surface;  // disparity, row
    surface.reserve(disparity.rows);
    for (int x = 0; x < width; ++x) {
      if (best_row[x] < 0) continue;
      surface.clear();
      const float band_floor = best[x] - static_cast<float>(surface_band_px_);
      for (int y = 0; y < disparity.rows; ++y) {
        const float d = disparity(y, x);
        if (d >= band_floor && d >= lowest_(y, x) && d <= highest_(y, x)) surface.emplace_back(d, y);
      }
      // The median, the lower one of an even count.
      const auto median = surface.begin() + surface.size() / 2;
      std::nth_element(surface.begin(), median, surface.end(), std::greater<>());
      surface_disparity[x] = median->first;
      surface_row[x] = median->second;
    }
  }
  if (floor_end_min_disparity_ > 0.0) {
    for (int x = 0; x < width; ++x) {
      float foot = 0.0f;
      int foot_row = -1;
      if (!unmatchedFoot(disparity, x, floor_end_min_disparity_, foot, foot_row)) continue;
      // A surface seen in the column at the foot's depth or nearer is the reading already.
      if (best_row[x] >= 0 && best[x] >= foot - 0.5f) continue;
      best[x] = foot;
      best_row[x] = foot_row;
      if (!scan.column_surface.empty()) {
        scan.column_surface[x] = foot;
        scan.column_surface_row[x] = foot_row;
      }
    }
  }
  if (clear_end_min_disparity_ > 0.0) {
    scan.column_clear_end.assign(width, kInvalidDisparity);
    scan.column_clear_end_row.assign(width, -1);
    for (int x = 0; x < width; ++x) {
      float foot = 0.0f;
      int foot_row = -1;
      // A reading at the foot or nearer is what the column sees; one beyond it has CLEAR to cut.
      if (unmatchedFoot(disparity, x, clear_end_min_disparity_, foot, foot_row) &&
          (best_row[x] < 0 || best[x] < foot - 0.5f)) {
        scan.column_clear_end[x] = foot;
        scan.column_clear_end_row[x] = foot_row;
      }
    }
  }
  if (!near_floor_top_row_.empty()) {
    scan.column_blind.resize(width);
    for (int x = 0; x < width; ++x) scan.column_blind[x] = blind(disparity, x);
  }
  const auto min_disparity = static_cast<float>(min_reading_disparity_);
  const auto drop_beyond_reach = [min_disparity](std::vector<float>& readings, std::vector<int>& rows) {
    for (size_t x = 0; x < readings.size(); ++x) {
      if (rows[x] < 0 || readings[x] < min_disparity) {
        readings[x] = kInvalidDisparity;
        rows[x] = -1;
      }
    }
  };
  drop_beyond_reach(scan.column_disparity, scan.column_row);
  drop_beyond_reach(scan.column_surface, scan.column_surface_row);
  return scan;
}

bool ColumnProjector::blind(const cv::Mat1f& disparity, int x) const {
  int rows = 0, unmatched = 0;
  for (int y = near_floor_top_row_[x]; y < disparity.rows; ++y) {
    ++rows;
    unmatched += !isValidDisparity(disparity(y, x));
  }
  return rows > 0 && unmatched >= kUnmatchedShare * rows;
}

bool ColumnProjector::unmatchedFoot(const cv::Mat1f& disparity, int x, double min_disparity,
                                    float& foot_disparity, int& foot_row) const {
  // Up from the bottom row: the floor's last matched pixel before anything off the floor (or the
  // horizon) comes into sight. Unmatched pixels on the way are floor without texture.
  int floor_end = -1;
  for (int y = disparity.rows - 1; y >= 0; --y) {
    const float k = height_factor_(y, x);
    if (k >= 0.0f) break;  // level or looking up: no floor in this row
    const float d = disparity(y, x);
    if (!isValidDisparity(d) || d <= 0.0f) continue;
    if (std::abs(mount_z_ + k / d) > floor_clearance_) break;
    floor_end = y;
  }
  if (floor_end < 0) return false;
  // Its disparity on the floor plane (mount_z + k / d = 0): the row's geometry, not the noise.
  const float foot = static_cast<float>(-height_factor_(floor_end, x) / mount_z_);
  if (foot < min_disparity) return false;
  // The rows above it that would show a surface standing there, from the floor up to
  // floor_clearance_m, must mostly match nothing: a gap in the floor's texture has the floor
  // again (or a farther surface) right above it.
  int rows = 0, unmatched = 0;
  for (int y = floor_end - 1; y >= 0 && mount_z_ + height_factor_(y, x) / foot <= floor_clearance_; --y) {
    ++rows;
    unmatched += !isValidDisparity(disparity(y, x));
  }
  if (rows == 0 || unmatched < kUnmatchedShare * rows) return false;
  foot_disparity = foot;
  foot_row = floor_end;
  return true;
}

}  // namespace stereonav
