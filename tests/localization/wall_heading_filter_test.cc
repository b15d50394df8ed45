#include "localization/wall_heading_filter.h"

#include <gtest/gtest.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include "hand_drawn_map.h"

namespace stereonav {
namespace {

// A 4 m square room centred on the origin, turned by `angle_deg`.
std::vector<testing::Segment> room(double angle_deg) {
  const double c = std::cos(mrpt::DEG2RAD(angle_deg)), s = std::sin(mrpt::DEG2RAD(angle_deg));
  const double corners[4][2] = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  std::vector<testing::Segment> walls;
  for (int i = 0; i < 4; ++i) {
    const double* a = corners[i];
    const double* b = corners[(i + 1) % 4];
    walls.push_back({c * a[0] - s * a[1], s * a[0] + c * a[1], c * b[0] - s * b[1], s * b[0] + c * b[1]});
  }
  return walls;
}

// Spins a robot in `walls` by `true_turn` per frame while odometry reads each turn `scale` times
// too large; returns the largest heading error of the filter over the last half of the frames.
double worstHeadingError(WallHeadingFilter& filter, const std::vector<testing::Segment>& walls,
                         double start_heading, double true_turn, double scale, int frames) {
  double truth = start_heading;
  double worst = 0.0;
  for (int frame = 0; frame < frames; ++frame) {
    const double turn = frame == 0 ? 0.0 : true_turn;
    truth += turn;
    const mrpt::poses::CPose2D robot(0.3, -0.2, truth);
    const double heading =
        filter.update(scale * turn, 0.0, wallSegments(testing::scanOf(walls, robot), WallSegmentOptions{}));
    if (frame >= frames / 2) worst = std::max(worst, std::abs(mrpt::math::wrapToPi(heading - truth)));
  }
  return worst;
}

TEST(WallHeadingFilterTest, KeepsTheHeadingWhileOdometryOverTurnsAndLearnsTheTurnScale) {
  // 300 frames of 0.2 rad, read 2% large: odometry alone ends 300 * 0.2 * 0.02 = 1.2 rad (69
  // degrees) off. The walls keep the heading, and the scale the filter learns is 1 / 1.02.
  WallHeadingFilter filter(WallHeadingOptions{}, 0.0);
  const double worst = worstHeadingError(filter, room(0.0), 0.0, 0.2, 1.02, 300);
  EXPECT_LT(worst, mrpt::DEG2RAD(0.2));
  EXPECT_NEAR(filter.turnScale(), 1.0 / 1.02, 0.002);
  ASSERT_EQ(filter.directions().size(), 1u);
  EXPECT_NEAR(filter.directions()[0], 0.0, mrpt::DEG2RAD(0.2));
}

TEST(WallHeadingFilterTest, WallsAtAnyAngleServeAndTheMapFrameStaysTheStarts) {
  // A room turned by 30 degrees, the robot starting at heading 10 degrees (the map's frame is the
  // start's): the known directions are the room's, 30 and 120 degrees, kept as 30.
  WallHeadingFilter filter(WallHeadingOptions{}, mrpt::DEG2RAD(10.0));
  const double worst = worstHeadingError(filter, room(30.0), mrpt::DEG2RAD(10.0), -0.15, 0.97, 300);
  EXPECT_LT(worst, mrpt::DEG2RAD(0.2));
  ASSERT_EQ(filter.directions().size(), 1u);
  EXPECT_NEAR(filter.directions()[0], mrpt::DEG2RAD(30.0), mrpt::DEG2RAD(0.2));
}

WallSegment segmentAlong(double direction_deg) {
  WallSegment segment;
  segment.direction_rad = mrpt::DEG2RAD(direction_deg);
  segment.sigma_rad = mrpt::DEG2RAD(0.5);
  segment.length_m = 1.0;
  return segment;
}

TEST(WallHeadingFilterTest, ADirectionCountsOnlyOnceEnoughSegmentsAgreeOnIt) {
  WallHeadingOptions options;
  options.new_direction_segments = 4;
  WallHeadingFilter filter(options, 0.0);
  // Three segments along 25 degrees (a chair set askew): not yet a direction, no correction.
  for (int frame = 0; frame < 3; ++frame) {
    EXPECT_DOUBLE_EQ(filter.update(0.0, 0.0, {segmentAlong(25.0)}), 0.0);
    EXPECT_TRUE(filter.directions().empty());
  }
  // The fourth agrees: the direction is taken up from the first sighting on.
  filter.update(0.0, 0.0, {segmentAlong(25.0)});
  ASSERT_EQ(filter.directions().size(), 1u);
  EXPECT_NEAR(filter.directions()[0], mrpt::DEG2RAD(25.0), 1e-9);
  // Walls perpendicular to it, seen 1 degree off after a turn, now correct the heading:
  // odometry says 90 degrees, the walls say 91 (or the turn was 1 degree short).
  const double heading =
      filter.update(mrpt::DEG2RAD(90.0), 0.0, {segmentAlong(26.0), segmentAlong(26.0), segmentAlong(26.0)});
  EXPECT_LT(heading, mrpt::DEG2RAD(90.0));
  EXPECT_GT(heading, mrpt::DEG2RAD(89.0));
}

TEST(WallHeadingFilterTest, AnUnsureHeadingIsCorrectedOnlyBySegmentsThatAgree) {
  // The direction 0 known, then a half turn with no wall in view leaves the heading unsure (a few
  // degrees). One segment 6 degrees off (a desk set askew) is within the wide gate but alone:
  // the heading stays odometry's. Three segments 1 degree off, over two frames, agree that the
  // heading is 1 degree less (a wall at 0 seen along +1): they correct it by most of that degree.
  WallHeadingFilter filter(WallHeadingOptions{}, 0.0);
  for (int frame = 0; frame < 10; ++frame) filter.update(0.0, 0.0, {segmentAlong(0.0)});
  ASSERT_EQ(filter.directions().size(), 1u);
  for (int frame = 0; frame < 6; ++frame) filter.update(M_PI / 6, 0.0, {});
  ASSERT_GT(std::sqrt(filter.estimate().variance), mrpt::DEG2RAD(WallHeadingOptions{}.new_direction_spread_deg));
  EXPECT_NEAR(filter.update(0.0, 0.0, {segmentAlong(6.0)}), M_PI, 1e-9);
  EXPECT_NEAR(filter.update(0.0, 0.0, {segmentAlong(1.0)}), M_PI, 1e-9);
  const double heading = filter.update(0.0, 0.0, {segmentAlong(1.0), segmentAlong(1.0)});
  EXPECT_LT(heading, M_PI - mrpt::DEG2RAD(0.7));
  EXPECT_GT(heading, M_PI - mrpt::DEG2RAD(1.0));
}

TEST(WallHeadingFilterTest, ALargeCorrectionWaitsForSegmentsThatAgreeEvenWhenTheHeadingIsSure) {
  // The direction 0 known, then a turn of 30 degrees with no wall in view: the heading is sure
  // to about 1.5 degrees (the turn scale's doubt), so the gate is about 5 degrees wide. A wall
  // at 0 seen at -27 degrees says the heading is 27, not 30. One such segment (it may be a desk
  // set askew) waits; three, over two frames, correct the heading by most of the 3 degrees.
  WallHeadingFilter filter(WallHeadingOptions{}, 0.0);
  for (int frame = 0; frame < 10; ++frame) filter.update(0.0, 0.0, {segmentAlong(0.0)});
  ASSERT_EQ(filter.directions().size(), 1u);
  const double turned = filter.update(M_PI / 6, 0.0, {});
  const double sigma = std::sqrt(filter.estimate().variance);
  ASSERT_LT(sigma, mrpt::DEG2RAD(WallHeadingOptions{}.new_direction_spread_deg));
  ASSERT_GT(WallHeadingOptions{}.gate_sigmas * sigma, mrpt::DEG2RAD(3.5));
  EXPECT_DOUBLE_EQ(filter.update(0.0, 0.0, {segmentAlong(-27.0)}), turned);
  const double heading = filter.update(0.0, 0.0, {segmentAlong(-27.0), segmentAlong(-27.0)});
  EXPECT_LT(heading, turned - mrpt::DEG2RAD(2.5));
  EXPECT_GT(heading, turned - mrpt::DEG2RAD(3.0));
}

TEST(WallHeadingFilterTest, WithoutWallsTheHeadingIsOdometrys) {
  WallHeadingFilter filter(WallHeadingOptions{}, 0.5);
  double expected = 0.5;
  for (const double turn : {0.1, -0.3, 0.25, 0.0, 1.0}) {
    expected += turn;
    EXPECT_DOUBLE_EQ(filter.update(turn, 0.2, {}), expected);
  }
  EXPECT_DOUBLE_EQ(filter.turnScale(), 1.0);
}

TEST(WallHeadingFilterTest, ATurnsOwnDoubtAddsToTheHeadingsVariance) {
  WallHeadingOptions options;
  WallHeadingFilter plain(options, 0.0), doubtful(options, 0.0);
  const double turn = 0.2, sigma = 0.01;
  plain.update(turn, 0.0, {});
  doubtful.update(turn, 0.0, {}, TurnDoubt{0.0, sigma, std::nullopt});
  // Without walls in view the heading is odometry's either way; only its doubt differs, by the
  // turn's own variance.
  EXPECT_DOUBLE_EQ(doubtful.estimate().heading, plain.estimate().heading);
  EXPECT_NEAR(doubtful.estimate().variance - plain.estimate().variance, sigma * sigma, 1e-15);
  const double expected_plain = mrpt::square(mrpt::DEG2RAD(options.heading_noise_deg_per_frame)) +
                                mrpt::square(options.heading_noise_per_rad * turn);
  EXPECT_NEAR(plain.estimate().variance, expected_plain, 1e-15);
}

TEST(WallHeadingFilterTest, MeasuringTheWheelsScaleRemovesItsDoubtButNotTheirRandomError) {
  WallHeadingOptions options;
  options.heading_noise_per_rad = 0.0;  // the variance then does not depend on the turns' sizes
  WallHeadingFilter filter(options, 0.0);
  const double random_sigma = 0.002, scale_sigma = 0.01;
  filter.update(0.2, 0.0, {}, TurnDoubt{random_sigma, scale_sigma, std::nullopt});
  filter.update(0.2, 0.0, {}, TurnDoubt{random_sigma, scale_sigma, std::nullopt});
  const double per_frame = mrpt::square(mrpt::DEG2RAD(options.heading_noise_deg_per_frame));
  EXPECT_NEAR(filter.estimate().variance,
              2 * (per_frame + mrpt::square(random_sigma) + mrpt::square(scale_sigma)), 1e-15);
  // The scale becomes known: the two wheel turns are corrected, so their scale's doubt goes; the
  // wheels' random error in each stays.
  filter.update(0.2, 0.0, {}, TurnDoubt{0.0, 0.0, 0.98});
  EXPECT_NEAR(filter.estimate().variance, 3 * per_frame + 2 * mrpt::square(random_sigma), 1e-15);
}

TEST(WallHeadingFilterTest, DoubtfulTurnsAreCorrectedWhereTheyWereTakenOnceTheirScaleIsKnown) {
  // Spinning by 0.2 rad per frame from heading 0 with a wall along 0 in view from frame 2 on.
  // Frames 1-4 are wheel turns read 2% large, with their doubt; from frame 5 on the turns are
  // measured exactly, and frame 5's also takes back the 4 * 0.204 * 0.02 / 1.02 rad (0.92
  // degrees) the wheels turned too far, telling the filter their scale. The walls first seen
  // during frames 2-4 were seen from headings 0.5-0.9 degrees off: with those turns corrected
  // where they were taken, every segment agrees with the heading and the wall's direction, and
  // both are exact; as one late turn, the filter would have to choose between the walls and it.
  WallHeadingOptions options;
  options.new_direction_segments = 4;
  WallHeadingFilter filter(options, 0.0);
  const double true_turn = 0.2, wheel_turn = 0.204, scale = 1.0 / 1.02;
  double truth = 0.0;
  filter.update(0.0, 0.0, {});
  for (int frame = 1; frame <= 12; ++frame) {
    truth += true_turn;
    const double wall_seen_deg = mrpt::RAD2DEG(mrpt::math::wrapToPi(-truth));
    std::vector<WallSegment> segments;
    if (frame >= 2) segments = {segmentAlong(wall_seen_deg), segmentAlong(wall_seen_deg)};
    if (frame <= 4) {
      filter.update(wheel_turn, 0.0, segments, TurnDoubt{0.0, 0.05 * wheel_turn, std::nullopt});
    } else if (frame == 5) {
      filter.update(true_turn + (scale - 1.0) * 4 * wheel_turn, 0.0, segments, TurnDoubt{0.0, 0.0, scale});
    } else {
      filter.update(true_turn, 0.0, segments);
    }
  }
  ASSERT_EQ(filter.directions().size(), 1u);
  EXPECT_NEAR(filter.directions()[0], 0.0, 1e-9);
  EXPECT_NEAR(mrpt::math::wrapToPi(filter.estimate().heading - truth), 0.0, 1e-9);
  EXPECT_NEAR(filter.turnScale(), 1.0, 1e-9);
}

}  // namespace
}  // namespace stereonav
