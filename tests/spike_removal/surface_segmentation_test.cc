#include "spike_removal/surface_segmentation.h"

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "pole_scene.h"
#include "noisy_tsukuba.h"

namespace stereonav {
namespace {

SurfaceSegmentationOptions segmentationOptions(int min_region_pixels, int connectivity = 8,
                                               float max_difference = 1.0f) {
  SurfaceSegmentationOptions options;
  options.min_region_pixels = min_region_pixels;
  options.connectivity = connectivity;
  options.max_difference = max_difference;
  return options;
}

cv::Mat1f segmented(const cv::Mat1f& input, const SurfaceSegmentationOptions& options,
                    cv::Mat1b* rejected = nullptr) {
  cv::Mat1f disparity = input.clone();
  cv::Mat1b mask;
  SurfaceSegmentation(options).apply(disparity, mask);
  if (rejected) *rejected = mask;
  return disparity;
}

int validCount(const cv::Mat1f& disparity) {
  int count = 0;
  for (const float d : disparity) count += isValidDisparity(d);
  return count;
}

TEST(SurfaceSegmentationTest, RemovesCompactBlobAndKeepsPoleStandingOnTheFloor) {
  const PoleScene scene;
  const cv::Mat1f input = scene.disparity();
  // 100 pixels: more than the blob (30) and more than the pole alone (60), far less than the
  // floor the pole belongs to.
  cv::Mat1b rejected;
  const cv::Mat1f output = segmented(input, segmentationOptions(100), &rejected);

  for (int y = 0; y < input.rows; ++y) {
    for (int x = 0; x < input.cols; ++x) {
      const bool in_blob = scene.blob.contains({x, y});
      EXPECT_EQ(rejected(y, x), in_blob ? 255 : 0) << "at " << x << "," << y;
      if (in_blob) {
        EXPECT_FALSE(isValidDisparity(output(y, x)));
      } else {
        EXPECT_EQ(output(y, x), input(y, x)) << "at " << x << "," << y;
      }
    }
  }
  EXPECT_EQ(scene.countInRect(output, scene.pole, PoleScene::kPoleDisparity), 60);
}

TEST(SurfaceSegmentationTest, PoleWithoutSupportIsRemoved) {
  const PoleScene scene;
  cv::Mat1f input = scene.disparity();
  // Cut the pole off the floor: alone it is a 59-pixel surface, below the 100-pixel threshold.
  input(PoleScene::kFloorTopRow - 1, PoleScene::kPoleColumn) = kInvalidDisparity;
  const cv::Mat1f output = segmented(input, segmentationOptions(100));
  EXPECT_EQ(scene.countInRect(output, scene.pole, PoleScene::kPoleDisparity), 0);
  EXPECT_EQ(validCount(output), validCount(input) - 59 - 30);
}

cv::Mat1f diagonalLines() {
  // A "\" line and a "/" line of 40 pixels each, not touching; nothing else is valid.
  cv::Mat1f image(50, 100, kInvalidDisparity);
  for (int i = 0; i < 40; ++i) {
    image(5 + i, 5 + i) = 30.0f;
    image(5 + i, 90 - i) = 12.0f;
  }
  return image;
}

TEST(SurfaceSegmentationTest, EightConnectivityJoinsDiagonalNeighbours) {
  const cv::Mat1f input = diagonalLines();
  EXPECT_EQ(validCount(segmented(input, segmentationOptions(40, 8))), 80);
  EXPECT_EQ(validCount(segmented(input, segmentationOptions(41, 8))), 0);
}

TEST(SurfaceSegmentationTest, FourConnectivityLeavesDiagonalPixelsAlone) {
  EXPECT_EQ(validCount(segmented(diagonalLines(), segmentationOptions(2, 4))), 0);
}

TEST(SurfaceSegmentationTest, DisparityStepLargerThanMaxDifferenceSplitsSurfaces) {
  // Two 10 x 10 patches side by side at disparities 10 and 12.
  cv::Mat1f input(20, 30, kInvalidDisparity);
  input(cv::Rect(5, 5, 10, 10)).setTo(10.0f);
  input(cv::Rect(15, 5, 10, 10)).setTo(12.0f);
  EXPECT_EQ(validCount(segmented(input, segmentationOptions(150, 8, 1.0f))), 0);
  EXPECT_EQ(validCount(segmented(input, segmentationOptions(150, 8, 2.0f))), 200);
}

TEST(SurfaceSegmentationTest, SlopedSurfaceStaysWholeWhileStepsStayWithinMaxDifference) {
  // A 20 x 10 ramp rising by `step` per column.
  const auto ramp = [](float step) {
    cv::Mat1f image(10, 20);
    for (int y = 0; y < 10; ++y) {
      for (int x = 0; x < 20; ++x) image(y, x) = 5.0f + step * x;
    }
    return image;
  };
  EXPECT_EQ(validCount(segmented(ramp(1.0f), segmentationOptions(200, 4))), 200);
  EXPECT_EQ(validCount(segmented(ramp(2.0f), segmentationOptions(11, 4))), 0);
  EXPECT_EQ(validCount(segmented(ramp(2.0f), segmentationOptions(10, 4))), 200);
}

TEST(SurfaceSegmentationTest, SurfacesJoinedLateInTheScanAreCountedWhole) {
  // A "U" and a "W": their arms get separate labels until the bottom row joins them.
  cv::Mat1f input(12, 30, kInvalidDisparity);
  input(cv::Rect(1, 1, 1, 10)).setTo(7.0f);
  input(cv::Rect(5, 1, 1, 10)).setTo(7.0f);
  input(cv::Rect(1, 10, 5, 1)).setTo(7.0f);  // U: 10 + 10 + 3 = 23 pixels
  for (const int x : {10, 14, 18, 22}) input(cv::Rect(x, 1, 1, 10)).setTo(9.0f);
  input(cv::Rect(10, 10, 13, 1)).setTo(9.0f);  // W: 4 * 10 + 9 = 49 pixels
  const cv::Mat1f output = segmented(input, segmentationOptions(23, 4));
  EXPECT_EQ(validCount(output), 23 + 49);
  EXPECT_EQ(validCount(segmented(input, segmentationOptions(24, 4))), 49);
  EXPECT_EQ(validCount(segmented(input, segmentationOptions(50, 4))), 0);
}

// A plain flood fill, the obvious way to find surfaces, as an independent reference.
cv::Mat1f floodFillReference(const cv::Mat1f& input, const SurfaceSegmentationOptions& options) {
  cv::Mat1f output = input.clone();
  cv::Mat1i label(input.size(), 0);
  int next = 0;
  std::vector<cv::Point> surface;
  for (int y = 0; y < input.rows; ++y) {
    for (int x = 0; x < input.cols; ++x) {
      if (label(y, x) || !isValidDisparity(input(y, x))) continue;
      label(y, x) = ++next;
      surface.assign(1, {x, y});
      for (size_t i = 0; i < surface.size(); ++i) {
        const cv::Point p = surface[i];
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if ((dx == 0 && dy == 0) || (options.connectivity == 4 && dx != 0 && dy != 0)) continue;
            const cv::Point q(p.x + dx, p.y + dy);
            if (q.x < 0 || q.y < 0 || q.x >= input.cols || q.y >= input.rows || label(q)) continue;
            if (!isValidDisparity(input(q))) continue;
            if (std::abs(input(q) - input(p)) > options.max_difference) continue;
            label(q) = next;
            surface.push_back(q);
          }
        }
      }
      if (static_cast<int>(surface.size()) < options.min_region_pixels) {
        for (const cv::Point& p : surface) output(p) = kInvalidDisparity;
      }
    }
  }
  return output;
}

