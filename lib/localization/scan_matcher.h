#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

#include <vector>

#include "localization/localization_options.h"
#include "localization/obstacle_distance_field.h"

namespace stereonav {

// A reading to match, in the robot frame, with its position uncertainty (metres).
struct ScanPoint {
  double x = 0.0;
  double y = 0.0;
  double sigma = 0.0;
};

// The readings of a (virtual) range scan worth matching: valid, nearer than max_range_m, thinned
// to one per point_spacing_m, each with sigma = max(min_point_sigma_m, r^2 / (f B) *
// disparity_sigma_px), the range error of a stereo reading at range r (f B: focal length in
// pixels times the baseline in metres; 0 for a laser, whose readings then all get
// min_point_sigma_m).
std::vector<ScanPoint> matchablePoints(const mrpt::obs::CObservation2DRangeScan& scan,
                                       double focal_baseline_px_m,
                                       const LocalizationOptions& options);

// What one match found.
struct ScanMatch {
  mrpt::poses::CPose2D pose;  // the corrected pose (the prior if nothing was corrected)
  // Covariance of the scan's likelihood over the poses tried, in (x, y, phi) each divided by its
  // window: 1/3 along a direction where the likelihood is flat, near 0 where a peak pins it.
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  int points = 0;          // readings matched
  int matched_points = 0;  // of them, within 3 sigma of a map obstacle at `pose`
  int constrained_directions = 0;  // directions of the pose the match corrected (0..3)
  bool corrected = false;
};

// How far the prior pose may be off: one sigma, in metres (x and y) and radians.
struct PriorSigma {
  double position_m = 0.0;
  double heading_rad = 0.0;
};

// Correlative scan matching (Olson, "Real-time correlative scan matching", ICRA 2009): every pose
// on a grid of steps within the window around `prior` is scored by the likelihood of the readings
// given the map's obstacle distances, sum of log(outlier + (1 - outlier) exp(-d^2 / 2 sigma^2))
// (a reading's own sigma, so precise near readings count more), times a Gaussian prior on the
// correction (`prior_sigma`); the best pose is refined on a four times finer grid. The correction is kept only
// along the directions where the likelihood alone is peaked (spread below max_spread), so a scan
// of a straight corridor corrects the distance to the walls and the heading but never the
// position along the corridor. With fewer than min_matched_points matched readings (or
// min_matched_fraction of them), or a map without obstacles, the prior is returned.
//
// Written here rather than taken from mrpt::slam::CICP because ICP needs point-to-point pairings
// that a stereo scan (one reading per image column, its range error growing with range squared)
// against a grid of cells does not give well, and because the correlative search yields the
// likelihood's spread over the window, which is what tells the well-constrained directions from
// the degenerate ones.
ScanMatch matchScan(const std::vector<ScanPoint>& points, const ObstacleDistanceField& field,
                    const mrpt::poses::CPose2D& prior, const PriorSigma& prior_sigma,
                    const LocalizationOptions& options);

// The prior's sigma after driving `motion` (the odometry increment since the last frame).
PriorSigma priorSigmaAfter(const mrpt::poses::CPose2D& motion, const LocalizationOptions& options);

}  // namespace stereonav
