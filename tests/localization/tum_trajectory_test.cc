#include "localization/tum_trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "support/scratch_directory.h"

namespace stereonav {
namespace {

class TumTrajectoryTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return scratch_.file(name); }

  test_support::ScratchDirectory scratch_;
};

TEST_F(TumTrajectoryTest, WritesTheTumFormatAndReadsItBack) {
  const std::vector<StampedPose> trajectory = {{0.0, {0.0, 0.0, 0.0}},
                                               {0.2, {1.5, -2.25, M_PI / 2}},
                                               {0.4, {3.0, 1.0, -3.0}}};
  saveTumTrajectory(path("t.tum"), trajectory);
  std::ifstream file(path("t.tum"));
  std::string header, second;
  std::getline(file, header);
  std::getline(file, second);
  std::getline(file, second);
  // A quarter turn about z: q = (0, 0, sin 45, cos 45).
  EXPECT_EQ(second, "0.200000 1.500000 -2.250000 0 0 0 0.707106781 0.707106781");

  const std::vector<StampedPose> loaded = loadTrajectory(path("t.tum"));
  ASSERT_EQ(loaded.size(), trajectory.size());
  for (size_t i = 0; i < loaded.size(); ++i) {
    EXPECT_NEAR(loaded[i].time_s, trajectory[i].time_s, 1e-6);
    EXPECT_NEAR(loaded[i].pose.x(), trajectory[i].pose.x(), 1e-6);
    EXPECT_NEAR(loaded[i].pose.y(), trajectory[i].pose.y(), 1e-6);
    EXPECT_NEAR(loaded[i].pose.phi(), trajectory[i].pose.phi(), 1e-6);
  }
}

TEST_F(TumTrajectoryTest, ReadsThePoseListFormatAndRejectsOthers) {
  std::ofstream(path("gt.txt")) << "# t x y phi\n0 1 7.5 0\n\n0.2 1.022 7.5 0.1  # moving\n";
  const std::vector<StampedPose> loaded = loadTrajectory(path("gt.txt"));
  ASSERT_EQ(loaded.size(), 2u);
  EXPECT_DOUBLE_EQ(loaded[1].pose.x(), 1.022);
  EXPECT_NEAR(loaded[1].pose.phi(), 0.1, 1e-12);

  std::ofstream(path("bad.txt")) << "0 1 7.5 0\n0 1 2\n";
  try {
    loadTrajectory(path("bad.txt"));
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("bad.txt:2"), std::string::npos) << error.what();
  }
  std::ofstream(path("text.txt")) << "0 1 x 0\n";
  EXPECT_THROW(loadTrajectory(path("text.txt")), std::runtime_error);
  EXPECT_THROW(loadTrajectory(path("missing.txt")), std::runtime_error);
}

}  // namespace
}  // namespace stereonav