void expectFloodFillResult(const cv::Mat1f& input, const SurfaceSegmentationOptions& options,
                           const std::string& what) {
  const cv::Mat1f expected = floodFillReference(input, options);
  const cv::Mat1f actual = segmented(input, options);
  ASSERT_EQ(cv::norm(actual != expected, cv::NORM_L1), 0.0)
      << what << ", " << options.connectivity << "-connected";
}

TEST(SurfaceSegmentationTest, MatchesFloodFillOnRandomImages) {
  cv::RNG rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    cv::Mat1f input(37, 53);
    for (float& d : input) d = rng.uniform(0.0, 1.0) < 0.1 ? kInvalidDisparity : rng.uniform(0, 4);
    for (const int connectivity : {4, 8}) {
      expectFloodFillResult(input, segmentationOptions(rng.uniform(2, 30), connectivity, 1.0f),
                            "trial " + std::to_string(trial));
    }
  }
}

TEST(SurfaceSegmentationTest, MatchesFloodFillOnSmoothImagesOfAnyWidth) {
  // Random walks along the rows make long surfaces whose rows span many pixels, across the
  // widths where a row's pixels fill whole 64-bit words, and one more or less.
  cv::RNG rng(11);
  for (const int width : {1, 2, 7, 63, 64, 65, 127, 128, 129, 300}) {
    for (int trial = 0; trial < 4; ++trial) {
      cv::Mat1f input(23, width);
      for (int y = 0; y < input.rows; ++y) {
        float d = static_cast<float>(rng.uniform(0, 6));
        for (int x = 0; x < width; ++x) {
          const double event = rng.uniform(0.0, 1.0);
          if (event < 0.03) d += rng.uniform(2, 4);  // a step that splits the row
          else if (event < 0.2) d += rng.uniform(-1, 2) * 0.5f;
          input(y, x) = rng.uniform(0.0, 1.0) < 0.05 ? kInvalidDisparity : d;
        }
      }
      for (const int connectivity : {4, 8}) {
        expectFloodFillResult(input, segmentationOptions(rng.uniform(2, 60), connectivity, 1.0f),
                              "width " + std::to_string(width) + ", trial " + std::to_string(trial));
      }
    }
  }
}

