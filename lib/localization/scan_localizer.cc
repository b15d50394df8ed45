#include "localization/scan_localizer.h"

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
                                       const DisparityTaggedGrid& map) {
  const mrpt::poses::CPose2D motion =
      last_odometry_ ? odometry - *last_odometry_ : mrpt::poses::CPose2D();
  const mrpt::poses::CPose2D predicted = last_odometry_ ? last_match_.pose + motion : odometry;
  last_odometry_ = odometry;
  const ObstacleDistanceField field(map, field_range_m_);
  last_match_ = matchScan(matchablePoints(scan, focal_baseline_px_m_, options_), field, predicted,
                          priorSigmaAfter(motion, options_), options_);
  return last_match_;
}

}  // namespace stereonav
