#include "explorer/free_travel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stereonav {
namespace {

constexpr double kRadius = 0.3;
constexpr double kHorizon = 5.0;

TEST(FreeTravel, StraightAheadTheDiscStopsWhereItsEdgeMeetsThePoint) {
  EXPECT_NEAR(freeTravel({{2.0, 0.0}}, kRadius, 0.0, 1.0, 0.0, kHorizon).to_contact_m, 1.7, 1e-12);
  // Off the centre line by 0.2: the disc's edge meets it sqrt(0.3^2 - 0.2^2) before the point.
  EXPECT_NEAR(freeTravel({{2.0, 0.2}}, kRadius, 0.0, 1.0, 0.0, kHorizon).to_contact_m, 2.0 - std::sqrt(0.05), 1e-12);
  // The nearest of several decides.
  EXPECT_NEAR(freeTravel({{3.0, 0.0}, {2.5, -0.1}, {1.0, 0.5}}, kRadius, 0.0, 1.0, 0.0, kHorizon).to_contact_m,
              2.5 - std::sqrt(0.08), 1e-12);
}

TEST(FreeTravel, PointsBesideOrBehindThePathOrBeyondTheHorizonLeaveItFree) {
  EXPECT_EQ(freeTravel({{2.0, 0.35}, {-1.0, 0.0}, {6.0, 0.0}}, kRadius, 0.0, 1.0, 0.0, kHorizon).to_contact_m, kHorizon);
  EXPECT_EQ(freeTravel({}, kRadius, 0.0, 1.0, 0.0, kHorizon).to_contact_m, kHorizon);
}

TEST(FreeTravel, ReversingSweepsBehind) {
  EXPECT_NEAR(freeTravel({{-2.0, 0.0}, {2.0, 0.0}}, kRadius, 0.0, -0.5, 0.0, kHorizon).to_contact_m, 1.7, 1e-12);
}

TEST(FreeTravel, TurningOnTheSpotNeverTouches) {
  EXPECT_EQ(freeTravel({{0.31, 0.0}, {0.0, -0.31}}, kRadius, 0.0, 0.0, 1.0, kHorizon).to_contact_m, kHorizon);
}

TEST(FreeTravel, OnAnArcTheDiscMeetsAPointOnItsPathOneChordEarly) {
  // v = 1, w = 0.5: a circle of radius 2 about (0, 2). A point on it 0.5 rad along is met when the
  // centre is a chord of 0.3 short of it, 2 asin(0.3 / 4) rad earlier.
  const double turn_radius = 2.0, angle = 0.5;
  const mrpt::math::TPoint2D on_arc(turn_radius * std::sin(angle), turn_radius * (1.0 - std::cos(angle)));
  const double expected = turn_radius * (angle - 2.0 * std::asin(kRadius / (2.0 * turn_radius)));
  EXPECT_NEAR(freeTravel({on_arc}, kRadius, 0.0, 1.0, 0.5, kHorizon).to_contact_m, expected, 1e-9);
  // Turning right instead, the mirror image of that point is met as soon.
  EXPECT_NEAR(freeTravel({{on_arc.x, -on_arc.y}}, kRadius, 0.0, 1.0, -0.5, kHorizon).to_contact_m, expected, 1e-9);
  // The point straight ahead at 1.5 m is 2.5 m from the centre of rotation, 0.5 m off the
  // centre's circle: more than the radius, so the disc never touches it.
  EXPECT_EQ(freeTravel({{1.5, 0.0}}, kRadius, 0.0, 1.0, 0.5, kHorizon).to_contact_m, kHorizon);
}

TEST(FreeTravel, APointAlreadyUnderTheDiscStopsItOnlyIfItIsAhead) {
  EXPECT_EQ(freeTravel({{0.1, 0.05}}, kRadius, 0.0, 1.0, 0.0, kHorizon).to_contact_m, 0.0);
  EXPECT_EQ(freeTravel({{-0.1, 0.05}}, kRadius, 0.0, 1.0, 0.0, kHorizon).to_contact_m, kHorizon);
  EXPECT_EQ(freeTravel({{-0.1, 0.05}}, kRadius, 0.0, -1.0, 0.0, kHorizon).to_contact_m, 0.0);
}

TEST(FreeTravel, TheMarginKeepsTheDiscFartherFromWhatItWouldRunInto) {
  constexpr double kMargin = 0.1;
  // Ahead on the centre line: the widened disc (0.4) stops 0.4 short.
  const FreeTravel ahead = freeTravel({{2.0, 0.0}}, kRadius, kMargin, 1.0, 0.0, kHorizon);
  EXPECT_NEAR(ahead.to_contact_m, 1.6, 1e-12);
  EXPECT_EQ(ahead.beside_m, kHorizon);
  // The bare disc itself touches it 0.3 short.
  EXPECT_NEAR(ahead.body_contact_m, 1.7, 1e-12);
  // 0.2 off the centre line, under the bare body's path: the widened disc meets it
  // sqrt(0.4^2 - 0.2^2) before it.
  EXPECT_NEAR(freeTravel({{2.0, 0.2}}, kRadius, kMargin, 1.0, 0.0, kHorizon).to_contact_m, 2.0 - std::sqrt(0.12),
              1e-12);
  // Within the margin straight ahead: the bare disc still stops 0.3 short of it.
  EXPECT_NEAR(freeTravel({{0.35, 0.0}}, kRadius, kMargin, 1.0, 0.0, kHorizon).to_contact_m, 0.05, 1e-12);
}

TEST(FreeTravel, WhatTheBodyPassesClearOfButWithinTheMarginCountsApart) {
  constexpr double kMargin = 0.1;
  // A door jamb 0.35 to the left of the path: the bare disc (0.3) passes it 0.05 clear, the
  // widened one meets it sqrt(0.4^2 - 0.35^2) before it.
  const FreeTravel jamb = freeTravel({{2.0, 0.35}}, kRadius, kMargin, 1.0, 0.0, kHorizon);
  EXPECT_EQ(jamb.to_contact_m, kHorizon);
  EXPECT_NEAR(jamb.beside_m, 2.0 - std::sqrt(0.0375), 1e-12);
  // Both jambs of a door 0.8 wide, the robot 0.05 off its centre line, and a wall 3 m ahead.
  const FreeTravel door = freeTravel({{1.0, 0.45}, {1.0, -0.35}, {3.0, 0.0}}, kRadius, kMargin, 1.0, 0.0, kHorizon);
  EXPECT_NEAR(door.to_contact_m, 2.6, 1e-12);
  EXPECT_NEAR(door.beside_m, 1.0 - std::sqrt(0.0375), 1e-12);
  // The bare disc touches neither jamb, only the wall.
  EXPECT_NEAR(door.body_contact_m, 2.7, 1e-12);
  // A jamb already 0.38 to the left, slightly ahead: within the margin now, so the bare disc
  // decides contact, and it passes 0.08 clear; but until the jamb is behind the robot it counts
  // as beside at once, so the robot keeps creeping. Once behind, it no longer counts.
  const FreeTravel within = freeTravel({{0.05, 0.38}}, kRadius, kMargin, 1.0, 0.0, kHorizon);
  EXPECT_EQ(within.to_contact_m, kHorizon);
  EXPECT_EQ(within.beside_m, 0.0);
  const FreeTravel passed = freeTravel({{-0.05, 0.38}}, kRadius, kMargin, 1.0, 0.0, kHorizon);
  EXPECT_EQ(passed.to_contact_m, kHorizon);
  EXPECT_EQ(passed.beside_m, kHorizon);
  // Reversing, "ahead" is behind the robot: the jamb ahead of it no longer slows it.
  EXPECT_EQ(freeTravel({{0.05, 0.38}}, kRadius, kMargin, -1.0, 0.0, kHorizon).beside_m, kHorizon);
  // On an arc the same split holds: turning left on a circle of radius 2 about (0, 2), a point
  // 2.35 from the centre of rotation is 0.35 outside the centre's circle.
  const double angle = 0.8;
  const mrpt::math::TPoint2D outside(2.35 * std::sin(angle), 2.0 - 2.35 * std::cos(angle));
  const FreeTravel arc = freeTravel({outside}, kRadius, kMargin, 1.0, 0.5, kHorizon);
  EXPECT_EQ(arc.to_contact_m, kHorizon);
  // The widened disc meets it where the centre comes within 0.4: an angle acos((R^2 + rho^2 -
  // 0.4^2) / (2 R rho)) short of the point's own.
  EXPECT_NEAR(arc.beside_m, 2.0 * (angle - std::acos((4.0 + 2.35 * 2.35 - 0.16) / (2.0 * 2.0 * 2.35))), 1e-9);
}

}  // namespace
}  // namespace stereonav
