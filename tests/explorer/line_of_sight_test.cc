#include "explorer/line_of_sight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace stereonav {
namespace {

TEST(LineOfSightTest, RoundsAsLroundDoesHalvesAndTheDoublesBesideThemIncluded) {
  std::vector<double> values;
  for (int whole = -300; whole <= 300; ++whole) {
    const double half = whole + 0.5;
    for (const double x : {static_cast<double>(whole), half, std::nextafter(half, -1e9), std::nextafter(half, 1e9),
                           whole + 0.25, whole + 0.75, std::nextafter(static_cast<double>(whole), 1e9)}) {
      values.push_back(x);
    }
  }
  // The samples of a line between cells: a fraction of the way, as alongStraightLine takes them.
  for (int steps = 1; steps <= 160; ++steps) {
    for (int step = 1; step < steps; ++step) values.push_back(7 + (-40 - 7) * (step / static_cast<double>(steps)));
  }
  for (const double x : values) EXPECT_EQ(roundHalfAwayFromZero(x), std::lround(x)) << x;
}

TEST(LineOfSightTest, ALineIsBlockedByACellItCrossesButNotByTheCellItStartsFrom) {
  // One blocked cell, column 5 of row 3.
  const auto open = [](int col, int row) { return !(col == 5 && row == 3); };
  EXPECT_FALSE(alongStraightLine(cv::Point(0, 3), cv::Point(10, 3), open));
  EXPECT_FALSE(alongStraightLine(cv::Point(3, 0), cv::Point(7, 6), open));
  EXPECT_TRUE(alongStraightLine(cv::Point(0, 0), cv::Point(10, 0), open));
  EXPECT_TRUE(alongStraightLine(cv::Point(5, 3), cv::Point(10, 3), open));
}

}  // namespace
}  // namespace stereonav
