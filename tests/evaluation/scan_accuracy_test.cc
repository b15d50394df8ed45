#include "evaluation/scan_accuracy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace stereonav {
namespace {

DisparityScan scanOf(const std::vector<float>& disparities, int row) {
  DisparityScan scan;
  scan.column_disparity = disparities;
  for (const float disparity : disparities) scan.column_row.push_back(isValidDisparity(disparity) ? row : -1);
  return scan;
}

TEST(ScanAccuracyTest, CountsPhantomsAndMissesAgainstTheTruthsColumns) {
  // A level camera on the robot's centre, f B = 16: disparity 16 is 1 m ahead, 4 is 4 m. Every
  // reading is on the optical axis's row, so its range on the floor is its depth to within 1%
  // (the columns are at most 4 pixels off the principal point).
  CameraRig rig;
  rig.reference.width = 8;
  rig.reference.cx = 3.0;
  rig.reference.cy = 100.0;
  rig.reference.focal_px = 160.0;
  rig.baseline_m = 0.1;
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);
  const float none = kInvalidDisparity;
  // Per column: nothing there, read at 1.6 m: a phantom within reach. 4 m, read 0.5 px nearer:
  // agrees. 4 m, read at 1.33 m: a phantom within reach. 1 m, read nothing: a miss. 1 m, read at
  // 3.2 m: a miss. 1.6 m, read 0.8 px nearer: agrees. 5.33 m, read at 3.2 m: a phantom out of reach.
  // 0.4 m (disparity 40), nearer than the matcher searches (31), read at its limit: too near.
  const DisparityScan truth = scanOf({none, 4.0f, 4.0f, 16.0f, 16.0f, 10.0f, 3.0f, 40.0f}, 100);
  const DisparityScan measured = scanOf({10.0f, 4.5f, 12.0f, none, 5.0f, 10.8f, 5.0f, 31.0f}, 100);
  ScanAccuracyOptions options;
  options.max_disparity = 31.0;
  const ScanAccuracy accuracy = compareScans(measured, truth, rig, options);
  EXPECT_EQ(accuracy.frames, 1u);
  EXPECT_EQ(accuracy.columns, 8u);
  EXPECT_EQ(accuracy.read, 7u);
  EXPECT_EQ(accuracy.agreeing, 2u);
  EXPECT_NEAR(accuracy.agreeingMeanError(), (0.5 + 0.8) / 2.0, 1e-6);
  EXPECT_NEAR(accuracy.agreeingRmsError(), std::sqrt((0.5 * 0.5 + 0.8 * 0.8) / 2.0), 1e-6);
  EXPECT_EQ(accuracy.phantoms, 3u);
  EXPECT_EQ(accuracy.close_phantoms, 2u);
  EXPECT_EQ(accuracy.too_near, 1u);
  EXPECT_EQ(accuracy.close_obstacles, 3u);
  EXPECT_EQ(accuracy.close_misses, 2u);

  ScanAccuracy twice = accuracy;
  twice += accuracy;
  EXPECT_EQ(twice.frames, 2u);
  EXPECT_EQ(twice.close_misses, 4u);
  EXPECT_EQ(twice.toJson(),
            "{\"frames\": 2, \"columns\": 16, \"read\": 14, \"agreeing\": 4, \"agreeing_mean_px\": 0.65, "
            "\"agreeing_rms_px\": 0.667083, \"phantoms\": 6, "
            "\"close_phantoms\": 4, \"too_near\": 2, \"close_obstacles\": 6, \"close_misses\": 4}");

  // Without a search limit the nearest column is an obstacle within reach, read 9 px farther: a miss.
  const ScanAccuracy unlimited = compareScans(measured, truth, rig, ScanAccuracyOptions{});
  EXPECT_EQ(unlimited.too_near, 0u);
  EXPECT_EQ(unlimited.close_obstacles, 4u);
  EXPECT_EQ(unlimited.close_misses, 3u);

  // Half a metre of reach leaves the phantoms and the obstacles out of it.
  options.close_range_m = 0.5;
  const ScanAccuracy near = compareScans(measured, truth, rig, options);
  EXPECT_EQ(near.phantoms, 3u);
  EXPECT_EQ(near.close_phantoms, 0u);
  EXPECT_EQ(near.close_obstacles, 0u);
  EXPECT_EQ(near.close_misses, 0u);
}

TEST(ScanAccuracyTest, ScansOfDifferentWidthsAreRefused) {
  EXPECT_THROW(compareScans(scanOf({1.0f, 2.0f}, 0), scanOf({1.0f}, 0), CameraRig{}, ScanAccuracyOptions{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
