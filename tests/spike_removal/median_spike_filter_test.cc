#include "spike_removal/median_spike_filter.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

TEST(MedianSpikeFilterTest, SinglePixelSpikeTakesItsNeighboursDisparity) {
  cv::Mat1f disparity(9, 9, 10.0f);
  disparity(4, 4) = 40.0f;
  cv::Mat1b rejected;
  MedianSpikeFilter(3).apply(disparity, rejected);
  EXPECT_EQ(disparity(4, 4), 10.0f);
  EXPECT_EQ(cv::countNonZero(rejected), 0);
}

TEST(MedianSpikeFilterTest, ValidPixelAmongMostlyInvalidNeighboursIsRejected) {
  cv::Mat1f disparity(9, 9, kInvalidDisparity);
  disparity(4, 4) = 12.0f;
  disparity(4, 5) = 12.0f;
  cv::Mat1b rejected;
  MedianSpikeFilter(3).apply(disparity, rejected);
  EXPECT_FALSE(isValidDisparity(disparity(4, 4)));
  EXPECT_FALSE(isValidDisparity(disparity(4, 5)));
  EXPECT_EQ(rejected(4, 4), 255);
  EXPECT_EQ(rejected(4, 5), 255);
  EXPECT_EQ(cv::countNonZero(rejected), 2);
}

TEST(MedianSpikeFilterTest, InvalidPixelIsNotFilledIn) {
  cv::Mat1f disparity(9, 9, 10.0f);
  disparity(4, 4) = kInvalidDisparity;
  cv::Mat1b rejected;
  MedianSpikeFilter(5).apply(disparity, rejected);
  EXPECT_FALSE(isValidDisparity(disparity(4, 4)));
  EXPECT_EQ(rejected(4, 4), 0);  // it was not valid to begin with
  EXPECT_EQ(cv::countNonZero(disparity == 10.0f), 80);
}

TEST(MedianSpikeFilterTest, KernelMustBeThreeOrFive) {
  EXPECT_THROW(MedianSpikeFilter(7), std::invalid_argument);
  EXPECT_THROW(MedianSpikeFilter(4), std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
