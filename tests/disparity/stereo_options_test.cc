#include "disparity/stereo_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include "shipped_config.h"
#include "support/options_loading.h"

namespace stereonav {
namespace {

StereoOptions load(const std::string& text) {
  return test_support::loadSectionText("stereo", text, loadStereoOptions);
}

std::string errorOf(const std::string& text) {
  return test_support::configErrorOf([&] { load(text); });
}

TEST(StereoOptionsTest, LoadsEveryKey) {
  const StereoOptions options = load(
      "backend = sgbm\nmin_disparity = 2\nmax_disparity = 47\nwindow = 9\nprefilter = log\nprefilter_cap = 20\n"
      "pixel_cost = birchfield_tomasi\nintensity_term = true\npartial_candidates = true\ncombination = best_half\naggregation = semiglobal\nscanline_p1 = 3\nscanline_p2 = 40\ntexture_threshold = 1.5\ntexture_sigma = 2\nuniqueness_threshold = 0.03\n"
      "second_best_ratio = 0.85\nleft_right_check = false\nleft_right_max_diff = 2\nfattening_min_step = 12\nfattening_min_jump = 3\nsubpixel = true\nthreads = 4\nsimd = sse2\n"
      "opencv_texture_threshold = 5\nopencv_uniqueness_ratio = 10\nopencv_speckle_window = 100\n"
      "opencv_speckle_range = 2\n");
  EXPECT_EQ(options.backend, StereoBackend::kOpenCvSgbm);
  EXPECT_EQ(options.min_disparity, 2);
  EXPECT_EQ(options.max_disparity, 47);
  EXPECT_EQ(options.disparityCount(), 46);
  EXPECT_EQ(options.window, 9);
  EXPECT_EQ(options.prefilter, Prefilter::kLog);
  EXPECT_EQ(options.prefilter_cap, 20);
  EXPECT_EQ(options.pixel_cost, PixelCost::kBirchfieldTomasi);
  EXPECT_TRUE(options.intensity_term);
  EXPECT_TRUE(options.partial_candidates);
  EXPECT_EQ(options.combination, CameraCombination::kBestHalf);
  EXPECT_EQ(options.aggregation, CostAggregation::kSemiGlobal);
  EXPECT_DOUBLE_EQ(options.scanline_p1, 3.0);
  EXPECT_DOUBLE_EQ(options.scanline_p2, 40.0);
  EXPECT_DOUBLE_EQ(options.texture_threshold, 1.5);
  EXPECT_DOUBLE_EQ(options.texture_sigma, 2.0);
  EXPECT_DOUBLE_EQ(options.uniqueness_threshold, 0.03);
  EXPECT_DOUBLE_EQ(options.second_best_ratio, 0.85);
  EXPECT_FALSE(options.left_right_check);
  EXPECT_DOUBLE_EQ(options.left_right_max_diff, 2.0);
  EXPECT_DOUBLE_EQ(options.fattening_min_step, 12.0);
  EXPECT_DOUBLE_EQ(options.fattening_min_jump, 3.0);
  EXPECT_TRUE(options.subpixel);
  EXPECT_EQ(options.threads, 4);
  EXPECT_EQ(options.simd, SimdLevel::kSse2);
  EXPECT_EQ(options.opencv_texture_threshold, 5);
  EXPECT_EQ(options.opencv_uniqueness_ratio, 10);
  EXPECT_EQ(options.opencv_speckle_window, 100);
  EXPECT_EQ(options.opencv_speckle_range, 2);
}

TEST(StereoOptionsTest, EmptySectionGivesTheDefaults) {
  const StereoOptions options = load("");
  const StereoOptions defaults;
  EXPECT_EQ(options.max_disparity, defaults.max_disparity);
  EXPECT_EQ(options.window, 7);
  EXPECT_EQ(options.backend, StereoBackend::kSad);
  EXPECT_FALSE(options.subpixel);  // paper section 3.2
  EXPECT_DOUBLE_EQ(options.second_best_ratio, 1.0);  // the paper's quality-of-match test only
  EXPECT_EQ(options.aggregation, CostAggregation::kWindow);  // the paper's window SAD alone
  EXPECT_EQ(options.simd, SimdLevel::kAuto);
  EXPECT_FALSE(options.intensity_term);      // the paper's cost on the prefiltered images alone
  EXPECT_FALSE(options.partial_candidates);  // pixels that miss candidates stay unmatched
  EXPECT_EQ(options.fattening_min_step, 0.0);  // the paper has no depth-edge test
}

TEST(StereoOptionsTest, UnknownKeyIsNamedWithTheNearestKnownOne) {
  const std::string message = errorOf("uniquenes_threshold = 0.1\n");
  EXPECT_NE(message.find("uniquenes_threshold"), std::string::npos) << message;
  EXPECT_NE(message.find("'uniqueness_threshold'"), std::string::npos) << message;
}

TEST(StereoOptionsTest, BadValuesNameTheKey) {
  EXPECT_NE(errorOf("window = 8\n").find("[stereo] window"), std::string::npos);
  EXPECT_NE(errorOf("window = 1\n").find("[stereo] window"), std::string::npos);
  EXPECT_NE(errorOf("max_disparity = 0\n").find("[stereo] max_disparity"), std::string::npos);
  EXPECT_NE(errorOf("backend = census\n").find("[stereo] backend: expected bm | sad | sgbm"), std::string::npos);
  EXPECT_NE(errorOf("prefilter = median\n").find("[stereo] prefilter"), std::string::npos);
  EXPECT_NE(errorOf("threads = 0\n").find("[stereo] threads"), std::string::npos);
  EXPECT_NE(errorOf("second_best_ratio = 0\n").find("[stereo] second_best_ratio"), std::string::npos);
  EXPECT_NE(errorOf("second_best_ratio = 1.5\n").find("[stereo] second_best_ratio"), std::string::npos);
  EXPECT_NE(errorOf("texture_threshold = -1\n").find("[stereo] texture_threshold"), std::string::npos);
  EXPECT_NE(errorOf("prefilter_cap = 200\n").find("[stereo] prefilter_cap"), std::string::npos);
  EXPECT_NE(errorOf("aggregation = sgm\n").find("[stereo] aggregation: expected scanline | semiglobal | window"), std::string::npos);
  EXPECT_NE(errorOf("pixel_cost = census\n").find("[stereo] pixel_cost: expected absolute_difference | birchfield_tomasi | birchfield_tomasi_one_sided"),
            std::string::npos);
  EXPECT_NE(errorOf("aggregation = semiglobal\nwindow = 231\n").find("[stereo] window: must be at most 229"),
            std::string::npos);
  EXPECT_NE(errorOf("scanline_p1 = -1\n").find("[stereo] scanline_p1"), std::string::npos);
  EXPECT_NE(errorOf("scanline_p1 = 10\nscanline_p2 = 5\n").find("[stereo] scanline_p2"), std::string::npos);
  EXPECT_NE(errorOf("scanline_p2 = 300\n").find("[stereo] scanline_p2"), std::string::npos);
  EXPECT_NE(errorOf("intensity_term = true\nprefilter = none\n").find("[stereo] intensity_term: needs prefilter"),
            std::string::npos);
  EXPECT_NE(errorOf("intensity_term = true\nprefilter_cap = 64\n").find("[stereo] intensity_term"), std::string::npos);
  EXPECT_NE(errorOf("fattening_min_step = -1\n").find("[stereo] fattening_min_step"), std::string::npos);
  EXPECT_NE(errorOf("fattening_min_jump = 0\n").find("[stereo] fattening_min_jump"), std::string::npos);
  EXPECT_NE(errorOf("simd = avx512\n").find("[stereo] simd: expected auto | avx2 | sse2"), std::string::npos);
}

TEST(StereoOptionsTest, ShippedConfigurationsLoad) {
  // The 320x240 example is the library's defaults; the 160x120 one halves the disparity range
  // and doubles the uniqueness threshold with it.
  const StereoOptions full = testing::shippedStereoOptions("trinocular_320x240.ini");
  const StereoOptions defaults;
  EXPECT_EQ(full.max_disparity, defaults.max_disparity);
  EXPECT_DOUBLE_EQ(full.uniqueness_threshold, defaults.uniqueness_threshold);
  EXPECT_DOUBLE_EQ(full.texture_threshold, defaults.texture_threshold);
  EXPECT_EQ(full.left_right_check, defaults.left_right_check);
  EXPECT_EQ(full.prefilter, defaults.prefilter);
  const StereoOptions half = testing::shippedStereoOptions("trinocular_160x120.ini");
  EXPECT_EQ(half.disparityCount(), full.disparityCount() / 2);
  EXPECT_DOUBLE_EQ(half.uniqueness_threshold, 2 * full.uniqueness_threshold);
}

}  // namespace
}  // namespace stereonav
