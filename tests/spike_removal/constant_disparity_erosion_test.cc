#include "spike_removal/constant_disparity_erosion.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

cv::Mat1f squareOnInvalid(int side, float disparity) {
  cv::Mat1f image(20, 20, kInvalidDisparity);
  image(cv::Rect(5, 5, side, side)).setTo(disparity);
  return image;
}

TEST(ConstantDisparityErosionTest, ErodesASquareByHalfTheKernel) {
  for (const int kernel : {3, 5}) {
    cv::Mat1f disparity = squareOnInvalid(7, 10.0f);
    cv::Mat1b rejected;
    ConstantDisparityErosion(kernel).apply(disparity, rejected);
    const int margin = kernel / 2;
    const cv::Rect survivors(5 + margin, 5 + margin, 7 - 2 * margin, 7 - 2 * margin);
    for (int y = 0; y < 20; ++y) {
      for (int x = 0; x < 20; ++x) {
        const bool in_square = cv::Rect(5, 5, 7, 7).contains({x, y});
        const bool survives = survivors.contains({x, y});
        EXPECT_EQ(isValidDisparity(disparity(y, x)), survives) << kernel << " at " << x << "," << y;
        EXPECT_EQ(rejected(y, x), in_square && !survives ? 255 : 0);
      }
    }
    EXPECT_EQ(disparity(8, 8), 10.0f);
  }
}

TEST(ConstantDisparityErosionTest, SameIntegerDisparityCountsAsConstant) {
  cv::Mat1f disparity(5, 5, 10.2f);
  disparity(1, 1) = 9.8f;  // rounds to 10 as well
  cv::Mat1b rejected;
  ConstantDisparityErosion(3).apply(disparity, rejected);
  EXPECT_EQ(disparity(2, 2), 10.2f);
  EXPECT_EQ(disparity(1, 1), 9.8f);
  EXPECT_EQ(cv::countNonZero(rejected), 0);  // the image border does not erode

  disparity(4, 4) = 11.0f;
  ConstantDisparityErosion(3).apply(disparity, rejected);
  // (4,4) and its three neighbours inside the image see both 10 and 11.
  EXPECT_EQ(cv::countNonZero(rejected), 4);
  EXPECT_FALSE(isValidDisparity(disparity(3, 3)));
  EXPECT_TRUE(isValidDisparity(disparity(2, 2)));
}

TEST(ConstantDisparityErosionTest, KernelMustBeOddAndAtLeastThree) {
  EXPECT_THROW(ConstantDisparityErosion(4), std::invalid_argument);
  EXPECT_THROW(ConstantDisparityErosion(1), std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
