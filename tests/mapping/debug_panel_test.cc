#include "mapping/debug_panel.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>

#include "support/scratch_directory.h"
#include "synthetic_scene.h"

namespace stereonav {
namespace {

using testing::SyntheticScene;
using testing::Wall;

int countColour(const cv::Mat3b& image, const cv::Vec3b& colour) {
  int count = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) count += image(y, x) == colour ? 1 : 0;
  }
  return count;
}

// A wall ahead seen through sensor noise, so that matching leaves spikes for segmentation to
// reject (the floor and the sky are flat but for the noise).
class DebugPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const SyntheticScene scene({Wall{2.0, -3.0, 2.0, 3.0}});
    frame_ = scene.renderFrame(testing::testRig(), {}, mrpt::Clock::fromDouble(1.0));
    cv::RNG noise(3);
    for (cv::Mat* image : {&frame_.reference, &frame_.secondaries[0], &frame_.secondaries[1]}) {
      cv::Mat1s deviation(image->size()), noisy;
      noise.fill(deviation, cv::RNG::NORMAL, 0.0, 3.0);
      image->convertTo(noisy, CV_16S);
      noisy += deviation;
      noisy.convertTo(*image, CV_8U);
    }
  }
  RigFrame frame_;
  MappingOptions options_;
};

TEST_F(DebugPanelTest, RejectedSurfacesAreMagentaPixelForPixel) {
  DisparityScanner scanner(testing::testRig(), options_.stereo, options_.spike_removal, options_.projection);
  StageTimes times;
  scanner.scan(frame_, times);
  const int rejected = cv::countNonZero(scanner.rejected());
  ASSERT_GT(rejected, 0) << "the noise should leave spikes to reject";
  DebugPanelRenderer renderer(options_, testing::testRig());
  const cv::Mat3b panel = renderer.render(scanner, 7, {});
  // The 320-pixel-wide reference is shown at scale 1; magenta appears nowhere else.
  EXPECT_EQ(countColour(panel, cv::Vec3b(255, 0, 255)), rejected);
}

TEST_F(DebugPanelTest, SmallImagesAreEnlargedToStayReadable) {
  CameraRig small = testing::testRig();
  small.reference = {160, 120, 80.0, 79.5, 59.5};
  const SyntheticScene scene({Wall{2.0, -3.0, 2.0, 3.0}});
  const RigFrame frame = scene.renderFrame(small, {}, mrpt::Clock::fromDouble(1.0));
  options_.stereo.max_disparity = 15;
  DisparityScanner scanner(small, options_.stereo, options_.spike_removal, options_.projection);
  StageTimes times;
  scanner.scan(frame, times);
  DebugPanelRenderer small_renderer(options_, small);
  DebugPanelRenderer renderer(options_, testing::testRig());
  DisparityScanner full_scanner(testing::testRig(), options_.stereo, options_.spike_removal, options_.projection);
  full_scanner.scan(frame_, times);
  // Twice the pixels per image pixel: the same layout as the 320x240 panel.
  EXPECT_EQ(small_renderer.render(scanner, 0, {}).size(), renderer.render(full_scanner, 0, {}).size());
}

TEST_F(DebugPanelTest, BlindColumnsAreMarkedBlackUnderTheColumnStrip) {
  // The scene's floor has no texture: every column whose bottom rows show it is blind.
  StageTimes times;
  DisparityScanner unchecked(testing::testRig(), options_.stereo, options_.spike_removal, options_.projection);
  unchecked.scan(frame_, times);
  const cv::Mat3b plain = DebugPanelRenderer(options_, testing::testRig()).render(unchecked, 0, {});
  options_.projection.near_floor_m = 0.3;
  DisparityScanner scanner(testing::testRig(), options_.stereo, options_.spike_removal, options_.projection);
  scanner.scan(frame_, times);
  int blind = 0;
  for (int column = 0; column < scanner.lastScan().columns(); ++column) blind += scanner.lastScan().blind(column);
  ASSERT_GT(blind, 0);
  const cv::Mat3b marked = DebugPanelRenderer(options_, testing::testRig()).render(scanner, 0, {});
  ASSERT_EQ(marked.size(), plain.size());
  // The lower third of the 28-pixel strip (10 rows) of each blind column (one panel pixel wide at
  // scale 1) turns black, and nothing else does (the caption also counts them).
  const cv::Vec3b black(0, 0, 0);
  int turned_black = 0;
  for (int y = 0; y < marked.rows; ++y) {
    for (int x = 0; x < marked.cols; ++x) turned_black += marked(y, x) == black && plain(y, x) != black;
  }
  EXPECT_EQ(turned_black, blind * 10);
}

TEST_F(DebugPanelTest, SavedPanelReadsBackUnchanged) {
  DisparityScanner scanner(testing::testRig(), options_.stereo, options_.spike_removal, options_.projection);
  StageTimes times;
  scanner.scan(frame_, times);
  DebugPanelRenderer renderer(options_, testing::testRig());
  const cv::Mat3b panel = renderer.render(scanner, 42, {});
  const test_support::ScratchDirectory scratch;
  const std::filesystem::path& directory = scratch.path();
  saveDebugPanel(panel, directory.string(), 42);
  const cv::Mat read = cv::imread((directory / "panel_000042.png").string(), cv::IMREAD_COLOR);
  ASSERT_EQ(read.size(), panel.size());
  EXPECT_EQ(cv::norm(read, panel, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace stereonav
