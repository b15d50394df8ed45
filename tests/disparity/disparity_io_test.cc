#include "disparity/disparity_io.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "disparity/disparity_image.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

class DisparityIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    disparity_ = cv::Mat1f(3, 4);
    disparity_ << 0.0f, 1.5f, 12.25f, kInvalidDisparity,  //
        7.0f, kInvalidDisparity, 100.0f, 0.5f,             //
        3.125f, 2.0f, 1.0f, 255.0f;
  }
  std::string path(const std::string& name) const { return scratch_.file(name); }

  test_support::ScratchDirectory scratch_;
  cv::Mat1f disparity_;
};

void expectSame(const cv::Mat1f& expected, const cv::Mat1f& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (int y = 0; y < expected.rows; ++y) {
    for (int x = 0; x < expected.cols; ++x) EXPECT_EQ(expected(y, x), actual(y, x)) << x << "," << y;
  }
}

TEST_F(DisparityIoTest, PfmRoundTripKeepsValuesAndInvalidPixels) {
  writeDisparityPfm(path("d.pfm"), disparity_);
  expectSame(disparity_, readDisparityPfm(path("d.pfm")));
}

TEST_F(DisparityIoTest, PfmStoresRowsBottomToTopWithLittleEndianScale) {
  writeDisparityPfm(path("d.pfm"), disparity_);
  std::ifstream in(path("d.pfm"), std::ios::binary);
  std::string header(std::istreambuf_iterator<char>(in), {});
  ASSERT_EQ(header.substr(0, 10), "Pf\n4 3\n-1\n");
  float first = 0.0f;
  std::memcpy(&first, header.data() + 10, sizeof(float));
  EXPECT_EQ(first, 3.125f);  // the bottom row comes first
}

TEST_F(DisparityIoTest, Png16RoundTripAtKittiResolution) {
  writeDisparityPng16(path("d.png"), disparity_);
  const cv::Mat raw = cv::imread(path("d.png"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(raw.type(), CV_16UC1);
  EXPECT_EQ(raw.at<ushort>(0, 2), 256 * 12.25);
  EXPECT_EQ(raw.at<ushort>(0, 3), 0);  // invalid
  EXPECT_EQ(raw.at<ushort>(0, 0), 1);  // disparity 0 stays valid, as 1/256
  cv::Mat1f expected = disparity_.clone();
  expected(0, 0) = 1.0f / 256.0f;
  expectSame(expected, readDisparityPng16(path("d.png")));
}

TEST_F(DisparityIoTest, Png16RejectsDisparitiesItCannotStore) {
  cv::Mat1f too_far(1, 1, 300.0f);
  EXPECT_THROW(writeDisparityPng16(path("d.png"), too_far), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path("d.png")));
}

TEST_F(DisparityIoTest, ExtensionChoosesTheFormat) {
  writeDisparityImage(path("d.PFM"), disparity_);
  expectSame(disparity_, readDisparityImage(path("d.PFM")));
  EXPECT_THROW(writeDisparityImage(path("d.tiff"), disparity_), std::runtime_error);
}

TEST_F(DisparityIoTest, ReadingAMissingOrBrokenFileNamesIt) {
  try {
    readDisparityPfm(path("missing.pfm"));
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("missing.pfm"), std::string::npos);
  }
  std::ofstream(path("short.pfm")) << "Pf\n4 3\n-1\n1234";
  EXPECT_THROW(readDisparityPfm(path("short.pfm")), std::runtime_error);
}

TEST_F(DisparityIoTest, ColourImagePaintsInvalidPixelsWhite) {
  writeDisparityColourPng(path("c.png"), disparity_, 16.0);
  const cv::Mat3b colour = cv::imread(path("c.png"), cv::IMREAD_COLOR);
  ASSERT_EQ(colour.size(), disparity_.size());
  EXPECT_EQ(colour(0, 3), cv::Vec3b(255, 255, 255));
  EXPECT_NE(colour(0, 0), cv::Vec3b(255, 255, 255));
  EXPECT_NE(colour(0, 0), colour(0, 2));  // far and near differ
}

}  // namespace
}  // namespace stereonav
