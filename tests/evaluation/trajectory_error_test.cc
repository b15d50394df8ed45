#include "evaluation/trajectory_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stereonav {
namespace {

TEST(TrajectoryErrorTest, HandMadePair) {
  // Truth: 4 m straight along x. Estimate: off sideways by 0, 0.1, -0.1, 0.2, 0.3 m, the last
  // two also turned by 2 degrees.
  std::vector<mrpt::poses::CPose2D> truth, estimate;
  const double offsets[] = {0.0, 0.1, -0.1, 0.2, 0.3};
  for (int i = 0; i < 5; ++i) {
    truth.emplace_back(i, 0.0, 0.0);
    estimate.emplace_back(i, offsets[i], i >= 3 ? mrpt::DEG2RAD(2.0) : 0.0);
  }
  const TrajectoryError error = trajectoryError(estimate, truth);
  EXPECT_EQ(error.poses, 5u);
  EXPECT_NEAR(error.length_m, 4.0, 1e-9);
  EXPECT_NEAR(error.rms_m, std::sqrt((0.01 + 0.01 + 0.04 + 0.09) / 5.0), 1e-9);
  EXPECT_NEAR(error.max_m, 0.3, 1e-9);
  EXPECT_NEAR(error.final_m, 0.3, 1e-9);
  EXPECT_NEAR(error.max_heading_deg, 2.0, 1e-9);
  EXPECT_NEAR(error.rms_heading_deg, std::sqrt(8.0 / 5.0), 1e-9);

  // The same estimate in another frame (its start elsewhere, turned a quarter) scores the same.
  const mrpt::poses::CPose2D elsewhere(5.0, -3.0, M_PI / 2);
  std::vector<mrpt::poses::CPose2D> moved;
  for (const auto& pose : estimate) moved.push_back(elsewhere + pose);
  const TrajectoryError moved_error = trajectoryError(moved, truth);
  EXPECT_NEAR(moved_error.rms_m, error.rms_m, 1e-9);
  EXPECT_NEAR(moved_error.final_m, error.final_m, 1e-9);
}

TEST(TrajectoryErrorTest, RejectsTrajectoriesThatDoNotPair) {
  EXPECT_THROW(trajectoryError({}, {}), std::invalid_argument);
  EXPECT_THROW(trajectoryError({{0, 0, 0}}, {{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
