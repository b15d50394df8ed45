#pragma once

#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace stereonav {

// Absolute trajectory error of an estimated trajectory against the true one (Sturm et al., "A
// benchmark for the evaluation of RGB-D SLAM systems", IROS 2012), in the plane. Poses pair by
// index (one per frame in both). The estimate is first moved rigidly so that its first pose lies
// on the truth's first pose: a robot's map frame is wherever it started, and what matters is how
// far it drifts from there.
struct TrajectoryError {
  size_t poses = 0;
  double length_m = 0.0;     // of the true trajectory
  double rms_m = 0.0;        // RMS of the position errors
  double max_m = 0.0;        // the largest position error
  double final_m = 0.0;      // the position error at the last pose: the final drift
  double rms_heading_deg = 0.0;
  double max_heading_deg = 0.0;

  std::string toText() const;
  std::string toJson() const;
};

// Throws std::invalid_argument if the trajectories are empty or differ in length.
TrajectoryError trajectoryError(const std::vector<mrpt::poses::CPose2D>& estimate,
                                const std::vector<mrpt::poses::CPose2D>& truth);

}  // namespace stereonav
