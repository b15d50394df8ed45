#include "disparity/disparity_evaluation.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <vector>

#include "disparity/disparity_image.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

TEST(DisparityEvaluationTest, CountsOnlyKnownPixelsInsideTheBorder) {
  // 6x3 image, 1-pixel border ignored: the inner 4x1 row is evaluated.
  cv::Mat1f truth(3, 6, 5.0f), disparity(3, 6, 100.0f);  // the border is all wrong: must not count
  truth(1, 4) = kInvalidDisparity;                           // unknown: not counted either
  disparity(1, 1) = 5.5f;                                    // error 0.5
  disparity(1, 2) = 6.5f;                                    // error 1.5: bad-1 only
  disparity(1, 3) = kInvalidDisparity;                       // known but no disparity
  disparity(1, 4) = 9.0f;                                    // unknown truth
  const DisparityEvaluation result = evaluateDisparity(disparity, truth, 1);
  EXPECT_EQ(result.known_pixels, 3);
  EXPECT_EQ(result.valid_pixels, 2);
  EXPECT_DOUBLE_EQ(result.density, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(result.bad_1, 0.5);
  EXPECT_DOUBLE_EQ(result.bad_2, 0.0);
  EXPECT_DOUBLE_EQ(result.mean_abs_error, 1.0);
}

TEST(DisparityEvaluationTest, ErrorsExactlyAtTheThresholdAreNotBad) {
  cv::Mat1f truth(1, 4, 4.0f), disparity(1, 4);
  disparity << 4.5f, 5.0f, 6.0f, 6.25f;
  const DisparityEvaluation result = evaluateDisparity(disparity, truth, 0);
  EXPECT_DOUBLE_EQ(result.bad_0_5, 3.0 / 4.0);
  EXPECT_DOUBLE_EQ(result.bad_1, 2.0 / 4.0);
  EXPECT_DOUBLE_EQ(result.bad_2, 1.0 / 4.0);
}

TEST(DisparityEvaluationTest, InlierRmsLeavesOutErrorsAboveOnePixel) {
  // Errors 0.25, -0.5, 1.0 (inliers) and 3.0 (left out): sqrt((0.0625 + 0.25 + 1) / 3).
  cv::Mat1f truth(1, 4, 10.0f), disparity(1, 4);
  disparity << 10.25f, 9.5f, 11.0f, 13.0f;
  const DisparityEvaluation result = evaluateDisparity(disparity, truth, 0);
  EXPECT_NEAR(result.inlier_rms_error, std::sqrt(1.3125 / 3.0), 1e-12);
  EXPECT_DOUBLE_EQ(result.mean_abs_error, (0.25 + 0.5 + 1.0 + 3.0) / 4.0);
}

TEST(DisparityEvaluationTest, LoadsMiddleburyGroundTruthWithScaleAndUnknownZero) {
  const test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("truth.pgm");
  cv::Mat1b raw(2, 2);
  raw << 0, 16, 80, 255;
  ASSERT_TRUE(cv::imwrite(path, raw));
  const cv::Mat1f truth = loadMiddleburyGroundTruth(path, 16.0);
  EXPECT_EQ(truth(0, 0), kInvalidDisparity);
  EXPECT_FLOAT_EQ(truth(0, 1), 1.0f);
  EXPECT_FLOAT_EQ(truth(1, 0), 5.0f);
  EXPECT_FLOAT_EQ(truth(1, 1), 255.0f / 16.0f);
  EXPECT_THROW(loadMiddleburyGroundTruth("/nonexistent/gt.pgm", 16.0), std::runtime_error);
}

TEST(DisparityEvaluationTest, MaskLeavesOutItsZeroPixels) {
  cv::Mat1f truth(1, 4, 3.0f), disparity(1, 4, 3.0f);
  disparity(0, 1) = 9.0f;  // bad, but masked out
  disparity(0, 2) = kInvalidDisparity;
  cv::Mat1b mask(1, 4, uchar{255});
  mask(0, 1) = 0;
  const DisparityEvaluation result = evaluateDisparity(disparity, truth, 0, mask);
  EXPECT_EQ(result.known_pixels, 3);
  EXPECT_EQ(result.valid_pixels, 2);
  EXPECT_DOUBLE_EQ(result.bad_1, 0.0);
  EXPECT_THROW(evaluateDisparity(disparity, truth, 0, cv::Mat1b(2, 4, uchar{255})), std::invalid_argument);
}

TEST(DisparityEvaluationTest, NonOccludedMaskHidesWhatTheForegroundCovers) {
  // One row: background at disparity 2, a foreground block at 6..8 with disparity 5. In the camera
  // at (1, 0), pixel x lands at x - d: the block lands on 1..3, where background pixels 3..5 land
  // too (they are hidden); background pixels 0 and 1 land outside the image.
  cv::Mat1f truth(1, 12, 2.0f);
  truth.colRange(6, 9).setTo(5.0f);
  truth(0, 10) = kInvalidDisparity;  // unknown
  const cv::Mat1b visible = nonOccludedMask(truth, SecondaryCamera{1.0, 0.0});
  const std::vector<int> expected{0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 0, 255};
  for (int x = 0; x < 12; ++x) EXPECT_EQ(visible(0, x), expected[x]) << "x = " << x;
  // A camera on the other side (x + d): background pixel 9 lands on 11 with block pixel 6 (hidden);
  // block pixels 7, 8 and background pixel 11 land outside.
  const cv::Mat1b mirrored = nonOccludedMask(truth, SecondaryCamera{-1.0, 0.0});
  const std::vector<int> expected_mirrored{255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0, 0};
  for (int x = 0; x < 12; ++x) EXPECT_EQ(mirrored(0, x), expected_mirrored[x]) << "x = " << x;
}

TEST(DisparityEvaluationTest, LoadsMiddleburyMasksAs255Only) {
  const test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("mask.png");
  cv::Mat1b raw(1, 3);
  raw << 0, 128, 255;
  ASSERT_TRUE(cv::imwrite(path, raw));
  const cv::Mat1b mask = loadEvaluationMask(path);
  EXPECT_EQ(mask(0, 0), 0);
  EXPECT_EQ(mask(0, 1), 0);
  EXPECT_EQ(mask(0, 2), 255);
  EXPECT_THROW(loadEvaluationMask("/nonexistent/mask.png"), std::runtime_error);
}

}  // namespace
}  // namespace stereonav
