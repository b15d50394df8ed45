#include "disparity/opencv_matchers.h"

#include <gtest/gtest.h>

#include "synthetic_scene.h"

namespace stereonav {
namespace {

using testing::rectMask;
using testing::shareCorrect;
using testing::SyntheticScene;

const cv::Size kSize(120, 100);

class OpenCvBackendTest : public ::testing::TestWithParam<std::tuple<StereoBackend, SecondaryCamera>> {};

// The OpenCV matchers only know a right camera at x - d; flipping and transposing must give the
// same disparity image convention for every unit baseline.
TEST_P(OpenCvBackendTest, FindsAPlaneForEveryUnitBaseline) {
  const auto [backend, camera] = GetParam();
  SyntheticScene scene(kSize, 7.0, 31);
  const StereoFrame frame{scene.view(0, 0), {{scene.view(camera.bx, camera.by), camera}}};
  StereoOptions options;
  options.backend = backend;
  options.max_disparity = 15;
  const cv::Mat1f disparity = matchOpenCv(frame, options);
  ASSERT_EQ(disparity.size(), kSize);
  EXPECT_GE(shareCorrect(disparity, scene.trueDisparity(), rectMask(kSize, cv::Rect(25, 25, 70, 50))), 0.98);
}

INSTANTIATE_TEST_SUITE_P(
    Baselines, OpenCvBackendTest,
    ::testing::Combine(::testing::Values(StereoBackend::kOpenCvBm, StereoBackend::kOpenCvSgbm),
                       ::testing::Values(SecondaryCamera{1, 0}, SecondaryCamera{-1, 0}, SecondaryCamera{0, 1},
                                         SecondaryCamera{0, -1})));

TEST(OpenCvBackendTest, RejectsRigsOpenCvCannotMatch) {
  const cv::Mat1b image(40, 60, uchar{0});
  StereoOptions options;
  options.backend = StereoBackend::kOpenCvBm;
  options.max_disparity = 15;
  EXPECT_THROW(matchOpenCv({image, {{image, {2, 0}}}}, options), std::invalid_argument);
  EXPECT_THROW(matchOpenCv({image, {{image, {1, 0}}, {image, {0, 1}}}}, options), std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
