#include "ros_bridge/odometry_history.h"

#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>

namespace stereonav {
namespace {

mrpt::system::TTimeStamp at(double t) { return mrpt::Clock::fromDouble(1.7e9 + t); }

TEST(OdometryHistoryTest, ExactBetweenAndAfterTheNewestReading) {
  OdometryHistory history;
  EXPECT_FALSE(history.poseAt(at(0.0)));
  history.add(at(0.0), {1.0, 2.0, 0.0});
  history.add(at(0.2), {2.0, 2.0, mrpt::DEG2RAD(20.0)});
  const auto exact = history.poseAt(at(0.2));
  ASSERT_TRUE(exact);
  EXPECT_DOUBLE_EQ(exact->x(), 2.0);
  // A quarter of the way: by hand 1.25 m, 5 degrees.
  const auto between = history.poseAt(at(0.05));
  ASSERT_TRUE(between);
  EXPECT_NEAR(between->x(), 1.25, 1e-5);
  EXPECT_NEAR(between->y(), 2.0, 1e-9);
  EXPECT_NEAR(between->phi(), mrpt::DEG2RAD(5.0), 1e-6);
  EXPECT_FALSE(history.poseAt(at(0.21)));  // a later reading may still come
  ASSERT_TRUE(history.poseAt(at(-1.0)));
  EXPECT_DOUBLE_EQ(history.poseAt(at(-1.0))->x(), 1.0);
}

TEST(OdometryHistoryTest, HeadingTurnsTheShortWayAcrossPi) {
  OdometryHistory history;
  history.add(at(0.0), {0.0, 0.0, mrpt::DEG2RAD(170.0)});
  history.add(at(1.0), {0.0, 0.0, mrpt::DEG2RAD(-170.0)});
  const auto middle = history.poseAt(at(0.5));
  ASSERT_TRUE(middle);
  EXPECT_NEAR(std::abs(middle->phi()), M_PI, 1e-6);
}

TEST(OdometryHistoryTest, OlderReadingsAreIgnoredAndOldOnesForgotten) {
  OdometryHistory history(1.0);
  history.add(at(0.0), {0.0, 0.0, 0.0});
  history.add(at(1.0), {1.0, 0.0, 0.0});
  history.add(at(0.5), {9.0, 0.0, 0.0});  // out of order: ignored
  EXPECT_NEAR(history.poseAt(at(0.5))->x(), 0.5, 1e-5);
  history.add(at(5.0), {5.0, 0.0, 0.0});
  history.add(at(6.0), {6.0, 0.0, 0.0});
  // The reading at 0 s is forgotten; before the oldest kept, the oldest kept.
  EXPECT_DOUBLE_EQ(history.poseAt(at(0.0))->x(), 5.0);
}

}  // namespace
}  // namespace stereonav
