#include "observations/dataset_conversion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "observations/rawlog_reader.h"
#include "sample_frames.h"

namespace stereonav {
namespace {

// Not shipped (their licences): read from ../shared beside the project, skipped when absent.
const std::string kEuroc = std::string(STEREONAV_SHARED_DATA_DIR) + "/euroc-v1-01-clip";
const std::string kKitti = std::string(STEREONAV_SHARED_DATA_DIR) + "/kitti-odometry-excerpt";

std::vector<RigFrame> readBack(const std::string& path, SkippedFrames* skipped = nullptr) {
  RawlogReader reader(path, {});
  std::vector<RigFrame> frames;
  while (auto frame = reader.next()) frames.push_back(std::move(*frame));
  EXPECT_FALSE(reader.damage().has_value());
  if (skipped) *skipped = reader.skipped();
  return frames;
}

TEST(DatasetConversionTest, EurocClipBecomesARawPairThatIsRectifiedWhenRead) {
  if (!std::filesystem::exists(kEuroc + "/cam0/data.csv")) {
    GTEST_SKIP() << kEuroc << " is absent (EuRoC data are read from ../shared/data, not shipped)";
  }
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("euroc.rawlog");
  RawlogWriterOptions options;
  options.sensor_label = "EUROC";
  RawlogWriter writer(path, options);
  EXPECT_EQ(convertEuroc(kEuroc, writer), 20u);  // data.csv lists 95; the clip holds 20 pairs
  writer.finish();
  SkippedFrames skipped;
  const std::vector<RigFrame> frames = readBack(path, &skipped);
  EXPECT_EQ(skipped.total(), 0u) << skipped.summary();
  ASSERT_EQ(frames.size(), 20u);
  const CameraRig& rig = frames[0].rig;
  // sensor.yaml: fv = 456.134 is the smallest focal length; cam1 0.110 m to the right of cam0.
  EXPECT_NEAR(rig.reference.focal_px, 456.134, 1e-9);
  EXPECT_NEAR(rig.baseline_m, 0.110, 0.002);
  EXPECT_DOUBLE_EQ(rig.secondaries[0].bx, 1.0);
  EXPECT_EQ(frames[0].reference.size(), cv::Size(752, 480));
  EXPECT_NEAR(mrpt::Clock::toDouble(frames[1].timestamp) - mrpt::Clock::toDouble(frames[0].timestamp),
              0.05, 1e-3);
}

TEST(DatasetConversionTest, KittiExcerptKeepsItsRectifiedPairAndPosesAsOdometry) {
  if (!std::filesystem::exists(kKitti + "/calib.txt")) {
    GTEST_SKIP() << kKitti << " is absent (KITTI data are read from ../shared/data, not shipped)";
  }
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("kitti.rawlog");
  RawlogWriterOptions options;
  options.sensor_label = "KITTI";
  RawlogWriter writer(path, options);
  EXPECT_EQ(convertKitti(loadKittiSequence(kKitti, 1.65), {}, writer), 51u);
  writer.finish();
  const std::vector<RigFrame> frames = readBack(path);
  ASSERT_EQ(frames.size(), 51u);
  const CameraRig& rig = frames[0].rig;
  EXPECT_NEAR(rig.reference.focal_px, 707.0912, 1e-9);
  EXPECT_NEAR(rig.baseline_m, 379.8145 / 707.0912, 1e-9);
  EXPECT_EQ(frames[0].reference.size(), cv::Size(1226, 370));
  // The README: about 60 m straight ahead, about 1.2 m per frame. poses.txt line 2 moves the
  // camera 1.199 m along z (forward) and 0.014 m along -x (left): robot x 1.199, y +0.014.
  ASSERT_TRUE(frames[1].odometry.has_value());
  EXPECT_NEAR(frames[1].odometry->x(), 1.198998, 1e-6);
  EXPECT_NEAR(frames[1].odometry->y(), 0.01401751, 1e-6);
  EXPECT_GT(frames[50].odometry->x(), 50.0);
  EXPECT_LT(std::abs(frames[50].odometry->y()), 0.2 * frames[50].odometry->x());
}

}  // namespace
}  // namespace stereonav
