#include "localization/localization_options.h"

#include <gtest/gtest.h>

#include "support/options_loading.h"

namespace stereonav {
namespace {

using test_support::configErrorOf;
using test_support::loadSectionText;

TEST(LocalizationOptionsTest, LoadsEveryKey) {
  const LocalizationOptions options = loadSectionText(
      "localization",
      "max_range_m = 3\npoint_spacing_m = 0.1\ndisparity_sigma_px = 0.5\nmin_point_sigma_m = 0.04\n"
      "outlier_probability = 0.3\nwindow_m = 0.5\nwindow_deg = 12\nstep_m = 0.05\nstep_deg = 2\n"
      "prior_sigma_m = 0.2\nprior_sigma_m_per_m = 0.05\nprior_sigma_deg = 4\nprior_sigma_per_rad = 0.2\n"
      "min_matched_points = 20\nmin_matched_fraction = 0.7\nmax_spread = 0.3\n"
      "wall_max_range_m = 2\nwall_max_gap_m = 0.3\nwall_split_tolerance_m = 0.04\nwall_min_points = 15\n"
      "wall_min_length_m = 0.8\nwall_min_sigma_deg = 0.4\nheading_noise_deg_per_frame = 0.1\n"
      "heading_noise_per_rad = 0.02\nheading_noise_deg_per_m = 0.5\nturn_scale_sigma = 0.03\n"
      "wall_gate_sigmas = 4\nwall_max_correction_deg = 8\nwall_new_direction_segments = 5\n"
      "wall_new_direction_spread_deg = 1.5\nwall_agreeing_segments = 2\nwall_offsets = false\nposition_noise_per_m = 0.04\n"
      "distance_scale_sigma = 0.02\nwall_min_offset_sigma_m = 0.03\nwall_max_join_gap_m = 2\n",
      loadLocalizationOptions);
  EXPECT_DOUBLE_EQ(options.max_range_m, 3.0);
  EXPECT_DOUBLE_EQ(options.point_spacing_m, 0.1);
  EXPECT_DOUBLE_EQ(options.disparity_sigma_px, 0.5);
  EXPECT_DOUBLE_EQ(options.min_point_sigma_m, 0.04);
  EXPECT_DOUBLE_EQ(options.outlier_probability, 0.3);
  EXPECT_DOUBLE_EQ(options.window_m, 0.5);
  EXPECT_DOUBLE_EQ(options.window_deg, 12.0);
  EXPECT_DOUBLE_EQ(options.step_m, 0.05);
  EXPECT_DOUBLE_EQ(options.step_deg, 2.0);
  EXPECT_DOUBLE_EQ(options.prior_sigma_m, 0.2);
  EXPECT_DOUBLE_EQ(options.prior_sigma_m_per_m, 0.05);
  EXPECT_DOUBLE_EQ(options.prior_sigma_deg, 4.0);
  EXPECT_DOUBLE_EQ(options.prior_sigma_per_rad, 0.2);
  EXPECT_EQ(options.min_matched_points, 20);
  EXPECT_DOUBLE_EQ(options.min_matched_fraction, 0.7);
  EXPECT_DOUBLE_EQ(options.max_spread, 0.3);
  const WallHeadingOptions& walls = options.walls;
  EXPECT_DOUBLE_EQ(walls.segments.max_range_m, 2.0);
  EXPECT_DOUBLE_EQ(walls.segments.max_gap_m, 0.3);
  EXPECT_DOUBLE_EQ(walls.segments.split_tolerance_m, 0.04);
  EXPECT_EQ(walls.segments.min_points, 15);
  EXPECT_DOUBLE_EQ(walls.segments.min_length_m, 0.8);
  EXPECT_DOUBLE_EQ(walls.min_sigma_deg, 0.4);
  EXPECT_DOUBLE_EQ(walls.heading_noise_deg_per_frame, 0.1);
  EXPECT_DOUBLE_EQ(walls.heading_noise_per_rad, 0.02);
  EXPECT_DOUBLE_EQ(walls.heading_noise_deg_per_m, 0.5);
  EXPECT_DOUBLE_EQ(walls.turn_scale_sigma, 0.03);
  EXPECT_DOUBLE_EQ(walls.gate_sigmas, 4.0);
  EXPECT_DOUBLE_EQ(walls.max_correction_deg, 8.0);
  EXPECT_EQ(walls.new_direction_segments, 5);
  EXPECT_DOUBLE_EQ(walls.new_direction_spread_deg, 1.5);
  EXPECT_EQ(walls.agreeing_segments, 2);
  const WallPositionOptions& position = options.wall_position;
  EXPECT_FALSE(position.enabled);
  EXPECT_DOUBLE_EQ(position.position_noise_per_m, 0.04);
  EXPECT_DOUBLE_EQ(position.distance_scale_sigma, 0.02);
  EXPECT_DOUBLE_EQ(position.min_offset_sigma_m, 0.03);
  EXPECT_DOUBLE_EQ(position.max_join_gap_m, 2.0);
}

TEST(LocalizationOptionsTest, FloorMotionLeavesTheFiltersNoScaleToLearnUnlessTold) {
  const LocalizationOptions wheels = loadSectionText("localization", "", loadLocalizationOptions);
  EXPECT_DOUBLE_EQ(wheels.walls.turn_scale_sigma, WallHeadingOptions().turn_scale_sigma);
  EXPECT_DOUBLE_EQ(wheels.wall_position.distance_scale_sigma, WallPositionOptions().distance_scale_sigma);
  EXPECT_GT(wheels.walls.turn_scale_sigma, 0.0);
  EXPECT_GT(wheels.wall_position.distance_scale_sigma, 0.0);

  const LocalizationOptions floor = loadSectionText("localization", "floor_motion = true\n", loadLocalizationOptions);
  EXPECT_EQ(floor.walls.turn_scale_sigma, 0.0);
  EXPECT_EQ(floor.wall_position.distance_scale_sigma, 0.0);

  const LocalizationOptions told = loadSectionText(
      "localization", "floor_motion = true\nturn_scale_sigma = 0.01\ndistance_scale_sigma = 0.02\n",
      loadLocalizationOptions);
  EXPECT_DOUBLE_EQ(told.walls.turn_scale_sigma, 0.01);
  EXPECT_DOUBLE_EQ(told.wall_position.distance_scale_sigma, 0.02);
}

TEST(LocalizationOptionsTest, RejectsBadValuesAndUnknownKeys) {
  for (const char* body : {"outlier_probability = 1\n", "step_m = 0\n", "min_matched_points = 0\n",
                           "wall_min_points = 2\n", "wall_max_correction_deg = 45\n",
                           "wall_new_direction_segments = 0\n",
                           "max_range_m = -1\n", "window = 0.3\n",
                           "min_matched_fraction = 1.5\n", "wall_min_offset_sigma_m = 0\n",
                           "wall_offsets = maybe\n", "wall_agreeing_segments = 0\n"}) {
    const std::string error =
        configErrorOf([&] { loadSectionText("localization", body, loadLocalizationOptions); });
    EXPECT_NE(error.find("[localization]"), std::string::npos) << body << ": " << error;
  }
}

}  // namespace
}  // namespace stereonav
