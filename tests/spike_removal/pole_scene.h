#pragma once

#include <opencv2/core.hpp>

#include "disparity/disparity_image.h"

namespace stereonav {

// The situation of paper section 4.1 as a disparity image, 80 x 100: a wall far away (disparity
// 5) above a floor whose disparity grows smoothly towards the camera (20 at its far edge, +0.5 per
// row), a 1-pixel-wide, 60-pixel-tall pole standing on the floor (disparity 20, like the floor where
// it stands), and a compact 5 x 6 = 30-pixel mismatch blob on the wall at disparity 30.
struct PoleScene {
  static constexpr int kWidth = 80;
  static constexpr int kHeight = 100;
  static constexpr int kFloorTopRow = 60;
  static constexpr int kPoleColumn = 40;
  static constexpr float kWallDisparity = 5.0f;
  static constexpr float kPoleDisparity = 20.0f;
  static constexpr float kBlobDisparity = 30.0f;
  const cv::Rect blob{10, 10, 6, 5};
  const cv::Rect pole{kPoleColumn, 0, 1, kFloorTopRow};

  static float floorDisparity(int row) { return kPoleDisparity + 0.5f * (row - kFloorTopRow); }

  cv::Mat1f disparity() const {
    cv::Mat1f image(kHeight, kWidth, kWallDisparity);
    for (int y = kFloorTopRow; y < kHeight; ++y) image.row(y).setTo(floorDisparity(y));
    image(pole).setTo(kPoleDisparity);
    image(blob).setTo(kBlobDisparity);
    return image;
  }

  int countInRect(const cv::Mat1f& image, const cv::Rect& rect, float value) const {
    int count = 0;
    for (int y = rect.y; y < rect.y + rect.height; ++y) {
      for (int x = rect.x; x < rect.x + rect.width; ++x) count += image(y, x) == value;
    }
    return count;
  }
};

}  // namespace stereonav
