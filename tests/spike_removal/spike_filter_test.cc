#include "spike_removal/spike_filter.h"

#include <gtest/gtest.h>

#include "pole_scene.h"

namespace stereonav {
namespace {

// Paper sections 4.1 and 4.2 on one scene: a thin pole on the floor and a compact mismatch blob.
class SpikeFilterPaperComparison : public ::testing::Test {
 protected:
  cv::Mat1f filtered(SpikeFilterType type) {
    SpikeRemovalOptions options;
    options.filter = type;
    options.segmentation.min_region_pixels = 100;  // > blob (30), > pole alone (60)
    options.median_kernel = 3;
    options.erosion_kernel = 3;
    cv::Mat1f disparity = scene_.disparity();
    SpikeFilter filter(options);
    EXPECT_EQ(filter.type(), type);
    filter.apply(disparity, rejected_);
    return disparity;
  }

  int polePixelsKept(const cv::Mat1f& disparity) const {
    return scene_.countInRect(disparity, scene_.pole, PoleScene::kPoleDisparity);
  }
  int blobPixelsKept(const cv::Mat1f& disparity) const {
    return scene_.countInRect(disparity, scene_.blob, PoleScene::kBlobDisparity);
  }

  const PoleScene scene_;
  cv::Mat1b rejected_;
};

TEST_F(SpikeFilterPaperComparison, NoneChangesNothing) {
  const cv::Mat1f output = filtered(SpikeFilterType::kNone);
  EXPECT_EQ(cv::norm(output != scene_.disparity(), cv::NORM_L1), 0.0);
  EXPECT_EQ(cv::countNonZero(rejected_), 0);
}

TEST_F(SpikeFilterPaperComparison, SegmentationKeepsThePoleAndRemovesTheBlob) {
  const cv::Mat1f output = filtered(SpikeFilterType::kSegmentation);
  EXPECT_EQ(polePixelsKept(output), 60);
  EXPECT_EQ(blobPixelsKept(output), 0);
  EXPECT_EQ(cv::countNonZero(rejected_), 30);
}

TEST_F(SpikeFilterPaperComparison, MedianLosesThePoleAndKeepsMostOfTheBlob) {
  const cv::Mat1f output = filtered(SpikeFilterType::kMedian);
  // Above the floor every pole pixel sees 3 pole and 6 wall pixels: the median is the wall.
  EXPECT_EQ(scene_.countInRect(output, {PoleScene::kPoleColumn, 0, 1, PoleScene::kFloorTopRow - 1},
                               PoleScene::kPoleDisparity),
            0);
  // Only the blob's 4 corners see fewer blob pixels than wall pixels.
  EXPECT_EQ(blobPixelsKept(output), 30 - 4);
}

TEST_F(SpikeFilterPaperComparison, ErosionLosesThePoleAndKeepsTheBlobsCore) {
  const cv::Mat1f output = filtered(SpikeFilterType::kErosion);
  EXPECT_EQ(polePixelsKept(output), 0);
  EXPECT_EQ(blobPixelsKept(output), (6 - 2) * (5 - 2));
}

}  // namespace
}  // namespace stereonav
