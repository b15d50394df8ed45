#include "evaluation/trajectory_error.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace stereonav {

TrajectoryError trajectoryError(const std::vector<mrpt::poses::CPose2D>& estimate,
                                const std::vector<mrpt::poses::CPose2D>& truth) {
  if (estimate.empty() || estimate.size() != truth.size()) {
    throw std::invalid_argument("trajectory error: the estimate has " +
                                std::to_string(estimate.size()) + " poses, the truth " +
                                std::to_string(truth.size()) + " (need the same, at least one)");
  }
  const mrpt::poses::CPose2D anchor = truth.front() - estimate.front();
  TrajectoryError error;
  error.poses = estimate.size();
  double squared_sum = 0.0, squared_heading_sum = 0.0;
  for (size_t i = 0; i < estimate.size(); ++i) {
    const mrpt::poses::CPose2D aligned = anchor + estimate[i];
    const double distance = std::hypot(aligned.x() - truth[i].x(), aligned.y() - truth[i].y());
    const double heading =
        std::abs(mrpt::RAD2DEG(mrpt::math::wrapToPi(aligned.phi() - truth[i].phi())));
    squared_sum += distance * distance;
    squared_heading_sum += heading * heading;
    error.max_m = std::max(error.max_m, distance);
    error.max_heading_deg = std::max(error.max_heading_deg, heading);
    error.final_m = distance;
    if (i > 0) {
      error.length_m += std::hypot(truth[i].x() - truth[i - 1].x(), truth[i].y() - truth[i - 1].y());
    }
  }
  error.rms_m = std::sqrt(squared_sum / static_cast<double>(error.poses));
  error.rms_heading_deg = std::sqrt(squared_heading_sum / static_cast<double>(error.poses));
  return error;
}

std::string TrajectoryError::toText() const {
  std::ostringstream text;
  text.precision(3);
  text << std::fixed << "poses                " << poses << " (true path " << length_m << " m)\n"
       << "position error RMS   " << rms_m << " m\n"
       << "position error max   " << max_m << " m\n"
       << "final drift          " << final_m << " m\n"
       << "heading error RMS    " << rms_heading_deg << " deg\n"
       << "heading error max    " << max_heading_deg << " deg\n";
  return text.str();
}

std::string TrajectoryError::toJson() const {
  std::ostringstream json;
  json.precision(6);
  json << "{\"poses\": " << poses << ", \"length_m\": " << length_m << ", \"rms_m\": " << rms_m
       << ", \"max_m\": " << max_m << ", \"final_m\": " << final_m
       << ", \"rms_heading_deg\": " << rms_heading_deg
       << ", \"max_heading_deg\": " << max_heading_deg << "}\n";
  return json.str();
}

}  // namespace stereonav
