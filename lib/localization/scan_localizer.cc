#include "localization/scan_localizer.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>

namespace stereonav {

ScanLocalizer::ScanLocalizer(const LocalizationOptions& options, double focal_baseline_px_m)
    : options_(options), focal_baseline_px_m_(focal_baseline_px_m) {
  const double far_sigma =
      focal_baseline_px_m > 0.0
          ? options.max_range_m * options.max_range_m / focal_baseline_px_m * options.disparity_sigma_px
          : 0.0;
  // The matcher counts a reading 6 sigma off as unmatched; the field needs to reach that far.
  field_range_m_ = 6.0 * std::max(options.min_point_sigma_m, far_sigma);
}

const ScanMatch& ScanLocalizer::update(const mrpt::poses::CPose2D& odometry,
                                       const mrpt::obs::CObservation2DRangeScan& scan,
                                       const DisparityTaggedGrid& map, const TurnDoubt& turn_doubt) {
  const mrpt::poses::CPose2D motion =
      last_odometry_ ? odometry - *last_odometry_ : mrpt::poses::CPose2D();
  const mrpt::poses::CPose2D previous = last_odometry_ ? last_match_.pose : odometry;
  const mrpt::poses::CPose2D predicted = previous + motion;
  last_odometry_ = odometry;
  if (options_.matches()) {
    const ObstacleDistanceField field(map, field_range_m_);
    last_match_ = matchScan(matchablePoints(scan, focal_baseline_px_m_, options_), field, predicted,
                            priorSigmaAfter(motion, options_), options_);
  } else {
    last_match_ = ScanMatch();
    last_match_.pose = predicted;
  }
  if (!wall_heading_) {
    wall_heading_.emplace(options_.walls, odometry.phi());
    wall_position_.emplace(options_.wall_position, options_.walls, Eigen::Vector2d(odometry.x(), odometry.y()));
  }
  const std::vector<WallSegment> segments = wallSegments(scan, options_.walls.segments);
  // The motion as matched where the match pinned it down, as odometry measured it otherwise.
  const mrpt::poses::CPose2D moved = last_match_.pose - previous;
  wall_heading_->update(moved.phi(), motion.norm(), segments, turn_doubt);
  const HeadingEstimate heading = wall_heading_->estimate();
  const Eigen::Vector2d position =
      wall_position_->update(Eigen::Vector2d(moved.x(), moved.y()), previous.phi(), wall_heading_->prediction(),
                             heading, wall_heading_->directions(), segments);
  last_match_.pose = mrpt::poses::CPose2D(position.x(), position.y(), mrpt::math::wrapToPi(heading.heading));
  if (wall_heading_->lastFrameCorrections() > 0 || wall_position_->lastFrameCorrections() > 0) {
    last_match_.corrected = true;
  }
  return last_match_;
}

}  // namespace stereonav
