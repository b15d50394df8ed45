#include "observations/kitti_sequence.h"

#include <mrpt/core/bits_math.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace stereonav {
namespace {

// The excerpt is not shipped (non-commercial licence): it lives beside the project, or where
// STEREONAV_KITTI_EXCERPT says (e.g. from a git worktree elsewhere).
std::string excerptDirectory() {
  const char* directory = std::getenv("STEREONAV_KITTI_EXCERPT");
  return directory ? directory
                   : std::string(STEREONAV_SHARED_DATA_DIR) + "/kitti-odometry-excerpt";
}

TEST(KittiSequenceTest, ReadsTheExcerptsRigAndPoses) {
  const std::string excerpt = excerptDirectory();
  if (!std::filesystem::exists(excerpt + "/poses.txt")) {
    GTEST_SKIP() << excerpt << " is absent (set STEREONAV_KITTI_EXCERPT); skipping the KITTI test";
  }
  const KittiSequence sequence = loadKittiSequence(excerpt, 1.65);
  // README: f = 707.0912 px, B = 379.8145 / 707.0912 m, 1226 x 370, 51 frames, about 60 m.
  EXPECT_DOUBLE_EQ(sequence.rig.reference.focal_px, 707.0912);
  EXPECT_NEAR(sequence.rig.baseline_m, 379.8145 / 707.0912, 1e-9);
  EXPECT_EQ(sequence.rig.reference.width, 1226);
  EXPECT_EQ(sequence.rig.reference.height, 370);
  ASSERT_EQ(sequence.poses.size(), 51u);
  EXPECT_NEAR(sequence.poses.front().norm(), 0.0, 1e-9);
  double length = 0.0;
  for (size_t i = 1; i < sequence.poses.size(); ++i) {
    const mrpt::poses::CPose2D step = sequence.poses[i] - sequence.poses[i - 1];
    EXPECT_GT(step.x(), 0.5) << i;  // forward, along the car's heading
    length += step.norm();
  }
  EXPECT_NEAR(length, 60.0, 5.0);
  // The camera's z axis is the robot's x: the car drives along +x.
  EXPECT_GT(sequence.poses.back().x(), 55.0);

  const RigFrame frame = kittiFrame(sequence, 50, sequence.poses[50]);
  EXPECT_EQ(frame.reference.cols, 1226);
  ASSERT_EQ(frame.secondaries.size(), 1u);
  EXPECT_NO_THROW(checkRigFrame(frame));
  EXPECT_NEAR(mrpt::Clock::toDouble(frame.timestamp), 5.0, 1e-6);
}

TEST(KittiSequenceTest, OdometryErrorScalesDistancesAndDriftsTheHeadingFromItsSeed) {
  // A hand-made L: 2 m east, a quarter turn, 1 m north.
  const std::vector<mrpt::poses::CPose2D> truth{
      {0, 0, 0}, {1, 0, 0}, {2, 0, M_PI / 2}, {2, 1, M_PI / 2}};
  const std::vector<mrpt::poses::CPose2D> exact = odometryWithError(truth, {});
  ASSERT_EQ(exact.size(), truth.size());
  for (size_t i = 0; i < truth.size(); ++i) EXPECT_NEAR((exact[i] - truth[i]).norm(), 0.0, 1e-12) << i;

  OdometryError bias;
  bias.distance_bias = 0.1;  // every step 10% long, the turn kept
  const std::vector<mrpt::poses::CPose2D> long_steps = odometryWithError(truth, bias);
  EXPECT_NEAR(long_steps[3].x(), 2.2, 1e-12);
  EXPECT_NEAR(long_steps[3].y(), 1.1, 1e-12);
  EXPECT_NEAR(long_steps[3].phi(), M_PI / 2, 1e-12);

  OdometryError drift;
  drift.drift_deg_per_m = 2.0;
  drift.seed = 7;
  const std::vector<mrpt::poses::CPose2D> drifted = odometryWithError(truth, drift);
  EXPECT_GT(std::abs(drifted[3].phi() - M_PI / 2), 1e-6);           // the heading drifts
  EXPECT_LT(std::abs(drifted[3].phi() - M_PI / 2), mrpt::DEG2RAD(2.0 * 3 * 5));  // within 5 sigma
  EXPECT_NEAR(drifted[1].norm(), 1.0, 1e-12);  // a distance is kept
  const std::vector<mrpt::poses::CPose2D> again = odometryWithError(truth, drift);
  EXPECT_DOUBLE_EQ(again[3].phi(), drifted[3].phi());  // the same seed, the same drift
}

TEST(KittiSequenceTest, AMissingSequenceIsNamed) {
  try {
    loadKittiSequence("/nonexistent/kitti", 1.65);
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/kitti/calib.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace stereonav