TEST(SurfaceSegmentationTest, KeepsWholeRowsThatFillTheirLastWord) {
  // One surface whose rows join from the first pixel to the last, at widths that fill whole
  // 64-bit words: a row's run ends where the row does.
  for (const int width : {64, 128}) {
    cv::Mat1f input(5, width, 3.0f);
    input(2, width - 1) = kInvalidDisparity;
    EXPECT_EQ(validCount(segmented(input, segmentationOptions(5 * width - 1))), 5 * width - 1) << width;
    EXPECT_EQ(validCount(segmented(input, segmentationOptions(5 * width))), 0) << width;
  }
}

TEST(SurfaceSegmentationTest, FourConnectedResultEqualsOpenCvFilterSpeckles) {
  const cv::Mat1f input = noisyTsukubaDisparity(3);
  constexpr int kMinRegion = 100;
  const cv::Mat1f ours = segmented(input, segmentationOptions(kMinRegion, 4, 1.0f));

  constexpr int16_t kInvalid = -16;
  cv::Mat1s theirs = toFixedPointDisparity(input, kInvalid);
  // filterSpeckles removes blobs of at most maxSpeckleSize pixels; we remove fewer than
  // min_region_pixels. Its disparities are x16.
  cv::filterSpeckles(theirs, kInvalid, kMinRegion - 1, 16.0);

  EXPECT_EQ(cv::norm(toFixedPointDisparity(ours, kInvalid) != theirs, cv::NORM_L1), 0.0);
  // The image really had spikes to remove.
  EXPECT_LT(validCount(ours), validCount(input) - 1000);
}

TEST(SurfaceSegmentationTest, BuffersAreReusedAcrossFramesOfDifferentSizes) {
  SurfaceSegmentation segmentation(segmentationOptions(100));
  cv::Mat1b rejected;
  const PoleScene scene;
  cv::Mat1f large = noisyTsukubaDisparity(5);
  segmentation.apply(large, rejected);
  cv::Mat1f small = scene.disparity();
  segmentation.apply(small, rejected);
  EXPECT_EQ(rejected.size(), small.size());
  EXPECT_EQ(cv::countNonZero(rejected), 30);
  EXPECT_EQ(scene.countInRect(small, scene.pole, PoleScene::kPoleDisparity), 60);
}

}  // namespace
}  // namespace stereonav
