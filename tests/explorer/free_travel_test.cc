#include "explorer/free_travel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stereonav {
namespace {

constexpr double kRadius = 0.3;
constexpr double kHorizon = 5.0;

TEST(FreeTravel, StraightAheadTheDiscStopsWhereItsEdgeMeetsThePoint) {
  EXPECT_NEAR(freeTravel({{2.0, 0.0}}, kRadius, 0.0, 1.0, 0.0, kHorizon), 1.7, 1e-12);
  // Off the centre line by 0.2: the disc's edge meets it sqrt(0.3^2 - 0.2^2) before the point.
  EXPECT_NEAR(freeTravel({{2.0, 0.2}}, kRadius, 0.0, 1.0, 0.0, kHorizon), 2.0 - std::sqrt(0.05), 1e-12);
  // The nearest of several decides.
  EXPECT_NEAR(freeTravel({{3.0, 0.0}, {2.5, -0.1}, {1.0, 0.5}}, kRadius, 0.0, 1.0, 0.0, kHorizon),
              2.5 - std::sqrt(0.08), 1e-12);
}

TEST(FreeTravel, PointsBesideOrBehindThePathOrBeyondTheHorizonLeaveItFree) {
  EXPECT_EQ(freeTravel({{2.0, 0.35}, {-1.0, 0.0}, {6.0, 0.0}}, kRadius, 0.0, 1.0, 0.0, kHorizon), kHorizon);
  EXPECT_EQ(freeTravel({}, kRadius, 0.0, 1.0, 0.0, kHorizon), kHorizon);
}

TEST(FreeTravel, ReversingSweepsBehind) {
  EXPECT_NEAR(freeTravel({{-2.0, 0.0}, {2.0, 0.0}}, kRadius, 0.0, -0.5, 0.0, kHorizon), 1.7, 1e-12);
}

TEST(FreeTravel, TurningOnTheSpotNeverTouches) {
  EXPECT_EQ(freeTravel({{0.31, 0.0}, {0.0, -0.31}}, kRadius, 0.0, 0.0, 1.0, kHorizon), kHorizon);
}

TEST(FreeTravel, OnAnArcTheDiscMeetsAPointOnItsPathOneChordEarly) {
  // v = 1, w = 0.5: a circle of radius 2 about (0, 2). A point on it 0.5 rad along is met when the
  // centre is a chord of 0.3 short of it, 2 asin(0.3 / 4) rad earlier.
  const double turn_radius = 2.0, angle = 0.5;
  const mrpt::math::TPoint2D on_arc(turn_radius * std::sin(angle), turn_radius * (1.0 - std::cos(angle)));
  const double expected = turn_radius * (angle - 2.0 * std::asin(kRadius / (2.0 * turn_radius)));
  EXPECT_NEAR(freeTravel({on_arc}, kRadius, 0.0, 1.0, 0.5, kHorizon), expected, 1e-9);
  // Turning right instead, the mirror image of that point is met as soon.
  EXPECT_NEAR(freeTravel({{on_arc.x, -on_arc.y}}, kRadius, 0.0, 1.0, -0.5, kHorizon), expected, 1e-9);
  // The point straight ahead at 1.5 m is 2.5 m from the centre of rotation, 0.5 m off the
  // centre's circle: more than the radius, so the disc never touches it.
  EXPECT_EQ(freeTravel({{1.5, 0.0}}, kRadius, 0.0, 1.0, 0.5, kHorizon), kHorizon);
}

TEST(FreeTravel, APointAlreadyUnderTheDiscStopsItOnlyIfItIsAhead) {
  EXPECT_EQ(freeTravel({{0.1, 0.05}}, kRadius, 0.0, 1.0, 0.0, kHorizon), 0.0);
  EXPECT_EQ(freeTravel({{-0.1, 0.05}}, kRadius, 0.0, 1.0, 0.0, kHorizon), kHorizon);
  EXPECT_EQ(freeTravel({{-0.1, 0.05}}, kRadius, 0.0, -1.0, 0.0, kHorizon), 0.0);
}

TEST(FreeTravel, TheMarginKeepsTheDiscFartherButNeverStopsItBesideAPointItIsAlreadyWithin) {
  constexpr double kMargin = 0.1;
  // Ahead on the centre line: the widened disc (0.4) stops 0.4 short.
  EXPECT_NEAR(freeTravel({{2.0, 0.0}}, kRadius, kMargin, 1.0, 0.0, kHorizon), 1.6, 1e-12);
  // Beside the path at 0.35: outside the body, inside the margin's reach as it passes, so the
  // widened disc meets it sqrt(0.4^2 - 0.35^2) before it.
  EXPECT_NEAR(freeTravel({{2.0, 0.35}}, kRadius, kMargin, 1.0, 0.0, kHorizon), 2.0 - std::sqrt(0.0375), 1e-12);
  // A door jamb already 0.38 to the left, slightly ahead: within the margin now, so only the
  // bare disc counts, and it passes 0.08 clear.
  EXPECT_EQ(freeTravel({{0.05, 0.38}}, kRadius, kMargin, 1.0, 0.0, kHorizon), kHorizon);
  // Within the margin straight ahead: the bare disc still stops 0.3 short of it.
  EXPECT_NEAR(freeTravel({{0.35, 0.0}}, kRadius, kMargin, 1.0, 0.0, kHorizon), 0.05, 1e-12);
}

}  // namespace
}  // namespace stereonav
