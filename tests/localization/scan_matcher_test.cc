#include "localization/scan_matcher.h"

#include <gtest/gtest.h>

#include <mrpt/math/wrap2pi.h>

#include "hand_drawn_map.h"

namespace stereonav {
namespace {

using testing::Segment;

// Walls are drawn on the centres of 5 cm cells (odd multiples of 2.5 cm), where the map puts them.

// A 4 m x 4 m room with a box in it: seen from inside, its corners pin down all three
// directions of a pose.
const std::vector<Segment> kRoom = {
    {0.025, 0.025, 4.025, 0.025}, {4.025, 0.025, 4.025, 4.025}, {4.025, 4.025, 0.025, 4.025},
    {0.025, 4.025, 0.025, 0.025}, {2.825, 1.025, 3.225, 1.025}, {3.225, 1.025, 3.225, 1.425},
    {3.225, 1.425, 2.825, 1.425}, {2.825, 1.425, 2.825, 1.025}};

// A straight corridor 2 m wide, far longer than the readings reach.
const std::vector<Segment> kCorridor = {{-10, 0.025, 10, 0.025}, {-10, 2.025, 10, 2.025}};

LocalizationOptions wideSearch() {
  LocalizationOptions options;
  options.max_range_m = 4.0;
  options.window_m = 0.4;
  options.window_deg = 15.0;
  // Spreads are fractions of the window; this one is wider than the default.
  options.max_spread = 0.2;
  return options;
}

// A loose prior: the scan alone has to find the offset.
const PriorSigma kLoosePrior{1.0, mrpt::DEG2RAD(30.0)};

double headingErrorDeg(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b) {
  return std::abs(mrpt::RAD2DEG(mrpt::math::wrapToPi(a.phi() - b.phi())));
}

TEST(ScanMatcherTest, RecoversAKnownOffsetAgainstAHandDrawnMap) {
  const DisparityTaggedGrid map = testing::drawGrid(kRoom, -1.0, 5.0, 0.05);
  const ObstacleDistanceField field(map, 1.0);
  const LocalizationOptions options = wideSearch();
  for (const mrpt::poses::CPose2D& truth :
       {mrpt::poses::CPose2D(1.5, 1.6, mrpt::DEG2RAD(30.0)), mrpt::poses::CPose2D(2.0, 2.5, mrpt::DEG2RAD(-60.0))}) {
    const auto points = matchablePoints(testing::scanOf(kRoom, truth), 0.0, options);
    ASSERT_GE(points.size(), 30u);
    // Odometry 0.3 m off to one side and 10 degrees off in heading.
    const mrpt::poses::CPose2D prior(truth.x() + 0.3 * std::cos(1.0), truth.y() - 0.3 * std::sin(1.0),
                                     truth.phi() + mrpt::DEG2RAD(10.0));
    const ScanMatch match = matchScan(points, field, prior, kLoosePrior, options);
    EXPECT_TRUE(match.corrected);
    EXPECT_EQ(match.constrained_directions, 3);
    EXPECT_NEAR(match.pose.x(), truth.x(), 0.02) << truth;
    EXPECT_NEAR(match.pose.y(), truth.y(), 0.02) << truth;
    EXPECT_LT(headingErrorDeg(match.pose, truth), 0.5) << truth;
    EXPECT_EQ(match.matched_points, match.points);
  }
}

TEST(ScanMatcherTest, AStraightCorridorCorrectsTheWallDistanceButNotThePositionAlongIt) {
  const DisparityTaggedGrid map = testing::drawGrid(kCorridor, -12.0, 12.0, 0.05);
  const ObstacleDistanceField field(map, 1.0);
  LocalizationOptions options = wideSearch();
  options.max_range_m = 2.5;
  const mrpt::poses::CPose2D truth(0.0, 1.025, 0.0);
  const auto points = matchablePoints(testing::scanOf(kCorridor, truth), 0.0, options);
  ASSERT_GE(points.size(), 30u);
  // Odometry 0.25 m ahead along the corridor, 0.15 m to the side, 5 degrees turned.
  const mrpt::poses::CPose2D prior(0.25, 1.175, mrpt::DEG2RAD(5.0));
  const ScanMatch match = matchScan(points, field, prior, kLoosePrior, options);
  EXPECT_TRUE(match.corrected);
  EXPECT_EQ(match.constrained_directions, 2);
  EXPECT_NEAR(match.pose.x(), prior.x(), 0.02) << "jumped along the corridor";
  EXPECT_NEAR(match.pose.y(), truth.y(), 0.02);
  EXPECT_LT(headingErrorDeg(match.pose, truth), 0.5);
}

TEST(ScanMatcherTest, KeepsThePriorWithoutEnoughReadingsOrAMap) {
  const DisparityTaggedGrid map = testing::drawGrid(kRoom, -1.0, 5.0, 0.05);
  const ObstacleDistanceField field(map, 1.0);
  const LocalizationOptions options = wideSearch();
  const mrpt::poses::CPose2D prior(1.8, 1.5, 0.5);
  EXPECT_FALSE(matchScan({}, field, prior, kLoosePrior, options).corrected);
  EXPECT_EQ(matchScan({}, field, prior, kLoosePrior, options).pose, prior);

  const DisparityTaggedGrid empty = testing::drawGrid({}, -1.0, 5.0, 0.05);
  const auto points = matchablePoints(testing::scanOf(kRoom, {1.5, 1.6, 0.5}), 0.0, options);
  const ScanMatch match = matchScan(points, ObstacleDistanceField(empty, 1.0), prior, kLoosePrior, options);
  EXPECT_FALSE(match.corrected);
  EXPECT_EQ(match.pose, prior);
}

TEST(ScanMatcherTest, MatchablePointsAreNearThinnedAndLessPreciseFarther) {
  // A wall 1 m ahead, seen over 90 degrees: ranges 1 .. 1.41 m.
  const std::vector<Segment> wall = {{1.0, -5.0, 1.0, 5.0}};
  const auto scan = testing::scanOf(wall, {0, 0, 0}, 400);
  LocalizationOptions options;
  options.point_spacing_m = 0.1;
  options.max_range_m = 1.2;
  options.disparity_sigma_px = 0.5;
  options.min_point_sigma_m = 0.01;
  const double focal_baseline = 8.0;  // 80 px x 0.1 m
  const auto points = matchablePoints(scan, focal_baseline, options);
  // The wall within 1.2 m spans y in [-0.66, 0.66]: about 13 points 0.1 m apart.
  EXPECT_GE(points.size(), 12u);
  EXPECT_LE(points.size(), 15u);
  for (const ScanPoint& point : points) {
    const double range = std::hypot(point.x, point.y);
    EXPECT_NEAR(point.x, 1.0, 1e-3);
    EXPECT_LE(range, 1.2 + 1e-6);
    EXPECT_NEAR(point.sigma, range * range / focal_baseline * 0.5, 1e-6);
  }
}

}  // namespace
}  // namespace stereonav
