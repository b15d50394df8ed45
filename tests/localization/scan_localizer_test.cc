#include "localization/scan_localizer.h"

#include <gtest/gtest.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include "hand_drawn_map.h"

namespace stereonav {
namespace {

// A 4 m x 4 m room, its walls on the centres of 5 cm cells.
const std::vector<testing::Segment> kRoom = {{0.025, 0.025, 4.025, 0.025},
                                             {4.025, 0.025, 4.025, 4.025},
                                             {4.025, 4.025, 0.025, 4.025},
                                             {0.025, 4.025, 0.025, 0.025}};

LocalizationOptions roomOptions() {
  LocalizationOptions options;
  options.max_range_m = 4.0;
  return options;
}

TEST(ScanLocalizerTest, AScanWithNoValidColumnsKeepsOdometry) {
  const DisparityTaggedGrid map = testing::drawGrid(kRoom, -1.0, 5.0, 0.05);
  ScanLocalizer localizer(roomOptions(), 0.0);
  const mrpt::poses::CPose2D start(1.5, 1.5, 0.4);
  localizer.update(start, testing::scanOf(kRoom, start), map);
  const mrpt::poses::CPose2D corrected_start = localizer.pose();

  mrpt::obs::CObservation2DRangeScan blind = testing::scanOf(kRoom, start);
  for (size_t ray = 0; ray < blind.getScanSize(); ++ray) blind.setScanRangeValidity(ray, false);
  const mrpt::poses::CPose2D odometry(1.8, 1.7, 0.6);
  const ScanMatch& match = localizer.update(odometry, blind, map);
  EXPECT_FALSE(match.corrected);
  EXPECT_EQ(match.points, 0);
  const mrpt::poses::CPose2D expected = corrected_start + (odometry - start);
  EXPECT_NEAR(localizer.pose().x(), expected.x(), 1e-9);
  EXPECT_NEAR(localizer.pose().y(), expected.y(), 1e-9);
  EXPECT_NEAR(localizer.pose().phi(), expected.phi(), 1e-9);
}

TEST(ScanLocalizerTest, CorrectsOdometryThatDriftsAwayFromTheMap) {
  // Odometry that over-reads every step by 10% and turns 1 degree too far: the localized poses
  // stay on the true path while raw odometry drifts off it.
  const DisparityTaggedGrid map = testing::drawGrid(kRoom, -1.0, 5.0, 0.05);
  ScanLocalizer localizer(roomOptions(), 0.0);
  mrpt::poses::CPose2D truth(1.0, 1.0, mrpt::DEG2RAD(45.0));
  mrpt::poses::CPose2D odometry = truth;
  const mrpt::poses::CPose2D step(0.1, 0.0, mrpt::DEG2RAD(2.0));
  const mrpt::poses::CPose2D step_read(0.11, 0.0, mrpt::DEG2RAD(3.0));
  for (int i = 0; i < 12; ++i) {
    if (i > 0) {
      truth = truth + step;
      odometry = odometry + step_read;
    }
    localizer.update(odometry, testing::scanOf(kRoom, truth), map);
    EXPECT_NEAR(localizer.pose().x(), truth.x(), 0.02) << i;
    EXPECT_NEAR(localizer.pose().y(), truth.y(), 0.02) << i;
    EXPECT_NEAR(localizer.pose().phi(), truth.phi(), mrpt::DEG2RAD(0.5)) << i;
  }
  EXPECT_GT(std::hypot(odometry.x() - truth.x(), odometry.y() - truth.y()), 0.1);
}

TEST(ScanLocalizerTest, WithoutMatchingTheWallsStillHoldTheHeading) {
  // Both windows 0: no match against the map (given empty), the position is odometry's, and the
  // heading is kept by the room's walls while odometry turns every turn 3% too far. The robot
  // turns on the spot and steps forward; after 120 frames odometry is 120 * 0.15 * 0.03 rad
  // (31 degrees) off.
  LocalizationOptions options = roomOptions();
  options.window_m = 0.0;
  options.window_deg = 0.0;
  ScanLocalizer localizer(options, 0.0);
  const DisparityTaggedGrid empty = testing::drawGrid({}, -1.0, 5.0, 0.05);
  mrpt::poses::CPose2D truth(2.0, 2.0, 0.3);
  mrpt::poses::CPose2D odometry = truth;
  for (int i = 0; i < 120; ++i) {
    if (i > 0) {
      const double forward = i % 10 == 0 ? 0.05 : 0.0;
      truth = truth + mrpt::poses::CPose2D(forward, 0.0, 0.15);
      odometry = odometry + mrpt::poses::CPose2D(forward, 0.0, 0.15 * 1.03);
    }
    localizer.update(odometry, testing::scanOf(kRoom, truth), empty);
    if (i >= 60) {
      EXPECT_NEAR(mrpt::math::wrapToPi(localizer.pose().phi() - truth.phi()), 0.0, mrpt::DEG2RAD(0.3)) << i;
    }
  }
  EXPECT_GT(std::abs(mrpt::math::wrapToPi(odometry.phi() - truth.phi())), mrpt::DEG2RAD(20.0));
  EXPECT_NEAR(localizer.pose().x(), truth.x(), 0.05);
  EXPECT_NEAR(localizer.pose().y(), truth.y(), 0.05);
}

}  // namespace
}  // namespace stereonav
