#include "localization/localization_options.h"

namespace stereonav {

LocalizationOptions loadLocalizationOptions(IniSection& section) {
  LocalizationOptions options;
  options.max_range_m = section.getPositive("max_range_m", options.max_range_m);
  options.point_spacing_m = section.getNonNegative("point_spacing_m", options.point_spacing_m);
  options.disparity_sigma_px = section.getNonNegative("disparity_sigma_px", options.disparity_sigma_px);
  options.min_point_sigma_m = section.getPositive("min_point_sigma_m", options.min_point_sigma_m);
  options.outlier_probability = section.getPositive("outlier_probability", options.outlier_probability);
  if (!(options.outlier_probability < 1.0)) {
    throw ConfigError("[" + section.name() + "] outlier_probability: must be in (0, 1)");
  }
  options.window_m = section.getNonNegative("window_m", options.window_m);
  options.window_deg = section.getNonNegative("window_deg", options.window_deg);
  options.step_m = section.getPositive("step_m", options.step_m);
  options.step_deg = section.getPositive("step_deg", options.step_deg);
  options.prior_sigma_m = section.getPositive("prior_sigma_m", options.prior_sigma_m);
  options.prior_sigma_m_per_m = section.getNonNegative("prior_sigma_m_per_m", options.prior_sigma_m_per_m);
  options.prior_sigma_deg = section.getPositive("prior_sigma_deg", options.prior_sigma_deg);
  options.prior_sigma_per_rad = section.getNonNegative("prior_sigma_per_rad", options.prior_sigma_per_rad);
  options.min_matched_points = section.getInt("min_matched_points", options.min_matched_points);
  if (options.min_matched_points < 1) {
    throw ConfigError("[" + section.name() + "] min_matched_points: must be >= 1");
  }
  options.min_matched_fraction = section.getNonNegative("min_matched_fraction", options.min_matched_fraction);
  if (options.min_matched_fraction > 1.0) {
    throw ConfigError("[" + section.name() + "] min_matched_fraction: must be in [0, 1]");
  }
  options.max_spread = section.getPositive("max_spread", options.max_spread);
  return options;
}

}  // namespace stereonav
