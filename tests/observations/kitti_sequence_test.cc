#include "observations/kitti_sequence.h"

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
                   : std::string(STEREONAV_SOURCE_DIR) + "/../shared/data/kitti-odometry-excerpt";
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
