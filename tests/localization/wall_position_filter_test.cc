#include "localization/wall_position_filter.h"

#include <gtest/gtest.h>

#include <mrpt/core/bits_math.h>

#include <Eigen/Geometry>

#include "hand_drawn_map.h"

namespace stereonav {
namespace {

// A 6 m x 4 m room centred on the origin.
const std::vector<testing::Segment> kRoom = {{-3, -2, 3, -2}, {3, -2, 3, 2}, {3, 2, -3, 2}, {-3, 2, -3, -2}};

struct LoopErrors {
  double filter_m = 0.0;    // the filter's largest position error over the last lap
  double odometry_m = 0.0;  // dead reckoning's over the same lap
};

// Drives `laps` counterclockwise laps of the rectangle 1 m inside kRoom's walls, 0.1 m a frame,
// turning at each corner in three frames. Odometry reads each distance `scale` times too long and
// drifts 0.5 mm to the left every frame; the heading is the true one (the filter under test keeps
// only the position).
LoopErrors driveLoops(WallPositionFilter& filter, double scale, int laps) {
  const double corners[4][2] = {{-2, -1}, {2, -1}, {2, 1}, {-2, 1}};
  const WallSegmentOptions segments;
  const std::vector<double> directions = {0.0};
  Eigen::Vector2d truth(-2.0, -1.0), odometry = truth;
  double heading = 0.0;
  LoopErrors errors;
  const auto frame = [&](const Eigen::Vector2d& displacement, double new_heading, int lap) {
    const Eigen::Vector2d measured = scale * displacement + Eigen::Vector2d(0.0, displacement.norm() > 0 ? 0.0005 : 0.0);
    truth += Eigen::Rotation2Dd(heading) * displacement;
    odometry += Eigen::Rotation2Dd(heading) * measured;
    const double previous = heading;
    heading = new_heading;
    const Eigen::Vector2d estimate = filter.update(
        measured, previous, {heading, 0.0}, {heading, 0.0}, directions,
        wallSegments(testing::scanOf(kRoom, mrpt::poses::CPose2D(truth.x(), truth.y(), heading)), segments));
    if (lap == laps - 1) {
      errors.filter_m = std::max(errors.filter_m, (estimate - truth).norm());
      errors.odometry_m = std::max(errors.odometry_m, (odometry - truth).norm());
    }
  };
  for (int lap = 0; lap < laps; ++lap) {
    for (int side = 0; side < 4; ++side) {
      const double* from = corners[side];
      const double* to = corners[(side + 1) % 4];
      const int steps = static_cast<int>(std::lround(std::hypot(to[0] - from[0], to[1] - from[1]) / 0.1));
      for (int step = 0; step < steps; ++step) frame({0.1, 0.0}, heading, lap);
      for (int turn = 1; turn <= 3; ++turn) frame({0.0, 0.0}, heading + M_PI / 6, lap);
    }
  }
  return errors;
}

TEST(WallPositionFilterTest, KeepsThePositionWhileOdometryReadsLongAndDriftsAndLearnsTheScale) {
  // Distances read 5% long: along a 4 m side dead reckoning ends 0.2 m off. The walls, seen
  // again lap after lap, keep the position within centimetres, and the scale the filter learns
  // is 1 / 1.05.
  WallPositionFilter filter(WallPositionOptions{}, WallHeadingOptions{}, Eigen::Vector2d(-2.0, -1.0));
  const LoopErrors errors = driveLoops(filter, 1.05, 4);
  EXPECT_GT(errors.odometry_m, 0.15);
  EXPECT_LT(errors.filter_m, 0.03);
  EXPECT_NEAR(filter.distanceScale(), 1.0 / 1.05, 0.005);
  // The room's four walls, each known once: a wall seen again is the same line.
  EXPECT_EQ(filter.wallCount(), 4u);
}

TEST(WallPositionFilterTest, OffItIsOdometryDrivenAlongTheHeading) {
  WallPositionOptions options;
  options.enabled = false;
  WallPositionFilter filter(options, WallHeadingOptions{}, Eigen::Vector2d(-2.0, -1.0));
  const LoopErrors errors = driveLoops(filter, 1.05, 1);
  EXPECT_NEAR(errors.filter_m, errors.odometry_m, 1e-9);
  EXPECT_EQ(filter.wallCount(), 0u);
}

TEST(WallPositionFilterTest, TheTwoFacesOfAThinWallAreTwoLines) {
  // A wall 5 cm thick along x = 0: seen from x = -1.5 its face x = 0 is 1.5 m ahead; seen from
  // x = 1.55 (reached by an exact displacement) its face x = 0.05 is also 1.5 m ahead. Taken for
  // one line, the second sighting would pull the position 5 cm; as two, it does not move it.
  const std::vector<testing::Segment> wall = {{0.0, -3.0, 0.0, 3.0}, {0.05, -3.0, 0.05, 3.0}};
  WallPositionFilter filter(WallPositionOptions{}, WallHeadingOptions{}, Eigen::Vector2d(-1.5, 0.0));
  const std::vector<double> directions = {0.0};
  const WallSegmentOptions segments;
  filter.update({0.0, 0.0}, 0.0, {0.0, 0.0}, {0.0, 0.0}, directions,
                wallSegments(testing::scanOf(wall, mrpt::poses::CPose2D(-1.5, 0.0, 0.0)), segments));
  const Eigen::Vector2d position =
      filter.update({3.05, 0.0}, 0.0, {M_PI, 0.0}, {M_PI, 0.0}, directions,
                    wallSegments(testing::scanOf(wall, mrpt::poses::CPose2D(1.55, 0.0, M_PI)), segments));
  EXPECT_EQ(filter.wallCount(), 2u);
  EXPECT_NEAR(position.x(), 1.55, 1e-3);
  EXPECT_NEAR(position.y(), 0.0, 1e-3);
}

TEST(WallPositionFilterTest, AHeadingFoundOffMovesWhatWasDrivenOnIt) {
  // The robot drives 5 m, 0.1 m a frame, believing it heads along x with a sigma of 2 degrees and
  // seeing no wall. It truly heads 2 degrees to the right: it ends 5 sin(2 deg) = 0.1745 m to the
  // right of its belief. When the walls' directions then tell the heading (-2 degrees, sigma 0.1),
  // the position moves by that much: the error that drove it off is the one just measured.
  WallPositionOptions options;
  options.position_noise_per_m = 0.0;
  WallPositionFilter filter(options, WallHeadingOptions{}, Eigen::Vector2d::Zero());
  const HeadingEstimate unsure{0.0, mrpt::square(mrpt::DEG2RAD(2.0))};
  Eigen::Vector2d position = filter.update({0.0, 0.0}, 0.0, unsure, unsure, {}, {});
  for (int frame = 0; frame < 50; ++frame) position = filter.update({0.1, 0.0}, 0.0, unsure, unsure, {}, {});
  EXPECT_NEAR(position.x(), 5.0, 1e-9);
  EXPECT_NEAR(position.y(), 0.0, 1e-9);
  // The sideways sigma is the distance times the heading's sigma, not the square root of the
  // frames' count times one frame's share.
  EXPECT_NEAR(std::sqrt(filter.positionCovariance()(1, 1)), 5.0 * mrpt::DEG2RAD(2.0), 1e-6);
  const HeadingEstimate corrected{mrpt::DEG2RAD(-2.0), mrpt::square(mrpt::DEG2RAD(0.1))};
  position = filter.update({0.0, 0.0}, 0.0, unsure, corrected, {}, {});
  EXPECT_NEAR(position.x(), 5.0, 1e-9);
  EXPECT_NEAR(position.y(), -5.0 * std::sin(mrpt::DEG2RAD(2.0)), 0.002);
  EXPECT_NEAR(std::sqrt(filter.positionCovariance()(1, 1)), 5.0 * mrpt::DEG2RAD(0.1), 1e-6);
}

TEST(WallPositionFilterTest, AStretchTellsItsWallsOffsetByItsMiddleNotByItsFittedLinesTilt) {
  // A wall along y = -1, seen straight from the origin (x = 1 .. 2.3 in view: 45 degrees to each
  // side, 2.5 m); the robot then drives exactly 1 m along x (the filter allows 3 cm) and sees
  // x = 2 .. 3.3 of it read 1 degree askew about its middle (2.65, -1), as a fit of noisy readings
  // may be. The wall's direction is known: the stretch's middle says the wall is 1 m away. The
  // fitted line, carried 1.65 m back to the foot of its normal through the robot, would say
  // 1 + 1.65 tan 1 deg = 1.029 m, and pull the position more than a centimetre.
  const std::vector<double> directions = {0.0};
  const WallSegmentOptions segments;
  const HeadingEstimate heading{0.0, mrpt::square(mrpt::DEG2RAD(0.1))};
  WallPositionFilter filter(WallPositionOptions{}, WallHeadingOptions{}, Eigen::Vector2d::Zero());
  filter.update({0.0, 0.0}, 0.0, heading, heading, directions,
                wallSegments(testing::scanOf({{0.0, -1.0, 3.0, -1.0}}, mrpt::poses::CPose2D(0.0, 0.0, 0.0)), segments));
  ASSERT_EQ(filter.wallCount(), 1u);
  const double rise = 0.65 * std::tan(mrpt::DEG2RAD(1.0));
  const Eigen::Vector2d position = filter.update(
      {1.0, 0.0}, 0.0, heading, heading, directions,
      wallSegments(testing::scanOf({{2.0, -1.0 - rise, 3.3, -1.0 + rise}}, mrpt::poses::CPose2D(1.0, 0.0, 0.0)),
                   segments));
  EXPECT_EQ(filter.lastFrameCorrections(), 1);
  EXPECT_EQ(filter.wallCount(), 1u);
  EXPECT_NEAR(position.x(), 1.0, 1e-9);
  // The readings crowd towards the near end, which lies a centimetre farther: their centroid is
  // a few millimetres beyond the middle's 1 m.
  EXPECT_NEAR(position.y(), 0.0, 0.004);
}

}  // namespace
}  // namespace stereonav
